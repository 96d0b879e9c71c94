//! The model `a·y'' + b·y' + c·y = f(t)` and what follows from its three coefficients.
//!
//! Conventions: time in s, angular frequency in rad/s. With `α = b/(2a)` (the decay rate,
//! "neper frequency", 1/s) and `ω_n² = c/a`, the characteristic equation is
//! `s² + 2α·s + ω_n² = 0`, with poles `s = −α ± √(α² − ω_n²)`.
//!
//! ```
//! use zeta_solver::{SecondOrder, Regime};
//! // Quarter-car corner: m = 300 kg, k = 24 000 N/m, c = 1610 N·s/m.
//! let car = SecondOrder::mechanical(300.0, 1610.0, 24_000.0).unwrap();
//! assert!((car.natural_frequency().unwrap() - 8.944_272).abs() < 1e-6);
//! assert_eq!(car.regime(), Regime::Underdamped);
//! ```

use crate::complex::Complex;
use crate::error::{finite, non_negative, positive, ModelError};
use crate::regime::Regime;

/// `a·y'' + b·y' + c·y = f(t)` with `a > 0` and `b`, `c` any finite reals.
///
/// `b < 0` is negative damping (flutter); `c ≤ 0` has no restoring force (neutral) or a
/// destabilising one (divergent). Fields are private so that every value of this type has
/// passed [`SecondOrder::new`]'s checks.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SecondOrder {
    a: f64,
    b: f64,
    c: f64,
}

/// Largest ratio between coefficients the solver accepts: beyond it, `ω_n` or `α`
/// would overflow or lose all precision in double precision.
const MAX_RATIO: f64 = 1e150;

impl SecondOrder {
    /// `a·y'' + b·y' + c·y = f(t)`. Errors if `a ≤ 0` or any coefficient is not finite.
    pub fn new(a: f64, b: f64, c: f64) -> Result<Self, ModelError> {
        let a = positive("inertia a", "(unit of a)", a)?;
        let b = finite("damping b", "(unit of b)", b)?;
        let c = finite("stiffness c", "(unit of c)", c)?;
        if (b / a).abs() > MAX_RATIO || (c / a).abs() > MAX_RATIO {
            return Err(ModelError::OutOfRange {
                name: "b/a or c/a",
                reason: "coefficient ratio beyond 1e150",
            });
        }
        Ok(Self { a, b, c })
    }

    /// Normalised form `x'' + 2ζω_n·x' + ω_n²·x = f(t)`: `a = 1`, `b = 2ζω_n` \[1/s\],
    /// `c = ω_n²` \[1/s²\]. `ω_n > 0` in rad/s; `ζ` any finite real (negative is negative damping).
    pub fn from_natural(wn: f64, zeta: f64) -> Result<Self, ModelError> {
        let wn = positive("natural frequency ω_n", "rad/s", wn)?;
        let zeta = finite("damping ratio ζ", "", zeta)?;
        Self::new(1.0, 2.0 * zeta * wn, wn * wn)
    }

    /// Quarter-car corner: sprung mass `m` \[kg\] > 0, damper rate `c` \[N·s/m\] ≥ 0 (negative
    /// values model an energy source), spring rate `k` \[N/m\].
    pub fn mechanical(m: f64, c: f64, k: f64) -> Result<Self, ModelError> {
        let m = positive("mass m", "kg", m)?;
        let c = finite("damping c", "N·s/m", c)?;
        let k = finite("stiffness k", "N/m", k)?;
        Self::new(m, c, k)
    }

    /// Series RLC loop, in the charge `q`: `L·q'' + R·q' + q/C = E(t)`, with inductance
    /// `l` \[H\] > 0, resistance `r` \[Ω\] ≥ 0 and capacitance `cap` \[F\] > 0.
    pub fn electrical(l: f64, r: f64, cap: f64) -> Result<Self, ModelError> {
        let l = positive("inductance L", "H", l)?;
        let r = non_negative("resistance R", "Ω", r)?;
        let cap = positive("capacitance C", "F", cap)?;
        Self::new(l, r, 1.0 / cap)
    }

    /// The inertia coefficient `a`, of `y''`: mass m \[kg\] for the quarter car, inductance
    /// L \[H\] for the RLC loop.
    pub fn inertia(&self) -> f64 {
        self.a
    }

    /// The damping coefficient `b`, of `y'`: damper rate c \[N·s/m\] for the quarter car
    /// (the `c` of [`SecondOrder::mechanical`]), resistance R \[Ω\] for the RLC loop.
    pub fn damping(&self) -> f64 {
        self.b
    }

    /// The stiffness coefficient `c`, of `y`: spring rate k \[N/m\] for the quarter car
    /// (not the damper's `c`), elastance 1/C \[1/F\] for the RLC loop.
    pub fn stiffness(&self) -> f64 {
        self.c
    }

    /// The mechanical reading `(m [kg], c [N·s/m], k [N/m])` of the coefficients.
    pub fn as_mechanical(&self) -> (f64, f64, f64) {
        (self.a, self.b, self.c)
    }

    /// The electrical reading `(L [H], R [Ω], C [F])` of the coefficients (force-voltage
    /// analogy m↔L, c↔R, k↔1/C). `None` when `c ≤ 0`, which no capacitor realises.
    pub fn as_electrical(&self) -> Option<(f64, f64, f64)> {
        (self.c > 0.0).then(|| (self.a, self.b, 1.0 / self.c))
    }

    /// Decay rate `α = b / (2a)` \[1/s\]; negative for negative damping.
    pub fn alpha(&self) -> f64 {
        self.b / (2.0 * self.a)
    }

    /// `ω_n² = c / a` \[1/s²\], defined (and possibly ≤ 0) for every system.
    pub fn omega_n_squared(&self) -> f64 {
        self.c / self.a
    }

    /// Undamped natural frequency `ω_n = √(c/a)` \[rad/s\]; `None` when `c ≤ 0`.
    pub fn natural_frequency(&self) -> Option<f64> {
        (self.c > 0.0).then(|| (self.c / self.a).sqrt())
    }

    /// Natural frequency in hertz, `f_n = ω_n / 2π` \[Hz\]; `None` when `c ≤ 0`.
    pub fn natural_frequency_hz(&self) -> Option<f64> {
        self.natural_frequency().map(|w| w / std::f64::consts::TAU)
    }

    /// Damping ratio `ζ = b / (2√(a·c))` \[-\]; `None` when `c ≤ 0`.
    pub fn damping_ratio(&self) -> Option<f64> {
        (self.c > 0.0).then(|| self.b / (2.0 * (self.a * self.c).sqrt()))
    }

    /// Damped natural frequency `ω_d = √(ω_n² − α²) = ω_n√(1 − ζ²)` \[rad/s\], for systems that
    /// oscillate (`ω_n² > α²`, any sign of damping); `None` otherwise.
    pub fn damped_frequency(&self) -> Option<f64> {
        let d = self.omega_n_squared() - self.alpha() * self.alpha();
        (d > 0.0 && self.regime() != Regime::CriticallyDamped).then(|| d.sqrt())
    }

    /// Quality factor `Q = 1/(2ζ) = √(a·c)/b` \[-\]; `None` unless `c > 0` and `b > 0`.
    pub fn quality_factor(&self) -> Option<f64> {
        (self.c > 0.0 && self.b > 0.0).then(|| (self.a * self.c).sqrt() / self.b)
    }

    /// Half-power bandwidth `Δω = b/a = 2ζω_n = ω_n/Q` \[rad/s\] of the *velocity* (for the
    /// RLC loop, *current*) resonance — exact for every ζ > 0: `|V(ω)|²` peaks at `ω_n` and
    /// falls to half its peak at two frequencies whose difference is `b/a`. Not the width of
    /// the displacement peak (see [`crate::frf::half_power_width`]). `None` unless `c > 0`
    /// and `b > 0`.
    pub fn velocity_half_power_bandwidth(&self) -> Option<f64> {
        (self.c > 0.0 && self.b > 0.0).then(|| self.b / self.a)
    }

    /// Critical damping coefficient `b_c = 2√(a·c)`: the damping that makes `ζ = 1`
    /// (N·s/m for the quarter car; for the RLC loop this is the critical resistance
    /// `2√(L/C)` in Ω). `None` when `c ≤ 0`.
    pub fn critical_damping(&self) -> Option<f64> {
        (self.c > 0.0).then(|| 2.0 * (self.a * self.c).sqrt())
    }

    /// The two poles (roots of `a·s² + b·s + c = 0`) \[1/s\]: a conjugate pair with the
    /// positive imaginary part first, or two reals with the larger (slower) first.
    pub fn poles(&self) -> [Complex; 2] {
        let alpha = self.alpha();
        let disc = alpha * alpha - self.omega_n_squared();
        if self.regime() == Regime::CriticallyDamped {
            return [Complex::real(-alpha); 2];
        }
        if disc < 0.0 {
            let wd = (-disc).sqrt();
            [Complex::new(-alpha, wd), Complex::new(-alpha, -wd)]
        } else {
            // Avoid cancellation: compute the larger-magnitude root first, the other from
            // the product of roots s1·s2 = c/a.
            let mu = disc.sqrt();
            let big = if alpha >= 0.0 {
                -alpha - mu
            } else {
                -alpha + mu
            };
            let small = if big != 0.0 {
                self.omega_n_squared() / big
            } else {
                0.0
            };
            let (hi, lo) = if small >= big {
                (small, big)
            } else {
                (big, small)
            };
            [Complex::real(hi), Complex::real(lo)]
        }
    }

    /// Time constants `τ = −1/Re(s)` \[s\] of the two poles, slowest first; `None` for a pole
    /// that does not decay (`Re(s) ≥ 0`).
    pub fn time_constants(&self) -> [Option<f64>; 2] {
        let p = self.poles();
        let tau = |s: Complex| (s.re < 0.0).then(|| -1.0 / s.re);
        [tau(p[0]), tau(p[1])]
    }

    /// The damping regime; see [`Regime`] for the tolerance at `ζ = 1` and `ζ = 0`.
    pub fn regime(&self) -> Regime {
        Regime::classify(self.c, self.damping_ratio())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::testing::variants;

    fn close(a: f64, b: f64, tol: f64) -> bool {
        (a - b).abs() <= tol * (1.0 + b.abs())
    }

    #[test]
    fn quarter_car_reference_values() {
        // m = 300 kg, k = 24 000 N/m: ω_n = √80 = 8.944272 rad/s, f_n = 1.4235 Hz.
        let s = SecondOrder::mechanical(300.0, 0.0, 24_000.0).unwrap();
        assert!(close(
            s.natural_frequency().unwrap(),
            8.944_271_909_999_16,
            1e-14
        ));
        assert!(close(s.natural_frequency_hz().unwrap(), 1.423_525, 1e-6));
        assert_eq!(s.regime(), Regime::Undamped);
        assert!(close(
            s.critical_damping().unwrap(),
            2.0 * (300.0f64 * 24_000.0).sqrt(),
            1e-15
        ));
    }

    #[test]
    fn rlc_reference_values() {
        // L = 0.5 H, C = 20 mF: ω_0 = 1/√(LC) = 10 rad/s, critical R = 2√(L/C) = 10 Ω.
        let s = SecondOrder::electrical(0.5, 4.0, 0.02).unwrap();
        assert!(close(s.natural_frequency().unwrap(), 10.0, 1e-14));
        assert!(close(s.critical_damping().unwrap(), 10.0, 1e-14));
        assert!(close(s.damping_ratio().unwrap(), 0.4, 1e-14));
        assert!(close(s.quality_factor().unwrap(), 1.25, 1e-14));
        assert!(close(
            s.velocity_half_power_bandwidth().unwrap(),
            8.0,
            1e-14
        ));
        assert!(close(s.alpha(), 4.0, 1e-15));
    }

    #[test]
    fn analogy_round_trips() {
        let mech = SecondOrder::mechanical(2.0, 3.0, 50.0).unwrap();
        let (l, r, cap) = mech.as_electrical().unwrap();
        let elec = SecondOrder::electrical(l, r, cap).unwrap();
        assert!(close(elec.stiffness(), mech.stiffness(), 1e-15));
        assert_eq!(
            (elec.inertia(), elec.damping()),
            (mech.inertia(), mech.damping())
        );
    }

    #[test]
    fn poles_satisfy_characteristic_equation() {
        for &(a, b, c) in &[
            (1.0, 0.2, 4.0),
            (1.0, 4.0, 4.0),
            (2.0, 100.0, 1.0),
            (1.0, -0.5, 9.0),
            (1.0, 1.0, -4.0),
            (1.0, 1e6, 1.0),
            (1.0, 1.0, 0.0),
        ] {
            let s = SecondOrder::new(a, b, c).unwrap();
            for p in s.poles() {
                let res = p * p * a + p * b + Complex::real(c);
                let scale = (a * p.abs() * p.abs())
                    .max(b.abs() * p.abs())
                    .max(c.abs())
                    .max(1e-300);
                assert!(
                    res.abs() / scale < 1e-12,
                    "{a} {b} {c}: {p:?} residual {res:?}"
                );
            }
        }
    }

    #[test]
    fn degenerate_inputs_are_typed_errors() {
        let bad = [
            SecondOrder::mechanical(0.0, 1.0, 1.0),
            SecondOrder::mechanical(f64::NAN, 1.0, 1.0),
            SecondOrder::electrical(1.0, -1.0, 1.0),
            SecondOrder::new(1e-200, 1.0, 1e200),
        ];
        let expected = ["NotPositive", "NotFinite", "Negative", "OutOfRange"];
        assert_eq!(variants(bad), expected);
        assert!(SecondOrder::from_natural(-1.0, 0.5).is_err());
        let msg = SecondOrder::mechanical(-3.0, 1.0, 1.0)
            .unwrap_err()
            .to_string();
        assert_eq!(msg, "mass m must be positive, got -3 kg");
    }
}
