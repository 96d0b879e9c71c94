//! Semi-implicit (symplectic) Euler for systems split into positions and velocities.

use super::IntegrationError;

/// Semi-implicit Euler, order 1, two `rhs` calls per step.
///
/// State convention: `y = [q₁ … q_m, p₁ … p_m]` with `N = 2m` — positions first, then
/// velocities (for [`super::Linear2`], `[x, v]`). The velocity half is advanced first with
/// the old state, then the position half with the new velocities:
/// `p₁ = p₀ + h·f_p(t, q₀, p₀)`, `q₁ = q₀ + h·f_q(t, q₀, p₁)`.
///
/// For a conservative mechanical system (`f_q = p`, `f_p` independent of `p`) the map is
/// symplectic: energy is not conserved exactly but its error stays bounded for all time
/// (for the undamped oscillator when `h·ω_n < 2`) instead of drifting as with forward
/// Euler. With damping it is still a consistent first-order method. Odd `N` is
/// [`IntegrationError::OddDimension`].
///
/// ```
/// use zeta_solver::integrate::{FixedStep, Linear2, SymplecticEuler};
/// use zeta_solver::SecondOrder;
/// let osc = Linear2::free(SecondOrder::from_natural(1.0, 0.0).unwrap());
/// let mut y = [1.0, 0.0];
/// SymplecticEuler.step(&osc, 0.0, 0.1, &mut y).unwrap();
/// // v₁ = −0.1, x₁ = 1 + 0.1·v₁ = 0.99.
/// assert!((y[1] + 0.1).abs() < 1e-15 && (y[0] - 0.99).abs() < 1e-15);
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct SymplecticEuler;

fixed_step!(SymplecticEuler, "symplectic Euler", order 1, |sys, t, h, y| {
    if !N.is_multiple_of(2) {
        return Err(IntegrationError::OddDimension { n: N });
    }
    let m = N / 2;
    let mut k = [0.0; N];
    sys.rhs(t, y, &mut k);
    for i in m..N {
        y[i] += h * k[i];
    }
    sys.rhs(t, y, &mut k);
    for i in 0..m {
        y[i] += h * k[i];
    }
    Ok(2)
});
