//! The resonance demo's prose: summary, equation and the figures' text alternatives.

use super::{Results, View, P};
use crate::format::si;
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

/// A dimensionless number with 3 significant digits and no trailing zeros (`0.05`, `1.05`).
pub(super) fn fmt_ratio(r: f64) -> String {
    let s = si(r, "", 3);
    if s.contains('.') && !s.contains('e') {
        s.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        s
    }
}

/// The half-power points of the |H| curve in words: the two-sided peak width, the
/// one-sided band of a broad peak, or the −3 dB cut-off when there is no peak.
pub(super) fn describe_band(h: &HalfPowerPoints, width: Option<f64>, has_peak: bool) -> String {
    match (h.lower, width) {
        (Some(l), Some(w)) => format!(
            "half-power points (|H| = |H|max/√2) at r = {} and {}: peak width r₂ − r₁ = {}",
            fmt_ratio(l),
            fmt_ratio(h.upper),
            fmt_ratio(w)
        ),
        _ if has_peak => format!(
            "|H| stays above |H|max/√2 from r = 0 up to r = {}: the peak has no lower \
             half-power point, so its half-power width is undefined",
            fmt_ratio(h.upper)
        ),
        _ => format!(
            "|H| falls to 1/√2 of its static value (−3 dB) at the cut-off r = {}; without a \
             peak there is no half-power width",
            fmt_ratio(h.upper)
        ),
    }
}

/// The legend entry of the half-power level line.
pub(super) fn band_legend(h: &HalfPowerPoints, width: Option<f64>, has_peak: bool) -> String {
    match width {
        Some(w) => format!("half-power width r₂ − r₁ = {}", fmt_ratio(w)),
        None if has_peak => format!("|H| ≥ |H|max/√2 up to r = {}", fmt_ratio(h.upper)),
        None => format!("−3 dB cut-off r = {}", fmt_ratio(h.upper)),
    }
}

/// Whether beats show in x(t), and if not why (see [`Beats`]).
pub(super) fn beats(b: Beats) -> &'static str {
    match b {
        Beats::Visible { .. } => "visible",
        Beats::NoFreeOscillation => "none (no free oscillation, ζ ≥ 1)",
        Beats::NoDrive => "none (constant force)",
        Beats::SameFrequency => "none (driven at ω_d)",
        Beats::TooFast { .. } => "none (as fast as the oscillation)",
        Beats::DiesOut { .. } => "none (the free motion dies out first)",
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
        Some(p) => format!(
            "resonant peak {} at r = {}",
            unit_text(p.gain),
            si(p.ratio, "", 4)
        ),
        None => "no resonant peak (ζ ≥ 1/√2): |H| only falls from 1 at r = 0".to_string(),
    };
    format!(
        "Magnitude{} for ζ = {}: {}; {}. At the drive r = {} the amplification is {}.",
        if db { " in dB" } else { "" },
        fmt_ratio(z),
        peak_text,
        band_text,
        fmt_ratio(res.p.r),
        unit_text(frf::magnitude(res.p.r, z)),
    )
}

/// The phase plot in words; `ph` is the phase at the drive \[rad\].
pub(super) fn describe_phase(res: &Results, ph: f64) -> String {
    format!(
        "Phase of the displacement behind the force for ζ = {}: 0° at low frequency, −90° at \
         r = 1 for every damping ratio, towards −180° above resonance; the smaller ζ, the \
         sharper the switch. At the drive r = {} the lag is {} ({} rad).",
        fmt_ratio(res.p.zeta),
        fmt_ratio(res.p.r),
        si(ph.to_degrees(), "°", 3),
        si(ph, "", 4),
    )
}

/// The time response in words.
pub(super) fn describe_time(p: &P, resp: &HarmonicResponse, t_end: f64, max_x: f64) -> String {
    let head = format!(
        "Driven from rest at r = {} (ω = {}) for {}",
        fmt_ratio(p.r),
        si(p.r * p.wn, "rad/s", 3),
        si(t_end, "s", 3)
    );
    let tau = 1.0 / (p.zeta * p.wn);
    let Some(s) = resp.steady_state() else {
        return format!(
            "{head}: no steady state; the amplitude grows, reaching {}.",
            si(max_x, "m", 3)
        );
    };
    let amp = si(s.amplitude, "m", 3);
    let body = if let Some(tb) = resp.beats().period() {
        format!(
            "the free and forced motions beat with period {} (time constant of the decay {}), \
             towards the steady amplitude {}",
            si(tb, "s", 3),
            si(tau, "s", 3),
            amp
        )
    } else if (p.r - 1.0).abs() < p.zeta.max(0.02) && p.zeta < 0.5 {
        format!(
            "at resonance the amplitude builds up towards the steady amplitude {} with time \
             constant 1/(ζωₙ) = {}",
            amp,
            si(tau, "s", 3)
        )
    } else {
        format!(
            "after a transient (time constant {}) it settles to the steady amplitude {}",
            si(tau, "s", 3),
            amp
        )
    };
    format!(
        "{head}: {body}, lagging the force by {}. Largest excursion shown {}.",
        si(s.phase.to_degrees().abs(), "°", 3),
        si(max_x, "m", 3)
    )
}

/// The animated mass in words.
pub(super) fn describe_schematic(force: f64, x: f64, t: f64) -> String {
    format!(
        "Mass on a spring and damper over a fixed base, pushed by the force F(t) = {} \
         (arrow above the mass) at t = {}: displaced {} from rest.",
        si(force, "N", 3),
        si(t, "s", 3),
        si(x, "m", 3)
    )
}
