//! Accuracy and stability analysis of the integrators: error against an exact solution,
//! observed order of convergence, amplification factors, the largest stable step, and
//! energy drift of the oscillator.
//!
//! ```
//! use zeta_solver::integrate::analysis::{Amplification, StepLimit};
//! use zeta_solver::integrate::{Euler, Rk4};
//! use zeta_solver::Complex;
//! // Forward Euler on λ = −10: stable for h ≤ 2/10.
//! let lim = Euler.step_limit(&[Complex::real(-10.0)]);
//! assert_eq!(lim, StepLimit::UpTo(0.2));
//! // RK4 on an undamped pole ±i·ω: stable for h ≤ 2√2/ω.
//! let w = 3.0;
//! let StepLimit::UpTo(h) = Rk4.step_limit(&[Complex::new(0.0, w)]) else { unreachable!() };
//! assert!((h - 8f64.sqrt() / w).abs() < 1e-9);
//! ```

use super::Solution;
use crate::complex::Complex;
use crate::model::SecondOrder;

/// Smallest `|hλ|` the stability scan looks at. A pole that is already unstable here
/// (an undamped pole under Euler or Heun, where `|R| − 1 ∝ |hλ|²` or `|hλ|⁴`) counts as
/// having no stable step: its true limit would need `ζ ≲ 1e−10`, which the app
/// classifies as undamped anyway.
const SCAN_START: f64 = 1e-3;
/// Largest `|hλ|` scanned: every explicit Runge–Kutta region used here lies inside
/// `|z| < 3`.
const SCAN_END: f64 = 10.0;
/// Geometric growth of the scan (0.2 % per point, about 3 500 points).
const SCAN_RATIO: f64 = 1.002;
/// Bisection iterations after the scan has bracketed the boundary.
const BISECTION_ITERATIONS: usize = 100;
/// `|R| ≤ 1 + STABILITY_SLACK` counts as stable, so that rounding of an exact `|R| = 1`
/// (the trapezoid or RK4 on the imaginary axis) does not count as growth.
pub(crate) const STABILITY_SLACK: f64 = 1e-14;

/// The step sizes for which a method keeps a linear problem's solution bounded.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum StepLimit {
    /// Every `h > 0` is stable (A-stable method, or no decaying pole).
    Unconditional,
    /// Stable for `0 < h ≤ h_max` (s).
    UpTo(f64),
    /// No `h > 0` is stable: a pole has `Re λ > 0` (the exact solution grows too) or the
    /// method cannot damp an undamped pole (Euler, Heun on `λ = ±iω`).
    NoStableStep,
}

impl StepLimit {
    /// The stricter of two limits (all poles must be stable at once).
    pub fn min(self, other: StepLimit) -> StepLimit {
        match (self, other) {
            (StepLimit::NoStableStep, _) | (_, StepLimit::NoStableStep) => StepLimit::NoStableStep,
            (StepLimit::Unconditional, x) | (x, StepLimit::Unconditional) => x,
            (StepLimit::UpTo(a), StepLimit::UpTo(b)) => StepLimit::UpTo(a.min(b)),
        }
    }

    /// Whether `h` (s) lies in the stable range.
    pub fn allows(self, h: f64) -> bool {
        match self {
            StepLimit::Unconditional => h > 0.0,
            StepLimit::UpTo(max) => h > 0.0 && h <= max,
            StepLimit::NoStableStep => false,
        }
    }
}

/// A geometric scan `y = start, start·ratio, start·ratio², … < end` along which
/// [`first_instability`] looks for the first unstable point before bisecting.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Scan {
    /// First point scanned (must be stable for a boundary to be found).
    pub start: f64,
    /// The scan stops at the first point at or past `end`.
    pub end: f64,
    /// Ratio of consecutive points, > 1.
    pub ratio: f64,
}

/// The scan of `|hλ|` used for step limits: 1e−3 to 10 by 0.2 % (about 4 600 points).
pub(crate) const STEP_SCAN: Scan = Scan {
    start: SCAN_START,
    end: SCAN_END,
    ratio: SCAN_RATIO,
};

/// Finds the first instability along `y ∈ [scan.start, scan.end]` of `is_stable(y)` and
/// refines it by bisection; returns the last stable `y`, `None` if unstable at the start,
/// `Some(∞)` if stable throughout. The one boundary search of the crate: step limits,
/// symplectic Euler's limit and the stability-region boundaries all use it (the regions
/// through [`first_instability_of_interval`], the same search with fewer tests).
pub(crate) fn first_instability(scan: Scan, is_stable: impl Fn(f64) -> bool) -> Option<f64> {
    if !(scan.ratio > 1.0 && scan.start > 0.0 && is_stable(scan.start)) {
        return None;
    }
    let mut lo = scan.start;
    for next in scan.points().skip(1) {
        if !is_stable(next) {
            return Some(bisect(lo, next, is_stable));
        }
        lo = next;
    }
    Some(f64::INFINITY)
}

impl Scan {
    /// The points [`first_instability`] tests, in order: `start`, then each times `ratio`
    /// until one reaches `end` (that one included): ln(end/start)/ln(ratio) of them.
    pub(crate) fn points(self) -> impl Iterator<Item = f64> {
        std::iter::successors(Some(self.start), move |&y| {
            (self.ratio > 1.0 && y < self.end).then_some(y * self.ratio)
        })
    }
}

/// [`Scan::points`], collected (for a search that halves their range).
pub(crate) fn scan_points(scan: Scan) -> Vec<f64> {
    scan.points().collect()
}

/// [`first_instability`] over `points` (its scan, [`scan_points`]) when the stable points
/// are known to come first and the unstable ones after them: along a ray from a point
/// inside a region that is star-shaped about it (the stability regions about `z = −1`).
/// The first unstable point is found by halving the range of indices (about 10 tests
/// instead of one per point, hundreds); the bracket, and so the bisection and the answer,
/// are then exactly `first_instability`'s.
pub(crate) fn first_instability_of_interval(
    points: &[f64],
    is_stable: impl Fn(f64) -> bool,
) -> Option<f64> {
    let (&first, &last) = (points.first()?, points.last()?);
    if !(first > 0.0 && is_stable(first)) {
        return None;
    }
    if points.len() < 2 || is_stable(last) {
        return Some(f64::INFINITY);
    }
    // Invariant: points[lo] is stable, points[hi] is not.
    let (mut lo, mut hi) = (0, points.len() - 1);
    while hi - lo > 1 {
        let mid = lo + (hi - lo) / 2;
        match points.get(mid).is_some_and(|&y| is_stable(y)) {
            true => lo = mid,
            false => hi = mid,
        }
    }
    Some(bisect(points[lo], points[hi], is_stable))
}

/// The last stable `y` of `[lo, hi]` (`lo` stable, `hi` not), to the resolution of `f64`.
fn bisect(mut lo: f64, mut hi: f64, is_stable: impl Fn(f64) -> bool) -> f64 {
    for _ in 0..BISECTION_ITERATIONS {
        let mid = 0.5 * (lo + hi);
        if mid <= lo || mid >= hi {
            break;
        }
        if is_stable(mid) {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    lo
}

/// One-step methods that map `y' = λy` to `y₁ = R(hλ)·y₀`.
pub trait Amplification {
    /// Amplification factor `R(z)` at `z = h·λ` (dimensionless).
    fn amplification(&self, z: Complex) -> Complex;

    /// Largest stable step for one pole `λ` [1/s]: the first `h` at which
    /// `|R(hλ)| > 1`, found by a geometric scan of `|hλ|` from 1e−3 to 10 (factor 1.002)
    /// and 100 bisection steps. Methods with a closed form override it.
    fn pole_step_limit(&self, lambda: Complex) -> StepLimit {
        if !(lambda.re.is_finite() && lambda.im.is_finite()) || lambda.re > 0.0 {
            return StepLimit::NoStableStep;
        }
        let size = lambda.abs();
        if size == 0.0 {
            return StepLimit::Unconditional;
        }
        let dir = lambda * (1.0 / size);
        let stable = |y: f64| self.amplification(dir * y).abs() <= 1.0 + STABILITY_SLACK;
        match first_instability(STEP_SCAN, stable) {
            None => StepLimit::NoStableStep,
            Some(y) if y.is_infinite() => StepLimit::Unconditional,
            Some(y) => StepLimit::UpTo(y / size),
        }
    }

    /// Largest `h` (s) stable for every pole at once (e.g. both poles of a
    /// [`SecondOrder`], see [`SecondOrder::poles`]). The methods' `R` are polynomials or
    /// quotients with real coefficients, so `|R(h·λ̄)| = |R(h·λ)|` (to the bit: IEEE
    /// arithmetic on conjugates gives conjugates): a pole whose conjugate came before is
    /// not searched again, which halves the work for an underdamped pair.
    fn step_limit(&self, poles: &[Complex]) -> StepLimit {
        let mut limit = StepLimit::Unconditional;
        for (i, &p) in poles.iter().enumerate() {
            if !poles[..i].contains(&p.conj()) {
                limit = limit.min(self.pole_step_limit(p));
            }
        }
        limit
    }
}

/// Closed form for forward Euler: `|1 + hλ|² ≤ 1 ⇔ h ≤ −2·Re(λ)/|λ|²`.
pub(crate) fn euler_pole_limit(lambda: Complex) -> StepLimit {
    let size2 = lambda.re * lambda.re + lambda.im * lambda.im;
    if !size2.is_finite() {
        return StepLimit::NoStableStep;
    }
    if size2 == 0.0 {
        return StepLimit::Unconditional;
    }
    let h = -2.0 * lambda.re / size2;
    if h > 0.0 {
        StepLimit::UpTo(h)
    } else {
        StepLimit::NoStableStep
    }
}

/// The symplectic-Euler map of the oscillator `a·x'' + b·x' + c·x = 0` over one step `h`
/// (s), on `[x, v]`: with `k = c/a`, `d = b/a`,
/// `v₁ = −hk·x₀ + (1 − hd)·v₀`, `x₁ = (1 − h²k)·x₀ + h(1 − hd)·v₀`, i.e.
/// `[[1 − h²k, h(1 − hd)], [−hk, 1 − hd]]`. Its determinant is `1 − hd` (area-preserving
/// when undamped).
pub fn symplectic_euler_matrix(sys: &SecondOrder, h: f64) -> [[f64; 2]; 2] {
    let k = sys.stiffness() / sys.inertia();
    let d = sys.damping() / sys.inertia();
    [[1.0 - h * h * k, h * (1.0 - h * d)], [-h * k, 1.0 - h * d]]
}

/// Spectral radius (largest `|μ|` of the two eigenvalues) of
/// [`symplectic_euler_matrix`]: the per-step growth of the slowest-decaying mode.
/// Symplectic Euler is not a scalar map `R(z)`, so this replaces `|R|` for it. For the
/// undamped oscillator it is exactly 1 while `h·ω_n ≤ 2`.
pub fn symplectic_euler_spectral_radius(sys: &SecondOrder, h: f64) -> f64 {
    let m = symplectic_euler_matrix(sys, h);
    let tr = m[0][0] + m[1][1];
    let det = m[0][0] * m[1][1] - m[0][1] * m[1][0];
    let disc = 0.25 * tr * tr - det;
    if disc < 0.0 {
        // Complex pair: |μ|² = det.
        det.abs().sqrt()
    } else {
        let r = disc.sqrt();
        (0.5 * tr + r).abs().max((0.5 * tr - r).abs())
    }
}

/// Largest stable step of symplectic Euler for the oscillator `sys`: first `h` at which
/// [`symplectic_euler_spectral_radius`] exceeds 1 (+1e−14 for rounding), scanned as
/// for [`Amplification::pole_step_limit`] in units of `1/s` with
/// `s = max(√|c/a|, |b/a|)`. Undamped: `h_max = 2/ω_n` exactly.
pub fn symplectic_euler_step_limit(sys: &SecondOrder) -> StepLimit {
    if sys.damping() < 0.0 || sys.stiffness() < 0.0 {
        return StepLimit::NoStableStep;
    }
    let scale = sys
        .omega_n_squared()
        .abs()
        .sqrt()
        .max((sys.damping() / sys.inertia()).abs());
    if scale == 0.0 {
        // x'' = 0: x grows linearly for any method; no step keeps it bounded.
        return StepLimit::NoStableStep;
    }
    let stable = |y: f64| symplectic_euler_spectral_radius(sys, y / scale) <= 1.0 + STABILITY_SLACK;
    match first_instability(STEP_SCAN, stable) {
        None => StepLimit::NoStableStep,
        Some(y) if y.is_infinite() => StepLimit::Unconditional,
        Some(y) => StepLimit::UpTo(y / scale),
    }
}

/// Error of one state component over a run's grid points.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct ErrorNorms {
    /// `maxᵢ |yᵢ − y(tᵢ)|`, in the component's unit.
    pub max: f64,
    /// `√(mean of (yᵢ − y(tᵢ))²)` over the grid points, in the component's unit.
    pub rms: f64,
}

/// Error of each state component of `sol` against the exact solution `exact(t)`,
/// at the solution's own time points. An empty solution gives zeros.
pub fn error_norms<const N: usize>(
    sol: &Solution<N>,
    exact: impl Fn(f64) -> [f64; N],
) -> [ErrorNorms; N] {
    norms(&sol.y, sol.t.iter().map(|&t| exact(t)))
}

/// [`error_norms`] against exact states already known at the solution's time points, in
/// their order (`exact[i]` at `sol.t[i]`; the shorter of the two sets the count): the same
/// numbers, without evaluating the exact solution, or finding each point, again.
pub fn error_norms_at<const N: usize>(sol: &Solution<N>, exact: &[[f64; N]]) -> [ErrorNorms; N] {
    norms(&sol.y, exact.iter().copied())
}

/// The norms of `ys` against `exact`, point by point.
fn norms<const N: usize>(
    ys: &[[f64; N]],
    exact: impl Iterator<Item = [f64; N]>,
) -> [ErrorNorms; N] {
    let mut out = [ErrorNorms::default(); N];
    let mut count = 0usize;
    for (y, e) in ys.iter().zip(exact) {
        for ((o, yi), ei) in out.iter_mut().zip(y).zip(&e) {
            let d = (yi - ei).abs();
            // NaN must win, so an unstable run is never reported as accurate.
            o.max = if d.is_nan() { f64::NAN } else { o.max.max(d) };
            o.rms += d * d;
        }
        count += 1;
    }
    if count > 0 {
        for o in &mut out {
            o.rms = (o.rms / count as f64).sqrt();
        }
    }
    out
}

/// Largest error over all components and grid points (see [`error_norms`]).
pub fn max_error<const N: usize>(sol: &Solution<N>, exact: impl Fn(f64) -> [f64; N]) -> f64 {
    error_norms(sol, exact).iter().fold(0.0f64, |acc, e| {
        if e.max.is_nan() {
            f64::NAN
        } else {
            acc.max(e.max)
        }
    })
}

/// Which errors count as "asymptotic" when fitting the order of convergence.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FitWindow {
    /// Errors at or below this are dominated by rounding and are dropped. Default `1e−12`:
    /// double-precision rounding (1.1e−16 per operation) accumulated over 10³–10⁴ steps of
    /// an O(1) solution.
    pub floor: f64,
    /// Errors at or above this (or non-finite) mean the step was too large to be in the
    /// asymptotic range, or unstable, and are dropped. Default `1e−2` (for O(1) solutions).
    pub ceiling: f64,
}

impl Default for FitWindow {
    fn default() -> Self {
        Self {
            floor: 1e-12,
            ceiling: 1e-2,
        }
    }
}

/// One run of a convergence study.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct ConvergencePoint {
    /// Step size used (s).
    pub h: f64,
    /// Error measured (`∞` when the run failed).
    pub error: f64,
    /// Whether the point lies in the fit window.
    pub used: bool,
}

/// Errors for a list of step sizes and the order fitted to them.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct ConvergenceStudy {
    /// One entry per step size, in the order given.
    pub points: Vec<ConvergencePoint>,
    /// Least-squares slope of `ln(error)` against `ln(h)` over the used points; `None`
    /// with fewer than two distinct used step sizes.
    pub order: Option<f64>,
}

impl ConvergenceStudy {
    /// The same study of a linear problem started from an initial state `s` times larger
    /// (`s > 0`), with its fit window scaled by `s` too: every error times `s`, the steps,
    /// the points used and the order unchanged. A linear method on `y' = A·y` gives
    /// `y_n(s·y₀) = s·y_n(y₀)` and the exact solution scales alike, so this is the study a
    /// rerun would measure, up to rounding.
    pub fn scaled(&self, s: f64) -> Self {
        Self {
            points: self
                .points
                .iter()
                .map(|q| ConvergencePoint {
                    error: q.error * s,
                    ..*q
                })
                .collect(),
            order: self.order,
        }
    }
}

/// Least-squares slope `p` of `ln e = p·ln h + c` over the points; `None` with fewer than
/// two points or all `h` equal. The order of [`super::convergence::fit_power_law`].
pub fn fit_order(points: &[(f64, f64)]) -> Option<f64> {
    super::convergence::fit_power_law(points).map(|f| f.order)
}

/// Runs `error_for(h)` — which returns `(h actually used, error)` — for each step size in
/// `steps`, keeps the points inside `window`, and fits the observed order by least squares
/// ([`fit_order`]). A failed run (an `Err`) counts as unstable (`error = ∞`).
pub fn convergence_study<E>(
    steps: &[f64],
    window: FitWindow,
    mut error_for: impl FnMut(f64) -> Result<(f64, f64), E>,
) -> ConvergenceStudy {
    let points: Vec<ConvergencePoint> = steps
        .iter()
        .map(|&h| {
            let (h_used, error) = error_for(h).unwrap_or((h, f64::INFINITY));
            let used = error.is_finite() && error > window.floor && error < window.ceiling;
            ConvergencePoint {
                h: h_used,
                error,
                used,
            }
        })
        .collect();
    let fit: Vec<(f64, f64)> = points
        .iter()
        .filter(|p| p.used)
        .map(|p| (p.h, p.error))
        .collect();
    ConvergenceStudy {
        order: fit_order(&fit),
        points,
    }
}

/// Mechanical energy `E = ½a·v² + ½c·x²` of the oscillator at state `[x, v]` (kinetic plus
/// potential: J for the quarter car with `x` in m).
pub fn oscillator_energy(sys: &SecondOrder, state: [f64; 2]) -> f64 {
    0.5 * sys.inertia() * state[1] * state[1] + 0.5 * sys.stiffness() * state[0] * state[0]
}

/// How far the energy wandered from its initial value over a run.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct EnergyDrift {
    /// `max |E(tᵢ) − E₀| / E₀` [-].
    pub max_relative: f64,
    /// `(E(t_end) − E₀) / E₀` [-], signed: positive means energy was gained.
    pub final_relative: f64,
}

/// Energy drift of a trajectory of the oscillator `sys`; `None` when there are no states or
/// the initial energy is not positive (nothing to compare with).
pub fn energy_drift(sys: &SecondOrder, states: &[[f64; 2]]) -> Option<EnergyDrift> {
    let e0 = oscillator_energy(sys, *states.first()?);
    if !(e0 > 0.0 && e0.is_finite()) {
        return None;
    }
    let mut max_relative = 0.0f64;
    let mut last = e0;
    for &s in states {
        last = oscillator_energy(sys, s);
        let rel = (last - e0).abs() / e0;
        max_relative = if rel.is_nan() {
            f64::NAN
        } else {
            max_relative.max(rel)
        };
    }
    Some(EnergyDrift {
        max_relative,
        final_relative: (last - e0) / e0,
    })
}

#[cfg(test)]
mod tests {
    use super::super::{Heun, Rk4, Trapezoid};
    use super::*;

    #[test]
    fn norms_against_tabulated_states_equal_norms_against_the_function() {
        let exact = |t: f64| [(-0.3 * t).exp() * (2.0 * t).cos(), -(2.0 * t).sin()];
        let t: Vec<f64> = (0..=40).map(|i| f64::from(i) * 0.25).collect();
        let y = t
            .iter()
            .map(|&t| exact(t).map(|v| v + 1e-3 * (7.0 * t).sin()))
            .collect();
        let mut sol = Solution {
            t,
            y,
            stats: Default::default(),
        };
        let table: Vec<[f64; 2]> = sol.t.iter().map(|&t| exact(t)).collect();
        let want = error_norms(&sol, exact);
        assert!(want[0].max > 9e-4 && want[1].rms > 1e-4, "{want:?}");
        assert_eq!(error_norms_at(&sol, &table), want);
        // A NaN in the run is reported the same way by both.
        sol.y[40][0] = f64::NAN;
        let want = error_norms(&sol, exact);
        assert!(want[0].max.is_nan());
        assert_eq!(
            format!("{:?}", error_norms_at(&sol, &table)),
            format!("{want:?}")
        );
    }

    #[test]
    fn rk4_real_axis_limit_matches_published_value() {
        // The RK4 stability interval on the negative real axis is [−2.785 293 563 …, 0]
        // (Hairer & Wanner, Solving ODEs II, Fig. IV.2.1; root of 1 + x + x²/2 + x³/6 + x⁴/24 = 1).
        let StepLimit::UpTo(h) = Rk4.step_limit(&[Complex::real(-1.0)]) else {
            panic!("RK4 must have a finite limit")
        };
        assert!((h - 2.785_293_563_405_282).abs() < 1e-9, "{h}");
    }

    #[test]
    fn heun_limits_on_the_axes() {
        // |1 + x + x²/2| = 1 at x = −2 (real axis); no stable step on the imaginary axis
        // since |R(iy)|² = 1 + y⁴/4.
        let StepLimit::UpTo(h) = Heun.step_limit(&[Complex::real(-4.0)]) else {
            panic!()
        };
        assert!((h - 0.5).abs() < 1e-10);
        assert_eq!(
            Heun.step_limit(&[Complex::new(0.0, 1.0)]),
            StepLimit::NoStableStep
        );
    }

    #[test]
    fn a_conjugate_pole_has_the_same_limit_to_the_bit() {
        // What lets step_limit search one pole of a conjugate pair.
        let dp45 = super::super::Dopri5::new(super::super::Dopri5Config::default()).unwrap();
        let methods: [&dyn Amplification; 5] =
            [&super::super::Euler, &Heun, &Rk4, &dp45, &Trapezoid];
        for m in methods {
            for zeta in [0.0, 0.05, 0.3, 0.7, 0.99] {
                let lambda = Complex::new(-zeta * 7.0, (1.0 - zeta * zeta).sqrt() * 7.0);
                let (a, b) = (m.pole_step_limit(lambda), m.pole_step_limit(lambda.conj()));
                assert_eq!(a, b, "ζ = {zeta}");
                assert_eq!(m.step_limit(&[lambda, lambda.conj()]), a);
            }
        }
    }

    #[test]
    fn trapezoid_is_a_stable() {
        assert_eq!(
            Trapezoid.step_limit(&[Complex::new(-1e-3, 1e4), Complex::real(-1e9)]),
            StepLimit::Unconditional
        );
        assert_eq!(
            Trapezoid.step_limit(&[Complex::real(0.1)]),
            StepLimit::NoStableStep
        );
    }

    #[test]
    fn symplectic_limit_for_undamped_is_two_over_omega() {
        let sys = SecondOrder::from_natural(5.0, 0.0).unwrap();
        let StepLimit::UpTo(h) = symplectic_euler_step_limit(&sys) else {
            panic!()
        };
        assert!((h - 0.4).abs() < 1e-9, "{h}");
        assert!((symplectic_euler_spectral_radius(&sys, 0.3) - 1.0).abs() < 1e-14);
    }

    #[test]
    fn order_fit_recovers_a_power_law() {
        let pts: Vec<(f64, f64)> = [0.1, 0.05, 0.025]
            .iter()
            .map(|&h| (h, 3.0 * h * h))
            .collect();
        assert!((fit_order(&pts).unwrap() - 2.0).abs() < 1e-12);
        assert_eq!(fit_order(&pts[..1]), None);
        assert_eq!(fit_order(&[(0.1, 1.0), (0.1, 2.0)]), None);
    }

    #[test]
    fn energy_of_the_oscillator() {
        let sys = SecondOrder::mechanical(2.0, 0.0, 8.0).unwrap();
        assert_eq!(
            oscillator_energy(&sys, [0.5, 1.0]),
            0.5 * 2.0 + 0.5 * 8.0 * 0.25
        );
        assert_eq!(energy_drift(&sys, &[]), None);
        assert_eq!(energy_drift(&sys, &[[0.0, 0.0]]), None);
        let d = energy_drift(&sys, &[[1.0, 0.0], [0.0, 2.0], [1.1, 0.0]]).unwrap();
        assert!((d.final_relative - 0.21).abs() < 1e-12);
    }
}
