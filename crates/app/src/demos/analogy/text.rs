//! The analogy demo's prose: summary, equation, the paper's Table 1 and the figures' text
//! alternatives.

use super::Results;
use crate::demos::digits::trimmed;
use crate::format::{self, si};
use crate::spec::Table;
use crate::t;

pub(super) const SUMMARY: &str =
    "A mass on a spring and damper and a series inductor–resistor–capacitor \
                      loop obey the same second-order equation. In the force–voltage analogy \
                      mass m ↔ inductance L, damping c ↔ resistance R, stiffness k ↔ 1/C, force \
                      F ↔ voltage E and displacement x ↔ charge q (so velocity ↔ current). \
                      Here the circuit is given the same numbers as the mechanism (L in H = m \
                      in kg, R in Ω = c in N·s/m, 1/C in 1/F = k in N/m, q₀ in C = x₀ in m), \
                      both released from rest: change any slider and both machines change \
                      together, their normalised responses stay one curve, and the energy \
                      swings between spring and mass exactly as between capacitor and inductor.";

pub(super) const EQUATION: &str = "<math display=\"block\"><mrow>\
<mi>m</mi><mover><mi>x</mi><mo>¨</mo></mover><mo>+</mo><mi>c</mi><mover><mi>x</mi><mo>˙</mo></mover>\
<mo>+</mo><mi>k</mi><mi>x</mi><mo>=</mo><mi>F</mi><mo>(</mo><mi>t</mi><mo>)</mo>\
</mrow></math>\
<math display=\"block\"><mrow><mo>⟷</mo><mspace width=\"0.5em\"/><mi>L</mi><mover><mi>q</mi><mo>¨</mo></mover><mo>+</mo><mi>R</mi><mover><mi>q</mi><mo>˙</mo></mover>\
<mo>+</mo><mfrac><mi>q</mi><mi>C</mi></mfrac><mo>=</mo><mi>E</mi><mo>(</mo><mi>t</mi><mo>)</mo>\
</mrow></math>";

/// The force–voltage analogy (the paper's Table 1), live: beside each quantity of either
/// machine, its current value in this demo (the readout of the same key).
pub(super) fn analogy_table() -> Table {
    use crate::live_cell as live;
    const AT_REST: &str = "0 at release";
    Table {
        caption: "The force–voltage analogy: a·y″ + b·y′ + c·y = f(t) read two ways, with \
                  the values of both machines now",
        columns: vec![
            "role in the equation",
            "mechanical",
            "value now",
            "electrical",
            "value now",
        ],
        rows: vec![
            (
                "inertia",
                vec![
                    "inertia a",
                    "mass m [kg]",
                    live!("m"),
                    "inductance L [H]",
                    live!("L"),
                ],
            ),
            (
                "dissipation",
                vec![
                    "dissipation b",
                    "damping coefficient c [N·s/m]",
                    live!("c"),
                    "resistance R [Ω]",
                    live!("R"),
                ],
            ),
            (
                "stiffness",
                vec![
                    "stiffness c",
                    "spring rate k [N/m]",
                    live!("k"),
                    "elastance 1/C [1/F]",
                    live!("elastance"),
                ],
            ),
            (
                "compliance",
                vec![
                    "compliance 1/c",
                    "compliance 1/k [m/N]",
                    live!("compliance"),
                    "capacitance C [F]",
                    live!("C"),
                ],
            ),
            (
                "drive",
                vec![
                    "drive f(t)",
                    "force F [N]",
                    "0: released from rest",
                    "voltage E [V]",
                    "0: no source in the loop",
                ],
            ),
            (
                "coordinate",
                vec![
                    "coordinate y, initially y₀",
                    "displacement x, initially x₀ [m]",
                    live!("x0"),
                    "charge q, initially q₀ [C]",
                    live!("q0"),
                ],
            ),
            (
                "rate",
                vec![
                    "rate y′",
                    "velocity v = ẋ [m/s]",
                    AT_REST,
                    "current i = q̇ [A]",
                    AT_REST,
                ],
            ),
            (
                "natural frequency",
                vec![
                    "natural frequency √(c/a)",
                    "ωₙ = √(k/m) [rad/s]",
                    live!("wn"),
                    "ω₀ = 1/√(LC) [rad/s]",
                    live!("w0"),
                ],
            ),
            (
                "damping ratio",
                vec![
                    "damping ratio ζ = b/(2√(ac))",
                    "ζ = c/(2√(mk))",
                    live!("zeta"),
                    "ζ = (R/2)·√(C/L)",
                    live!("zeta"),
                ],
            ),
            (
                "quality factor",
                vec![
                    "quality factor Q = √(ac)/b",
                    "Q = √(mk)/c",
                    live!("Q"),
                    "Q = √(L/C)/R",
                    live!("Q"),
                ],
            ),
            (
                "potential energy",
                vec![
                    "stored by the stiffness",
                    "spring ½kx², at release ½kx₀² [J]",
                    live!("energy"),
                    "capacitor ½q²/C, at release ½q₀²/C [J]",
                    live!("energy"),
                ],
            ),
            (
                "kinetic energy",
                vec![
                    "stored by the inertia",
                    "mass ½mv² [J]",
                    AT_REST,
                    "inductor ½Li² [J]",
                    AT_REST,
                ],
            ),
            (
                "power lost",
                vec![
                    "dissipated power",
                    "damper c·v² [W]",
                    AT_REST,
                    "resistor R·i² [W]",
                    AT_REST,
                ],
            ),
        ],
        // No row matches a regime name: the table is a fixed dictionary, not a
        // selection, so nothing is highlighted.
        highlight_readout: "regime",
    }
}

/// The normalised responses in words; `gap` is the largest difference between a
/// mechanical curve and its electrical twin.
pub(super) fn describe_responses(r: &Results, gap: f64) -> String {
    let zeta = r.mech.damping_ratio().unwrap_or(0.0);
    let (motion, frequency, time) = match r.mech.damped_frequency() {
        Some(wd) if zeta > 0.0 => (
            "decaying",
            si(wd, "rad/s", 3),
            si(1.0 / (zeta * r.wn()), "s", 3),
        ),
        Some(wd) => ("lasting", si(wd, "rad/s", 3), String::new()),
        None => ("creeping", String::new(), String::new()),
    };
    t!(
        "analogy-describe-responses",
        regime = format::regime(r.mech.regime()),
        zeta = trimmed(zeta, 3),
        same = if gap == 0.0 { "exact" } else { "close" },
        difference = si(gap, "", 2),
        motion = motion,
        frequency = frequency,
        time = time
    )
}

/// The energy exchange in words: `e0` stored at release, `left` at the end of the window
/// and at most `kinetic_peak` in the mass at once \[J\].
pub(super) fn describe_energy(r: &Results, e0: f64, left: f64, kinetic_peak: f64) -> String {
    t!(
        "analogy-describe-energy",
        energy = si(e0, "J", 3),
        exchange = if r.mech.damped_frequency().is_some() {
            "swings"
        } else {
            "passes"
        },
        peak = si(kinetic_peak, "J", 3),
        loss = if left >= 0.999_999 * e0 {
            "none"
        } else {
            "heat"
        },
        left = si(left, "J", 3),
        percent = si(100.0 * left / e0.max(1e-300), "%", 3),
        time = si(r.t_end, "s", 3)
    )
}

/// Both machines at time `t` \[s\] in words.
pub(super) fn describe_schematic(t: f64, [x, v]: [f64; 2], [q, i]: [f64; 2]) -> String {
    t!(
        "analogy-schematic",
        time = si(t, "s", 3),
        displacement = si(x, "m", 3),
        velocity = si(v, "m/s", 3),
        charge = si(q, "C", 3),
        current = si(i, "A", 3)
    )
}
