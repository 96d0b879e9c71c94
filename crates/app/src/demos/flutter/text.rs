//! The flutter demo's prose: summary, equation, the flutter-versus-resonance table and the
//! figures' text alternatives.

use super::{Aero, Results, U_MAX};
use crate::format::{si, significant};
use crate::spec::Table;
use zeta_solver::flutter::{degrees, FlutterState};
use zeta_solver::Regime;

/// Metres per second in one mile per hour.
const MPH: f64 = 0.447_04;

pub(super) const SUMMARY: &str =
    "A steady wind can feed a twisting bridge deck energy through its own motion. Scanlan \
     wrote the wind's moment on a twisting deck with flutter derivatives measured in wind \
     tunnels: A₂* multiplies the twist rate (a damping term) and A₃* the twist (a stiffness \
     term), both functions of the reduced frequency K = Bω/U. The deck's damping ratio becomes \
     ζ_eff ≈ ζ_s − ρB⁴A₂*(K)/(4I): for the bluff H-section of the 1940 Tacoma deck A₂* changes \
     sign as the wind rises, and once it passes the threshold 4Iζ_s/(ρB⁴) any small twist \
     grows at the deck's own torsional frequency (near 0.2 Hz) — flutter, not resonance: a \
     steady wind has no frequency to match, the motion makes its own forcing. The frequency \
     is found by iteration at each wind speed, since K depends on it. Linear theory lets the \
     twist grow for ever; here the wind's damping term is assumed to halve at a twist θ_s, \
     which bounds the motion in a large limit cycle, as on 7 November 1940, when in winds of \
     about 42 mph the twist grew within the hour until the deck tore apart. Teaching \
     approximations, stated as such: A₂* and A₃* are smooth curves shaped like the published \
     H-section and airfoil-like results (Scanlan & Tomko 1971; Billah & Scanlan 1991), not \
     values read from them; I, ζ_s and θ_s are assumed. A streamlined box, whose A₂* stays \
     negative, never flutters in this range. The simplest picture ζ_eff = ζ_s − g·U is kept \
     for comparison.";

pub(super) const EQUATION: &str = "<math display=\"block\"><mtable>\
<mtr><mtd><mover><mi>θ</mi><mo>¨</mo></mover><mo>+</mo><mrow><mo>[</mo><mn>2</mn>\
<msub><mi>ζ</mi><mi>s</mi></msub><msub><mi>ω</mi><mn>0</mn></msub><mo>−</mo>\
<mfrac><mrow><mi>ρ</mi><msup><mi>B</mi><mn>4</mn></msup><mi>ω</mi>\
<msubsup><mi>A</mi><mn>2</mn><mo>*</mo></msubsup><mo>(</mo><mi>K</mi><mo>)</mo></mrow>\
<mrow><mn>2</mn><mi>I</mi><mo>(</mo><mn>1</mn><mo>+</mo><msup><mi>a</mi><mn>2</mn></msup>\
<mo>/</mo><msubsup><mi>θ</mi><mi>s</mi><mn>2</mn></msubsup><mo>)</mo></mrow></mfrac>\
<mo>]</mo></mrow><mover><mi>θ</mi><mo>˙</mo></mover><mo>+</mo><mrow><mo>[</mo>\
<msubsup><mi>ω</mi><mn>0</mn><mn>2</mn></msubsup><mo>−</mo>\
<mfrac><mrow><mi>ρ</mi><msup><mi>B</mi><mn>4</mn></msup><msup><mi>ω</mi><mn>2</mn></msup>\
<msubsup><mi>A</mi><mn>3</mn><mo>*</mo></msubsup><mo>(</mo><mi>K</mi><mo>)</mo></mrow>\
<mrow><mn>2</mn><mi>I</mi></mrow></mfrac><mo>]</mo></mrow><mi>θ</mi><mo>=</mo><mn>0</mn>\
</mtd></mtr>\
<mtr><mtd><mi>K</mi><mo>=</mo><mfrac><mrow><mi>B</mi><mi>ω</mi></mrow><mi>U</mi></mfrac>\
<mo>,</mo><mspace width=\"1em\"/>\
<msub><mi>ζ</mi><mtext>eff</mtext></msub><mo>≈</mo><msub><mi>ζ</mi><mi>s</mi></msub>\
<mo>−</mo><mfrac><mrow><mi>ρ</mi><msup><mi>B</mi><mn>4</mn></msup>\
<msubsup><mi>A</mi><mn>2</mn><mo>*</mo></msubsup><mo>(</mo><mi>K</mi><mo>)</mo></mrow>\
<mrow><mn>4</mn><mi>I</mi></mrow></mfrac></mtd></mtr></mtable></math>";

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
                    "steady wind; moment ∝ twist rate (A₂*) and twist (A₃*)",
                    "the deck's own, shifted a little by A₃*",
                    "ζ_eff > 0: A₂* below the threshold 4Iζ_s/(ρB⁴)",
                    "a twist dies away",
                    "—",
                ],
            ),
            (
                "undamped",
                vec![
                    "At U_crit",
                    "steady wind; moment ∝ twist rate (A₂*) and twist (A₃*)",
                    "the deck's own",
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
                    "the deck's own, no matching needed",
                    "ζ_eff < 0: energy flows in every cycle",
                    "grows until the amplitude bound (or the deck) gives",
                    "a section whose A₂* stays negative: streamlined, open or stiffened deck",
                ],
            ),
        ],
        highlight_readout: "regime",
    }
}

/// A duration in seconds, or in minutes from two minutes on.
pub(super) fn duration(t: f64) -> String {
    if t < 120.0 {
        si(t, "s", 3)
    } else {
        format!("{} min", significant(t / 60.0, 3))
    }
}

/// K as text (∞ in still air).
pub(super) fn reduced_frequency(s: &FlutterState) -> String {
    if s.reduced_frequency.is_finite() {
        si(s.reduced_frequency, "", 3)
    } else {
        "∞".to_string()
    }
}

fn speed_text(u: f64) -> String {
    format!("{} ({} mph)", si(u, "m/s", 3), si(u / MPH, "", 3))
}

/// Frequency \[rad/s\] at which the poles cross the imaginary axis, if they do on the plot.
pub(super) fn crossing_frequency(r: &Results) -> Option<f64> {
    let uc = r.u_crit.filter(|&uc| uc <= U_MAX)?;
    Some(r.model.state(uc)?.omega)
}

fn model_name(r: &Results) -> &'static str {
    match (r.p.aero, r.p.section) {
        (Aero::Simplest, _) => "the simplest picture",
        (_, super::Section::H) => "the 1940 H-section",
        (_, super::Section::Box) => "the streamlined box",
    }
}

/// The A₂* plot in words.
pub(super) fn describe_derivative(r: &Results, threshold: f64) -> String {
    let now = match r.state {
        Some(s) => format!(
            "At U = {} (K = {}, U/(fB) = {}) A₂* = {}, {} the threshold {}.",
            si(r.p.u, "m/s", 3),
            reduced_frequency(&s),
            si(s.reduced_velocity, "", 3),
            si(s.a2, "", 3),
            if s.a2 > threshold { "above" } else { "below" },
            si(threshold, "", 3)
        ),
        None => String::new(),
    };
    format!(
        "A₂* against reduced velocity for {} (teaching approximation, not measured values): \
         the twist grows where A₂* rises above 4Iζ_s/(ρB⁴). {now}",
        model_name(r)
    )
}

/// The damping curve in words.
pub(super) fn describe_damping(r: &Results) -> String {
    let crit = match r.u_crit {
        Some(uc) if uc <= U_MAX => {
            format!("crosses zero at the critical speed {}", speed_text(uc))
        }
        Some(uc) => format!(
            "would cross zero only at {}, beyond the plotted {}",
            si(uc, "m/s", 3),
            si(U_MAX, "m/s", 3)
        ),
        None => "never crosses zero up to 100 m/s: the wind only adds damping".to_string(),
    };
    let now = match r.state {
        Some(s) => {
            let z = s.damping_ratio();
            let side = if z > 0.0 {
                "positive (stable)"
            } else if z < 0.0 {
                "negative (flutter)"
            } else {
                "zero"
            };
            format!(
                " At U = {} it is {}, {}.",
                si(r.p.u, "m/s", 3),
                si(z, "", 3),
                side
            )
        }
        None => " At this wind the deck does not oscillate.".to_string(),
    };
    format!(
        "Effective damping ratio of {} from ζ_s = {} in calm air; it {}.{now}",
        model_name(r),
        si(r.p.zeta_s, "", 3),
        crit
    )
}

/// The root locus in words.
pub(super) fn describe_locus(r: &Results) -> String {
    let now = match r.state {
        Some(s) => format!(
            " At U = {} the poles are {} ± {}i 1/s, in the {} half-plane.",
            si(r.p.u, "m/s", 3),
            si(s.growth_rate(), "", 3),
            si(s.omega, "", 4),
            if s.growth_rate() > 0.0 {
                "right (unstable)"
            } else {
                "left (stable)"
            }
        ),
        None => String::new(),
    };
    let first = r.locus.first();
    let last = r.locus.last();
    format!(
        "Pole pair as the wind rises: {} ± {}i 1/s in calm air, {} ± {}i 1/s at {}{}.{now}",
        si(first.map_or(f64::NAN, |s| s.growth_rate()), "", 3),
        si(first.map_or(f64::NAN, |s| s.omega), "", 4),
        si(last.map_or(f64::NAN, |s| s.growth_rate()), "", 3),
        si(last.map_or(f64::NAN, |s| s.omega), "", 4),
        si(U_MAX, "m/s", 3),
        match crossing_frequency(r) {
            Some(_) => ", crossing the imaginary axis at U_crit",
            None => ", never crossing the imaginary axis",
        },
    )
}

/// The twist in words.
pub(super) fn describe_response(r: &Results) -> String {
    let regime = r.regime.map_or("no oscillation", |g: Regime| g.key());
    let end = r.history.amplitude.last().map_or(0.0, |&a| degrees(a));
    let window = duration(r.window);
    let change = match (r.limit, r.t_large) {
        (Some(lc), Some(t)) if t <= r.window => format!(
            "grows to {} by the end of the plot ({window}), settling near the limit cycle of {} \
             (90 % of it after {})",
            si(end, "°", 3),
            si(degrees(lc), "°", 3),
            duration(t)
        ),
        (Some(lc), Some(t)) => format!(
            "grows only to {} by the end of the plot ({window}); it would take {} to reach 90 % \
             of the limit cycle of {}",
            si(end, "°", 3),
            duration(t),
            si(degrees(lc), "°", 3)
        ),
        (Some(lc), None) => format!(
            "settles onto the limit cycle of {} by the end of the plot ({window})",
            si(degrees(lc), "°", 3)
        ),
        (None, _) if end > r.p.theta0_deg => {
            format!(
                "grows to {} by the end of the plot ({window})",
                si(end, "°", 3)
            )
        }
        (None, _) => format!(
            "dies down to {} by the end of the plot ({window})",
            si(end, "°", 3)
        ),
    };
    let survive = if r.limit.is_some_and(|lc| degrees(lc) > 45.0) {
        " A twist this large would have torn any deck apart long before; the bound is only \
         a teaching assumption."
    } else {
        ""
    };
    let freq = r.state.map_or(String::new(), |s| {
        format!(" at {} Hz", si(s.frequency_hz(), "", 3))
    });
    format!(
        "{regime}: from an initial twist of {}, the oscillation{freq} {change}.{survive}",
        si(r.p.theta0_deg, "°", 3),
    )
}
