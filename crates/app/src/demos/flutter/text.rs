//! The flutter demo's prose: summary, equation, the flutter-versus-resonance table and the
//! figures' text alternatives.

use super::{Results, U_MAX};
use crate::format::si;
use crate::spec::Table;
use zeta_solver::flutter::degrees;
use zeta_solver::Regime;

/// Metres per second in one mile per hour.
const MPH: f64 = 0.447_04;

pub(super) const SUMMARY: &str =
    "A steady wind can feed a twisting bridge deck energy through its own \
                      motion: the aerodynamic moment follows the twist rate, acting as negative \
                      damping. The structure's damping ratio ζ_s is eaten away as the wind \
                      speed U rises, ζ_eff = ζ_s − g·U, until at the critical speed U_crit = \
                      ζ_s/g it reaches zero: the poles cross the imaginary axis and any small \
                      twist grows like e^(σt) at the deck's own torsional frequency. This is not \
                      resonance. Forced resonance needs a force that oscillates near the natural \
                      frequency, and its amplitude stays bounded (by the damping); a steady wind \
                      has no frequency to match, and flutter needs none — the motion makes its \
                      own forcing, so above U_crit there is no bounded steady state at all, and \
                      more damping only raises U_crit. Teaching model: Scanlan's A2* term alone, \
                      linear in U; preset values are approximate (≈ 0.2 Hz torsion, ζ_s = 0.5 % \
                      assumed, U_crit set to the ≈ 42 mph of 7 November 1940).";

pub(super) const EQUATION: &str = "<math display=\"block\"><mtable>\
<mtr><mtd><mover><mi>θ</mi><mo>¨</mo></mover><mo>+</mo><mn>2</mn>\
<msub><mi>ζ</mi><mtext>eff</mtext></msub><mo>(</mo><mi>U</mi><mo>)</mo><mi>ω</mi>\
<mover><mi>θ</mi><mo>˙</mo></mover><mo>+</mo><msup><mi>ω</mi><mn>2</mn></msup><mi>θ</mi>\
<mo>=</mo><mn>0</mn></mtd></mtr>\
<mtr><mtd><msub><mi>ζ</mi><mtext>eff</mtext></msub><mo>(</mo><mi>U</mi><mo>)</mo><mo>=</mo>\
<msub><mi>ζ</mi><mi>s</mi></msub><mo>−</mo><mi>g</mi><mi>U</mi></mtd></mtr></mtable></math>";

/// Flutter against forced resonance; the row of the current regime is highlighted.
pub(super) fn table() -> Table {
    Table {
        caption: "Flutter is not resonance",
        columns: vec![
            "case",
            "what drives it",
            "frequency",
            "damping",
            "amplitude",
            "cure",
        ],
        rows: vec![
            (
                "resonance",
                vec![
                    "Forced resonance (for contrast)",
                    "an outside force oscillating near ωₙ (marching feet, an engine)",
                    "set by the force; must match ωₙ",
                    "positive: limits the peak to about 1/(2ζ) × static",
                    "bounded steady state",
                    "detune, or add damping",
                ],
            ),
            (
                "underdamped",
                vec![
                    "Wind below U_crit",
                    "steady wind; moment ∝ twist rate",
                    "the deck's own ω_d",
                    "ζ_eff = ζ_s − gU > 0",
                    "a twist dies away",
                    "—",
                ],
            ),
            (
                "undamped",
                vec![
                    "At U_crit",
                    "steady wind; moment ∝ twist rate",
                    "the deck's own ω",
                    "ζ_eff = 0: poles on the imaginary axis",
                    "a twist persists unchanged",
                    "—",
                ],
            ),
            (
                "negatively damped",
                vec![
                    "Flutter, wind above U_crit",
                    "steady wind; the motion makes its own forcing",
                    "the deck's own ω_d, no matching needed",
                    "ζ_eff < 0: energy flows in every cycle",
                    "grows like e^(σt) until something breaks",
                    "raise U_crit: stiffer, streamlined, open deck",
                ],
            ),
        ],
        highlight_readout: "regime",
    }
}

fn speed_text(u: f64) -> String {
    format!("{} ({} mph)", si(u, "m/s", 3), si(u / MPH, "", 3))
}

/// Frequency \[rad/s\] at which the poles cross the imaginary axis, if they do on the plot.
pub(super) fn crossing_frequency(r: &Results) -> Option<f64> {
    r.model
        .critical_speed()
        .filter(|&uc| uc <= U_MAX)
        .and_then(|uc| r.model.damped_frequency(uc))
}

/// The damping line in words.
pub(super) fn describe_damping(r: &Results) -> String {
    let crit_text = match r.model.critical_speed() {
        Some(uc) if uc <= U_MAX => {
            format!("crosses zero at the critical speed {}", speed_text(uc))
        }
        Some(uc) => format!(
            "would cross zero only at {}, beyond the plotted {}",
            si(uc, "m/s", 3),
            si(U_MAX, "m/s", 3)
        ),
        None => "never crosses zero: the wind does not remove damping (g = 0)".to_string(),
    };
    let side = if r.zeta > 0.0 {
        "positive (stable)"
    } else if r.zeta < 0.0 {
        "negative (flutter)"
    } else {
        "zero"
    };
    format!(
        "Effective damping ratio falls in a straight line from ζ_s = {} at no wind; it {}. \
         At U = {} it is {}, {}.",
        si(r.model.config().structural_damping, "", 3),
        crit_text,
        si(r.u, "m/s", 3),
        si(r.zeta, "", 3),
        side
    )
}

/// The root locus in words; `start_re` is the real part of the poles in calm air.
pub(super) fn describe_locus(r: &Results, start_re: f64) -> String {
    let where_now = match r.model.poles(r.u) {
        Ok(p) => {
            let s = if p[0].im >= p[1].im { p[0] } else { p[1] };
            format!(
                "At U = {} the poles are {} ± {}i 1/s, in the {} half-plane.",
                si(r.u, "m/s", 3),
                si(s.re, "", 3),
                si(s.im.abs(), "", 4),
                if s.re > 0.0 {
                    "right (unstable)"
                } else {
                    "left (stable)"
                }
            )
        }
        Err(_) => String::new(),
    };
    format!(
        "As the wind rises from 0 to {} the complex pole pair moves horizontally, at almost \
         constant frequency ±{} rad/s, from real part {} 1/s{}. {}",
        si(U_MAX, "m/s", 3),
        si(r.model.config().omega, "", 4),
        si(start_re, "", 3),
        match crossing_frequency(r) {
            Some(_) => " across the imaginary axis at U_crit",
            None => ", never crossing the imaginary axis",
        },
        where_now
    )
}

/// The twist in words; `end_factor` is e^(σ·t_end).
pub(super) fn describe_response(r: &Results, end_factor: f64) -> String {
    let regime = r.regime.map_or("invalid", |g: Regime| g.key());
    let change = if end_factor > 1.0 + 1e-9 {
        format!(
            "grows by a factor {} in {}",
            si(end_factor, "", 3),
            si(r.t_end, "s", 3)
        )
    } else if end_factor < 1.0 - 1e-9 {
        format!(
            "decays to {} of its start in {}",
            si(100.0 * end_factor, "%", 3),
            si(r.t_end, "s", 3)
        )
    } else {
        format!("keeps its amplitude over {}", si(r.t_end, "s", 3))
    };
    format!(
        "{regime}: from an initial twist of {}, the oscillation at {} Hz {}.",
        si(degrees(r.theta0), "°", 3),
        si(
            r.model.damped_frequency(r.u).unwrap_or(f64::NAN) / std::f64::consts::TAU,
            "",
            3
        ),
        change
    )
}
