//! The flutter demo's prose: summary, equation, the flutter-versus-resonance table, the
//! figures' text alternatives and the regime readout.

use super::{Aero, Results, U_MAX};
use crate::format::{self, si, significant};
use crate::spec::Table;
use crate::t;
use zeta_solver::flutter::{degrees, FlutterState};

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
     about 42 mph the twist grew within the hour until the deck tore apart. Stated as such: \
     the H-section's A₂* and A₃* are a teaching approximation, smooth curves shaped like the \
     published wind-tunnel results (Scanlan & Tomko 1971; Billah & Scanlan 1991), not values \
     read from them; I, ζ_s and θ_s are assumed. The streamlined box is idealised as a thin \
     flat plate, whose A₂* and A₃* are exact in potential flow (Theodorsen 1935): its A₂* \
     stays negative, so it never flutters in this range. The simplest picture \
     ζ_eff = ζ_s − g·U is kept for comparison.";

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

/// Which model of the wind's moment, as a selector key of the messages that name it.
fn model_key(r: &Results) -> &'static str {
    match (r.p.aero, r.p.section) {
        (Aero::Simplest, _) => "simplest",
        (_, super::Section::H) => "h",
        (_, super::Section::Box) => "box",
    }
}

/// The regime of a small twist in words ("no oscillation" where the wind leaves none).
pub(super) fn regime(r: &Results) -> String {
    r.regime
        .map_or_else(|| t!("flutter-no-oscillation"), format::regime)
}

/// The A₂* plot in words.
pub(super) fn describe_derivative(r: &Results, threshold: f64) -> String {
    let description = t!("flutter-describe-derivative", model = model_key(r));
    match r.state {
        Some(s) => t!(
            "flutter-describe-derivative-now",
            description = description,
            speed = si(r.p.u, "m/s", 3),
            k = reduced_frequency(&s),
            reduced_velocity = si(s.reduced_velocity, "", 3),
            a2 = si(s.a2, "", 3),
            side = if s.a2 > threshold { "above" } else { "below" },
            threshold = si(threshold, "", 3)
        ),
        None => description,
    }
}

/// The damping curve in words.
pub(super) fn describe_damping(r: &Results) -> String {
    let (crossing, speed) = match r.u_crit {
        Some(uc) if uc <= U_MAX => ("inside", speed_text(uc)),
        Some(uc) => ("beyond", si(uc, "m/s", 3)),
        None => ("never", String::new()),
    };
    let description = t!(
        "flutter-describe-damping",
        model = model_key(r),
        zeta_s = si(r.p.zeta_s, "", 3),
        crossing = crossing,
        speed = speed,
        limit = si(U_MAX, "m/s", 3)
    );
    match r.state {
        Some(s) => {
            let z = s.damping_ratio();
            let sign = if z > 0.0 {
                "positive"
            } else if z < 0.0 {
                "negative"
            } else {
                "zero"
            };
            t!(
                "flutter-describe-damping-now",
                description = description,
                speed = si(r.p.u, "m/s", 3),
                zeta = si(z, "", 3),
                sign = sign
            )
        }
        None => t!("flutter-describe-damping-still", description = description),
    }
}

/// The root locus in words.
pub(super) fn describe_locus(r: &Results) -> String {
    let first = r.locus.first();
    let last = r.locus.last();
    let description = t!(
        "flutter-describe-locus",
        re_calm = si(first.map_or(f64::NAN, |s| s.growth_rate()), "", 3),
        im_calm = si(first.map_or(f64::NAN, |s| s.omega), "", 4),
        re_end = si(last.map_or(f64::NAN, |s| s.growth_rate()), "", 3),
        im_end = si(last.map_or(f64::NAN, |s| s.omega), "", 4),
        limit = si(U_MAX, "m/s", 3),
        crosses = if crossing_frequency(r).is_some() {
            "yes"
        } else {
            "no"
        }
    );
    match r.state {
        Some(s) => t!(
            "flutter-describe-locus-now",
            description = description,
            speed = si(r.p.u, "m/s", 3),
            re = si(s.growth_rate(), "", 3),
            im = si(s.omega, "", 4),
            side = if s.growth_rate() > 0.0 {
                "right"
            } else {
                "left"
            }
        ),
        None => description,
    }
}

/// The twist in words.
pub(super) fn describe_response(r: &Results) -> String {
    let end = r.history.amplitude.last().map_or(0.0, |&a| degrees(a));
    let (case, limit, time) = match (r.limit, r.t_large) {
        (Some(lc), Some(t)) if t <= r.window => ("settling", Some(lc), Some(t)),
        (Some(lc), Some(t)) => ("slow", Some(lc), Some(t)),
        (Some(lc), None) => ("settled", Some(lc), None),
        (None, _) if end > r.p.theta0_deg => ("grows", None, None),
        (None, _) => ("dies", None, None),
    };
    let oscillation = r.state.map_or_else(
        || t!("flutter-oscillation"),
        |s| {
            t!(
                "flutter-oscillation-at",
                frequency = si(s.frequency_hz(), "", 3)
            )
        },
    );
    let description = t!(
        "flutter-describe-response",
        regime = regime(r),
        twist = si(r.p.theta0_deg, "°", 3),
        oscillation = oscillation,
        case = case,
        end = si(end, "°", 3),
        window = duration(r.window),
        limit = si(limit.map_or(f64::NAN, degrees), "°", 3),
        time = time.map_or_else(String::new, duration)
    );
    if r.limit.is_some_and(|lc| degrees(lc) > 45.0) {
        t!("flutter-describe-response-torn", description = description)
    } else {
        description
    }
}
