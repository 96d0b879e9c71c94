//! The nonlinear demo's prose: summary, equation, presets, the table of nonlinearities and
//! the figures' text alternatives.

use super::{Results, ESCAPE};
use crate::demos::rows;
use crate::format::si;
use crate::spec::{Preset, Table};
use crate::t;
use zeta_solver::nonlinear::NonlinearModel;

pub(super) const SUMMARY: &str =
    "A real suspension is only linear for small motions. Here the quarter car gets a cubic \
     spring (k₃ > 0 hardening, k₃ < 0 softening), a damper that is stiffer in rebound \
     (x′ > 0) than in compression, Coulomb friction in the joints and rubber bump stops beyond \
     ±gap. Friction sticks and slips: while the mass slides it drags with the force F_c; once \
     it stops, static friction holds it up to F_static, a set multiple of F_c, and it moves \
     again only if the spring pulls harder. The motion is integrated with RK4, every stop \
     located within its step, and drawn against the linear model m·x″ + c̄·x′ + k·x = 0 (c̄ \
     the mean damper rate) from the same start. Watch where the prediction fails: the period \
     depends on the amplitude (hardening shortens it, softening lengthens it), friction makes \
     the amplitude fall in a straight line and then holds the mass off-centre for good \
     (stick–slip), a bump stop turns a smooth swing into an impact, and an asymmetric damper \
     shifts the mean position. The defaults are a plausible car corner: 300 kg, \
     24 kN/m (1.4 Hz), a 1 500 N·s/m damper (ζ ≈ 0.28) and a mildly progressive spring. x is \
     the suspension extension from static equilibrium (positive = body up).";

pub(super) const EQUATION: &str = "<math display=\"block\"><mrow>\
<mi>m</mi><mover><mi>x</mi><mo>¨</mo></mover><mo>+</mo>\
<msub><mi>F</mi><mi>d</mi></msub><mo>(</mo><mover><mi>x</mi><mo>˙</mo></mover><mo>)</mo><mo>+</mo>\
<msub><mi>F</mi><mi>c</mi></msub><mi>sgn</mi><mo>(</mo><mover><mi>x</mi><mo>˙</mo></mover><mo>)</mo>\
<mo>+</mo><mi>k</mi><mi>x</mi><mo>+</mo><msub><mi>k</mi><mn>3</mn></msub><msup><mi>x</mi><mn>3</mn></msup>\
<mo>+</mo><msub><mi>F</mi><mtext>stop</mtext></msub><mo>(</mo><mi>x</mi><mo>)</mo><mo>=</mo><mn>0</mn>\
</mrow></math>";

/// One preset per nonlinearity, and one with all of them off. Each sets every parameter:
/// its `defaults` (the declared sliders') with a linear spring, then its changes.
pub(super) fn presets(defaults: &[(&'static str, f64)]) -> Vec<Preset> {
    let linear = rows::preset("", defaults, &[("k3", 0.0)]).values;
    let preset = |label, changes: &[(&'static str, f64)]| rows::preset(label, &linear, changes);
    vec![
        preset("Linear (all off)", &[]),
        preset(
            "Hardening spring",
            &[("k3", 3.0e6), ("c_comp", 150.0), ("c_reb", 150.0)],
        ),
        preset(
            "Softening spring",
            &[("k3", -2.0e6), ("c_comp", 150.0), ("c_reb", 150.0)],
        ),
        preset(
            "Friction stick–slip",
            &[("friction", 300.0), ("c_comp", 50.0), ("c_reb", 50.0)],
        ),
        preset(
            "Bump-stop impact",
            &[
                ("k_stop", 300_000.0),
                ("gap", 0.05),
                ("x0", 0.0),
                ("v0", 1.5),
                ("c_comp", 500.0),
                ("c_reb", 500.0),
            ],
        ),
        preset(
            "Asymmetric damper",
            &[("c_comp", 1_000.0), ("c_reb", 3_000.0)],
        ),
    ]
}

/// Where the linear model fails; the row of the dominant effect is highlighted.
pub(super) fn table() -> Table {
    Table {
        caption: "Where the linear model fails",
        columns: vec![
            "nonlinearity",
            "force law",
            "what the linear model misses",
            "signature in the plots",
        ],
        rows: vec![
            (
                "linear",
                vec![
                    "None (linear)",
                    "k·x + c·x′",
                    "nothing: the model is exact",
                    "the two curves coincide",
                ],
            ),
            (
                "hardening spring",
                vec![
                    "Hardening spring",
                    "k·x + k₃·x³, k₃ > 0",
                    "frequency rises with amplitude",
                    "shorter period while the swing is large; the curves drift apart",
                ],
            ),
            (
                "softening spring",
                vec![
                    "Softening spring",
                    "k·x + k₃·x³, k₃ < 0",
                    "frequency falls with amplitude; past √(−k/k₃) the spring gives way",
                    "longer period; a large start can escape",
                ],
            ),
            (
                "stick-slip",
                vec![
                    "Coulomb friction",
                    "F_c·sgn(x′) sliding; up to F_static at rest",
                    "amplitude falls by about 4F_c/k per cycle, in a straight line, then \
                             the mass sticks for good where |k·x| ≤ F_static",
                    "straight-line envelope; a flat end off zero",
                ],
            ),
            (
                "bump-stop impact",
                vec![
                    "Bump stops",
                    "k_stop·(|x| − gap) beyond ±gap",
                    "a sudden stiff contact: large force, fast reversal",
                    "clipped peaks at ±gap; kinks in the phase loop",
                ],
            ),
            (
                "asymmetric damper",
                vec![
                    "Asymmetric damper",
                    "c_r·x′ in rebound, c_c·x′ in compression",
                    "a mean shift (jacking) and unequal half-cycles",
                    "lopsided decay; the phase spiral is off-centre",
                ],
            ),
            (
                "several at once",
                vec![
                    "Several at once",
                    "sum of the above",
                    "their effects add and interact",
                    "see each row",
                ],
            ),
            (
                "escaped",
                vec![
                    "Softening spring past its limit",
                    "k·x + k₃·x³ < 0 for |x| > √(−k/k₃)",
                    "the model stops describing a suspension",
                    "the run is cut where |x| exceeds 1 m",
                ],
            ),
        ],
        highlight_readout: "effect",
    }
}

/// The dominant effect (a table row key) in the interface language.
pub(super) fn effect_name(effect: &str) -> String {
    match effect {
        "hardening spring" => t!("nonlinear-effect-hardening"),
        "softening spring" => t!("nonlinear-effect-softening"),
        "stick-slip" => t!("nonlinear-effect-stick-slip"),
        "bump-stop impact" => t!("nonlinear-effect-bump-stop"),
        "asymmetric damper" => t!("nonlinear-effect-asymmetric"),
        "several at once" => t!("nonlinear-effect-several"),
        "escaped" => t!("nonlinear-effect-escaped"),
        _ => t!("nonlinear-effect-linear"),
    }
}

/// The two responses in words.
pub(super) fn describe_response(r: &Results) -> String {
    let cmp = &r.cmp;
    let worst = cmp.largest_deviation();
    let mut clauses = vec![t!(
        "nonlinear-differ",
        deviation = si(worst.0, "m", 3),
        time = si(worst.1, "s", 3)
    )];
    if let (Some(a), Some(b)) = (cmp.first_swing_nonlinear(), cmp.first_swing_linear()) {
        clauses.push(t!(
            "nonlinear-first-swing",
            nonlinear = si(a, "s", 3),
            linear = si(b, "s", 3),
            ratio = si(a / b, "", 3)
        ));
    }
    if let Some(st) = cmp.sticking {
        clauses.push(t!(
            "nonlinear-sticks-at",
            position = si(st.x, "m", 3),
            time = si(st.t, "s", 3)
        ));
    }
    if cmp.escaped {
        clauses.push(t!(
            "nonlinear-escapes",
            limit = si(ESCAPE, "m", 2),
            time = si(cmp.t.last().copied().unwrap_or(0.0), "s", 3)
        ));
    }
    t!(
        "nonlinear-describe-response",
        effect = effect_name(r.effect),
        clauses = clauses.join(&t!("nonlinear-join"))
    )
}

/// The phase plane in words, from the plotted points.
pub(super) fn describe_phase(nl: &[(f64, f64)], lin: &[(f64, f64)]) -> String {
    let end = |pts: &[(f64, f64)]| pts.last().copied().unwrap_or((0.0, 0.0));
    let (ne, le) = (end(nl), end(lin));
    t!(
        "nonlinear-describe-phase",
        x0 = si(nl.first().map_or(0.0, |p| p.0), "m", 3),
        v0 = si(nl.first().map_or(0.0, |p| p.1), "m/s", 3),
        x_linear = si(le.0, "m", 2),
        v_linear = si(le.1, "m/s", 2),
        x_end = si(ne.0, "m", 3),
        v_end = si(ne.1, "m/s", 3),
        speed = si(nl.iter().map(|p| p.1.abs()).fold(0.0, f64::max), "m/s", 3),
        speed_linear = si(lin.iter().map(|p| p.1.abs()).fold(0.0, f64::max), "m/s", 3)
    )
}

/// The spring curve in words, over ±`reach` (m).
pub(super) fn describe_spring(model: &NonlinearModel, reach: f64, max_travel: f64) -> String {
    let cfg = model.config();
    let at = max_travel.max(1e-6);
    let (reach, travel) = (si(reach, "m", 3), si(at, "m", 3));
    let (force, linear) = (si(model.elastic_force(at), "N", 3), si(cfg.k * at, "N", 3));
    let stops = if cfg.stop_stiffness > 0.0 {
        "yes"
    } else {
        "no"
    };
    t!(
        "nonlinear-describe-spring",
        reach = reach,
        travel = travel,
        force = force,
        linear = linear,
        stops = stops,
        rate = si(cfg.stop_stiffness, "N/m", 3),
        gap = si(cfg.stop_gap, "m", 3)
    )
}

/// The damper curve in words, over ±`vmax` (m/s); `c_mean` the linear model's rate.
pub(super) fn describe_damper(model: &NonlinearModel, vmax: f64, c_mean: f64) -> String {
    let cfg = model.config();
    let speed = si(vmax, "m/s", 3);
    let rebound = si(model.dissipative_force(vmax), "N", 3);
    let compression = si(model.dissipative_force(-vmax), "N", 3);
    let linear = si(c_mean * vmax, "N", 3);
    t!(
        "nonlinear-describe-damper",
        speed = speed,
        rebound = rebound,
        compression = compression,
        linear = linear,
        coulomb = if cfg.friction > 0.0 { "yes" } else { "no" },
        friction = si(cfg.friction, "N", 3),
        holding = si(model.static_limit(), "N", 3)
    )
}
