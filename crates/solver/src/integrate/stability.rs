//! Linear stability of every method on the oscillator through one trait, [`Stability`]:
//! the growth per step of the slowest-decaying mode, and the steps that keep it bounded.
//!
//! For a one-step method with amplification factor `R(z)` ([`Amplification`]), each mode
//! `e^{λt}` of `a·x'' + b·x' + c·x = 0` is multiplied by `R(hλ)` per step, so the growth
//! per step is `max |R(hλᵢ)|` over the two poles. Symplectic Euler treats `x` and `v`
//! differently and is no scalar map; its growth is the spectral radius of its 2×2 step
//! matrix ([`symplectic_euler_spectral_radius`]). Dormand–Prince 5(4) propagates its
//! 5th-order solution, whose `R(z)` follows from the tableau ([`Dopri5`]'s
//! [`Amplification`]).
//!
//! ```
//! use zeta_solver::integrate::stability::Stability;
//! use zeta_solver::integrate::{Euler, SymplecticEuler};
//! use zeta_solver::SecondOrder;
//! let undamped = SecondOrder::from_natural(2.0, 0.0).unwrap();
//! // Euler grows by |1 + 2i·h| per step; symplectic Euler keeps |μ| = 1 while 2h ≤ 2.
//! assert!((Euler.growth_per_step(&undamped, 0.5) - 2f64.sqrt()).abs() < 1e-12);
//! assert!((SymplecticEuler.growth_per_step(&undamped, 0.5) - 1.0).abs() < 1e-12);
//! assert!(SymplecticEuler.stable_steps(&undamped).allows(0.9));
//! ```

use super::analysis::{
    first_instability_of_interval, scan_points, symplectic_euler_spectral_radius,
    symplectic_euler_step_limit, Amplification, Scan, StepLimit,
};
use super::{Dopri5, Method, SymplecticEuler};
use crate::complex::Complex;
use crate::model::SecondOrder;

/// Linear stability of a method on the oscillator `sys`.
pub trait Stability {
    /// Factor by which the slowest-decaying mode is multiplied per step of `h` (s)
    /// \[-\]: `max |R(hλᵢ)|` over the poles, or the spectral radius of the step matrix.
    /// Above 1 the numbers grow whatever the accuracy.
    fn growth_per_step(&self, sys: &SecondOrder, h: f64) -> f64;

    /// The steps `h` for which [`Stability::growth_per_step`] stays at most 1.
    fn stable_steps(&self, sys: &SecondOrder) -> StepLimit;
}

impl<A: Amplification> Stability for A {
    fn growth_per_step(&self, sys: &SecondOrder, h: f64) -> f64 {
        sys.poles()
            .iter()
            .map(|&p| self.amplification(p * h).abs())
            .fold(0.0f64, f64::max)
    }

    fn stable_steps(&self, sys: &SecondOrder) -> StepLimit {
        self.step_limit(&sys.poles())
    }
}

impl Stability for SymplecticEuler {
    fn growth_per_step(&self, sys: &SecondOrder, h: f64) -> f64 {
        symplectic_euler_spectral_radius(sys, h)
    }

    fn stable_steps(&self, sys: &SecondOrder) -> StepLimit {
        symplectic_euler_step_limit(sys)
    }
}

impl Stability for Method {
    fn growth_per_step(&self, sys: &SecondOrder, h: f64) -> f64 {
        with_method!(self, |m| m.growth_per_step(sys, h))
    }

    fn stable_steps(&self, sys: &SecondOrder) -> StepLimit {
        with_method!(self, |m| m.stable_steps(sys))
    }
}

/// Dormand–Prince 5(4) advances with its 5th-order weights `b`, so on `y' = λy` one step
/// gives `R(z) = 1 + z·Σᵢ bᵢ·Kᵢ` with stage values `Kᵢ = 1 + z·Σ_{j<i} aᵢⱼ·Kⱼ`
/// (`K₁ = 1`), a polynomial of degree 6: `1 + z + z²/2 + z³/6 + z⁴/24 + z⁵/120 + z⁶/600`,
/// evaluated here in Horner form (a test checks it against the stages of the tableau).
/// Its real stability interval is about `[−3.31, 0]`.
impl Amplification for Dopri5 {
    fn amplification(&self, z: Complex) -> Complex {
        // Six complex products instead of the stages' 27: the stable-step search
        // evaluates it a few thousand times whenever ζ or ωₙ moves.
        DP45_R
            .iter()
            .fold(Complex::real(0.0), |acc, &c| acc * z + Complex::real(c))
    }
}

/// Coefficients of DP45's `R(z)`, highest power first.
const DP45_R: [f64; 7] = [
    1.0 / 600.0,
    1.0 / 120.0,
    1.0 / 24.0,
    1.0 / 6.0,
    0.5,
    1.0,
    1.0,
];

/// Rays traced per stability-region boundary.
pub const REGION_RAYS: usize = 360;

/// The scan along each ray: radius 10⁻³ … 4 by 1 %, then bisection.
const REGION_SCAN: Scan = Scan {
    start: 1e-3,
    end: 4.0,
    ratio: 1.01,
};

/// The boundary `|R(z)| = 1` of the stability region of `method`, as `rays + 1` points
/// (closed): along each ray `z = −1 + r·e^{iθ}`, `θ = 2πk/rays`, the radius `r` of the
/// first instability (scanned outward from 10⁻³ to 4, refined by bisection; `r = 4` when
/// the ray stays stable). `z = −1` lies inside every explicit region here, and these
/// regions are star-shaped about it, so the curve is the region's outline.
///
/// For regions star-shaped about −1 (Euler, Heun, RK4; not DP45's, which has lobes), the
/// stable scan points of a ray come first, so the first unstable one is found by halving
/// the range of points rather than testing each: the same boundary to the bit, in a tenth
/// of the time (a test compares the two searches on every ray).
pub fn region_boundary(method: &impl Amplification, rays: usize) -> Vec<Complex> {
    let centre = Complex::real(-1.0);
    let rays = rays.max(1);
    let points = scan_points(REGION_SCAN);
    (0..=rays)
        .map(|k| {
            let th = std::f64::consts::TAU * k as f64 / rays as f64;
            let dir = Complex::new(th.cos(), th.sin());
            let stable = |r: f64| method.amplification(centre + dir * r).abs() <= 1.0;
            let r = match first_instability_of_interval(&points, stable) {
                Some(r) if r.is_finite() => r,
                Some(_) => REGION_SCAN.end,
                None => 0.0,
            };
            centre + dir * r
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::integrate::analysis::first_instability;
    use crate::integrate::tableau::dopri5 as tab;
    use crate::integrate::{Dopri5Config, Euler, Heun, Rk4};

    /// DP45's `R(z)` from the stages of its tableau (see the `impl`).
    fn dp45_stages(z: Complex) -> Complex {
        let one = Complex::real(1.0);
        let rows: [&[f64]; 6] = [&[], &[tab::A21], &tab::A3, &tab::A4, &tab::A5, &tab::A6];
        let mut k = [one; 6];
        for (i, row) in rows.iter().enumerate() {
            let mut sum = Complex::real(0.0);
            for (a, kj) in row.iter().zip(&k) {
                sum = sum + *kj * *a;
            }
            k[i] = one + z * sum;
        }
        let mut sum = Complex::real(0.0);
        for (b, ki) in tab::B.iter().zip(&k) {
            sum = sum + *ki * *b;
        }
        one + z * sum
    }

    #[test]
    fn dp45_amplification_is_the_published_polynomial() {
        let dp = Dopri5::new(Dopri5Config::default()).unwrap();
        for z in [
            Complex::new(-1.3, 0.7),
            Complex::new(0.2, -2.0),
            Complex::real(-3.0),
            Complex::new(-0.01, 3.2),
        ] {
            let want = dp45_stages(z);
            assert!((dp.amplification(z) - want).abs() < 1e-13 * want.abs().max(1.0));
        }
        // Real stability interval ≈ [−3.3066, 0] (Hairer & Wanner II, Fig. IV.2.1).
        let StepLimit::UpTo(h) = dp.step_limit(&[Complex::real(-1.0)]) else {
            panic!("DP45 has a finite real limit")
        };
        assert!((h - 3.3066).abs() < 1e-3, "{h}");
    }

    /// The search by halving finds exactly what the scan point by point finds, on every
    /// ray of every region drawn (it relies on the regions being star-shaped about −1;
    /// DP45's is not: along some rays it is unstable, then stable again before |z+1| = 4).
    #[test]
    fn halving_the_scan_finds_the_boundary_the_full_scan_finds() {
        let points = scan_points(REGION_SCAN);
        let methods: [&dyn Amplification; 3] = [&Euler, &Heun, &Rk4];
        for (m, method) in methods.iter().enumerate() {
            for k in 0..=REGION_RAYS {
                let th = std::f64::consts::TAU * k as f64 / REGION_RAYS as f64;
                let dir = Complex::new(th.cos(), th.sin());
                let at = |r: f64| Complex::real(-1.0) + dir * r;
                let stable = |r: f64| method.amplification(at(r)).abs() <= 1.0;
                let full = first_instability(REGION_SCAN, stable);
                let halved = first_instability_of_interval(&points, stable);
                assert_eq!(full.map(f64::to_bits), halved.map(f64::to_bits), "{m} {k}");
            }
        }
        // Stable throughout, unstable at once, and an empty scan.
        assert_eq!(
            first_instability_of_interval(&points, |_| true),
            Some(f64::INFINITY)
        );
        assert_eq!(first_instability_of_interval(&points, |_| false), None);
        assert_eq!(first_instability_of_interval(&[], |_| true), None);
    }

    #[test]
    fn euler_region_is_the_unit_disk_about_minus_one() {
        for z in region_boundary(&Euler, 72) {
            assert!(
                ((z - Complex::real(-1.0)).abs() - 1.0).abs() < 1e-12,
                "{z:?}"
            );
        }
    }

    #[test]
    fn region_boundaries_lie_on_abs_r_equal_one() {
        for pts in [region_boundary(&Heun, 90), region_boundary(&Rk4, 90)] {
            assert_eq!(pts.len(), 91);
            for (k, z) in pts.iter().enumerate() {
                // The ray along the positive real axis ends at z = 0, where R = 1.
                let r = Heun
                    .amplification(*z)
                    .abs()
                    .max(Rk4.amplification(*z).abs());
                assert!(r > 0.999 || k == 0 || k == 90, "{k}: {z:?} {r}");
            }
        }
    }

    #[test]
    fn growth_matches_the_amplification_at_the_poles() {
        let sys = SecondOrder::from_natural(2.0, 0.05).unwrap();
        let h = 0.3;
        let want = sys
            .poles()
            .iter()
            .map(|&p| Rk4.amplification(p * h).abs())
            .fold(0.0, f64::max);
        assert_eq!(Method::Rk4.growth_per_step(&sys, h), want);
        assert_eq!(
            Method::SymplecticEuler.stable_steps(&sys),
            symplectic_euler_step_limit(&sys)
        );
    }
}
