//! Work–precision of the adaptive method: error against right-hand-side evaluations over a
//! sweep of tolerances, the comparison the ODE literature uses for adaptive methods
//! (Hairer–Nørsett–Wanner, Solving ODEs I, §II.10).
//!
//! A method of order `p` reaches error `e ∝ h^p` with `N ∝ 1/h` evaluations, so
//! `e ≈ C·N^(−p)`: the slope of the log–log work–precision curve is `−p`, for fixed-step and
//! adaptive methods alike — but for an adaptive method only while the **tolerance** sets its
//! steps. When **stability** sets them (a decayed or stiff solution, where the controller
//! pushes `h` to the edge of the stability region), tightening the tolerance barely changes
//! `N` while the error still falls, and the slope means nothing. Such runs are detected from
//! the steps themselves and left out of the fit.
//!
//! ```
//! use zeta_solver::integrate::analysis::FitWindow;
//! use zeta_solver::integrate::stability::Stability;
//! use zeta_solver::integrate::work_precision::dopri5_sweep;
//! use zeta_solver::integrate::{Dopri5, Dopri5Config, Linear2};
//! use zeta_solver::{FreeResponse, SecondOrder};
//! let sys = SecondOrder::from_natural(2.0, 0.05).unwrap();
//! let exact = FreeResponse::new(sys, 1.0, 0.0);
//! let limit = Dopri5::new(Dopri5Config::default()).unwrap().stable_steps(&sys);
//! let tols = [1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9];
//! let wp = dopri5_sweep(&Linear2::free(sys), [1.0, 0.0], 20.0, &tols,
//!     |tol| Dopri5Config { rtol: tol, atol: tol, ..Default::default() },
//!     |sol| sol.t.iter().zip(&sol.y).map(|(&t, y)| (y[0] - exact.displacement(t)).abs()).fold(0.0, f64::max),
//!     limit, FitWindow { floor: 1e-10, ceiling: 0.5 }, 0.1);
//! assert!((wp.order().unwrap() - 5.0).abs() < 0.15);
//! ```

use super::analysis::{FitWindow, StepLimit};
use super::convergence::{asymptotic_range, fit_power_law, PowerLaw};
use super::{Dopri5, Dopri5Config, Solution, System};

/// A step counts as set by stability when it is at least this share of the largest stable
/// step (the controller of a stability-limited run hovers around and beyond the limit).
pub const STABILITY_SHARE: f64 = 0.9;
/// A run counts as tolerance-set when at most this share of its accepted steps is set by
/// stability.
pub const MAX_STABILITY_STEPS: f64 = 0.01;

/// One adaptive run of a sweep.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct WorkPoint {
    /// The tolerance of the run.
    pub tolerance: f64,
    /// Right-hand-side evaluations `N` it took (0 when the run failed).
    pub work: usize,
    /// Error of the run, in the solution's unit (`∞` when the run failed).
    pub error: f64,
    /// Accepted steps at or above [`STABILITY_SHARE`] of the largest stable step.
    pub stability_steps: usize,
    /// Accepted steps.
    pub steps: usize,
    /// Whether the point is in the fit.
    pub used: bool,
}

impl WorkPoint {
    /// Whether the tolerance, not stability, set this run's steps: at most
    /// [`MAX_STABILITY_STEPS`] of its steps are stability-set.
    pub fn tolerance_set(&self) -> bool {
        self.steps > 0 && (self.stability_steps as f64) <= MAX_STABILITY_STEPS * self.steps as f64
    }
}

/// A sweep of tolerances and the power law `e = C·N^(−p)` fitted over its asymptotic,
/// tolerance-set runs.
#[derive(Debug, Clone, PartialEq)]
pub struct WorkPrecision {
    /// One point per tolerance, in the order given.
    pub points: Vec<WorkPoint>,
    /// The fit `e = C·N^{law.order}` (its `order` is `−p`); `None` with fewer than two
    /// usable runs.
    pub law: Option<PowerLaw>,
}

impl WorkPrecision {
    /// The observed order `p` (minus the slope of error against evaluations).
    pub fn order(&self) -> Option<f64> {
        self.law.map(|l| -l.order)
    }

    /// `(fewest, most)` evaluations of the runs in the fit.
    pub fn fitted_span(&self) -> Option<(f64, f64)> {
        self.law?;
        let used = self.points.iter().filter(|p| p.used).map(|p| p.work as f64);
        let (lo, hi) = used.fold((f64::INFINITY, 0.0f64), |(lo, hi), w| {
            (lo.min(w), hi.max(w))
        });
        (lo <= hi).then_some((lo, hi))
    }

    /// The same sweep of a linear problem from an initial state `s` times larger
    /// (`s > 0`), with the absolute tolerance and the fit window scaled by `s` too: the
    /// errors and the law's coefficient times `s`, everything else unchanged. The
    /// controller's error ratio `|err|/(atol + rtol·|y|)` is then the same at every step, so
    /// a rerun takes the same steps and every state is `s` times larger, up to rounding.
    /// A run whose steps stability sets hovers at the stability limit, where rounding may
    /// turn an accepted step into a rejected one: a rerun of such a run can take a few steps
    /// more or fewer (about 1 % in the tests), with the same verdict.
    pub fn scaled(&self, s: f64) -> Self {
        Self {
            points: self
                .points
                .iter()
                .map(|q| WorkPoint {
                    error: q.error * s,
                    ..*q
                })
                .collect(),
            law: self.law.map(|l| l.scaled(s)),
        }
    }

    /// Runs whose steps stability set (not counted in the fit).
    pub fn stability_set(&self) -> usize {
        self.points
            .iter()
            .filter(|p| p.work > 0 && !p.tolerance_set())
            .count()
    }
}

/// Runs [`Dopri5`] from `y0` at `t = 0` to `t_end` (s) for each tolerance (ordered loose to
/// tight) with the settings `config(tol)`, measures `error(solution)` and the evaluations
/// `N = stats.n_rhs`, and fits `e = C·N^(−p)` ([`fit_power_law`]) over the tolerance-set
/// runs ([`WorkPoint::tolerance_set`], with `stable` the method's largest stable step for
/// the problem, e.g. from [`super::stability::Stability::stable_steps`]) whose errors lie in
/// `window`, restricted to their asymptotic range ([`asymptotic_range`], local orders within
/// `spread` of the finest). A failed run or invalid setting gives a point with error `∞`.
/// The same as [`dopri5_point`] for each tolerance, then [`fit_work_points`].
#[allow(clippy::too_many_arguments)]
pub fn dopri5_sweep<const N: usize, S: System<N>>(
    sys: &S,
    y0: [f64; N],
    t_end: f64,
    tolerances: &[f64],
    config: impl Fn(f64) -> Dopri5Config,
    error: impl Fn(&Solution<N>) -> f64,
    stable: StepLimit,
    window: FitWindow,
    spread: f64,
) -> WorkPrecision {
    let run = |tol| dopri5_point(sys, y0, t_end, tol, &config, &error, stable, window);
    fit_work_points(tolerances.iter().map(|&tol| run(tol)).collect(), spread)
}

/// One run of [`dopri5_sweep`], at tolerance `tol`; `used` says only whether the run may
/// enter the fit (tolerance-set, error finite and inside `window`): the fit decides.
/// For a sweep computed a run at a time (a page's progressive study).
#[allow(clippy::too_many_arguments)]
pub fn dopri5_point<const N: usize, S: System<N>>(
    sys: &S,
    y0: [f64; N],
    t_end: f64,
    tol: f64,
    config: impl Fn(f64) -> Dopri5Config,
    error: impl Fn(&Solution<N>) -> f64,
    stable: StepLimit,
    window: FitWindow,
) -> WorkPoint {
    let limit = match stable {
        StepLimit::UpTo(h) => h,
        _ => f64::INFINITY,
    };
    let failed = WorkPoint {
        tolerance: tol,
        work: 0,
        error: f64::INFINITY,
        stability_steps: 0,
        steps: 0,
        used: false,
    };
    let Ok(out) = Dopri5::new(config(tol)).and_then(|d| d.solve(sys, y0, 0.0, t_end)) else {
        return failed;
    };
    let sol = &out.solution;
    let stability_steps = sol
        .t
        .windows(2)
        .filter(|w| w[1] - w[0] >= STABILITY_SHARE * limit)
        .count();
    let e = error(sol);
    let mut p = WorkPoint {
        tolerance: tol,
        work: sol.stats.n_rhs,
        error: if e.is_nan() { f64::INFINITY } else { e },
        stability_steps,
        steps: sol.stats.n_accepted,
        used: false,
    };
    p.used = p.tolerance_set()
        && p.error.is_finite()
        && p.error > window.floor
        && p.error < window.ceiling;
    p
}

/// The fit of [`dopri5_sweep`] over its runs (loose to tight, from [`dopri5_point`]): the
/// finest stretch of consecutive usable runs, restricted to its asymptotic range (local
/// orders within `spread` of the finest), fitted as `e = C·N^(−p)`; `used` then marks the
/// fitted runs.
pub fn fit_work_points(mut points: Vec<WorkPoint>, spread: f64) -> WorkPrecision {
    // The finest run of consecutive usable points, then its asymptotic range.
    let end = points.iter().rposition(|p| p.used).map_or(0, |i| i + 1);
    let start = points[..end]
        .iter()
        .rposition(|p| !p.used)
        .map_or(0, |i| i + 1);
    let run: Vec<(f64, f64)> = points[start..end]
        .iter()
        .map(|p| (p.work as f64, p.error))
        .collect();
    let range = asymptotic_range(&run, spread);
    for (i, p) in points.iter_mut().enumerate() {
        p.used = range
            .as_ref()
            .is_some_and(|r| i >= start && r.contains(&(i - start)));
    }
    let fit: Vec<(f64, f64)> = points
        .iter()
        .filter(|p| p.used)
        .map(|p| (p.work as f64, p.error))
        .collect();
    WorkPrecision {
        law: fit_power_law(&fit),
        points,
    }
}
