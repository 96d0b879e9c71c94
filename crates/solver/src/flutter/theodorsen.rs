//! Theodorsen's function and the torsional flutter derivatives of a thin flat plate, the
//! closed-form reference for a streamlined (aerofoil-like) deck.
//!
//! # Theodorsen's function
//!
//! For a thin aerofoil of half-chord `b` \[m\] oscillating at `ω` \[rad/s\] in a flow `U`
//! \[m/s\], with reduced frequency `k = bω/U` \[-\], potential-flow theory (T. Theodorsen,
//! "General theory of aerodynamic instability and the mechanism of flutter", NACA Report
//! 496, 1935) gives the lag of the circulatory forces behind the motion as
//!
//! `C(k) = F(k) + i·G(k) = H₁⁽²⁾(k) / (H₁⁽²⁾(k) + i·H₀⁽²⁾(k))`,  `Hₙ⁽²⁾ = Jₙ − i·Yₙ`,
//!
//! with `Jₙ`, `Yₙ` the Bessel functions of the first and second kind. `C` runs from 1 at
//! `k = 0` (steady flow) to ½ as `k → ∞`; `G < 0` for all `k > 0`.
//!
//! Evaluated here from the Bessel functions, not from a rational approximation:
//! - `k ≤ 12`: `J₀`, `J₁`, `Y₀`, `Y₁` by their ascending series (Abramowitz & Stegun,
//!   *Handbook of Mathematical Functions*, 1964, eqs. 9.1.10–9.1.11), 60 terms;
//! - `k > 12`: Hankel's asymptotic expansion `Hₙ⁽²⁾(k) ≈ √(2/(πk))·e^{−iχₙ}·(Pₙ − i·Qₙ)`,
//!   `χₙ = k − nπ/2 − π/4` (A&S 9.2.5–9.2.10), summed while its terms shrink. The common
//!   factor cancels in the ratio, which leaves
//!   `C = (P₁ − iQ₁) / ((P₀ + P₁) − i(Q₀ + Q₁))`.
//!
//! Both branches agree with 30-digit values (mpmath 1.3 `besselj`/`bessely`) to better
//! than 10⁻¹⁰ (tests below).
//!
//! # Flat-plate flutter derivatives
//!
//! Theodorsen's moment about mid-chord on a plate twisting by `α = α₀·e^{iωt}` (no heave) is
//!
//! `M = −πρb⁴·α''/8 − πρUb³·α'/2 + πρUb²·C(k)·(U·α + b·α'/2)`.
//!
//! The first term is the apparent moment of inertia of the air, `πρb⁴/8`; it does not
//! depend on the wind, so it belongs to the still-air frequency `f₀` and is left out.
//! Writing the rest as Scanlan's `M = ½ρU²B²·[K·A₂*·B·α'/U + K²·A₃*·α]` with `B = 2b` and
//! `K = Bω/U = 2k` gives (the classical flat-plate values in this convention):
//!
//! `A₂*(K) = −π/(8K)·(1 − F − 4G/K)`,  `A₃*(K) = π/(2K²)·(F − K·G/4)`.
//!
//! `A₂* < 0` at every `K`: the wind only damps the twist of a flat plate. As `K → 0`,
//! `A₃* → π/(2K²)`, the quasi-steady moment slope `π/2` /rad about mid-chord.

use crate::complex::Complex;
use std::f64::consts::{FRAC_2_PI, FRAC_PI_2, FRAC_PI_8, PI, TAU};

/// Euler–Mascheroni constant `γ`.
const EULER_GAMMA: f64 = 0.577_215_664_901_532_9;
/// Largest argument evaluated by the ascending series; above it, Hankel's expansion.
pub const SERIES_LIMIT: f64 = 12.0;
/// Terms of the ascending series (the 60th term is below 10⁻⁵⁰ of the sum at `x = 12`).
const SERIES_TERMS: usize = 60;
/// Most terms of the asymptotic expansion.
const ASYMPTOTIC_TERMS: usize = 40;

/// `[J₀(x), J₁(x), Y₀(x), Y₁(x)]` for `0 < x ≤ 12` by the ascending series (A&S 9.1.10,
/// 9.1.11 with `ψ(m + 1) = −γ + Σ_{j ≤ m} 1/j`).
pub fn bessel_series(x: f64) -> [f64; 4] {
    let h = 0.5 * x;
    let step = -h * h;
    let (mut t0, mut t1) = (1.0, h); // (−x²/4)^m/(m!)², (x/2)(−x²/4)^m/(m!(m+1)!)
    let (mut j0, mut j1, mut s0, mut s1) = (0.0, 0.0, 0.0, 0.0);
    let mut psi = -EULER_GAMMA; // ψ(m + 1)
    for m in 0..SERIES_TERMS {
        let n = (m + 1) as f64;
        let psi_next = psi + 1.0 / n; // ψ(m + 2)
        j0 += t0;
        j1 += t1;
        s0 += psi * t0;
        s1 += (psi + psi_next) * t1;
        t0 *= step / (n * n);
        t1 *= step / (n * (n + 1.0));
        psi = psi_next;
    }
    let ln = h.ln();
    let y0 = FRAC_2_PI * (ln * j0 - s0);
    let y1 = -FRAC_2_PI / x + FRAC_2_PI * ln * j1 - s1 / PI;
    [j0, j1, y0, y1]
}

/// Hankel's `(Pₙ(x), Qₙ(x))` for order `n` (A&S 9.2.9–9.2.10), summed while the terms
/// shrink; meant for `x > 12`.
pub fn hankel_pq(n: u32, x: f64) -> (f64, f64) {
    let mu = 4.0 * f64::from(n * n);
    let (mut p, mut q) = (1.0, 0.0);
    let mut term = 1.0; // a_j/x^j with a_j = Π_{i ≤ j}(μ − (2i − 1)²)/(j!·8^j)
    let mut last = f64::INFINITY;
    for j in 1..=ASYMPTOTIC_TERMS {
        let odd = (2 * j - 1) as f64;
        term *= (mu - odd * odd) / (8.0 * j as f64 * x);
        if term.abs() >= last || term == 0.0 {
            break;
        }
        last = term.abs();
        // Signs: Q = a₁ − a₃ + a₅ …, P = 1 − a₂ + a₄ …
        let sign = if (j / 2) % 2 == 0 { 1.0 } else { -1.0 };
        if j % 2 == 1 {
            q += sign * term;
        } else {
            p += sign * term;
        }
    }
    (p, q)
}

/// Theodorsen's function `C(k) = F + iG` at reduced frequency `k = bω/U > 0` (see the
/// module doc). `None` for `k ≤ 0` or non-finite `k`.
pub fn theodorsen(k: f64) -> Option<Complex> {
    if !(k.is_finite() && k > 0.0) {
        return None;
    }
    let (num, den) = if k <= SERIES_LIMIT {
        let [j0, j1, y0, y1] = bessel_series(k);
        // H₁ = J₁ − iY₁; H₁ + iH₀ = (J₁ + Y₀) + i(J₀ − Y₁).
        (Complex::new(j1, -y1), Complex::new(j1 + y0, j0 - y1))
    } else {
        let (p0, q0) = hankel_pq(0, k);
        let (p1, q1) = hankel_pq(1, k);
        (Complex::new(p1, -q1), Complex::new(p0 + p1, -(q0 + q1)))
    };
    let c = num / den;
    (c.re.is_finite() && c.im.is_finite()).then_some(c)
}

/// `(A₂*, A₃*)` \[-\] of a thin flat plate twisting about mid-chord, at reduced velocity
/// `V_r = U/(fB) = 2π/K` (module doc): `A₂* = −π/(8K)·(1 − F − 4G/K)`,
/// `A₃* = π/(2K²)·(F − K·G/4)`, `C(K/2) = F + iG`. Both are 0 at `V_r = 0` (their limit);
/// `None` for a negative or non-finite `V_r`.
pub fn flat_plate(reduced_velocity: f64) -> Option<(f64, f64)> {
    if !(reduced_velocity.is_finite() && reduced_velocity >= 0.0) {
        return None;
    }
    if reduced_velocity == 0.0 {
        return Some((0.0, 0.0));
    }
    let big_k = TAU / reduced_velocity;
    let c = theodorsen(0.5 * big_k)?;
    let (f, g) = (c.re, c.im);
    let a2 = -FRAC_PI_8 / big_k * (1.0 - f - 4.0 * g / big_k);
    let a3 = FRAC_PI_2 / (big_k * big_k) * (f - 0.25 * big_k * g);
    (a2.is_finite() && a3.is_finite()).then_some((a2, a3))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `(x, J₀, J₁, Y₀, Y₁)` from mpmath 1.3 at 30 digits, rounded to 15.
    const BESSEL: [(f64, [f64; 4]); 5] = [
        (
            0.5,
            [
                0.938469807240813,
                0.242268457674874,
                -0.444518733506707,
                -1.47147239267024,
            ],
        ),
        (
            1.0,
            [
                0.765197686557967,
                0.440050585744934,
                0.088256964215677,
                -0.781212821300289,
            ],
        ),
        (
            2.0,
            [
                0.223890779141236,
                0.576724807756873,
                0.510375672649745,
                -0.107032431540938,
            ],
        ),
        (
            5.0,
            [
                -0.177596771314338,
                -0.327579137591465,
                -0.308517625249034,
                0.147863143391227,
            ],
        ),
        (
            10.0,
            [
                -0.245935764451348,
                0.0434727461688614,
                0.0556711672835994,
                0.249015424206954,
            ],
        ),
    ];

    /// `(k, F, G)` from mpmath 1.3 (`besselj`, `bessely` at 30 digits), rounded to 12.
    const THEODORSEN: [(f64, f64, f64); 9] = [
        (0.05, 0.909008997477, -0.130644389694),
        (0.1, 0.831924104965, -0.172302228734),
        (0.2, 0.727579921291, -0.188624212130),
        (0.5, 0.597936064250, -0.150709503163),
        (1.0, 0.539434871078, -0.100272902864),
        (11.9, 0.500437762873, -0.010472307726),
        (12.1, 0.500423521615, -0.010300223406),
        (20.0, 0.500155791262, -0.006243206957),
        (100.0, 0.500006249258, -0.001249945326),
    ];

    #[test]
    fn bessel_series_matches_high_precision_values() {
        // The alternating series cancels: terms reach ~10³ at x = 10, so ~10⁻¹³ absolute.
        for (x, want) in BESSEL {
            let got = bessel_series(x);
            for (g, w) in got.iter().zip(want) {
                assert!((g - w).abs() < 1e-12, "x = {x}: {got:?} vs {want:?}");
            }
        }
    }

    #[test]
    fn theodorsen_matches_high_precision_values_on_both_branches() {
        for (k, f, g) in THEODORSEN {
            let c = theodorsen(k).unwrap();
            assert!((c.re - f).abs() < 1e-10, "k = {k}: F = {} vs {f}", c.re);
            assert!((c.im - g).abs() < 1e-10, "k = {k}: G = {} vs {g}", c.im);
        }
        // The limits: C → 1 as k → 0, C → ½ as k → ∞; G < 0 throughout.
        let small = theodorsen(1e-6).unwrap();
        assert!((small.re - 1.0).abs() < 1e-5 && small.im < 0.0);
        for i in 1..400 {
            let k = 0.05 * i as f64;
            let c = theodorsen(k).unwrap();
            assert!(c.im < 0.0 && c.re > 0.5 && c.re < 1.0, "k = {k}: {c:?}");
        }
        assert!(theodorsen(0.0).is_none() && theodorsen(f64::NAN).is_none());
    }

    #[test]
    fn flat_plate_has_the_quasi_steady_limit_and_always_damps() {
        assert_eq!(flat_plate(0.0), Some((0.0, 0.0)));
        assert!(flat_plate(-1.0).is_none() && flat_plate(f64::INFINITY).is_none());
        for i in 1..=400 {
            let vr = 0.1 * i as f64;
            let (a2, a3) = flat_plate(vr).unwrap();
            assert!(a2 < 0.0 && a3 > 0.0, "V_r = {vr}: {a2} {a3}");
        }
        // K → 0: A₃*·K² → π/2 (F → 1, K·G → 0), slowly (G ~ k·ln k).
        let vr = 1e6;
        let big_k = TAU / vr;
        let (_, a3) = flat_plate(vr).unwrap();
        assert!((a3 * big_k * big_k / FRAC_PI_2 - 1.0).abs() < 1e-4);
    }
}
