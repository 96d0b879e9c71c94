//! Response metrics: step-response figures (`step`) and free-response figures (`free`).
//!
//! Both come in two flavours: *exact*, computed from the closed-form response with
//! bracketed root finding (no time grid, so no sampling error), and *data*, computed from
//! any sampled signal `(t[], y[])` with the definitions stated on each function.
//!
//! ```
//! use zeta_solver::metrics::{free::FreeMetrics, SettlingBand};
//! use zeta_solver::SecondOrder;
//! let sys = SecondOrder::from_natural(8.944_272, 0.3).unwrap();
//! let m = FreeMetrics::exact(&sys, 0.06, 0.0, SettlingBand::FREE_DEFAULT).unwrap();
//! // Rebound after release from rest: exp(−πζ/√(1−ζ²)).
//! assert!((m.peak_rebound - (-std::f64::consts::PI * 0.3 / 0.91f64.sqrt()).exp()).abs() < 1e-12);
//! ```

use std::fmt;

pub mod free;
pub mod step;

/// Why a metric could not be computed from the given settings or samples.
#[derive(Debug, Clone, PartialEq)]
pub enum MetricError {
    /// The settling band is not a fraction strictly between 0 and 1.
    BandOutOfRange {
        /// The band given (a fraction, 0.02 for 2 %).
        band: f64,
    },
    /// The rise-time limits are not `0 ≤ lo < hi ≤ 1`.
    RiseLimitsInvalid {
        /// Lower limit given (fraction of the steady state).
        lo: f64,
        /// Upper limit given (fraction of the steady state).
        hi: f64,
    },
    /// The time and value arrays have different lengths.
    LengthMismatch {
        /// Number of times.
        times: usize,
        /// Number of values.
        values: usize,
    },
    /// Fewer than two samples.
    TooFewSamples {
        /// Number of samples given.
        len: usize,
    },
    /// A time or value is NaN or infinite.
    NotFinite {
        /// Index of the first offending sample.
        index: usize,
    },
    /// Times are not strictly increasing.
    TimeNotIncreasing {
        /// Index of the first sample whose time is not after the previous one.
        index: usize,
    },
    /// The reference the metric is relative to (initial displacement or steady state) is zero.
    ZeroReference {
        /// Which reference, e.g. `"initial displacement"`.
        what: &'static str,
    },
}

impl fmt::Display for MetricError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            MetricError::BandOutOfRange { band } => write!(
                f,
                "settling band must be a fraction between 0 and 1 (0.02 for 2 %), got {band}"
            ),
            MetricError::RiseLimitsInvalid { lo, hi } => write!(
                f,
                "rise-time limits must satisfy 0 ≤ low < high ≤ 1, got low {lo} and high {hi}"
            ),
            MetricError::LengthMismatch { times, values } => write!(
                f,
                "need one value per time, got {times} times and {values} values"
            ),
            MetricError::TooFewSamples { len } => {
                write!(f, "need at least 2 samples, got {len}")
            }
            MetricError::NotFinite { index } => {
                write!(f, "sample {index} is not a finite number")
            }
            MetricError::TimeNotIncreasing { index } => write!(
                f,
                "times must increase, but sample {index} is not later than the one before"
            ),
            MetricError::ZeroReference { what } => {
                write!(f, "the {what} is zero, so a band relative to it is empty")
            }
        }
    }
}

impl std::error::Error for MetricError {}

/// A settling band as a fraction of the reference (0.05 = ±5 %), validated `0 < band < 1`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SettlingBand(f64);

impl SettlingBand {
    /// ±5 % of the initial displacement: the usual choice in suspension practice.
    pub const FREE_DEFAULT: SettlingBand = SettlingBand(0.05);
    /// ±2 % of the steady state: the default of MATLAB `stepinfo` and python-control
    /// `step_info` (`SettlingTimeThreshold = 0.02`).
    pub const STEP_DEFAULT: SettlingBand = SettlingBand(0.02);

    /// A band of `fraction` (e.g. `0.02` for 2 %); errors unless `0 < fraction < 1`.
    pub fn new(fraction: f64) -> Result<Self, MetricError> {
        if fraction > 0.0 && fraction < 1.0 {
            Ok(Self(fraction))
        } else {
            Err(MetricError::BandOutOfRange { band: fraction })
        }
    }

    /// The band as a fraction [-].
    pub fn fraction(self) -> f64 {
        self.0
    }
}

/// Checks a sampled signal: equal lengths, at least 2 samples, all finite, times increasing.
pub(crate) fn validate_samples(t: &[f64], y: &[f64]) -> Result<(), MetricError> {
    if t.len() != y.len() {
        return Err(MetricError::LengthMismatch {
            times: t.len(),
            values: y.len(),
        });
    }
    if t.len() < 2 {
        return Err(MetricError::TooFewSamples { len: t.len() });
    }
    let mut prev = f64::NEG_INFINITY;
    for (index, (&ti, &yi)) in t.iter().zip(y).enumerate() {
        if !ti.is_finite() || !yi.is_finite() {
            return Err(MetricError::NotFinite { index });
        }
        if ti <= prev {
            return Err(MetricError::TimeNotIncreasing { index });
        }
        prev = ti;
    }
    Ok(())
}

/// Iteration cap of [`solve_decreasing`]: bisection alone halves the bracket each step, so
/// 200 steps reach double precision from any finite bracket.
const ROOT_MAX_ITER: usize = 200;

/// Root of `g` in `[lo, hi]` where `g(lo) > 0 ≥ g(hi)` (the caller guarantees the bracket;
/// `g` returns `(value, derivative)`), starting from `guess` when it lies strictly inside
/// the bracket and from the midpoint otherwise.
///
/// Safeguarded Newton: a Newton step is taken when it stays strictly inside the current
/// bracket and at least halves the previous step, otherwise the bracket is bisected, so
/// convergence never becomes slower than bisection. Stops when the step falls below a few
/// ulps of `t`, or after [`ROOT_MAX_ITER`] iterations.
pub(crate) fn solve_decreasing(
    mut g: impl FnMut(f64) -> (f64, f64),
    lo: f64,
    hi: f64,
    guess: f64,
) -> f64 {
    let (mut lo, mut hi) = (lo, hi);
    let mut t = if guess > lo && guess < hi {
        guess
    } else {
        0.5 * (lo + hi)
    };
    let mut last_step = hi - lo;
    for _ in 0..ROOT_MAX_ITER {
        let (f, df) = g(t);
        if f == 0.0 {
            return t;
        }
        if f > 0.0 {
            lo = t;
        } else {
            hi = t;
        }
        let newton_step = f / df;
        let newton = t - newton_step;
        // Converged: the Newton correction is below rounding. (Testing this before the
        // bracket check matters: the corrected point may round onto the bracket end.)
        if newton_step.abs() <= 4.0 * f64::EPSILON * t.abs() + f64::MIN_POSITIVE {
            return newton.clamp(lo, hi);
        }
        let next = if newton.is_finite()
            && newton > lo
            && newton < hi
            && newton_step.abs() < 0.5 * last_step
        {
            newton
        } else {
            0.5 * (lo + hi)
        };
        last_step = (next - t).abs();
        t = next;
        let tol = 4.0 * f64::EPSILON * t.abs() + f64::MIN_POSITIVE;
        if last_step <= tol || hi - lo <= tol {
            return t;
        }
    }
    t
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn band_rejects_values_outside_the_open_unit_interval() {
        for bad in [0.0, 1.0, -0.1, 1.5, f64::NAN, f64::INFINITY] {
            assert!(SettlingBand::new(bad).is_err(), "{bad}");
        }
        assert_eq!(
            SettlingBand::new(0.02).map(SettlingBand::fraction),
            Ok(0.02)
        );
        let msg = SettlingBand::new(2.0).unwrap_err().to_string();
        assert!(msg.contains("got 2"), "{msg}");
    }

    #[test]
    fn solver_finds_the_root_of_cos_on_a_wide_bracket() {
        let r = solve_decreasing(|t| (t.cos(), -t.sin()), 0.0, 3.0, f64::NAN);
        assert!((r - std::f64::consts::FRAC_PI_2).abs() < 1e-15);
        // A flat function forces bisection; the cap still ends the loop.
        let r = solve_decreasing(|t| (if t < 0.3 { 1.0 } else { -1.0 }, 0.0), 0.0, 1.0, 0.9);
        assert!((r - 0.3).abs() < 1e-15);
    }

    #[test]
    fn solver_stops_once_newton_has_converged() {
        // Regression: a converged Newton point rounding onto the bracket end must not fall
        // back to bisection. From a near guess, quadratic convergence needs ≤ 6 evaluations.
        let evals = std::cell::Cell::new(0);
        let r = solve_decreasing(
            |t| {
                evals.set(evals.get() + 1);
                (t.cos(), -t.sin())
            },
            0.0,
            3.0,
            1.4,
        );
        assert!((r - std::f64::consts::FRAC_PI_2).abs() < 1e-15);
        assert!(evals.get() <= 6, "{} evaluations", evals.get());
    }

    #[test]
    fn sample_validation_names_the_offending_index() {
        assert_eq!(
            validate_samples(&[0.0, 1.0], &[1.0]),
            Err(MetricError::LengthMismatch {
                times: 2,
                values: 1
            })
        );
        assert_eq!(
            validate_samples(&[0.0, 1.0, 1.0], &[1.0, 2.0, 3.0]),
            Err(MetricError::TimeNotIncreasing { index: 2 })
        );
        assert_eq!(
            validate_samples(&[0.0, f64::NAN], &[1.0, 2.0]),
            Err(MetricError::NotFinite { index: 1 })
        );
        assert_eq!(
            validate_samples(&[0.0], &[1.0]),
            Err(MetricError::TooFewSamples { len: 1 })
        );
    }
}
