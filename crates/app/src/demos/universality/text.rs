//! The universality demo's prose: summary, equation, the table of machines, the match
//! status and the figures' text alternatives.

use super::params::Kind;
use super::{machine, Matching, One};
use crate::format::{si, significant};
use crate::spec::Table;
use crate::t;
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
        Matching::Off => t!("universality-match-off"),
        Matching::Exact => t!("universality-match-on"),
        Matching::TooLight { zeta_min, zeta } => t!(
            "universality-match-too-light",
            zeta_min = significant(zeta_min, 4),
            zeta = significant(zeta, 4)
        ),
        Matching::OutOfRange {
            symbol,
            unit,
            value,
            range,
        } => t!(
            "universality-match-out-of-range",
            symbol = symbol,
            value = amount(value, unit),
            low = amount(range.0, unit),
            high = amount(range.1, unit)
        ),
        Matching::Impossible => t!("universality-match-impossible"),
    }
}

/// The name of a machine in the interface language (the option's declared label).
pub(super) fn machine_name(kind: Kind) -> String {
    match kind {
        Kind::MassSpring => t!("universality-param-A-mass-spring"),
        Kind::Rlc => t!("universality-param-A-rlc"),
        Kind::UTube => t!("universality-param-A-u-tube"),
        Kind::Servo => t!("universality-param-A-servo"),
        Kind::Storey => t!("universality-param-A-storey"),
        Kind::Thermal => t!("universality-param-A-thermal"),
    }
}

/// How a machine returns to rest, as a selector key of the descriptions.
fn behaviour(one: &One) -> &'static str {
    match one.sys.regime() {
        Regime::Undamped => "forever",
        Regime::Underdamped => "dies-away",
        Regime::CriticallyDamped => "fastest",
        _ => "creeps",
    }
}

/// A machine's damping ratio as the descriptions write it (`0.1000`).
fn zeta(one: &One) -> String {
    significant(one.sys.damping_ratio().unwrap_or(0.0), 4)
}

/// The normalised responses in words; `gap` is the largest difference between them.
pub(super) fn describe_normalised(m: &[One; 2], gap: f64) -> String {
    let coincide = gap <= 1e-9;
    t!(
        "universality-describe-normalised",
        machine_a = machine_name(m[0].kind),
        zeta_a = zeta(&m[0]),
        behaviour_a = behaviour(&m[0]),
        machine_b = machine_name(m[1].kind),
        zeta_b = zeta(&m[1]),
        behaviour_b = behaviour(&m[1]),
        relation = if coincide { "coincide" } else { "differ" },
        gap = si(gap, "", if coincide { 2 } else { 3 }),
        thermal = if m.iter().any(|one| one.kind == Kind::Thermal) {
            "yes"
        } else {
            "no"
        }
    )
}

/// The real-time responses in words.
pub(super) fn describe_realtime(m: &[One; 2], t_end: f64) -> String {
    let (wa, wb) = (m[0].wn(), m[1].wn());
    let ratio = wb / wa;
    let (pace, factor) = if (ratio - 1.0).abs() <= 1e-9 {
        ("same", String::new())
    } else if ratio > 1.0 {
        ("faster", significant(ratio, 3))
    } else {
        ("slower", significant(1.0 / ratio, 3))
    };
    t!(
        "universality-describe-realtime",
        window = si(t_end, "s", 3),
        scale_a = si(1.0 / wa, "s", 3),
        scale_b = si(1.0 / wb, "s", 3),
        pace = pace,
        factor = factor
    )
}

/// The schematic in words at time `t` \[s\], with the normalised positions `y/y₀`.
pub(super) fn describe_schematic(m: &[One; 2], t: f64, y: [f64; 2]) -> String {
    t!(
        "universality-schematic",
        time = si(t, "s", 3),
        machine_a = machine_name(m[0].kind),
        coordinate_a = machine::normalised_coordinate(m[0].kind),
        value_a = significant(y[0], 3),
        machine_b = machine_name(m[1].kind),
        coordinate_b = machine::normalised_coordinate(m[1].kind),
        value_b = significant(y[1], 3)
    )
}
