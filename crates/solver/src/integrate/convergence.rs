//! Convergence studies of fixed-step methods on nested grids, and the power law
//! `e = C·hᵖ` fitted to their errors.
//!
//! A method of order `p` has a global error `e(h) ≈ C·hᵖ` once `h` is small enough (the
//! asymptotic range) and large enough that rounding does not dominate. The study runs the
//! method on grids that halve the step each level and measures the error at check points
//! common to every level, so that each level's error is measured at the same times.
//!
//! ```
//! use zeta_solver::integrate::convergence::{fit_power_law, nested_study, NestedGrids};
//! use zeta_solver::integrate::analysis::FitWindow;
//! use zeta_solver::integrate::{Linear2, Rk4};
//! use zeta_solver::{FreeResponse, SecondOrder};
//! // A power law is recovered exactly.
//! let pts: Vec<(f64, f64)> = [0.1, 0.05, 0.025].iter().map(|&h| (h, 3.0 * h * h)).collect();
//! let fit = fit_power_law(&pts).unwrap();
//! assert!((fit.order - 2.0).abs() < 1e-12 && (fit.coefficient - 3.0).abs() < 1e-12);
//! // RK4 on the oscillator converges with order 4.
//! let sys = SecondOrder::from_natural(2.0, 0.1).unwrap();
//! let exact = FreeResponse::new(sys, 1.0, 0.0);
//! let grids = NestedGrids::new(10.0, 20, 5, 100_000).unwrap();
//! let out = nested_study(&Rk4, &Linear2::free(sys), [1.0, 0.0], 0, |t| exact.displacement(t),
//!     &grids, FitWindow { floor: 1e-11, ceiling: 1e-2 });
//! assert!((out.study.order.unwrap() - 4.0).abs() < 0.1);
//! ```

use super::analysis::{convergence_study, ConvergenceStudy, FitWindow};
use super::{FixedStep, IntegrationError, System};

/// A power law `e = C·hᵖ`: the error model of a method of order `p`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PowerLaw {
    /// The exponent `p` (the observed order) \[-\].
    pub order: f64,
    /// The coefficient `C`, in the error's unit per `sᵖ`.
    pub coefficient: f64,
}

impl PowerLaw {
    /// The power law of exponent `order` through the point `(h, e)`: `C = e/hᵖ`.
    pub fn through((h, e): (f64, f64), order: f64) -> Self {
        Self {
            order,
            coefficient: e / h.powf(order),
        }
    }

    /// `C·hᵖ` at step `h` (s).
    pub fn at(&self, h: f64) -> f64 {
        self.coefficient * h.powf(self.order)
    }

    /// The step at which the law reaches `e`: `h = (e/C)^(1/p)` (s); NaN for `p = 0`.
    pub fn step_for(&self, e: f64) -> f64 {
        (e / self.coefficient).powf(1.0 / self.order)
    }
}

/// Least-squares fit of `ln e = p·ln h + ln C` over the points `(h, e)` (all positive):
/// `p = Σ(xᵢ − x̄)(yᵢ − ȳ)/Σ(xᵢ − x̄)²` with `x = ln h`, `y = ln e`, and
/// `C = exp(ȳ − p·x̄)`. `None` with fewer than two points, all `h` equal, or a non-finite
/// slope.
pub fn fit_power_law(points: &[(f64, f64)]) -> Option<PowerLaw> {
    let n = points.len() as f64;
    if points.len() < 2 {
        return None;
    }
    let mx = points.iter().map(|p| p.0.ln()).sum::<f64>() / n;
    let my = points.iter().map(|p| p.1.ln()).sum::<f64>() / n;
    let (mut sxy, mut sxx) = (0.0, 0.0);
    for &(h, e) in points {
        let dx = h.ln() - mx;
        sxy += dx * (e.ln() - my);
        sxx += dx * dx;
    }
    let slope = sxy / sxx;
    (sxx > 0.0 && slope.is_finite()).then(|| PowerLaw {
        order: slope,
        coefficient: (my - slope * mx).exp(),
    })
}

/// The local orders `qᵢ = ln(eᵢ/eᵢ₊₁)/ln(hᵢ/hᵢ₊₁)` between neighbouring points `(h, e)`:
/// the slope of each segment of the log–log error curve.
pub fn local_orders(points: &[(f64, f64)]) -> Vec<f64> {
    points
        .windows(2)
        .map(|w| (w[0].1 / w[1].1).ln() / (w[0].0 / w[1].0).ln())
        .collect()
}

/// The asymptotic range of an error curve `(h, e)` ordered from coarse to fine: the finest
/// two points, extended towards coarser ones while each segment's local order
/// ([`local_orders`]) stays within `spread` of the finest segment's. Coarse steps outside
/// the asymptotic range have local orders that still drift (upward for an overdamped
/// system, where `e ≈ C·hᵖ·(1 + D·h)`), so fitting over them biases the order. Returns the
/// index range of the points, `None` with fewer than two points or a non-finite local order.
pub fn asymptotic_range(points: &[(f64, f64)], spread: f64) -> Option<std::ops::Range<usize>> {
    let q = local_orders(points);
    let finest = *q.last()?;
    if !finest.is_finite() {
        return None;
    }
    let mut start = q.len() - 1;
    while start > 0 && (q[start - 1] - finest).abs() <= spread {
        start -= 1;
    }
    Some(start..points.len())
}

impl ConvergenceStudy {
    /// The points used by the fit, as `(h, error)`.
    pub fn used(&self) -> Vec<(f64, f64)> {
        self.points
            .iter()
            .filter(|p| p.used)
            .map(|p| (p.h, p.error))
            .collect()
    }

    /// The power law through the used points ([`fit_power_law`]), when there is an order.
    pub fn power_law(&self) -> Option<PowerLaw> {
        self.order?;
        fit_power_law(&self.used())
    }

    /// `(smallest, largest)` step of the used points (s): the range the fit covers.
    pub fn fitted_span(&self) -> Option<(f64, f64)> {
        self.order?;
        let used = self.used();
        let lo = used.iter().map(|q| q.0).fold(f64::INFINITY, f64::min);
        let hi = used.iter().map(|q| q.0).fold(0.0f64, f64::max);
        (lo <= hi).then_some((lo, hi))
    }

    /// Restricts the fit to the asymptotic range ([`asymptotic_range`]) of the finest run
    /// of consecutive used points, and refits. Points outside it stay measured but unused.
    pub fn restrict_to_asymptotic(&mut self, spread: f64) {
        // The finest run of consecutive used points.
        let end = self
            .points
            .iter()
            .rposition(|p| p.used)
            .map_or(0, |i| i + 1);
        let start = self.points[..end]
            .iter()
            .rposition(|p| !p.used)
            .map_or(0, |i| i + 1);
        let run: Vec<(f64, f64)> = self.points[start..end]
            .iter()
            .map(|p| (p.h, p.error))
            .collect();
        let range = asymptotic_range(&run, spread);
        for (i, p) in self.points.iter_mut().enumerate() {
            p.used = range
                .as_ref()
                .is_some_and(|r| i >= start && r.contains(&(i - start)));
        }
        self.order = fit_power_law(&self.used()).map(|f| f.order);
    }
}

/// Nested grids over `[0, T]`: level `j` has `n₀·2ʲ` steps of `h_j = T/(n₀·2ʲ)` (s), and
/// every level passes through the `n₀ + 1` check points `t_k = k·T/n₀`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct NestedGrids {
    t_end: f64,
    n0: usize,
    levels: usize,
    budget: usize,
}

/// Most levels of a study (`2⁴⁰` steps per check interval is far beyond any budget).
const MAX_LEVELS: usize = 40;

impl NestedGrids {
    /// Grids over `[0, t_end]` (s) with `n0 ≥ 1` check intervals and `levels` (1 … 40)
    /// step sizes; `budget` is the most steps one method may spend on the whole study
    /// (summed over its levels): finer levels beyond it are skipped.
    pub fn new(
        t_end: f64,
        n0: usize,
        levels: usize,
        budget: usize,
    ) -> Result<Self, IntegrationError> {
        if !(t_end.is_finite() && t_end > 0.0) {
            return Err(IntegrationError::InvalidSpan { t0: 0.0, t_end });
        }
        if n0 == 0 || levels == 0 || levels > MAX_LEVELS {
            return Err(IntegrationError::InvalidSetting {
                name: "levels",
                value: levels as f64,
                rule: "must lie in 1 … 40, with at least one check interval",
            });
        }
        Ok(Self {
            t_end,
            n0,
            levels,
            budget,
        })
    }

    /// Grids whose coarsest step is `h₀ = T/n₀` with `n₀ = max(⌈T·rate/h_rate⌉,
    /// min_checkpoints)`: `h₀·rate ≤ h_rate` for the fastest rate `rate` \[1/s\] of the
    /// problem (e.g. the largest pole modulus `max|λ|`).
    pub fn for_rate(
        t_end: f64,
        rate: f64,
        h_rate: f64,
        min_checkpoints: usize,
        levels: usize,
        budget: usize,
    ) -> Result<Self, IntegrationError> {
        let wanted = (t_end * rate / h_rate).ceil();
        // Beyond the budget no level could run anyway.
        let n0 = if wanted.is_finite() && wanted >= 0.0 {
            (wanted.min(budget as f64 + 1.0) as usize).max(min_checkpoints)
        } else {
            min_checkpoints
        };
        Self::new(t_end, n0, levels, budget)
    }

    /// The same grids with another step budget (e.g. a larger one for a cheap method).
    pub fn with_budget(self, budget: usize) -> Self {
        Self { budget, ..self }
    }

    /// Number of check intervals `n₀`.
    pub fn intervals(&self) -> usize {
        self.n0
    }

    /// Number of levels.
    pub fn levels(&self) -> usize {
        self.levels
    }

    /// The step budget of one method.
    pub fn budget(&self) -> usize {
        self.budget
    }

    /// Check time `t_k = k·T/n₀` (s).
    pub fn check_time(&self, k: usize) -> f64 {
        k as f64 * (self.t_end / self.n0 as f64)
    }

    /// Step of level `j`, `T/(n₀·2ʲ)` (s).
    pub fn step(&self, j: usize) -> f64 {
        self.t_end / (self.n0 as f64 * (1u64 << j.min(MAX_LEVELS)) as f64)
    }

    /// Every level's step, coarsest first (s).
    pub fn steps(&self) -> Vec<f64> {
        (0..self.levels).map(|j| self.step(j)).collect()
    }
}

/// How one level of a nested study ended.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub enum RunStatus {
    /// The error was measured.
    Measured,
    /// The numbers overflowed (the method is violently unstable at this step).
    Overflow,
    /// Not run: over the step budget, or a coarser level already reached the rounding floor.
    Skipped,
}

/// A nested-grid convergence study and how each level ended.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct NestedStudy {
    /// Errors per level and the fitted order.
    pub study: ConvergenceStudy,
    /// One status per level.
    pub status: Vec<RunStatus>,
    /// Right-hand-side evaluations of each measured level (0 for levels not measured).
    pub work: Vec<usize>,
}

impl PowerLaw {
    /// The law of errors `s` times larger: `s·C·hᵖ` (the same order).
    pub fn scaled(self, s: f64) -> Self {
        Self {
            coefficient: self.coefficient * s,
            ..self
        }
    }
}

impl NestedStudy {
    /// The same study from an initial state `s` times larger (`s > 0`) of a linear
    /// problem, its fit window scaled alike ([`ConvergenceStudy::scaled`]): the errors times
    /// `s`; statuses, evaluations and order unchanged.
    pub fn scaled(&self, s: f64) -> Self {
        Self {
            study: self.study.scaled(s),
            status: self.status.clone(),
            work: self.work.clone(),
        }
    }

    /// The measured levels as `(f-evaluations, error)`, coarsest first: the method's
    /// points on a work–precision diagram.
    pub fn work_precision(&self) -> Vec<(f64, f64)> {
        self.status
            .iter()
            .zip(&self.study.points)
            .zip(&self.work)
            .filter(|((s, p), _)| **s == RunStatus::Measured && p.error.is_finite())
            .map(|((_, p), &w)| (w as f64, p.error))
            .collect()
    }
}

/// Runs `method` on every level of `grids` from `y0` at `t = 0` and measures the error of
/// state component `component` at the common check points:
/// `e_j = max_k |y_j(t_k)[component] − exact(t_k)|` (in the component's unit). Levels are
/// skipped once the steps spent exceed the budget or a coarser level's error is already at
/// or below `window.floor`; a level that overflows counts as unstable. The order is fitted
/// over the levels inside `window` ([`convergence_study`]).
pub fn nested_study<const N: usize, S: System<N>, M: FixedStep>(
    method: &M,
    sys: &S,
    y0: [f64; N],
    component: usize,
    exact: impl Fn(f64) -> f64,
    grids: &NestedGrids,
    window: FitWindow,
) -> NestedStudy {
    let reference: Vec<f64> = (0..=grids.n0).map(|k| exact(grids.check_time(k))).collect();
    let mut status = Vec::with_capacity(grids.levels);
    let mut work = Vec::with_capacity(grids.levels);
    let mut level = 0usize;
    let mut resolved = false;
    let mut spent = 0usize;
    let study = convergence_study(&grids.steps(), window, |h| {
        // 2^level steps per check interval; beyond usize (level ≥ 32 on wasm32) it saturates,
        // which the budget then skips.
        let stride = u32::try_from(level)
            .ok()
            .and_then(|l| 1usize.checked_shl(l))
            .unwrap_or(usize::MAX);
        level += 1;
        spent = spent.saturating_add(grids.n0.saturating_mul(stride));
        if resolved || spent > grids.budget {
            status.push(RunStatus::Skipped);
            work.push(0);
            return Err(());
        }
        match checkpoint_error(method, sys, y0, component, h, stride, &reference) {
            Some((e, n_rhs)) => {
                resolved = e <= window.floor;
                status.push(RunStatus::Measured);
                work.push(n_rhs);
                Ok((h, e))
            }
            None => {
                status.push(RunStatus::Overflow);
                work.push(0);
                Err(())
            }
        }
    });
    NestedStudy {
        study,
        status,
        work,
    }
}

/// Error at the check points of a run of `(reference.len() − 1)·stride` steps of `h`, and
/// the `rhs` calls it took; `None` if the numbers overflow or a step fails.
fn checkpoint_error<const N: usize, S: System<N>, M: FixedStep>(
    method: &M,
    sys: &S,
    y0: [f64; N],
    component: usize,
    h: f64,
    stride: usize,
    reference: &[f64],
) -> Option<(f64, usize)> {
    let mut y = y0;
    let mut err = 0.0f64;
    let mut n_rhs = 0usize;
    let n = reference.len().saturating_sub(1).saturating_mul(stride);
    for i in 1..=n {
        n_rhs += method.step(sys, (i - 1) as f64 * h, h, &mut y).ok()?;
        if i.is_multiple_of(stride) {
            let d = (y.get(component)? - reference.get(i / stride)?).abs();
            if !d.is_finite() {
                return None;
            }
            err = err.max(d);
        }
    }
    Some((err, n_rhs))
}
