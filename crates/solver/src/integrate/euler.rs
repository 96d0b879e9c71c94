//! Forward (explicit) Euler: `y₁ = y₀ + h·f(t₀, y₀)`.

use super::analysis::{euler_pole_limit, Amplification, StepLimit};
use crate::complex::Complex;

/// Forward Euler, order 1, one `rhs` call per step. Amplification `R(z) = 1 + z`: stable
/// for `|1 + hλ| ≤ 1`, i.e. `h ≤ −2·Re(λ)/|λ|²`; never stable for an undamped oscillator.
///
/// ```
/// use zeta_solver::integrate::{Euler, FixedStep, Scalar};
/// let mut y = [1.0];
/// Euler.step(&Scalar { lambda: -2.0 }, 0.0, 0.1, &mut y).unwrap();
/// assert!((y[0] - 0.8).abs() < 1e-15);
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Euler;

fixed_step!(Euler, "Euler", order 1, |sys, t, h, y| {
    let mut k = [0.0; N];
    sys.rhs(t, y, &mut k);
    for (yi, ki) in y.iter_mut().zip(&k) {
        *yi += h * ki;
    }
    Ok(1)
});

impl Amplification for Euler {
    fn amplification(&self, z: Complex) -> Complex {
        Complex::real(1.0) + z
    }

    /// Closed form `h ≤ −2·Re(λ)/|λ|²` (from `|1 + hλ|² ≤ 1`).
    fn pole_step_limit(&self, lambda: Complex) -> StepLimit {
        euler_pole_limit(lambda)
    }
}
