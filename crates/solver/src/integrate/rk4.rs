//! The classical fourth-order Runge–Kutta method.

use super::analysis::Amplification;
use super::tableau::rk4::{B, C};
use crate::complex::Complex;

/// Classical RK4, order 4, four `rhs` calls per step. Amplification
/// `R(z) = 1 + z + z²/2 + z³/6 + z⁴/24`: stable on the negative real axis to
/// `h|λ| ≈ 2.785` and on the imaginary axis to `h|λ| = 2√2`.
///
/// ```
/// use zeta_solver::integrate::{FixedStep, Rk4, Scalar};
/// let mut y = [1.0];
/// Rk4.step(&Scalar { lambda: -1.0 }, 0.0, 0.1, &mut y).unwrap();
/// assert!((y[0] - (-0.1f64).exp()).abs() < 1e-7);
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Rk4;

fixed_step!(Rk4, "RK4", order 4, |sys, t, h, y| {
    let mut k1 = [0.0; N];
    let mut k2 = [0.0; N];
    let mut k3 = [0.0; N];
    let mut k4 = [0.0; N];
    let mut stage = [0.0; N];
    sys.rhs(t, y, &mut k1);
    for i in 0..N {
        stage[i] = y[i] + C[1] * h * k1[i];
    }
    sys.rhs(t + C[1] * h, &stage, &mut k2);
    for i in 0..N {
        stage[i] = y[i] + C[2] * h * k2[i];
    }
    sys.rhs(t + C[2] * h, &stage, &mut k3);
    for i in 0..N {
        stage[i] = y[i] + C[3] * h * k3[i];
    }
    sys.rhs(t + C[3] * h, &stage, &mut k4);
    for i in 0..N {
        y[i] += h * (B[0] * k1[i] + B[1] * k2[i] + B[2] * k3[i] + B[3] * k4[i]);
    }
    Ok(4)
});

impl Amplification for Rk4 {
    fn amplification(&self, z: Complex) -> Complex {
        // Horner form of the degree-4 Taylor polynomial of e^z.
        let one = Complex::real(1.0);
        one + z * (one + z * (one * 0.5 + z * (one * (1.0 / 6.0) + z * (1.0 / 24.0))))
    }
}
