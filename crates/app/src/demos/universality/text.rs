//! The universality demo's prose: summary, equation, the table of machines, the match
//! status and the figures' text alternatives.

use super::params::Kind;
use super::{machine, Matching, One};
use crate::declare::Choice;
use crate::format::{si, significant};
use crate::spec::Table;
use zeta_solver::Regime;

pub(super) const SUMMARY: &str =
    "Six machines, one equation a·y″ + b·y′ + c·y = f(t). Choose a machine for A and one \
     for B and set each by its own physical parameters: each gives its own a, b and c, in \
     its own units, and so a natural frequency ωₙ = √(c/a) and a damping ratio \
     ζ = b/(2√(ac)). Released from y₀ at rest, a machine's normalised response y/y₀ \
     against ωₙt depends on ζ alone, so machines with equal ζ draw one curve. Tick \
     \u{201c}match\u{201d} and B's tuning parameters are solved so that its ωₙ and ζ equal \
     A's: then B behaves exactly like A, second by second. The two-capacity thermal \
     system never oscillates: b² − 4ac = (τ₁ − τ₂)² + R₁C₂(2τ₁ + 2τ₂ + R₁C₂) > 0, so its \
     ζ > 1 whatever its capacities and resistances — heat has no inertia to carry it \
     past equilibrium.";

pub(super) const EQUATION: &str = "<math display=\"block\"><mrow>\
<mi>a</mi><mover><mi>y</mi><mo>¨</mo></mover><mo>+</mo><mi>b</mi><mover><mi>y</mi><mo>˙</mo></mover>\
<mo>+</mo><mi>c</mi><mi>y</mi><mo>=</mo><mi>f</mi><mo>(</mo><mi>t</mi><mo>)</mo><mo>,</mo>\
<mspace width=\"1em\"/><msub><mi>ω</mi><mi>n</mi></msub><mo>=</mo><msqrt><mi>c</mi><mo>/</mo><mi>a</mi></msqrt>\
<mo>,</mo><mspace width=\"1em\"/><mi>ζ</mi><mo>=</mo><mfrac><mi>b</mi><mrow><mn>2</mn><msqrt><mi>a</mi><mi>c</mi></msqrt></mrow></mfrac>\
</mrow></math>";

/// What y, a, b and c are in each machine.
pub(super) fn table() -> Table {
    Table {
        caption: "One equation, many machines: what y, a, b and c are",
        columns: vec!["machine", "coordinate y", "a", "b", "c", "ωₙ", "ζ"],
        rows: vec![
            (
                "mass-spring",
                vec![
                    "mass–spring–damper",
                    "displacement x [m]",
                    "mass m [kg]",
                    "damping coefficient c [N·s/m]",
                    "spring rate k [N/m]",
                    "√(k/m)",
                    "c/(2√(km))",
                ],
            ),
            (
                "rlc",
                vec![
                    "series RLC circuit",
                    "charge q [C]",
                    "inductance L [H]",
                    "resistance R [Ω]",
                    "1/C [1/F]",
                    "1/√(LC)",
                    "(R/2)·√(C/L)",
                ],
            ),
            (
                "u-tube",
                vec![
                    "U-tube manometer",
                    "level change h [m]",
                    "ρAL [kg]",
                    "8πμL [N·s/m]",
                    "2ρgA [N/m]",
                    "√(2g/L)",
                    "16μ/(ρd²ωₙ)",
                ],
            ),
            (
                "servo",
                vec![
                    "DC-motor position servo (PD control)",
                    "angle error θ [rad]",
                    "J [kg·m²]",
                    "K_t(K_t + K_d)/R_a [N·m·s/rad]",
                    "K_t·K_p/R_a [N·m/rad]",
                    "√(K_t·K_p/(R_a·J))",
                    "≥ K_t²/(2ωₙR_a·J), the back-EMF alone",
                ],
            ),
            (
                "storey",
                vec![
                    "building storey under ground motion",
                    "storey drift u [m]",
                    "floor mass m [kg]",
                    "damping coefficient c [N·s/m]",
                    "12·4·EI/h³ [N/m]",
                    "√(48EI/(m·h³))",
                    "c/(2√(km))",
                ],
            ),
            (
                "thermal",
                vec![
                    "two-capacity thermal system",
                    "temperature excess T₂ [K]",
                    "R₁C₁R₂C₂ [s²]",
                    "R₁C₁ + R₂C₂ + R₁C₂ [s]",
                    "1",
                    "1/√(τ₁τ₂)",
                    "(τ₁ + τ₂ + R₁C₂)/(2√(τ₁τ₂)) > 1",
                ],
            ),
        ],
        // The rows name machines and no readout carries a machine's key, so nothing is
        // highlighted: both chosen machines are named in the controls above.
        highlight_readout: "match",
    }
}

/// `v` in `unit`: with an SI prefix where one reads well, plainly for units that already
/// carry a prefix or a power (kg, kg·m², s²).
pub(super) fn amount(v: f64, unit: &str) -> String {
    if unit.starts_with("kg") || unit.ends_with('²') {
        format!("{} {unit}", significant(v, 4))
    } else {
        si(v, unit, 4)
    }
}

/// The match status, for its readout.
pub(super) fn matching(m: &Matching) -> String {
    match *m {
        Matching::Off => "off".to_string(),
        Matching::Exact => "on: B has the ωₙ and ζ of A".to_string(),
        Matching::TooLight { zeta_min, zeta } => format!(
            "not reachable: with its other parameters kept, B cannot go below ζ = {}; A has ζ = {}",
            significant(zeta_min, 4),
            significant(zeta, 4)
        ),
        Matching::OutOfRange {
            symbol,
            unit,
            value,
            range,
        } => format!(
            "not reachable within the sliders: B would need {symbol} = {}, outside {} … {}",
            amount(value, unit),
            amount(range.0, unit),
            amount(range.1, unit)
        ),
        Matching::Impossible => "not reachable: A has no natural frequency".to_string(),
    }
}

/// How a machine returns to rest, in words.
fn behaviour(one: &One) -> &'static str {
    match one.sys.regime() {
        Regime::Undamped => "oscillates for ever",
        Regime::Underdamped => "oscillates and dies away",
        Regime::CriticallyDamped => "returns as fast as it can without overshoot",
        _ => "creeps back without overshoot",
    }
}

/// `"A (mass–spring–damper, ζ = 0.1000)"`.
fn named(slot: &str, one: &One) -> String {
    format!(
        "{slot} ({}, ζ = {})",
        one.kind.label(),
        significant(one.sys.damping_ratio().unwrap_or(0.0), 4)
    )
}

/// The normalised responses in words; `gap` is the largest difference between them.
pub(super) fn describe_normalised(m: &[One; 2], gap: f64) -> String {
    let relation = if gap <= 1e-9 {
        format!(
            "The two curves coincide (largest difference {}).",
            si(gap, "", 2)
        )
    } else {
        format!("The curves differ by up to {} of y₀.", si(gap, "", 3))
    };
    let thermal = if m.iter().any(|one| one.kind == Kind::Thermal) {
        " A two-capacity thermal system cannot oscillate: its ζ is above 1 for any capacities and resistances."
    } else {
        ""
    };
    format!(
        "Released from rest: {} {}; {} {}. {relation}{thermal}",
        named("A", &m[0]),
        behaviour(&m[0]),
        named("B", &m[1]),
        behaviour(&m[1]),
    )
}

/// The real-time responses in words.
pub(super) fn describe_realtime(m: &[One; 2], t_end: f64) -> String {
    let (wa, wb) = (m[0].wn(), m[1].wn());
    let ratio = wb / wa;
    let pace = if (ratio - 1.0).abs() <= 1e-9 {
        "B keeps pace with A exactly".to_string()
    } else if ratio > 1.0 {
        format!("B runs {} times faster than A", significant(ratio, 3))
    } else {
        format!("B runs {} times slower than A", significant(1.0 / ratio, 3))
    };
    format!(
        "Real time over {}: time scale 1/ωₙ of A {}, of B {}; {pace}.",
        si(t_end, "s", 3),
        si(1.0 / wa, "s", 3),
        si(1.0 / wb, "s", 3),
    )
}

/// The schematic in words at time `t` \[s\], with the normalised positions `y/y₀`.
pub(super) fn describe_schematic(m: &[One; 2], t: f64, y: [f64; 2]) -> String {
    let part = |slot: &str, one: &One, y: f64| {
        format!(
            "{slot}, {}: {} = {}",
            one.kind.label(),
            machine::normalised_coordinate(one.kind),
            significant(y, 3)
        )
    };
    format!(
        "At t = {}: {}; {}.",
        si(t, "s", 3),
        part("A", &m[0], y[0]),
        part("B", &m[1], y[1])
    )
}
