//! Numerical integrators for first-order systems `y' = f(t, y)` of any fixed dimension `N`.
//!
//! A second-order model `a·x'' + b·x' + c·x = f(t)` becomes the first-order system
//! `x' = v`, `v' = (f(t) − b·v − c·x)/a` on the state `[x, v]` ([`Linear2`]).
//!
//! Methods (each a type implementing [`FixedStep`], or adaptive):
//!
//! | method | order | rhs calls / step | stable for |
//! |---|---|---|---|
//! | [`Euler`] (forward) | 1 | 1 | `|1 + hλ| ≤ 1` |
//! | [`SymplecticEuler`] (semi-implicit) | 1 | 2 | undamped oscillator if `h·ω_n ≤ 2`, energy bounded |
//! | [`Heun`] (RK2) | 2 | 2 | `|1 + z + z²/2| ≤ 1` |
//! | [`Rk4`] (classical) | 4 | 4 | `|Σ_{k≤4} zᵏ/k!| ≤ 1` |
//! | [`Trapezoid`] (implicit) | 2 | 1 + Newton | every `h` when `Re λ ≤ 0` (A-stable) |
//! | [`Dopri5`] (Dormand–Prince 5(4)) | 5 | 6 (FSAL) | adaptive to `rtol`, `atol` |
//!
//! Fixed-step runs store at most [`MAX_STEPS`] steps; beyond that they return
//! [`IntegrationError::TooManySteps`] instead of allocating. [`FixedStep::step`] and
//! [`FixedStep::solve_into`] never allocate, for redraws while a slider moves.
//!
//! ```
//! use zeta_solver::integrate::{FixedStep, Linear2, Rk4};
//! use zeta_solver::{FreeResponse, SecondOrder};
//! let sys = SecondOrder::from_natural(8.944_272, 0.3).unwrap();
//! let sol = Rk4.solve(&Linear2::free(sys), [0.06, 0.0], 0.0, 2.0, 1e-3).unwrap();
//! let exact = FreeResponse::new(sys, 0.06, 0.0).displacement(2.0);
//! let last = sol.y.last().unwrap();
//! assert!((last[0] - exact).abs() < 1e-12);
//! assert_eq!(sol.stats.n_rhs, 4 * 2000);
//! ```

// Stage loops index several arrays in lock-step, exactly as the formulas are written.
#![allow(clippy::needless_range_loop)]

/// Implements [`FixedStep`] for a one-step method: its name, its order and the body of its
/// `step(sys, t, h, y)`, which advances `y: &mut [f64; N]` from `t` to `t + h` and returns
/// `Result<usize, IntegrationError>` (the number of `rhs` calls). Everything else
/// ([`FixedStep::solve`] and the other drivers) comes from the trait's default methods.
macro_rules! fixed_step {
    ($method:ty, $name:literal, order $order:literal, |$sys:ident, $t:ident, $h:ident, $y:ident| $body:block) => {
        impl $crate::integrate::FixedStep for $method {
            fn name(&self) -> &'static str {
                $name
            }

            fn order(&self) -> u32 {
                $order
            }

            fn step<const N: usize, S: $crate::integrate::System<N>>(
                &self,
                $sys: &S,
                $t: f64,
                $h: f64,
                $y: &mut [f64; N],
            ) -> Result<usize, $crate::integrate::IntegrationError> $body
        }
    };
}

/// `$body` evaluated with `$m` bound to the one-step method (a unit struct) that
/// `$method: &Method` names: how [`Method`] forwards each trait to the methods themselves.
macro_rules! with_method {
    ($method:expr, |$m:ident| $body:expr) => {
        with_method!(@each $method, $m, $body, Euler, SymplecticEuler, Heun, Rk4, Trapezoid)
    };
    (@each $method:expr, $m:ident, $body:expr, $($variant:ident),+) => {
        match $method {
            $($crate::integrate::Method::$variant => {
                let $m = $crate::integrate::$variant;
                $body
            })+
        }
    };
}

pub mod analysis;
pub mod convergence;
mod dopri5;
mod error;
mod euler;
mod heun;
mod linalg;
mod rk4;
pub mod stability;
mod symplectic_euler;
pub mod tableau;
mod trapezoid;
pub mod work_precision;

pub use dopri5::{DenseOutput, Dopri5, Dopri5Config, Dopri5Solution, StepControl};
pub use error::IntegrationError;
pub use euler::Euler;
pub use heun::Heun;
pub use rk4::Rk4;
pub use symplectic_euler::SymplecticEuler;
pub use trapezoid::Trapezoid;

use crate::model::SecondOrder;

/// Most steps a single run may store (2 million: 48 MB for a 2-state system). Runs that
/// need more return [`IntegrationError::TooManySteps`] before allocating.
pub const MAX_STEPS: usize = 2_000_000;

/// Relative step `√ε ≈ 1.5e-8` of the forward-difference Jacobian: balances truncation
/// (∝ δ) against rounding (∝ ε/δ).
const FD_REL_STEP: f64 = 1.490_116_119_384_765_6e-8;

/// A first-order system `y' = f(t, y)` with state `y ∈ ℝᴺ`.
pub trait System<const N: usize> {
    /// Writes `f(t, y)` into `dy`. Must not allocate: it is called every stage.
    fn rhs(&self, t: f64, y: &[f64; N], dy: &mut [f64; N]);

    /// Writes the Jacobian `J[i][j] = ∂fᵢ/∂yⱼ` at `(t, y)` into `jac`; used by the implicit
    /// [`Trapezoid`]. The default is a forward difference with relative step
    /// `√ε·max(|yⱼ|, 1)` (N extra `rhs` calls); linear systems should override it with
    /// the exact matrix.
    fn jacobian(&self, t: f64, y: &[f64; N], jac: &mut [[f64; N]; N]) {
        let mut f0 = [0.0; N];
        self.rhs(t, y, &mut f0);
        let mut yp = *y;
        let mut fp = [0.0; N];
        for j in 0..N {
            let delta = FD_REL_STEP * y[j].abs().max(1.0);
            yp[j] = y[j] + delta;
            self.rhs(t, &yp, &mut fp);
            for i in 0..N {
                jac[i][j] = (fp[i] - f0[i]) / delta;
            }
            yp[j] = y[j];
        }
    }
}

/// The second-order model `a·x'' + b·x' + c·x = f(t)` as the first-order system on
/// `[x, v]`: `x' = v`, `v' = (f(t) − b·v − c·x)/a`, with its exact Jacobian
/// `[[0, 1], [−c/a, −b/a]]`.
#[derive(Debug, Clone, Copy)]
pub struct Linear2<F> {
    sys: SecondOrder,
    inv_a: f64,
    force: F,
}

/// No forcing: `f(t) = 0`.
fn zero_force(_t: f64) -> f64 {
    0.0
}

impl<F: Fn(f64) -> f64> Linear2<F> {
    /// `sys` driven by the force (or voltage) `force(t)` in the unit of `a·x''`.
    pub fn new(sys: SecondOrder, force: F) -> Self {
        Self {
            sys,
            inv_a: 1.0 / sys.inertia(),
            force,
        }
    }

    /// The model being integrated.
    pub fn model(&self) -> SecondOrder {
        self.sys
    }
}

impl Linear2<fn(f64) -> f64> {
    /// `sys` with no forcing (free response).
    pub fn free(sys: SecondOrder) -> Self {
        Self::new(sys, zero_force)
    }
}

impl<F: Fn(f64) -> f64> System<2> for Linear2<F> {
    fn rhs(&self, t: f64, y: &[f64; 2], dy: &mut [f64; 2]) {
        dy[0] = y[1];
        dy[1] = ((self.force)(t) - self.sys.damping() * y[1] - self.sys.stiffness() * y[0])
            * self.inv_a;
    }

    fn jacobian(&self, _t: f64, _y: &[f64; 2], jac: &mut [[f64; 2]; 2]) {
        *jac = [
            [0.0, 1.0],
            [
                -self.sys.stiffness() * self.inv_a,
                -self.sys.damping() * self.inv_a,
            ],
        ];
    }
}

/// The scalar test equation `y' = λ·y` (λ in 1/s), exact solution `y₀·e^{λt}`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Scalar {
    /// The rate `λ` [1/s].
    pub lambda: f64,
}

impl System<1> for Scalar {
    fn rhs(&self, _t: f64, y: &[f64; 1], dy: &mut [f64; 1]) {
        dy[0] = self.lambda * y[0];
    }

    fn jacobian(&self, _t: f64, _y: &[f64; 1], jac: &mut [[f64; 1]; 1]) {
        jac[0][0] = self.lambda;
    }
}

/// Work counters of a run.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Stats {
    /// Calls of [`System::rhs`] made by the method (the default finite-difference
    /// Jacobian's own calls are not counted; the trapezoid evaluates one Jacobian per step).
    pub n_rhs: usize,
    /// Steps accepted.
    pub n_accepted: usize,
    /// Steps rejected by the error control (always 0 for fixed-step methods).
    pub n_rejected: usize,
}

/// A computed trajectory: `y[i]` approximates the state at `t[i]`.
#[derive(Debug, Clone, PartialEq)]
pub struct Solution<const N: usize> {
    /// Time points (s), increasing, from `t0` to `t_end` inclusive.
    pub t: Vec<f64>,
    /// States at those times.
    pub y: Vec<[f64; N]>,
    /// Work counters.
    pub stats: Stats,
}

/// The fixed step actually used and the number of steps for a span: `n = ⌈T/h⌉` steps of
/// `T/n ≤ h`, so the grid ends exactly at `t_end` (a relative slack of 1e-9 keeps
/// `T/h = 10.000000001` at 10 steps).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Grid {
    /// Start time (s).
    pub t0: f64,
    /// Step (s) (`T/n`, or `h` when `T = 0`).
    pub h: f64,
    /// Number of steps.
    pub n: usize,
}

impl Grid {
    /// Validates `t0`, `t_end` (finite, `t_end ≥ t0`) and `h` (finite, > 0) and fits the
    /// grid; errors with [`IntegrationError::TooManySteps`] beyond [`MAX_STEPS`].
    pub fn new(t0: f64, t_end: f64, h: f64) -> Result<Self, IntegrationError> {
        if !(h.is_finite() && h > 0.0) {
            return Err(IntegrationError::InvalidStep { h });
        }
        if !(t0.is_finite() && t_end.is_finite() && t_end >= t0) {
            return Err(IntegrationError::InvalidSpan { t0, t_end });
        }
        let span = t_end - t0;
        let needed = (span / h * (1.0 - 1e-9)).ceil();
        if needed.is_nan() || needed > MAX_STEPS as f64 {
            return Err(IntegrationError::TooManySteps {
                needed,
                limit: MAX_STEPS,
            });
        }
        let n = needed as usize;
        let h = if n == 0 { h } else { span / n as f64 };
        Ok(Self { t0, h, n })
    }

    /// Time of grid point `i`: `t0 + i·h` (s).
    pub fn time(&self, i: usize) -> f64 {
        self.t0 + i as f64 * self.h
    }
}

/// Steps of exactly `h` from `t0`, the last one shorter when `h` does not divide the span,
/// so that the run still ends at `t_end`: `n = ⌈(t_end − t0)/h⌉` steps (a relative slack of
/// 1e-9 keeps `T/h = 10.000000001` at 10 steps), `t_i = t0 + i·h` for `i < n` and
/// `t_n = t_end`; the last step is `t_end − t0 − (n − 1)·h ∈ (0, h]` (up to the slack).
///
/// ```
/// use zeta_solver::integrate::ExactStepGrid;
/// let g = ExactStepGrid::new(0.0, 20.0, 0.3).unwrap();
/// assert_eq!(g.steps(), 67);
/// assert_eq!(g.step(0), 0.3);
/// assert!((g.last_step() - 0.2).abs() < 1e-12);
/// assert_eq!(g.time(67), 20.0);
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ExactStepGrid {
    t0: f64,
    t_end: f64,
    h: f64,
    n: usize,
}

impl ExactStepGrid {
    /// Validates `t0`, `t_end` (finite, `t_end ≥ t0`) and `h` (finite, > 0); errors with
    /// [`IntegrationError::TooManySteps`] beyond [`MAX_STEPS`].
    pub fn new(t0: f64, t_end: f64, h: f64) -> Result<Self, IntegrationError> {
        // The same validation and step count as the evenly divided grid.
        let n = Grid::new(t0, t_end, h)?.n;
        Ok(Self { t0, t_end, h, n })
    }

    /// Number of steps `n`.
    pub fn steps(&self) -> usize {
        self.n
    }

    /// The chosen step `h` (s): every step but the last has exactly this length.
    pub fn h(&self) -> f64 {
        self.h
    }

    /// Time of grid point `i` (s): `t0 + i·h` for `i < n`, `t_end` for `i ≥ n`.
    pub fn time(&self, i: usize) -> f64 {
        if i >= self.n {
            self.t_end
        } else {
            self.t0 + i as f64 * self.h
        }
    }

    /// Length of step `i` (from point `i` to `i + 1`) (s).
    pub fn step(&self, i: usize) -> f64 {
        self.time(i + 1) - self.time(i)
    }

    /// Length of the last step (s): `h` when `h` divides the span (to the relative slack
    /// 1e-9, so that rounding of `(n − 1)·h` does not show), 0 for an empty span.
    pub fn last_step(&self) -> f64 {
        if self.n == 0 {
            return 0.0;
        }
        let last = self.step(self.n - 1);
        if (last - self.h).abs() <= 1e-9 * self.h {
            self.h
        } else {
            last
        }
    }
}

/// `Ok` when every component of `y` is finite, else [`IntegrationError::NonFinite`] at
/// `t` (s), the time of `y`.
fn finite_at<const N: usize>(y: &[f64; N], t: f64) -> Result<(), IntegrationError> {
    if y.iter().all(|v| v.is_finite()) {
        Ok(())
    } else {
        Err(IntegrationError::NonFinite { t })
    }
}

/// One step of a fixed-step driver: advances `y` from `t` by `h` (s) with `method`, adds
/// the work to `stats`, and checks the new state at `t_next` (s), the step's end as the
/// driver's grid gives it (which may differ from `t + h` by rounding).
fn counted_step<M: FixedStep + ?Sized, const N: usize, S: System<N>>(
    method: &M,
    sys: &S,
    (t, h, t_next): (f64, f64, f64),
    y: &mut [f64; N],
    stats: &mut Stats,
) -> Result<(), IntegrationError> {
    stats.n_rhs += method.step(sys, t, h, y)?;
    stats.n_accepted += 1;
    finite_at(y, t_next)
}

/// A one-step method with a fixed step size.
pub trait FixedStep {
    /// Short name for plots and logs, e.g. `"RK4"`.
    fn name(&self) -> &'static str;

    /// Global order of accuracy `p`: the error at a fixed time scales as `hᵖ`.
    fn order(&self) -> u32;

    /// Advances `y` in place from `t` to `t + h` (s); returns the number of `rhs` calls.
    /// Never allocates. Only the trapezoid ([`IntegrationError::ImplicitSolveFailed`])
    /// and symplectic Euler on an odd dimension ([`IntegrationError::OddDimension`]) can
    /// fail.
    fn step<const N: usize, S: System<N>>(
        &self,
        sys: &S,
        t: f64,
        h: f64,
        y: &mut [f64; N],
    ) -> Result<usize, IntegrationError>;

    /// Integrates from `y0` at `t0` to `t_end` with steps of at most `h` (s) (see [`Grid`])
    /// and stores every step.
    fn solve<const N: usize, S: System<N>>(
        &self,
        sys: &S,
        y0: [f64; N],
        t0: f64,
        t_end: f64,
        h: f64,
    ) -> Result<Solution<N>, IntegrationError> {
        let grid = Grid::new(t0, t_end, h)?;
        finite_at(&y0, t0)?;
        let mut t = Vec::with_capacity(grid.n + 1);
        let mut ys = Vec::with_capacity(grid.n + 1);
        t.push(t0);
        ys.push(y0);
        let mut y = y0;
        let mut stats = Stats::default();
        for i in 0..grid.n {
            let ti = grid.time(i + 1);
            counted_step(self, sys, (grid.time(i), grid.h, ti), &mut y, &mut stats)?;
            t.push(ti);
            ys.push(y);
        }
        Ok(Solution { t, y: ys, stats })
    }

    /// Integrates on an [`ExactStepGrid`]: steps of exactly `h`, the last one shorter to end
    /// at the grid's end. Writes the state at `grid.time(i)` into `out[i]` for
    /// `i ≤ min(n, out.len() − 1)` and returns the work counters. On failure the points
    /// after the failing step are left as they were (e.g. NaN from the caller), so a run
    /// that overflows can still be drawn up to where it went.
    fn solve_exact_step_into<const N: usize, S: System<N>>(
        &self,
        sys: &S,
        y0: [f64; N],
        grid: &ExactStepGrid,
        out: &mut [[f64; N]],
    ) -> Result<Stats, IntegrationError> {
        finite_at(&y0, grid.time(0))?;
        match out.first_mut() {
            Some(first) => *first = y0,
            None => return Ok(Stats::default()),
        }
        self.resume_exact_step_into(sys, grid, 0, out)
    }

    /// Continues a run on an [`ExactStepGrid`] from its point `from`, whose state is
    /// `out[from]`: writes the state at `grid.time(i)` into `out[i]` for
    /// `from < i ≤ min(n, out.len() − 1)` and returns the work counters of those steps. A run
    /// resumed slice by slice (`out` one slice longer each time) is the one run, to the bit.
    /// On failure, as [`FixedStep::solve_exact_step_into`].
    fn resume_exact_step_into<const N: usize, S: System<N>>(
        &self,
        sys: &S,
        grid: &ExactStepGrid,
        from: usize,
        out: &mut [[f64; N]],
    ) -> Result<Stats, IntegrationError> {
        let mut stats = Stats::default();
        let Some(&start) = out.get(from) else {
            return Ok(stats);
        };
        finite_at(&start, grid.time(from))?;
        let mut y = start;
        let end = grid.steps().min(out.len() - 1);
        for (i, slot) in out.iter_mut().enumerate().take(end + 1).skip(from + 1) {
            let step = (grid.time(i - 1), grid.step(i - 1), grid.time(i));
            counted_step(self, sys, step, &mut y, &mut stats)?;
            *slot = y;
        }
        Ok(stats)
    }

    /// Allocation-free run into a reused buffer: `out[0] = y0` and `out[i]` is the state at
    /// `t0 + i·h` for every `i < out.len()`. Returns the work counters.
    fn solve_into<const N: usize, S: System<N>>(
        &self,
        sys: &S,
        y0: [f64; N],
        t0: f64,
        h: f64,
        out: &mut [[f64; N]],
    ) -> Result<Stats, IntegrationError> {
        if !(h.is_finite() && h > 0.0) {
            return Err(IntegrationError::InvalidStep { h });
        }
        if !t0.is_finite() {
            return Err(IntegrationError::InvalidSpan { t0, t_end: t0 });
        }
        finite_at(&y0, t0)?;
        let mut stats = Stats::default();
        let mut y = y0;
        for (i, slot) in out.iter_mut().enumerate() {
            if i > 0 {
                let t = t0 + (i - 1) as f64 * h;
                counted_step(self, sys, (t, h, t + h), &mut y, &mut stats)?;
            }
            *slot = y;
        }
        Ok(stats)
    }
}

/// The fixed-step methods as one value, for choosing at run time (e.g. from a menu).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Method {
    /// [`Euler`].
    Euler,
    /// [`SymplecticEuler`].
    SymplecticEuler,
    /// [`Heun`].
    Heun,
    /// [`Rk4`].
    Rk4,
    /// [`Trapezoid`].
    Trapezoid,
}

impl Method {
    /// Every fixed-step method, simplest first.
    pub const ALL: [Method; 5] = [
        Method::Euler,
        Method::SymplecticEuler,
        Method::Heun,
        Method::Rk4,
        Method::Trapezoid,
    ];
}

impl FixedStep for Method {
    fn name(&self) -> &'static str {
        with_method!(self, |m| m.name())
    }

    fn order(&self) -> u32 {
        with_method!(self, |m| m.order())
    }

    fn step<const N: usize, S: System<N>>(
        &self,
        sys: &S,
        t: f64,
        h: f64,
        y: &mut [f64; N],
    ) -> Result<usize, IntegrationError> {
        with_method!(self, |m| m.step(sys, t, h, y))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn grid_lands_on_the_end_point() {
        let g = Grid::new(0.0, 1.0, 0.3).unwrap();
        assert_eq!(g.n, 4);
        assert!((g.h - 0.25).abs() < 1e-16);
        assert_eq!(g.time(4), 1.0);
        // 0.1 does not divide 1 exactly in binary, but 10 steps must result.
        assert_eq!(Grid::new(0.0, 1.0, 0.1).unwrap().n, 10);
        assert_eq!(Grid::new(2.0, 2.0, 0.1).unwrap().n, 0);
    }

    #[test]
    fn a_run_resumed_slice_by_slice_is_the_one_run() {
        let sys = Linear2::free(SecondOrder::from_natural(3.0, 0.1).unwrap());
        let grid = ExactStepGrid::new(0.0, 5.0, 0.013).unwrap();
        let n = grid.steps() + 1;
        for m in Method::ALL {
            let mut whole = vec![[f64::NAN; 2]; n];
            let stats = m.solve_exact_step_into(&sys, [1.0, 0.0], &grid, &mut whole);
            let mut sliced = vec![[f64::NAN; 2]; n];
            sliced[0] = [1.0, 0.0];
            let mut rhs = 0;
            // `out` a point longer each slice: its last point is where the next one starts.
            for (from, end) in [(0, 1), (0, 100), (99, 101), (100, n)] {
                rhs += m
                    .resume_exact_step_into(&sys, &grid, from, &mut sliced[..end])
                    .unwrap()
                    .n_rhs;
            }
            // Bit for bit, and the same work.
            assert_eq!(whole, sliced, "{}", m.name());
            assert_eq!(stats.unwrap().n_rhs, rhs, "{}", m.name());
        }
        // Nothing past the grid's end, nothing from a point outside `out`.
        let mut out = vec![[1.0, 0.0]; n + 3];
        let done = Rk4
            .resume_exact_step_into(&sys, &grid, 0, &mut out)
            .unwrap();
        assert_eq!(done.n_accepted, grid.steps());
        assert_eq!(out[n], [1.0, 0.0]);
        let none = Rk4
            .resume_exact_step_into(&sys, &grid, n + 5, &mut out)
            .unwrap();
        assert_eq!(none.n_accepted, 0);
    }

    #[test]
    fn grid_rejects_bad_settings() {
        let bad = [
            Grid::new(0.0, 1.0, 0.0),
            Grid::new(0.0, 1.0, f64::NAN),
            Grid::new(0.0, -1.0, 0.1),
            Grid::new(0.0, 1e300, 1e-300),
        ];
        let expected = ["InvalidStep", "InvalidStep", "InvalidSpan", "TooManySteps"];
        assert_eq!(crate::testing::variants(bad), expected);
        assert!(matches!(
            Grid::new(0.0, 1.0, 1e-9),
            Err(IntegrationError::TooManySteps {
                limit: MAX_STEPS,
                ..
            })
        ));
    }

    #[test]
    fn default_jacobian_matches_exact_one() {
        struct Wrapped(Linear2<fn(f64) -> f64>);
        impl System<2> for Wrapped {
            fn rhs(&self, t: f64, y: &[f64; 2], dy: &mut [f64; 2]) {
                self.0.rhs(t, y, dy);
            }
        }
        let lin = Linear2::free(SecondOrder::new(2.0, 3.0, 50.0).unwrap());
        let mut exact = [[0.0; 2]; 2];
        let mut fd = [[0.0; 2]; 2];
        lin.jacobian(0.0, &[0.1, 0.2], &mut exact);
        Wrapped(lin).jacobian(0.0, &[0.1, 0.2], &mut fd);
        for i in 0..2 {
            for j in 0..2 {
                assert!((exact[i][j] - fd[i][j]).abs() < 1e-6 * (1.0 + exact[i][j].abs()));
            }
        }
    }
}
