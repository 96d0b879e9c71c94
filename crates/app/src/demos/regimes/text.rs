//! The regimes demo's prose: summary, equation, the table of regimes and the figures'
//! text alternatives.

use super::Results;
use crate::format::{self, si};
use crate::spec::Table;
use crate::t;
use zeta_solver::{Complex, Regime};

pub(super) const SUMMARY: &str =
    "Free response from x(0) = x₀, x′(0) = v₀. The damping ratio ζ decides the \
                      regime: ζ = 0 undamped, 0 < ζ < 1 underdamped, ζ = 1 critically damped, \
                      ζ > 1 overdamped, ζ < 0 negatively damped (the response grows). The poles \
                      s = −ζωₙ ± ωₙ√(ζ² − 1) move around a circle of radius ωₙ, onto the real \
                      axis at ζ = 1 and across the imaginary axis at ζ = 0.";

pub(super) const EQUATION: &str = "<math display=\"block\"><mrow>\
<mover><mi>x</mi><mo>¨</mo></mover><mo>+</mo><mn>2</mn><mi>ζ</mi><msub><mi>ω</mi><mi>n</mi></msub>\
<mover><mi>x</mi><mo>˙</mo></mover><mo>+</mo><msubsup><mi>ω</mi><mi>n</mi><mn>2</mn></msubsup><mi>x</mi>\
<mo>=</mo><mn>0</mn></mrow></math>";

/// The regimes side by side; the row of the current regime is highlighted.
pub(super) fn regime_table() -> Table {
    Table {
        caption: "The damping regimes",
        columns: vec![
            "regime",
            "condition",
            "roots s₁, s₂",
            "behaviour",
            "engineering examples",
        ],
        rows: vec![
            (
                "undamped",
                vec![
                    "Undamped",
                    "ζ = 0",
                    "±iωₙ, on the imaginary axis",
                    "oscillates forever at ωₙ",
                    "ideal pendulum, LC tank circuit",
                ],
            ),
            (
                "underdamped",
                vec![
                    "Underdamped",
                    "0 < ζ < 1",
                    "−ζωₙ ± iω_d, complex pair",
                    "decaying oscillation at ω_d",
                    "car suspension (ζ ≈ 0.2–0.7), guitar string",
                ],
            ),
            (
                "critically damped",
                vec![
                    "Critically damped",
                    "ζ = 1",
                    "−ωₙ, double real root",
                    "fastest return without oscillating",
                    "door closer, analogue meter needle",
                ],
            ),
            (
                "overdamped",
                vec![
                    "Overdamped",
                    "ζ > 1",
                    "two negative real roots",
                    "slow return, no oscillation",
                    "heavy hydraulic damper, thermometer",
                ],
            ),
            (
                "negatively damped",
                vec![
                    "Negatively damped",
                    "ζ < 0",
                    "right half-plane",
                    "growing oscillation",
                    "flutter (Tacoma Narrows), squealing brakes",
                ],
            ),
        ],
        highlight_readout: "regime",
    }
}

/// The response described in words, for screen readers and the plot's text alternative.
pub(super) fn describe(r: &Results) -> String {
    let regime = format::regime(r.regime);
    match &r.metrics {
        Some(m) => {
            let rebound = si(100.0 * m.peak_rebound, "%", 3);
            // The solver counts crossings before the response settles into the band.
            let swings = m.zero_crossings;
            match m.settling_time {
                Some(t) => t!(
                    "regimes-describe-settles",
                    regime = regime,
                    swings = swings,
                    time = si(t, "s", 3),
                    rebound = rebound
                ),
                None => t!(
                    "regimes-describe-unsettled",
                    regime = regime,
                    swings = swings,
                    rebound = rebound
                ),
            }
        }
        None => match r.regime {
            Regime::Undamped => t!(
                "regimes-describe-undamped",
                amplitude = si(r.response.envelope_amplitude().unwrap_or(0.0), "m", 3),
                frequency = si(r.sys.natural_frequency().unwrap_or(0.0), "rad/s", 3)
            ),
            Regime::NegativelyDamped => t!(
                "regimes-describe-growing",
                time = si(1.0 / (-r.sys.alpha()).max(1e-300), "s", 3)
            ),
            _ => t!("regimes-describe-at-rest", regime = regime),
        },
    }
}

/// The poles in words.
pub(super) fn describe_poles(poles: &[Complex; 2]) -> String {
    let sign = |im: f64| if im < 0.0 { "−" } else { "+" };
    t!(
        "regimes-poles",
        re1 = si(poles[0].re, "", 4),
        sign1 = sign(poles[0].im),
        im1 = si(poles[0].im.abs(), "", 4),
        re2 = si(poles[1].re, "", 4),
        sign2 = sign(poles[1].im),
        im2 = si(poles[1].im.abs(), "", 4),
        side = if poles[0].re > 0.0 { "right" } else { "left" }
    )
}
