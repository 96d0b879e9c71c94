//! Frequency response of the normalised system `x'' + 2ζω_n·x' + ω_n²·x = ω_n²·u(t)`:
//!
//! `H(r) = 1/(1 − r² + 2iζr)`, with frequency ratio `r = ω/ω_n` \[-\] and damping ratio `ζ` \[-\].
//!
//! `|H|` is the dynamic amplification of the displacement over its static value `F0/k`;
//! the phase is the lag of the displacement behind the force. Here the half-power points
//! are those of `|H|` (displacement); [`crate::SecondOrder::velocity_half_power_bandwidth`] is the
//! velocity-resonance bandwidth `2ζω_n`, which the two agree on to first order in ζ.
//! [`half_power_width`] is the two-sided width of the |H| peak (undefined once the lower
//! point reaches `r = 0`); [`displacement_half_power_band`] continues it one-sided, and past `ζ = 1/√2` it is
//! the −3 dB cut-off of a curve without a peak.
//!
//! ```
//! use zeta_solver::frf;
//! let zeta = 0.05;
//! assert!((frf::magnitude(1.0, zeta) - 10.0).abs() < 1e-12); // |H(1)| = 1/(2ζ)
//! let p = frf::peak(zeta).unwrap();
//! assert!((p.gain - 10.0125).abs() < 5e-5 && (p.ratio - 0.997497).abs() < 5e-7);
//! let grid = frf::logspace(0.1, 10.0, 3).unwrap();
//! assert_eq!((grid[0], grid[2]), (0.1, 10.0));
//! assert!((grid[1] - 1.0).abs() < 1e-15);
//! ```

use crate::complex::Complex;
use crate::error::{positive, ModelError};
use std::f64::consts::FRAC_PI_2;

/// Lowest value returned by [`magnitude_db`] \[dB\]: `|H| = 0` (which happens only when
/// `r²` overflows) is reported as this floor instead of `−∞`.
pub const DB_FLOOR: f64 = -400.0;

/// Highest value returned by [`magnitude_db`] \[dB\]: the infinite peak of the undamped
/// system (`ζ = 0`, `r = 1`) is reported as this ceiling instead of `+∞`.
pub const DB_CEILING: f64 = 400.0;

/// `1 − r²` computed as `(1 − r)(1 + r)`, accurate near `r = 1` where `1 − r·r` cancels.
fn one_minus_r2(r: f64) -> f64 {
    (1.0 - r) * (1.0 + r)
}

/// Complex frequency response `H(r) = 1/(1 − r² + 2iζr)` \[-\]. Non-finite at `ζ = 0, r = 1`.
pub fn response(r: f64, zeta: f64) -> Complex {
    Complex::new(one_minus_r2(r), 2.0 * zeta * r).recip()
}

/// Magnitude `|H(r)| = 1/√((1 − r²)² + (2ζr)²)` \[-\]. Equals 1 at `r = 0`, `1/(2|ζ|)` at
/// `r = 1` (`+∞` when `ζ = 0`), and tends to `1/r²` as `r → ∞`. Depends on ζ only through ζ².
pub fn magnitude(r: f64, zeta: f64) -> f64 {
    1.0 / one_minus_r2(r).hypot(2.0 * zeta * r)
}

/// Magnitude in decibels, `20·log10|H(r)|` \[dB\], clamped to \[[`DB_FLOOR`], [`DB_CEILING`]\] so
/// plots never receive infinities. NaN inputs give NaN.
pub fn magnitude_db(r: f64, zeta: f64) -> f64 {
    (20.0 * magnitude(r, zeta).log10()).clamp(DB_FLOOR, DB_CEILING)
}

/// Phase `arg H(r) = −atan2(2ζr, 1 − r²)` \[rad\] for `r ≥ 0`.
///
/// For `ζ ≥ 0` it lies in `[−π, 0]` and is continuous in `r` (the denominator's imaginary
/// part `2ζr` never changes sign, so atan2 never wraps): 0 at `r = 0`, `−π/2` at `r = 1`,
/// → `−π` as `r → ∞`. At `ζ = 0` it jumps from 0 to `−π` through `r = 1`, where `−π/2` (the
/// limit `ζ → 0⁺`) is returned. For `ζ < 0` it is the mirror image, in `[0, π]` (a lead).
pub fn phase(r: f64, zeta: f64) -> f64 {
    let re = one_minus_r2(r);
    // `+ 0.0` turns −0 into +0, so ζ = −0 behaves like ζ = 0 (atan2 looks at the sign of 0).
    let im = 2.0 * zeta * r + 0.0;
    if re == 0.0 && im == 0.0 {
        return -FRAC_PI_2;
    }
    -im.atan2(re)
}

/// Fills `out[i] = |H(r[i])|` (pairs beyond the shorter slice are left alone). No allocation.
pub fn magnitude_into(r: &[f64], zeta: f64, out: &mut [f64]) {
    for (o, &ri) in out.iter_mut().zip(r) {
        *o = magnitude(ri, zeta);
    }
}

/// Fills `out[i] = 20·log10|H(r[i])|` (clamped, see [`magnitude_db`]). No allocation.
pub fn magnitude_db_into(r: &[f64], zeta: f64, out: &mut [f64]) {
    for (o, &ri) in out.iter_mut().zip(r) {
        *o = magnitude_db(ri, zeta);
    }
}

/// Fills `out[i] = arg H(r[i])` \[rad\] (see [`phase`]). No allocation.
pub fn phase_into(r: &[f64], zeta: f64, out: &mut [f64]) {
    for (o, &ri) in out.iter_mut().zip(r) {
        *o = phase(ri, zeta);
    }
}

/// The maximum of a frequency-response magnitude over `r ≥ 0`, e.g. of `|H|` ([`peak`]) or
/// of the transmissibility ([`crate::base::peak_transmissibility`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Peak {
    /// Frequency ratio of the maximum `r_p` \[-\]; for `|H|`, `√(1 − 2ζ²)` when
    /// `0 < ζ < 1/√2`, else 0.
    pub ratio: f64,
    /// The maximum \[-\]; for `|H|`, `1/(2ζ√(1 − ζ²))` when `0 < ζ < 1/√2`, else 1.
    pub gain: f64,
}

/// `Some(ζ)` for a damping ratio that gives a finite peak, `ζ > 0`; `None` for `ζ ≤ 0`
/// (infinite peak at `ζ = 0`; no steady state at all for `ζ < 0`) or NaN.
pub(crate) fn damped(zeta: f64) -> Option<f64> {
    (zeta > 0.0).then_some(zeta)
}

/// The maximum of `|H|` over `r ≥ 0`: at `r_p = √(1 − 2ζ²)` with gain `1/(2ζ√(1−ζ²))` when
/// `0 < ζ < 1/√2`; at `r = 0` with gain 1 when `ζ ≥ 1/√2` (the curve only falls).
/// `None` for `ζ ≤ 0` (infinite peak at `ζ = 0`; no steady state at all for `ζ < 0`) or NaN.
pub fn peak(zeta: f64) -> Option<Peak> {
    let zeta = damped(zeta)?;
    let z2 = zeta * zeta;
    Some(if 2.0 * z2 < 1.0 {
        Peak {
            ratio: (1.0 - 2.0 * z2).sqrt(),
            gain: 1.0 / (2.0 * zeta * (1.0 - z2).sqrt()),
        }
    } else {
        Peak {
            ratio: 0.0,
            gain: 1.0,
        }
    })
}

/// The frequency ratios where `|H|` has fallen to `peak gain/√2` (−3 dB from the peak).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HalfPowerPoints {
    /// Lower point \[-\]; `None` when `|H|` stays above the level down to `r = 0`
    /// (`ζ > sin(π/8) ≈ 0.3827`).
    pub lower: Option<f64>,
    /// Upper point \[-\].
    pub upper: f64,
}

/// Half-power points of `|H|`: with `s = r²` and peak gain `G`, `|H|² = G²/2` is the
/// quadratic `s² − 2(1 − 2ζ²)s + 1 − 2/G² = 0`. With a resonant peak (`ζ < 1/√2`) its roots
/// are `s = 1 − 2ζ² ± 2ζ√(1 − ζ²)`; the lower one is positive only for
/// `ζ < sin(π/8) ≈ 0.382683` (it is taken as product/upper to avoid cancellation). For
/// `ζ ≥ 1/√2` (`G = 1`) only `s = 1/(B + √(B² + 1))`, `B = 2ζ² − 1`, is positive.
/// `None` for `ζ ≤ 0` or NaN (see [`peak`]).
pub fn half_power_points(zeta: f64) -> Option<HalfPowerPoints> {
    peak(zeta)?;
    let z2 = zeta * zeta;
    if 2.0 * z2 < 1.0 {
        let root = 2.0 * zeta * (1.0 - z2).sqrt();
        let s_upper = (1.0 - 2.0 * z2) + root;
        let product = 1.0 - 2.0 * root * root; // 1 − 2/G² = 1 − 8ζ²(1 − ζ²)
        Some(HalfPowerPoints {
            lower: (product >= 0.0).then(|| (product / s_upper).sqrt()),
            upper: s_upper.sqrt(),
        })
    } else {
        let b = 2.0 * z2 - 1.0;
        Some(HalfPowerPoints {
            lower: None,
            upper: (1.0 / (b + b.hypot(1.0))).sqrt(),
        })
    }
}

/// The displacement's half-power band as a frequency ratio, `r_upper − r_lower` \[-\], with
/// `r_lower = 0` when there is no lower point (the band then starts at DC; the value is
/// continuous in ζ, and past `ζ = 1/√2` it is the −3 dB cut-off `r_upper`).
/// For small ζ it equals `2ζ + 2ζ³ + O(ζ⁴)`, i.e. `1/Q` with relative error ≈ ζ².
/// `None` for `ζ ≤ 0` or NaN.
pub fn displacement_half_power_band(zeta: f64) -> Option<f64> {
    let p = half_power_points(zeta)?;
    Some(p.upper - p.lower.unwrap_or(0.0))
}

/// Width of the resonant peak of the displacement response between its two half-power
/// points, `r₂ − r₁` \[-\], where `|H(r₁)| = |H(r₂)| = |H|max/√2` and `r₁ < r_p < r₂`:
/// `r₁,₂² = 1 − 2ζ² ∓ 2ζ√(1 − ζ²)`. For light damping it is `2ζ + 2ζ³ + O(ζ⁵)` (so ≈ `1/Q`).
///
/// Defined only while the peak has both half-power points: `0 < ζ < sin(π/8) ≈ 0.3827`.
/// Above that `|H|` stays above `|H|max/√2` all the way down to `r = 0` (the peak is
/// one-sided), and above `ζ = 1/√2` there is no peak at all; `None` then, as for `ζ ≤ 0`.
/// Unlike [`displacement_half_power_band`], which continues past `ζ = 0.3827` with `r₁ = 0` (and becomes the
/// −3 dB cut-off of a low-pass curve past `1/√2`), this is always a two-sided peak width.
pub fn half_power_width(zeta: f64) -> Option<f64> {
    let p = half_power_points(zeta)?;
    if 2.0 * zeta * zeta >= 1.0 {
        return None;
    }
    p.lower.filter(|&l| l > 0.0).map(|lower| p.upper - lower)
}

/// Half-power bandwidth in rad/s, `ω_n·(r_upper − r_lower)`, for a natural frequency
/// `wn` \[rad/s\]. `None` for `ζ ≤ 0`, or when `wn` is not finite and positive.
pub fn displacement_half_power_band_rad_s(zeta: f64, wn: f64) -> Option<f64> {
    let wn = positive("natural frequency ω_n", "rad/s", wn).ok()?;
    displacement_half_power_band(zeta).map(|b| b * wn)
}

/// Quality factor `Q = 1/(2ζ)` \[-\]; `None` for `ζ ≤ 0` or NaN. `Q ≈ 1/bandwidth` for light
/// damping, and `Q = |H(1)|`.
pub fn quality_factor(zeta: f64) -> Option<f64> {
    (zeta > 0.0).then(|| 1.0 / (2.0 * zeta))
}

/// `n` points from `r_min` to `r_max` (both included exactly) evenly spaced in `log r`,
/// for Bode plots. `n = 0` gives an empty grid and `n = 1` gives `[r_min]`. Errors unless
/// both bounds are finite and positive. Descending grids (`r_min > r_max`) are allowed.
pub fn logspace(r_min: f64, r_max: f64, n: usize) -> Result<Vec<f64>, ModelError> {
    let mut out = vec![0.0; n];
    logspace_into(r_min, r_max, &mut out)?;
    Ok(out)
}

/// Allocation-free [`logspace`]: fills all of `out` (its length is the number of points).
/// On error `out` is left untouched.
pub fn logspace_into(r_min: f64, r_max: f64, out: &mut [f64]) -> Result<(), ModelError> {
    let lo = positive("lowest frequency ratio r_min", "(ratio)", r_min)?;
    let hi = positive("highest frequency ratio r_max", "(ratio)", r_max)?;
    let n = out.len();
    let (l0, l1) = (lo.ln(), hi.ln());
    let step = if n > 1 {
        (l1 - l0) / (n - 1) as f64
    } else {
        0.0
    };
    for (i, o) in out.iter_mut().enumerate() {
        *o = (l0 + step * i as f64).exp();
    }
    if let Some(first) = out.first_mut() {
        *first = lo;
    }
    if n > 1 {
        if let Some(last) = out.last_mut() {
            *last = hi;
        }
    }
    Ok(())
}

/// `n` frequency ratios from `r_min` to `r_max` (both included), symmetric in `log r` about
/// the geometric mean `r_c = √(r_min·r_max)` and crowded there:
/// `ln r_i = ln r_c + h·sinh(B·u_i)/sinh(B)` with `h = ½·ln(r_max/r_min)` and `u_i` evenly
/// spaced over −1…1. The stretch `B > 0` sets the crowding: the spacing in `log r` at the
/// centre is `B/sinh(B)` times that of [`logspace`] (≈ 0.067 for `B = 5`), so a narrow
/// resonance peak at `r_c = 1` gets dozens of points while the ends stay covered; `B → 0`
/// tends to [`logspace`]. Values are clamped into `[r_min, r_max]` against rounding.
/// Errors unless both bounds are finite and positive and `B` is finite and positive;
/// `n < 2` gives two points.
pub fn stretched_logspace(
    r_min: f64,
    r_max: f64,
    n: usize,
    stretch: f64,
) -> Result<Vec<f64>, ModelError> {
    let lo = positive("lowest frequency ratio r_min", "(ratio)", r_min)?;
    let hi = positive("highest frequency ratio r_max", "(ratio)", r_max)?;
    let b = positive("grid stretch B", "", stretch)?;
    let half = (hi / lo).ln() / 2.0;
    let centre = (lo * hi).sqrt().ln();
    let n = n.max(2);
    let (lower, upper) = (lo.min(hi), lo.max(hi));
    Ok((0..n)
        .map(|i| {
            let u = -1.0 + 2.0 * i as f64 / (n - 1) as f64;
            (centre + half * (b * u).sinh() / b.sinh()).exp()
        })
        .map(|r| r.clamp(lower, upper))
        .collect())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn response_matches_magnitude_and_phase() {
        for &(r, z) in &[
            (0.3, 0.1),
            (1.0, 0.05),
            (2.5, 0.7),
            (0.999, 0.01),
            (4.0, -0.2),
        ] {
            let h = response(r, z);
            assert!((h.abs() - magnitude(r, z)).abs() < 1e-14 * h.abs());
            assert!((h.arg() - phase(r, z)).abs() < 1e-14);
        }
    }

    #[test]
    fn undamped_resonance_is_clamped_in_db() {
        assert_eq!(magnitude(1.0, 0.0), f64::INFINITY);
        assert_eq!(magnitude_db(1.0, 0.0), DB_CEILING);
        assert_eq!(magnitude_db(1e300, 0.1), DB_FLOOR);
        assert_eq!(phase(1.0, 0.0), -FRAC_PI_2);
        assert_eq!(phase(2.0, -0.0), -std::f64::consts::PI);
    }

    #[test]
    fn logspace_rejects_bad_bounds() {
        assert!(matches!(
            logspace(0.0, 1.0, 5),
            Err(ModelError::NotPositive { .. })
        ));
        assert!(matches!(
            logspace(-1.0, 1.0, 5),
            Err(ModelError::NotPositive { .. })
        ));
        assert!(matches!(
            logspace(0.1, f64::INFINITY, 5),
            Err(ModelError::NotFinite { .. })
        ));
        assert!(matches!(
            logspace(f64::NAN, 1.0, 5),
            Err(ModelError::NotFinite { .. })
        ));
        assert_eq!(logspace(0.5, 8.0, 1).unwrap(), vec![0.5]);
        assert!(logspace(0.5, 8.0, 0).unwrap().is_empty());
    }
}
