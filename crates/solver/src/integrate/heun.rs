//! Heun's method (explicit trapezoid, RK2): predictor by Euler, corrector by the average slope.

use super::analysis::Amplification;
use super::tableau::heun::B;
use crate::complex::Complex;

/// Heun's method, order 2, two `rhs` calls per step:
/// `k₁ = f(t, y)`, `k₂ = f(t + h, y + h·k₁)`, `y₁ = y + h·(k₁ + k₂)/2`.
/// Amplification `R(z) = 1 + z + z²/2`.
///
/// ```
/// use zeta_solver::integrate::{FixedStep, Heun, Scalar};
/// let mut y = [1.0];
/// Heun.step(&Scalar { lambda: -2.0 }, 0.0, 0.1, &mut y).unwrap();
/// assert!((y[0] - 0.82).abs() < 1e-15); // 1 − 0.2 + 0.02
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Heun;

fixed_step!(Heun, "Heun (RK2)", order 2, |sys, t, h, y| {
    let mut k1 = [0.0; N];
    let mut k2 = [0.0; N];
    sys.rhs(t, y, &mut k1);
    let mut stage = *y;
    for (s, k) in stage.iter_mut().zip(&k1) {
        *s += h * k;
    }
    sys.rhs(t + h, &stage, &mut k2);
    for ((yi, a), b) in y.iter_mut().zip(&k1).zip(&k2) {
        *yi += h * (B[0] * a + B[1] * b);
    }
    Ok(2)
});

impl Amplification for Heun {
    fn amplification(&self, z: Complex) -> Complex {
        Complex::real(1.0) + z + z * z * 0.5
    }
}
