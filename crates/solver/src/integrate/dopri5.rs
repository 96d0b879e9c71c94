//! Dormand–Prince 5(4): an adaptive explicit Runge–Kutta pair with error control and
//! dense output.
//!
//! Each step computes a 5th-order solution and an embedded 4th-order one from the same
//! seven stages; their difference estimates the local error. The seventh stage is
//! `f(t + h, y₁)`, which is the first stage of the next step (FSAL), so an accepted step
//! costs six new `rhs` calls.
//!
//! Error norm (Hairer–Nørsett–Wanner, Solving ODEs I, §II.4):
//! `err = √(mean over i of (eᵢ / (atol + rtol·max(|y₀ᵢ|, |y₁ᵢ|)))²)`; the step is accepted
//! when `err ≤ 1`. Step-size control: after an accepted step, the PI controller
//! `h_new = h·safety·err^(−0.17)·err_prev^(0.04)` (Hairer's DOPRI5 defaults, β = 0.04)
//! or the elementary `h·safety·err^(−1/5)`, the factor clamped to `[fac_min, fac_max]`
//! and not above 1 right after a rejection; after a rejection `h·max(fac_min,
//! safety·err^(−1/5))`.
//!
//! Dense output: the 4th-order continuous extension of Shampine (1986) — for
//! `θ = (t − t₀)/h`, `y(t) ≈ y₀ + θ(Δ + (1−θ)(B + θ(Δ − h·k₇ − B + (1−θ)·h·Σdᵢkᵢ)))` with
//! `Δ = y₁ − y₀`, `B = h·k₁ − Δ` — exact at both ends of each step and continuous with
//! continuous derivative between steps.

use super::tableau::dopri5 as tab;
use super::{IntegrationError, Solution, Stats, System, MAX_STEPS};

/// PI-controller exponent on the current error (`1/5 − 0.75·β`, β = 0.04).
const PI_ALPHA: f64 = 0.17;
/// PI-controller exponent on the previous accepted error.
const PI_BETA: f64 = 0.04;
/// Error exponent of the elementary controller, `1/(q + 1)` with `q = 4`.
const ELEMENTARY_EXP: f64 = 0.2;
/// Floor on the remembered previous error, so that one exact step does not blow up the PI
/// factor (Hairer's `facold` floor).
const ERR_PREV_FLOOR: f64 = 1e-4;
/// Smallest relative tolerance accepted: below it the requested accuracy is below
/// double-precision rounding and the controller would shrink `h` until it underflows.
const MIN_RTOL: f64 = 1e-14;

/// How the next step size is chosen from the error estimate.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum StepControl {
    /// Elementary (I) control: `h·safety·err^(−1/5)`.
    Elementary,
    /// Proportional–integral control: `h·safety·err^(−0.17)·err_prev^(0.04)`; smoother
    /// step sequences, fewer rejections.
    #[default]
    Pi,
}

/// Settings of [`Dopri5`]. Validated by [`Dopri5::new`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Dopri5Config {
    /// Relative tolerance [-], ≥ 1e−14. Default `1e−6`.
    pub rtol: f64,
    /// Absolute tolerance, in the state's units, ≥ 0. Default `1e−9`.
    pub atol: f64,
    /// First trial step (s); `None` picks one from the problem (Hairer's starting-step
    /// heuristic, one extra `rhs` call). Default `None`.
    pub h_initial: Option<f64>,
    /// Largest step (s); `None` means the whole span. Default `None`.
    pub h_max: Option<f64>,
    /// Step attempts (accepted + rejected) before [`IntegrationError::MaxSteps`];
    /// 1 … [`MAX_STEPS`]. Default 100 000.
    pub max_steps: usize,
    /// Safety factor on the predicted step, in (0, 1]. Default `0.9`.
    pub safety: f64,
    /// Smallest factor by which one step may shrink the next, in (0, 1). Default `0.2`.
    pub fac_min: f64,
    /// Largest factor by which one step may grow the next, > 1. Default `10`.
    pub fac_max: f64,
    /// Step-size controller. Default [`StepControl::Pi`].
    pub control: StepControl,
}

impl Default for Dopri5Config {
    fn default() -> Self {
        Self {
            rtol: 1e-6,
            atol: 1e-9,
            h_initial: None,
            h_max: None,
            max_steps: 100_000,
            safety: 0.9,
            fac_min: 0.2,
            fac_max: 10.0,
            control: StepControl::Pi,
        }
    }
}

/// Returns an [`IntegrationError::InvalidSetting`] unless `ok`.
fn check(
    ok: bool,
    name: &'static str,
    value: f64,
    rule: &'static str,
) -> Result<(), IntegrationError> {
    if ok {
        Ok(())
    } else {
        Err(IntegrationError::InvalidSetting { name, value, rule })
    }
}

/// The Dormand–Prince 5(4) integrator with validated settings.
///
/// ```
/// use zeta_solver::integrate::{Dopri5, Dopri5Config, Linear2};
/// use zeta_solver::{FreeResponse, SecondOrder};
/// let sys = SecondOrder::from_natural(2.0, 0.1).unwrap();
/// let dp = Dopri5::new(Dopri5Config { rtol: 1e-8, atol: 1e-10, ..Default::default() }).unwrap();
/// let out = dp.solve(&Linear2::free(sys), [1.0, 0.0], 0.0, 10.0).unwrap();
/// let exact = FreeResponse::new(sys, 1.0, 0.0);
/// let mid = out.dense.eval(3.3).unwrap();
/// assert!((mid[0] - exact.displacement(3.3)).abs() < 1e-6);
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Dopri5 {
    config: Dopri5Config,
}

/// A Dormand–Prince run: the accepted steps and the dense output between them.
#[derive(Debug, Clone, PartialEq)]
pub struct Dopri5Solution<const N: usize> {
    /// The step record: `t` holds `t0` and the end of every accepted step.
    pub solution: Solution<N>,
    /// Continuous 4th-order interpolant over `[t0, t_end]`.
    pub dense: DenseOutput<N>,
}

/// One accepted step's interpolation data.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Segment<const N: usize> {
    t0: f64,
    t1: f64,
    h: f64,
    coef: [[f64; N]; 5],
}

/// Dense output of a [`Dopri5`] run: the solution at any `t` in the run's span.
#[derive(Debug, Clone, PartialEq)]
pub struct DenseOutput<const N: usize> {
    start: f64,
    y_start: [f64; N],
    segments: Vec<Segment<N>>,
}

impl<const N: usize> DenseOutput<N> {
    /// The covered span `(t0, t_end)` (s).
    pub fn span(&self) -> (f64, f64) {
        (
            self.start,
            self.segments.last().map_or(self.start, |s| s.t1),
        )
    }

    /// The interpolated state at `t` (s); `None` outside the span or for NaN.
    pub fn eval(&self, t: f64) -> Option<[f64; N]> {
        let (lo, hi) = self.span();
        if !(t >= lo && t <= hi) {
            return None;
        }
        let idx = self.segments.partition_point(|s| s.t1 < t);
        let Some(seg) = self.segments.get(idx) else {
            return Some(self.y_start);
        };
        let theta = (t - seg.t0) / seg.h;
        let theta1 = 1.0 - theta;
        let c = &seg.coef;
        let mut out = [0.0; N];
        for (i, o) in out.iter_mut().enumerate() {
            *o = c[0][i]
                + theta * (c[1][i] + theta1 * (c[2][i] + theta * (c[3][i] + theta1 * c[4][i])));
        }
        Some(out)
    }

    /// Allocation-free sampling: `out[i] = y(t[i])` for `i < min(t.len(), out.len())`;
    /// points outside the span get NaN. Returns how many points were inside the span.
    pub fn sample_into(&self, t: &[f64], out: &mut [[f64; N]]) -> usize {
        let mut inside = 0;
        for (o, &ti) in out.iter_mut().zip(t) {
            match self.eval(ti) {
                Some(y) => {
                    *o = y;
                    inside += 1;
                }
                None => *o = [f64::NAN; N],
            }
        }
        inside
    }
}

/// Scaled RMS norm `√(mean (vᵢ/scᵢ)²)`.
fn scaled_rms<const N: usize>(v: &[f64; N], sc: &[f64; N]) -> f64 {
    if N == 0 {
        return 0.0;
    }
    let sum: f64 = v.iter().zip(sc).map(|(a, s)| (a / s) * (a / s)).sum();
    (sum / N as f64).sqrt()
}

/// `out = y + h·Σⱼ aⱼ·kⱼ` component by component, or `h·Σⱼ aⱼ·kⱼ` without `y`: a stage,
/// the solution or the error estimate of a step, from a row `a` of the tableau and the
/// stage derivatives `k`. Zero coefficients are left out (`b₂ = e₂ = 0`) and the sum runs
/// in the order of `j`, so it rounds as the formula written out does.
#[inline]
fn combine<const N: usize>(
    out: &mut [f64; N],
    y: Option<&[f64; N]>,
    h: f64,
    a: &[f64],
    k: &[&[f64; N]],
) {
    for (i, o) in out.iter_mut().enumerate() {
        let terms = a.iter().zip(k).filter(|(aj, _)| **aj != 0.0);
        let sum = terms.map(|(aj, kj)| aj * kj[i]).reduce(|s, x| s + x);
        let sum = sum.unwrap_or(0.0);
        *o = match y {
            Some(y) => y[i] + h * sum,
            None => h * sum,
        };
    }
}

impl Dopri5 {
    /// Validates `config` (see the field docs for the allowed ranges).
    pub fn new(config: Dopri5Config) -> Result<Self, IntegrationError> {
        let c = &config;
        check(
            c.rtol.is_finite() && c.rtol >= MIN_RTOL,
            "rtol",
            c.rtol,
            "must be at least 1e-14",
        )?;
        check(
            c.atol.is_finite() && c.atol >= 0.0,
            "atol",
            c.atol,
            "must not be negative",
        )?;
        for (name, step) in [("initial step", c.h_initial), ("maximum step", c.h_max)] {
            if let Some(h) = step {
                check(h.is_finite() && h > 0.0, name, h, "must be positive")?;
            }
        }
        check(
            c.max_steps >= 1 && c.max_steps <= MAX_STEPS,
            "max_steps",
            c.max_steps as f64,
            "must be between 1 and 2 000 000",
        )?;
        check(
            c.safety > 0.0 && c.safety <= 1.0,
            "safety",
            c.safety,
            "must lie in (0, 1]",
        )?;
        check(
            c.fac_min > 0.0 && c.fac_min < 1.0,
            "fac_min",
            c.fac_min,
            "must lie in (0, 1)",
        )?;
        check(
            c.fac_max > 1.0 && c.fac_max.is_finite(),
            "fac_max",
            c.fac_max,
            "must exceed 1",
        )?;
        Ok(Self { config })
    }

    /// The validated settings.
    pub fn config(&self) -> Dopri5Config {
        self.config
    }

    /// Error-weight vector `atol + rtol·max(|a|, |b|)`, kept above the smallest positive
    /// double so that a pure relative tolerance on a zero component does not divide by 0.
    fn scale<const N: usize>(&self, a: &[f64; N], b: &[f64; N]) -> [f64; N] {
        let mut sc = [0.0; N];
        for i in 0..N {
            sc[i] = (self.config.atol + self.config.rtol * a[i].abs().max(b[i].abs()))
                .max(f64::MIN_POSITIVE);
        }
        sc
    }

    /// Starting step (after Hairer–Nørsett–Wanner I, §II.4): `h₀ = 0.01·‖y₀‖/‖f₀‖`,
    /// then `h₁ = (0.01/max(‖f₀‖, ‖f₁ − f₀‖/h₀))^{1/5}` from one Euler step, and
    /// `min(100·h₀, h₁)`. One `rhs` call.
    fn initial_step<const N: usize, S: System<N>>(
        &self,
        sys: &S,
        t0: f64,
        y0: &[f64; N],
        f0: &[f64; N],
        h_cap: f64,
    ) -> f64 {
        let sc = self.scale(y0, y0);
        let d0 = scaled_rms(y0, &sc);
        let d1 = scaled_rms(f0, &sc);
        let h0 = if d0 < 1e-5 || d1 < 1e-5 {
            1e-6
        } else {
            0.01 * d0 / d1
        };
        let h0 = h0.min(h_cap);
        let mut y1 = *y0;
        for i in 0..N {
            y1[i] += h0 * f0[i];
        }
        let mut f1 = [0.0; N];
        sys.rhs(t0 + h0, &y1, &mut f1);
        let mut df = [0.0; N];
        for i in 0..N {
            df[i] = f1[i] - f0[i];
        }
        let d2 = scaled_rms(&df, &sc) / h0;
        let big = d1.max(d2);
        let h1 = if big <= 1e-15 {
            (h0 * 1e-3).max(1e-6)
        } else {
            (0.01 / big).powf(ELEMENTARY_EXP)
        };
        let h = (100.0 * h0).min(h1).min(h_cap);
        if h.is_finite() && h > 0.0 {
            h
        } else {
            h0
        }
    }

    /// Integrates from `y0` at `t0` to `t_end` (s) (`t_end ≥ t0`), returning the accepted
    /// steps and the dense output.
    pub fn solve<const N: usize, S: System<N>>(
        &self,
        sys: &S,
        y0: [f64; N],
        t0: f64,
        t_end: f64,
    ) -> Result<Dopri5Solution<N>, IntegrationError> {
        if !(t0.is_finite() && t_end.is_finite() && t_end >= t0) {
            return Err(IntegrationError::InvalidSpan { t0, t_end });
        }
        if !y0.iter().all(|v| v.is_finite()) {
            return Err(IntegrationError::NonFinite { t: t0 });
        }
        let cfg = &self.config;
        let span = t_end - t0;
        let mut stats = Stats::default();
        let mut ts = vec![t0];
        let mut ys = vec![y0];
        let mut segments = Vec::new();
        let done = |ts: Vec<f64>, ys, segments, stats| Dopri5Solution {
            solution: Solution {
                t: ts,
                y: ys,
                stats,
            },
            dense: DenseOutput {
                start: t0,
                y_start: y0,
                segments,
            },
        };
        if span == 0.0 {
            return Ok(done(ts, ys, segments, stats));
        }

        let mut k1 = [0.0; N];
        sys.rhs(t0, &y0, &mut k1);
        stats.n_rhs += 1;
        if !k1.iter().all(|v| v.is_finite()) {
            return Err(IntegrationError::NonFinite { t: t0 });
        }
        let h_max = cfg.h_max.unwrap_or(span).min(span);
        let mut h = match cfg.h_initial {
            Some(h) => h.min(h_max),
            None => {
                stats.n_rhs += 1;
                self.initial_step(sys, t0, &y0, &k1, h_max)
            }
        };

        let (mut t, mut y) = (t0, y0);
        let mut err_prev = ERR_PREV_FLOOR;
        let mut after_reject = false;
        let mut last_was_nonfinite = false;
        let (mut k2, mut k3, mut k4, mut k5, mut k6, mut k7) =
            ([0.0; N], [0.0; N], [0.0; N], [0.0; N], [0.0; N], [0.0; N]);
        let mut stage = [0.0; N];
        let mut y_new = [0.0; N];
        let mut attempts = 0usize;
        while t < t_end {
            if attempts >= cfg.max_steps {
                return Err(IntegrationError::MaxSteps { t, n: attempts });
            }
            attempts += 1;
            // Stretch the last step (up to 1 %) to land exactly on t_end, so no sliver of a
            // step remains.
            let last = t + 1.01 * h >= t_end;
            if last {
                h = t_end - t;
            }
            let h_min = 16.0 * f64::EPSILON * t.abs().max(t_end.abs()).max(span);
            if h < h_min {
                return Err(if last_was_nonfinite {
                    IntegrationError::NonFinite { t }
                } else {
                    IntegrationError::StepSizeUnderflow { t }
                });
            }

            // Written out: `(h·a₂₁)·k₁` rounds otherwise than `combine`'s `h·(a₂₁·k₁)`.
            for i in 0..N {
                stage[i] = y[i] + h * tab::A21 * k1[i];
            }
            sys.rhs(t + tab::C2 * h, &stage, &mut k2);
            combine(&mut stage, Some(&y), h, &tab::A3, &[&k1, &k2]);
            sys.rhs(t + tab::C3 * h, &stage, &mut k3);
            combine(&mut stage, Some(&y), h, &tab::A4, &[&k1, &k2, &k3]);
            sys.rhs(t + tab::C4 * h, &stage, &mut k4);
            combine(&mut stage, Some(&y), h, &tab::A5, &[&k1, &k2, &k3, &k4]);
            sys.rhs(t + tab::C5 * h, &stage, &mut k5);
            let ks = [&k1, &k2, &k3, &k4, &k5];
            combine(&mut stage, Some(&y), h, &tab::A6, &ks);
            let t_next = if last { t_end } else { t + h };
            sys.rhs(t_next, &stage, &mut k6);
            let ks = [&k1, &k2, &k3, &k4, &k5, &k6];
            combine(&mut y_new, Some(&y), h, &tab::B, &ks);
            sys.rhs(t_next, &y_new, &mut k7);
            stats.n_rhs += 6;

            let mut err_vec = [0.0; N];
            let ks = [&k1, &k2, &k3, &k4, &k5, &k6, &k7];
            combine(&mut err_vec, None, h, &tab::E, &ks);
            let sc = self.scale(&y, &y_new);
            let err = scaled_rms(&err_vec, &sc);
            let finite = err.is_finite()
                && y_new.iter().all(|v| v.is_finite())
                && k7.iter().all(|v| v.is_finite());
            if !finite {
                // Overflow inside the step: shrink as hard as allowed and retry.
                stats.n_rejected += 1;
                last_was_nonfinite = true;
                after_reject = true;
                h *= cfg.fac_min;
                continue;
            }
            last_was_nonfinite = false;

            if err <= 1.0 {
                let d = &tab::D;
                let mut coef = [[0.0; N]; 5];
                for i in 0..N {
                    let diff = y_new[i] - y[i];
                    let bspl = h * k1[i] - diff;
                    coef[0][i] = y[i];
                    coef[1][i] = diff;
                    coef[2][i] = bspl;
                    coef[3][i] = diff - h * k7[i] - bspl;
                    coef[4][i] = h
                        * (d[0] * k1[i]
                            + d[2] * k3[i]
                            + d[3] * k4[i]
                            + d[4] * k5[i]
                            + d[5] * k6[i]
                            + d[6] * k7[i]);
                }
                segments.push(Segment {
                    t0: t,
                    t1: t_next,
                    h,
                    coef,
                });
                stats.n_accepted += 1;
                t = t_next;
                y = y_new;
                k1 = k7;
                ts.push(t);
                ys.push(y);

                let raw = match cfg.control {
                    StepControl::Elementary => cfg.safety * err.powf(-ELEMENTARY_EXP),
                    StepControl::Pi => cfg.safety * err.powf(-PI_ALPHA) * err_prev.powf(PI_BETA),
                };
                let mut fac = raw.clamp(cfg.fac_min, cfg.fac_max);
                if after_reject {
                    fac = fac.min(1.0);
                }
                err_prev = err.max(ERR_PREV_FLOOR);
                after_reject = false;
                h = (h * fac).min(h_max);
            } else {
                stats.n_rejected += 1;
                after_reject = true;
                h *= (cfg.safety * err.powf(-ELEMENTARY_EXP)).max(cfg.fac_min);
            }
        }
        Ok(done(ts, ys, segments, stats))
    }
}

#[cfg(test)]
mod tests {
    use super::super::Scalar;
    use super::*;

    #[test]
    fn dense_output_is_exact_at_step_ends_and_accurate_between() {
        let dp = Dopri5::new(Dopri5Config {
            rtol: 1e-9,
            atol: 1e-12,
            ..Default::default()
        })
        .unwrap();
        let out = dp.solve(&Scalar { lambda: -1.5 }, [2.0], 0.0, 4.0).unwrap();
        for (t, y) in out.solution.t.iter().zip(&out.solution.y) {
            assert!((out.dense.eval(*t).unwrap()[0] - y[0]).abs() < 1e-15);
        }
        for i in 0..=400 {
            let t = 0.01 * i as f64;
            let exact = 2.0 * (-1.5 * t).exp();
            // A 4th-order interpolant between steps sized for a 1e-9 local error.
            assert!(
                (out.dense.eval(t).unwrap()[0] - exact).abs() < 2e-8,
                "t={t}"
            );
        }
        assert_eq!(out.dense.eval(4.000_001), None);
        assert_eq!(out.dense.eval(f64::NAN), None);
    }

    #[test]
    fn invalid_settings_are_rejected() {
        let bad = |c: Dopri5Config| {
            matches!(Dopri5::new(c), Err(IntegrationError::InvalidSetting { .. }))
        };
        let d = Dopri5Config::default();
        assert!(bad(Dopri5Config { rtol: 0.0, ..d }));
        assert!(bad(Dopri5Config {
            rtol: f64::NAN,
            ..d
        }));
        assert!(bad(Dopri5Config { atol: -1.0, ..d }));
        assert!(bad(Dopri5Config {
            h_initial: Some(-1.0),
            ..d
        }));
        assert!(bad(Dopri5Config {
            h_max: Some(0.0),
            ..d
        }));
        assert!(!bad(Dopri5Config {
            h_max: Some(0.5),
            ..d
        }));
        assert!(bad(Dopri5Config {
            max_steps: MAX_STEPS + 1,
            ..d
        }));
        assert!(bad(Dopri5Config { fac_max: 1.0, ..d }));
        assert!(bad(Dopri5Config { safety: 1.5, ..d }));
    }

    #[test]
    fn zero_span_returns_the_initial_state() {
        let dp = Dopri5::new(Dopri5Config::default()).unwrap();
        let out = dp.solve(&Scalar { lambda: -1.0 }, [3.0], 1.0, 1.0).unwrap();
        assert_eq!(out.solution.y, vec![[3.0]]);
        assert_eq!(out.dense.eval(1.0), Some([3.0]));
    }
}
