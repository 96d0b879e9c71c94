//! Step-response metrics with the definitions of python-control's `step_info` (and MATLAB's
//! `stepinfo`, which it mirrors).
//!
//! Definitions, as read in python-control 0.10 (`control/timeresp.py`, `step_info`), for a
//! response `y(t)` with steady state `y_ss` and `σ = sign(y_ss)`:
//!
//! - **rise time**: from the first time `σ·y ≥ σ·lo·y_ss` to the first time
//!   `σ·y ≥ σ·hi·y_ss`, with `(lo, hi) = (0.1, 0.9)` by default (`RiseTimeLimits`);
//! - **settling time**: the end of the last excursion with `|y/y_ss − 1| ≥ band`, band
//!   0.02 by default (`SettlingTimeThreshold`); on samples, the time of the sample after
//!   the last one outside the band;
//! - **overshoot** \[%\]: `100·(max σ·y − |y_ss|)/|y_ss|` when positive, else 0;
//! - **undershoot** \[%\]: `100·|min σ·y|/|y_ss|` when `min σ·y < 0` (the response first goes
//!   the wrong way), else 0;
//! - **peak**: `max |y|`, and **peak time**: the first time it is reached;
//! - **steady-state value**: `y_ss` (the DC gain for a model; the last sample for data).
//!
//! Two paths. [`StepInfo::exact`] uses the closed-form step response from rest of a stable
//! [`SecondOrder`] under a constant force `F0`: `y(t) = y_ss·(1 − z(t))` with `y_ss = F0/c`
//! and `z` the free response from `z(0) = 1`, `z'(0) = 0`. So `|y − y_ss| = |y_ss|·|z|` and
//! the settling time is the free-response settling time of `z` (see [`super::free`]); the
//! rise times are the first roots of `z = 1 − level`, found by safeguarded Newton on the
//! interval where `z` falls monotonically; the overshoot is `100·e^{−πζ/√(1−ζ²)}` at the
//! peak time `π/ω_d`. No time grid is involved. [`StepInfo::from_samples`] applies the data
//! definitions above to any sampled signal, so it reproduces python-control's numbers when
//! given python-control's time grid.
//!
//! ```
//! use zeta_solver::metrics::step::{StepConfig, StepInfo};
//! use zeta_solver::SecondOrder;
//! let sys = SecondOrder::from_natural(80f64.sqrt(), 0.7).unwrap();
//! // Unit DC gain: a force of c = ω_n² gives y_ss = 1.
//! let info = StepInfo::exact(&sys, sys.stiffness(), &StepConfig::default()).unwrap();
//! assert!((info.overshoot_percent - 4.598_791_026).abs() < 1e-8);
//! assert!((info.peak_time.unwrap() - 0.491_835_408).abs() < 1e-8);
//! ```

use std::f64::consts::PI;

use super::free::FreeShape;
use super::{solve_decreasing, validate_samples, MetricError, SettlingBand};
use crate::free::FreeResponse;
use crate::model::SecondOrder;
use crate::regime::Regime;

/// Rise-time limits as fractions of the steady state, validated `0 ≤ lo < hi ≤ 1`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RiseLimits {
    lo: f64,
    hi: f64,
}

impl RiseLimits {
    /// 10 % to 90 %, the default of python-control (`RiseTimeLimits=(0.1, 0.9)`) and MATLAB.
    pub const TEN_NINETY: RiseLimits = RiseLimits { lo: 0.1, hi: 0.9 };

    /// Limits `lo` and `hi` as fractions of `y_ss`; errors unless `0 ≤ lo < hi ≤ 1`.
    pub fn new(lo: f64, hi: f64) -> Result<Self, MetricError> {
        if lo >= 0.0 && lo < hi && hi <= 1.0 {
            Ok(Self { lo, hi })
        } else {
            Err(MetricError::RiseLimitsInvalid { lo, hi })
        }
    }

    /// Lower limit [-].
    pub fn lo(self) -> f64 {
        self.lo
    }

    /// Upper limit [-].
    pub fn hi(self) -> f64 {
        self.hi
    }
}

/// Settings of the step metrics; `Default` is a 2 % band and 10–90 % rise time.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StepConfig {
    /// Settling band as a fraction of `|y_ss|`.
    pub settling_band: SettlingBand,
    /// Rise-time limits.
    pub rise_limits: RiseLimits,
}

impl Default for StepConfig {
    fn default() -> Self {
        Self {
            settling_band: SettlingBand::STEP_DEFAULT,
            rise_limits: RiseLimits::TEN_NINETY,
        }
    }
}

/// Step-response metrics (each field's doc starts with its python-control `step_info` key).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StepInfo {
    /// `RiseTime`: from the low to the high limit \[s\]; `None` when the high limit is never
    /// reached (exact path: `hi = 1` without overshoot; data path: not within the record).
    pub rise_time: Option<f64>,
    /// `SettlingTime`: \[s\]; `None` when the record ends outside the band (data path).
    pub settling_time: Option<f64>,
    /// `Overshoot`: \[%\].
    pub overshoot_percent: f64,
    /// `Undershoot`: \[%\].
    pub undershoot_percent: f64,
    /// `Peak`: `max |y|` (unit of `y`).
    pub peak: f64,
    /// `PeakTime`: \[s\]; on the exact path `None` when the supremum `|y_ss|` is only
    /// approached as `t → ∞` (critically and over-damped systems).
    pub peak_time: Option<f64>,
    /// `SteadyStateValue`: `y_ss` (unit of `y`).
    pub steady_state: f64,
}

/// Cap on the doubling search for the rise-time bracket of a non-oscillating response.
const MAX_DOUBLINGS: usize = 200;

impl StepInfo {
    /// Exact metrics of the step response from rest of `sys` to a constant force `force`
    /// (unit of `f`, so `y_ss = force / c`).
    ///
    /// `None` unless the system is stable (under-, critically or over-damped) and `force`
    /// is finite and non-zero.
    pub fn exact(sys: &SecondOrder, force: f64, config: &StepConfig) -> Option<Self> {
        if !force.is_finite() || force == 0.0 {
            return None;
        }
        let y_ss = force / sys.stiffness();
        let shape = FreeShape::new(sys, 1.0, 0.0)?;
        let settling = shape.settle(config.settling_band)?.time;
        let z = FreeResponse::new(*sys, 1.0, 0.0);

        // Interval on which z falls monotonically from 1: up to its first minimum at π/ω_d
        // when it oscillates, otherwise all of [0, ∞).
        let oscillates = sys.regime() == Regime::Underdamped;
        let t_min = sys
            .damped_frequency()
            .filter(|_| oscillates)
            .map(|wd| PI / wd);
        let tau = sys.time_constants()[0].unwrap_or(1.0);
        let first_time_at = |level: f64| first_fall_to(&z, 1.0 - level, t_min, tau);

        let rise_time = match (
            first_time_at(config.rise_limits.lo),
            first_time_at(config.rise_limits.hi),
        ) {
            (Some(a), Some(b)) => Some(b - a),
            _ => None,
        };
        let (overshoot, peak_time) = match t_min {
            Some(tp) => ((-sys.alpha() * tp).exp(), Some(tp)),
            None => (0.0, None),
        };
        Some(Self {
            rise_time,
            settling_time: Some(settling),
            overshoot_percent: 100.0 * overshoot,
            // y/y_ss = 1 − z ≥ 0 because z ≤ 1 for a release from rest: never undershoots.
            undershoot_percent: 0.0,
            peak: y_ss.abs() * (1.0 + overshoot),
            peak_time,
            steady_state: y_ss,
        })
    }

    /// Metrics of a sampled step response, with python-control's data definitions (module
    /// docs): no interpolation, every time is a sample time. `steady_state` defaults to the
    /// last sample, as in python-control.
    ///
    /// Errors on mismatched lengths, fewer than 2 samples, non-finite values, times that do
    /// not increase, or a zero (or non-finite) steady state.
    pub fn from_samples(
        t: &[f64],
        y: &[f64],
        steady_state: Option<f64>,
        config: &StepConfig,
    ) -> Result<Self, MetricError> {
        validate_samples(t, y)?;
        let y_ss = steady_state.or_else(|| y.last().copied()).unwrap_or(0.0);
        if y_ss == 0.0 || !y_ss.is_finite() {
            return Err(MetricError::ZeroReference {
                what: "steady-state value",
            });
        }
        let sg = y_ss.signum();
        let time_of = |i: Option<usize>| i.and_then(|i| t.get(i).copied());

        let first_at = |level: f64| time_of(y.iter().position(|&v| sg * (v - level * y_ss) >= 0.0));
        let rise_time = match (
            first_at(config.rise_limits.lo),
            first_at(config.rise_limits.hi),
        ) {
            (Some(a), Some(b)) => Some(b - a),
            _ => None,
        };

        let band = config.settling_band.fraction();
        let settled_from = match y.iter().rposition(|&v| (v / y_ss - 1.0).abs() >= band) {
            Some(i) => i + 1,
            None => 0,
        };
        let settling_time = time_of(Some(settled_from));

        let (mut max_s, mut min_s) = (f64::NEG_INFINITY, f64::INFINITY);
        let (mut peak, mut peak_idx) = (f64::NEG_INFINITY, 0usize);
        for (i, &v) in y.iter().enumerate() {
            max_s = max_s.max(sg * v);
            min_s = min_s.min(sg * v);
            if v.abs() > peak {
                peak = v.abs();
                peak_idx = i;
            }
        }
        let excess = max_s - y_ss.abs();
        let overshoot_percent = if excess > 0.0 {
            100.0 * excess / y_ss.abs()
        } else {
            0.0
        };
        let undershoot_percent = if min_s < 0.0 {
            -100.0 * min_s / y_ss.abs()
        } else {
            0.0
        };

        Ok(Self {
            rise_time,
            settling_time,
            overshoot_percent,
            undershoot_percent,
            peak,
            peak_time: time_of(Some(peak_idx)),
            steady_state: y_ss,
        })
    }
}

/// First time `z(t) = target` for `z` falling monotonically from `z(0) = 1`, on `[0, end]`
/// (`end = None`: unbounded, bracketed by doubling steps of `tau`). `None` if it is never
/// reached.
fn first_fall_to(z: &FreeResponse, target: f64, end: Option<f64>, tau: f64) -> Option<f64> {
    if target >= 1.0 {
        return Some(0.0);
    }
    let g = |t: f64| {
        let [x, v] = z.state(t);
        (x - target, v)
    };
    match end {
        Some(b) => (g(b).0 <= 0.0).then(|| solve_decreasing(g, 0.0, b, f64::NAN)),
        // z > 0 for all t when it does not oscillate: the level y_ss itself is never reached.
        None if target <= 0.0 => None,
        None => {
            let (mut lo, mut step) = (0.0, tau);
            for _ in 0..MAX_DOUBLINGS {
                let t = step;
                if !t.is_finite() {
                    return None;
                }
                if g(t).0 <= 0.0 {
                    return Some(solve_decreasing(g, lo, t, f64::NAN));
                }
                lo = t;
                step *= 2.0;
            }
            None
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rise_limits_are_validated() {
        assert!(RiseLimits::new(0.9, 0.1).is_err());
        assert!(RiseLimits::new(-0.1, 0.9).is_err());
        assert!(RiseLimits::new(0.1, 1.1).is_err());
        assert!(RiseLimits::new(0.0, 1.0).is_ok());
    }

    #[test]
    fn negative_force_mirrors_the_response() {
        let sys = SecondOrder::from_natural(3.0, 0.4).unwrap();
        let cfg = StepConfig::default();
        let up = StepInfo::exact(&sys, 9.0, &cfg).unwrap();
        let down = StepInfo::exact(&sys, -9.0, &cfg).unwrap();
        assert_eq!(up.rise_time, down.rise_time);
        assert_eq!(up.settling_time, down.settling_time);
        assert_eq!(up.overshoot_percent, down.overshoot_percent);
        assert_eq!(down.steady_state, -1.0);
        assert!(StepInfo::exact(&sys, 0.0, &cfg).is_none());
        assert!(
            StepInfo::exact(&SecondOrder::from_natural(3.0, 0.0).unwrap(), 1.0, &cfg).is_none()
        );
    }

    #[test]
    fn overdamped_has_no_overshoot_and_full_rise_is_never_reached() {
        let sys = SecondOrder::from_natural(3.0, 1.5).unwrap();
        let full = StepConfig {
            rise_limits: RiseLimits::new(0.0, 1.0).unwrap(),
            ..StepConfig::default()
        };
        let info = StepInfo::exact(&sys, 9.0, &full).unwrap();
        assert_eq!(info.overshoot_percent, 0.0);
        assert_eq!(info.peak_time, None);
        assert_eq!(info.rise_time, None);
        assert_eq!(info.peak, 1.0);
    }
}
