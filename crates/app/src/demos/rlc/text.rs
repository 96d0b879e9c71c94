//! The RLC demo's prose: summary, equation and the figures' text alternatives.

use super::figures::Signal;
use super::Results;
use crate::format::si;
use zeta_solver::Regime;

pub(super) const SUMMARY: &str =
    "A capacitor charged to V₀ is switched into a loop with an inductor and a \
                      resistor at t = 0. Charge q obeys the same equation as a mass on a spring: \
                      L plays the mass, R the damper, 1/C the spring. With R below the critical \
                      resistance 2√(L/C) the energy sloshes between C and L and the current \
                      rings at ω_d, decaying as e^(−αt), α = R/(2L); at R = 2√(L/C) the \
                      capacitor empties fastest without reversing; above it the discharge is \
                      slower again. Q = 1/(2ζ) counts the ringing, and R/L is the \
                      half-power bandwidth of the current's resonance: driven by a sine \
                      voltage, |I|² stays above half its peak over a band exactly R/L rad/s \
                      wide, for any R. The current is negative while the capacitor \
                      discharges (i = dq/dt).";

pub(super) const EQUATION: &str = "<math display=\"block\"><mrow>\
<mi>L</mi><mover><mi>q</mi><mo>¨</mo></mover><mo>+</mo><mi>R</mi><mover><mi>q</mi><mo>˙</mo></mover>\
<mo>+</mo><mfrac><mi>q</mi><mi>C</mi></mfrac><mo>=</mo><mn>0</mn><mo>,</mo><mspace width=\"1em\"/>\
<mi>i</mi><mo>=</mo><mover><mi>q</mi><mo>˙</mo></mover><mo>,</mo><mspace width=\"0.6em\"/>\
<msub><mi>v</mi><mi>C</mi></msub><mo>=</mo><mfrac><mi>q</mi><mi>C</mi></mfrac></mrow></math>";

/// A resistance with 3 significant digits, e.g. `"10 Ω"`.
pub(super) fn ohms(r: f64) -> String {
    si(r, "Ω", 3)
}

/// The response described in words, by regime.
pub(super) fn describe(r: &Results, signal: Signal) -> String {
    let sys = &r.sys;
    let metrics = r.metrics;
    let r_crit = sys.critical_damping().unwrap_or(0.0);
    let w0 = sys.natural_frequency().unwrap_or(0.0);
    let bound = si(r.current_scale(), "A", 3);
    let settle = metrics
        .and_then(|m| m.settling_time)
        .map(|t| format!("stays within 5 % of V₀ after {}", si(t, "s", 3)))
        .unwrap_or_else(|| "never settles".to_string());
    // The solver counts zero crossings before the settling time.
    let reversals = match metrics {
        Some(m) if m.zero_crossings == 0 && m.rebound_time.is_some() => format!(
            "reverses only slightly (at most {} of V₀, inside the band)",
            si(100.0 * m.peak_rebound, "%", 3)
        ),
        Some(m) if m.zero_crossings == 1 => "reverses polarity once before settling".to_string(),
        Some(m) if m.zero_crossings > 1 => {
            format!(
                "reverses polarity {} times before settling",
                m.zero_crossings
            )
        }
        _ => "never reverses polarity".to_string(),
    };
    match (sys.regime(), signal) {
        (Regime::Undamped, Signal::Current) => format!(
            "R = {}, undamped (a lossless LC loop): the current oscillates forever at ω₀ = {}, \
             between ±{} (all the energy passes to the inductor and back every half period).",
            ohms(r.p.r),
            si(w0, "rad/s", 3),
            bound
        ),
        (Regime::Undamped, Signal::Voltage) => format!(
            "R = {}, undamped (a lossless LC loop): the capacitor voltage swings between +{v} \
             and −{v} forever at ω₀ = {}.",
            ohms(r.p.r),
            si(w0, "rad/s", 3),
            v = si(r.p.v0.abs(), "V", 3)
        ),
        (Regime::Underdamped, Signal::Current) => format!(
            "R = {} below the critical {}, underdamped: the current rings at ω_d = {} \
             (Q = {}), decaying as e^(−αt) with α = {}; it never exceeds {}.",
            ohms(r.p.r),
            ohms(r_crit),
            si(sys.damped_frequency().unwrap_or(0.0), "rad/s", 3),
            si(sys.quality_factor().unwrap_or(f64::NAN), "", 3),
            si(sys.alpha(), "1/s", 3),
            bound
        ),
        (Regime::Underdamped, Signal::Voltage) => format!(
            "R = {} below the critical {}, underdamped: the capacitor voltage {}, and {}.",
            ohms(r.p.r),
            ohms(r_crit),
            reversals,
            settle
        ),
        (Regime::CriticallyDamped, Signal::Current) => format!(
            "R = {} equals the critical resistance, critically damped: one pulse of current \
             (negative, the capacitor discharging) that returns to zero without reversing; it \
             never exceeds {}.",
            ohms(r.p.r),
            bound
        ),
        (Regime::CriticallyDamped, Signal::Voltage) => format!(
            "R = {} equals the critical resistance, critically damped: the capacitor empties \
             as fast as it can without reversing; it {}.",
            ohms(r.p.r),
            settle
        ),
        (_, Signal::Current) => format!(
            "R = {} above the critical {}, overdamped: one slow pulse of current (negative, \
             the capacitor discharging) without reversing, slow time constant {}.",
            ohms(r.p.r),
            ohms(r_crit),
            si(sys.time_constants()[0].unwrap_or(f64::NAN), "s", 3)
        ),
        (_, Signal::Voltage) => format!(
            "R = {} above the critical {}, overdamped: the capacitor discharges slowly \
             without reversing; it {}.",
            ohms(r.p.r),
            ohms(r_crit),
            settle
        ),
    }
}
