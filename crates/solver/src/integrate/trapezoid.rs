//! The implicit trapezoidal rule (Crank–Nicolson; for `m·x'' + c·x' + k·x = f` it is the
//! same map as Newmark's average-acceleration method, β = ¼, γ = ½).

use super::analysis::{Amplification, StepLimit};
use super::linalg::Lu;
use super::tableau::trapezoid::THETA;
use super::IntegrationError;
use crate::complex::Complex;

/// Newton iterations allowed per step before giving up.
const MAX_NEWTON: usize = 20;
/// Newton stops when the update is below this fraction of the state's size.
const NEWTON_RTOL: f64 = 1e-12;
/// ... or below this absolute size (states that pass through zero).
const NEWTON_ATOL: f64 = 1e-300;

/// Implicit trapezoidal rule, order 2, A-stable:
/// `y₁ = y₀ + (h/2)·(f(t, y₀) + f(t + h, y₁))`. Amplification
/// `R(z) = (1 + z/2)/(1 − z/2)`, `|R| ≤ 1` for every `h` when `Re λ ≤ 0`, and `|R| = 1`
/// exactly on the imaginary axis (no numerical damping of an undamped oscillator).
///
/// The implicit equation is solved by a simplified Newton iteration with the matrix
/// `I − (h/2)·J(t, y₀)` factorised once per step (LU with partial pivoting), starting from
/// `y₀`, for at most 20 iterations until the update is below `1e-12` of the state.
/// For a linear system with an exact [`System::jacobian`](super::System::jacobian) (such as
/// [`super::Linear2`], whose 2×2 matrix is exact) the first iteration is already the exact
/// solution of the linear step and the second only confirms it. Nonlinear systems converge
/// when `h` is small enough for the contraction; otherwise the step fails with
/// [`IntegrationError::ImplicitSolveFailed`].
///
/// ```
/// use zeta_solver::integrate::{FixedStep, Scalar, Trapezoid};
/// let mut y = [1.0];
/// // Stiff: λ = −1e6 with h = 1 — explicit methods explode, the trapezoid does not.
/// Trapezoid.step(&Scalar { lambda: -1e6 }, 0.0, 1.0, &mut y).unwrap();
/// assert!(y[0].abs() <= 1.0);
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Trapezoid;

fixed_step!(Trapezoid, "trapezoid", order 2, |sys, t, h, y| {
    let failed = IntegrationError::ImplicitSolveFailed { t };
    let mut f0 = [0.0; N];
    sys.rhs(t, y, &mut f0);
    let mut jac = [[0.0; N]; N];
    sys.jacobian(t, y, &mut jac);
    let mut m = [[0.0; N]; N];
    for i in 0..N {
        for j in 0..N {
            let identity = if i == j { 1.0 } else { 0.0 };
            m[i][j] = identity - THETA * h * jac[i][j];
        }
    }
    let lu = Lu::new(m).ok_or(failed.clone())?;
    let t1 = t + h;
    let y0 = *y;
    let mut y1 = y0;
    let mut f1 = [0.0; N];
    let mut n_rhs = 1;
    for _ in 0..MAX_NEWTON {
        sys.rhs(t1, &y1, &mut f1);
        n_rhs += 1;
        // Residual G(y₁) = y₁ − y₀ − (h/2)(f₀ + f₁); Newton update Δ = M⁻¹·G.
        let mut g = [0.0; N];
        for i in 0..N {
            g[i] = y1[i] - y0[i] - THETA * h * (f0[i] + f1[i]);
        }
        let delta = lu.solve(&g);
        let mut size = 0.0f64;
        let mut change = 0.0f64;
        for i in 0..N {
            y1[i] -= delta[i];
            size = size.max(y1[i].abs()).max(y0[i].abs());
            change = change.max(delta[i].abs());
        }
        if !change.is_finite() {
            return Err(failed);
        }
        if change <= NEWTON_RTOL * size + NEWTON_ATOL {
            *y = y1;
            return Ok(n_rhs);
        }
    }
    Err(failed)
});

impl Amplification for Trapezoid {
    fn amplification(&self, z: Complex) -> Complex {
        let half = z * THETA;
        (Complex::real(1.0) + half) / (Complex::real(1.0) - half)
    }

    /// A-stable: `|R(hλ)| ≤ 1` for every `h > 0` exactly when `Re λ ≤ 0`.
    fn pole_step_limit(&self, lambda: Complex) -> StepLimit {
        if lambda.re.is_finite() && lambda.im.is_finite() && lambda.re <= 0.0 {
            StepLimit::Unconditional
        } else {
            StepLimit::NoStableStep
        }
    }
}
