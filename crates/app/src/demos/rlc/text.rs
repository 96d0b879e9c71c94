//! The RLC demo's prose: summary, equation and the figures' text alternatives.

use super::figures::Signal;
use super::Results;
use crate::format::si;
use crate::t;
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
    let resistance = ohms(r.p.r);
    let critical = ohms(sys.critical_damping().unwrap_or(0.0));
    let w0 = si(sys.natural_frequency().unwrap_or(0.0), "rad/s", 3);
    let bound = si(r.current_scale(), "A", 3);
    let settling = metrics.and_then(|m| m.settling_time);
    let settles = if settling.is_some() { "yes" } else { "no" };
    let time = settling.map(|t| si(t, "s", 3)).unwrap_or_default();
    // The solver counts zero crossings before the settling time.
    let (reversal, crossings, rebound) = match metrics {
        Some(m) if m.zero_crossings == 0 && m.rebound_time.is_some() => {
            ("slight", 0, si(100.0 * m.peak_rebound, "%", 3))
        }
        Some(m) if m.zero_crossings >= 1 => ("count", m.zero_crossings, String::new()),
        _ => ("never", 0, String::new()),
    };
    let regime = match sys.regime() {
        Regime::Undamped => "undamped",
        Regime::Underdamped => "underdamped",
        Regime::CriticallyDamped => "critical",
        _ => "overdamped",
    };
    match signal {
        Signal::Current => t!(
            "rlc-describe-current",
            regime = regime,
            resistance = resistance,
            critical = critical,
            frequency = w0,
            ringing = si(sys.damped_frequency().unwrap_or(0.0), "rad/s", 3),
            q = si(sys.quality_factor().unwrap_or(f64::NAN), "", 3),
            alpha = si(sys.alpha(), "1/s", 3),
            bound = bound,
            time = si(sys.time_constants()[0].unwrap_or(f64::NAN), "s", 3)
        ),
        Signal::Voltage => t!(
            "rlc-describe-voltage",
            regime = regime,
            resistance = resistance,
            critical = critical,
            voltage = si(r.p.v0.abs(), "V", 3),
            frequency = w0,
            reversal = reversal,
            crossings = crossings,
            rebound = rebound,
            settles = settles,
            time = time
        ),
    }
}
