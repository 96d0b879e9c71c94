//! The resonance demo's prose: summary, equation, the figures' text alternatives and
//! legend entries, and the beats readout.

use super::{Results, View, P};
use crate::demos::digits::trimmed;
use crate::format::si;
use crate::t;
use zeta_solver::forced::{Beats, HarmonicResponse};
use zeta_solver::frf::{self, HalfPowerPoints};
use zeta_solver::grid::decibels;

pub(super) const SUMMARY: &str =
    "A 1 kg mass on a spring (k = ωₙ²·m) and damper (c = 2ζωₙ·m), at rest, is \
                      driven from t = 0 by F(t) = F₀·cos(ωt). In the steady state it moves at the \
                      drive frequency with amplitude |H(r)|·F₀/k, lagging the force by the phase \
                      of H, where r = ω/ωₙ. Light damping gives a tall, narrow peak near r = 1 \
                      (height ≈ Q = 1/(2ζ)). Its half-power width, r₂ − r₁ between the two \
                      frequency ratios where |H| = |H|max/√2, is ≈ 2ζ for light damping; above \
                      ζ ≈ 0.383 the lower point reaches r = 0 and the width is undefined, and \
                      above ζ = 1/√2 there is no peak at all. Driven exactly at resonance, the \
                      amplitude builds up over a few time constants 1/(ζωₙ) without beating; \
                      driven near it, the free and forced motions beat against each other \
                      until the free part dies away.";

pub(super) const EQUATION: &str = "<math display=\"block\"><mrow>\
<mi>m</mi><mover><mi>x</mi><mo>¨</mo></mover><mo>+</mo><mi>c</mi><mover><mi>x</mi><mo>˙</mo></mover>\
<mo>+</mo><mi>k</mi><mi>x</mi><mo>=</mo><msub><mi>F</mi><mn>0</mn></msub><mi>cos</mi><mo>⁡</mo>\
<mo>(</mo><mi>ω</mi><mi>t</mi><mo>)</mo></mrow></math>\
<math display=\"block\"><mrow><mi>H</mi><mo>(</mo><mi>r</mi><mo>)</mo><mo>=</mo><mfrac><mn>1</mn><mrow><mn>1</mn><mo>−</mo>\
<msup><mi>r</mi><mn>2</mn></msup><mo>+</mo><mn>2</mn><mi>i</mi><mi>ζ</mi><mi>r</mi></mrow></mfrac>\
</mrow></math>";

/// The half-power points of the |H| curve in words: the two-sided peak width, the
/// one-sided band of a broad peak, or the −3 dB cut-off when there is no peak.
pub(super) fn describe_band(h: &HalfPowerPoints, width: Option<f64>, has_peak: bool) -> String {
    match (h.lower, width) {
        (Some(l), Some(w)) => t!(
            "resonance-band-width",
            lower = trimmed(l, 3),
            upper = trimmed(h.upper, 3),
            width = trimmed(w, 3)
        ),
        _ if has_peak => t!("resonance-band-broad", upper = trimmed(h.upper, 3)),
        _ => t!("resonance-band-cutoff", upper = trimmed(h.upper, 3)),
    }
}

/// The legend entry of the half-power level line.
pub(super) fn band_legend(h: &HalfPowerPoints, width: Option<f64>, has_peak: bool) -> String {
    match width {
        Some(w) => t!("resonance-legend-width", width = trimmed(w, 3)),
        None if has_peak => t!("resonance-legend-broad", upper = trimmed(h.upper, 3)),
        None => t!("resonance-legend-cutoff", upper = trimmed(h.upper, 3)),
    }
}

/// Whether beats show in x(t), and if not why (see [`Beats`]).
pub(super) fn beats(b: Beats) -> String {
    match b {
        Beats::Visible { .. } => t!("resonance-beats-visible"),
        Beats::NoFreeOscillation => t!("resonance-beats-no-free-oscillation"),
        Beats::NoDrive => t!("resonance-beats-no-drive"),
        Beats::SameFrequency => t!("resonance-beats-same-frequency"),
        Beats::TooFast { .. } => t!("resonance-beats-too-fast"),
        Beats::DiesOut { .. } => t!("resonance-beats-dies-out"),
    }
}

/// The magnitude plot in words.
pub(super) fn describe_magnitude(res: &Results, band_text: &str) -> String {
    let (z, db) = (res.p.zeta, res.p.view == View::Db);
    let unit_text = |g: f64| {
        if db {
            si(decibels(g), "dB", 3)
        } else {
            si(g, "", 3)
        }
    };
    let peak_text = match res.peak {
        Some(p) => t!(
            "resonance-peak-at",
            gain = unit_text(p.gain),
            ratio = si(p.ratio, "", 4)
        ),
        None => t!("resonance-no-peak"),
    };
    t!(
        "resonance-describe-magnitude",
        view = if db { "db" } else { "linear" },
        zeta = trimmed(z, 3),
        peak = peak_text,
        band = band_text,
        drive = trimmed(res.p.r, 3),
        gain = unit_text(frf::magnitude(res.p.r, z)),
    )
}

/// The phase plot in words; `ph` is the phase at the drive \[rad\].
pub(super) fn describe_phase(res: &Results, ph: f64) -> String {
    t!(
        "resonance-describe-phase",
        zeta = trimmed(res.p.zeta, 3),
        drive = trimmed(res.p.r, 3),
        degrees = si(ph.to_degrees(), "°", 3),
        radians = si(ph, "", 4),
    )
}

/// The time response in words.
pub(super) fn describe_time(p: &P, resp: &HarmonicResponse, t_end: f64, max_x: f64) -> String {
    let (ratio, omega, span) = (
        trimmed(p.r, 3),
        si(p.r * p.wn, "rad/s", 3),
        si(t_end, "s", 3),
    );
    let tau = si(1.0 / (p.zeta * p.wn), "s", 3);
    let Some(s) = resp.steady_state() else {
        return t!(
            "resonance-describe-time-growing",
            ratio = ratio,
            omega = omega,
            span = span,
            largest = si(max_x, "m", 3)
        );
    };
    let period = resp.beats().period();
    let case = if period.is_some() {
        "beats"
    } else if (p.r - 1.0).abs() < p.zeta.max(0.02) && p.zeta < 0.5 {
        "build-up"
    } else {
        "transient"
    };
    t!(
        "resonance-describe-time",
        case = case,
        ratio = ratio,
        omega = omega,
        span = span,
        period = si(period.unwrap_or(f64::NAN), "s", 3),
        tau = tau,
        amplitude = si(s.amplitude, "m", 3),
        lag = si(s.phase.to_degrees().abs(), "°", 3),
        largest = si(max_x, "m", 3)
    )
}

/// The animated mass in words.
pub(super) fn describe_schematic(force: f64, x: f64, t: f64) -> String {
    t!(
        "resonance-schematic",
        force = si(force, "N", 3),
        time = si(t, "s", 3),
        displacement = si(x, "m", 3)
    )
}
