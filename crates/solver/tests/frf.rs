#![cfg(not(target_arch = "wasm32"))]
//! Frequency response H(r) = 1/(1 − r² + 2iζr): reference values, limits, peak, half-power
//! points, bandwidth and Q, log grids.

use proptest::prelude::*;
use std::f64::consts::{FRAC_1_SQRT_2, FRAC_PI_2, PI};
use zeta_solver::frf;

#[test]
fn peak_reference_values_to_the_digits_given() {
    // ζ = 0.05: peak gain 10.0125 at r = 0.997497 (textbook values, e.g. Rao, Mechanical
    // Vibrations, §3.4: r_p = √(1 − 2ζ²), gain 1/(2ζ√(1 − ζ²))). Tolerance: half a unit in
    // the last digit given.
    let p = frf::peak(0.05).unwrap();
    assert!((p.gain - 10.0125).abs() < 5e-5, "{}", p.gain);
    assert!((p.ratio - 0.997497).abs() < 5e-7, "{}", p.ratio);
    // The peak really is the maximum of |H| on a fine grid around it.
    for i in 0..=2000 {
        let r = 0.99 + i as f64 * 1e-5;
        assert!(frf::magnitude(r, 0.05) <= p.gain * (1.0 + 1e-15));
    }
    assert!((frf::magnitude(p.ratio, 0.05) - p.gain).abs() < 1e-13 * p.gain);
}

#[test]
fn near_one_over_root_two_the_peak_is_at_low_ratio_with_gain_near_one() {
    // ζ = 0.707 is just below 1/√2 = 0.70711: the peak still exists, at
    // r_p = √(1 − 2·0.707²) = 0.0173781 with gain 1 + 4.5602e-8 (values computed from the
    // closed forms above). It is "at r ≈ 0" only in the sense of the plot.
    let p = frf::peak(0.707).unwrap();
    assert!((p.ratio - 0.017_378_147).abs() < 1e-9, "{}", p.ratio);
    assert!((p.gain - 1.000_000_045_602).abs() < 1e-12, "{}", p.gain);
    // At and beyond 1/√2 the maximum is |H(0)| = 1.
    for z in [FRAC_1_SQRT_2 + 1e-12, 0.8, 3.0] {
        assert_eq!(
            frf::peak(z),
            Some(frf::Peak {
                ratio: 0.0,
                gain: 1.0
            })
        );
        assert!(frf::magnitude(0.01, z) < 1.0);
    }
    assert!(frf::peak(0.0).is_none() && frf::peak(-0.1).is_none() && frf::peak(f64::NAN).is_none());
}

#[test]
fn magnitude_limits_and_resonance() {
    for &z in &[0.01, 0.05, 0.3, 1.0, 5.0] {
        assert_eq!(frf::magnitude(0.0, z), 1.0);
        assert!((frf::magnitude(1.0, z) - 1.0 / (2.0 * z)).abs() < 1e-15 / z);
        assert!((frf::phase(1.0, z) + FRAC_PI_2).abs() < 1e-15);
        // |H| ~ 1/r² as r → ∞: r²|H| = 1/√((1 − 1/r²)² + (2ζ/r)²) → 1, error O(ζ²/r² + 1/r²).
        let r = 1e4;
        assert!((frf::magnitude(r, z) * r * r - 1.0).abs() < 2.0 * (1.0 + 2.0 * z * z) / (r * r));
    }
}

#[test]
fn phase_is_a_continuous_lag_for_positive_damping() {
    for &z in &[1e-3, 0.05, 0.7, 2.0] {
        let mut prev = frf::phase(0.0, z);
        assert_eq!(prev, 0.0);
        for i in 1..=4000 {
            let r = i as f64 * 0.005;
            let p = frf::phase(r, z);
            assert!((-PI..=0.0).contains(&p), "ζ={z} r={r}: {p}");
            assert!(p <= prev, "phase must fall monotonically");
            // Largest jump for ζ = 1e-3 near r = 1: dφ/dr = 1/ζ there, times the step 0.005
            // gives 5 rad if discontinuous; a continuous curve stays under π.
            assert!(prev - p < PI, "ζ={z} r={r}");
            prev = p;
        }
    }
    // Negative damping: the mirror image, a lead in [0, π].
    assert!((frf::phase(2.0, -0.1) - (-frf::phase(2.0, 0.1))).abs() < 1e-15);
}

#[test]
fn decibels_match_the_magnitude() {
    for &(r, z) in &[(0.5, 0.1), (1.0, 0.05), (10.0, 0.2)] {
        let db = frf::magnitude_db(r, z);
        assert!(
            (10f64.powf(db / 20.0) - frf::magnitude(r, z)).abs() < 1e-12 * frf::magnitude(r, z)
        );
    }
    // |H(1)| at ζ = 0.05 is 10 → exactly 20 dB.
    assert!((frf::magnitude_db(1.0, 0.05) - 20.0).abs() < 1e-12);
}

#[test]
fn half_power_points_sit_three_db_below_the_peak() {
    for &z in &[
        0.001,
        0.05,
        0.2,
        0.38,
        0.383,
        0.5,
        0.7,
        FRAC_1_SQRT_2,
        1.0,
        10.0,
    ] {
        let hp = frf::half_power_points(z).unwrap();
        let level = frf::peak(z).unwrap().gain / 2f64.sqrt();
        assert!(
            (frf::magnitude(hp.upper, z) - level).abs() < 1e-12 * level,
            "ζ={z}"
        );
        if let Some(lo) = hp.lower {
            assert!(
                (frf::magnitude(lo, z) - level).abs() < 1e-12 * level,
                "ζ={z}"
            );
            assert!(lo < hp.upper);
        }
        // A lower point exists exactly when ζ < sin(π/8) = 0.3826834.
        assert_eq!(hp.lower.is_some(), z < (PI / 8.0).sin(), "ζ={z}");
    }
    assert!(frf::half_power_points(0.0).is_none());
}

#[test]
fn bandwidth_is_continuous_where_the_lower_point_disappears() {
    let s = (PI / 8.0).sin();
    let below = frf::displacement_half_power_band(s - 1e-9).unwrap();
    let above = frf::displacement_half_power_band(s + 1e-9).unwrap();
    // d(bw)/dζ is finite away from the lower point's √ branch; 1e-4 covers the √(Δζ) term.
    assert!((below - above).abs() < 1e-4, "{below} {above}");
    assert!(
        (frf::displacement_half_power_band_rad_s(0.05, 8.0).unwrap()
            - 8.0 * frf::displacement_half_power_band(0.05).unwrap())
        .abs()
            < 1e-15
    );
    assert!(frf::displacement_half_power_band_rad_s(0.05, -1.0).is_none());
}

#[test]
fn bandwidth_approximates_inverse_q_with_error_of_order_zeta_squared() {
    // Exact bandwidth = 2ζ + 2ζ³ + O(ζ⁴) (series of √s± about s = 1), so the relative error of
    // 1/Q is ζ²·(1 + O(ζ)): the ratio below tends to 1 (1.0365 at ζ = 0.1, 1.00035 at 0.01).
    let mut prev = f64::INFINITY;
    for &z in &[0.1, 0.03, 0.01, 0.003, 0.001] {
        let bw = frf::displacement_half_power_band(z).unwrap();
        let inv_q = 1.0 / frf::quality_factor(z).unwrap();
        let rel = (bw - inv_q) / inv_q;
        let ratio = rel / (z * z);
        assert!((1.0..1.04).contains(&ratio), "ζ={z}: {ratio}");
        assert!(ratio < prev, "must approach 1 monotonically");
        prev = ratio;
    }
    assert_eq!(frf::quality_factor(0.05), Some(10.0));
    assert!(frf::quality_factor(0.0).is_none());
}

#[test]
fn logspace_is_geometric_with_exact_ends() {
    let g = frf::logspace(0.01, 100.0, 41).unwrap();
    assert_eq!((g[0], g[40]), (0.01, 100.0));
    for w in g.windows(2) {
        assert!((w[1] / w[0] - 10f64.powf(0.1)).abs() < 1e-13);
    }
    let mut buf = [0.0; 5];
    frf::logspace_into(1.0, 16.0, &mut buf).unwrap();
    for (b, want) in buf.iter().zip([1.0, 2.0, 4.0, 8.0, 16.0]) {
        assert!((b - want).abs() < 1e-14 * want);
    }
    let mut untouched = [7.0; 3];
    assert!(frf::logspace_into(0.0, 1.0, &mut untouched).is_err());
    assert_eq!(untouched, [7.0; 3]);
}

#[test]
fn into_variants_match_scalar_functions() {
    let r = frf::logspace(0.1, 10.0, 7).unwrap();
    let (mut m, mut d, mut p) = ([0.0; 7], [0.0; 7], [0.0; 7]);
    frf::magnitude_into(&r, 0.2, &mut m);
    frf::magnitude_db_into(&r, 0.2, &mut d);
    frf::phase_into(&r, 0.2, &mut p);
    for i in 0..7 {
        assert_eq!(m[i], frf::magnitude(r[i], 0.2));
        assert_eq!(d[i], frf::magnitude_db(r[i], 0.2));
        assert_eq!(p[i], frf::phase(r[i], 0.2));
    }
}

proptest! {
    #[test]
    fn magnitude_is_even_in_zeta_and_never_nan(r in 0.0f64..1e6, z in -10.0f64..10.0) {
        let m = frf::magnitude(r, z);
        prop_assert!(!m.is_nan());
        prop_assert_eq!(m, frf::magnitude(r, -z));
        let db = frf::magnitude_db(r, z);
        prop_assert!(db.is_finite() && (frf::DB_FLOOR..=frf::DB_CEILING).contains(&db));
    }

    #[test]
    fn peak_bounds_the_magnitude(z in 1e-3f64..5.0, r in 0.0f64..20.0) {
        let g = frf::peak(z).unwrap().gain;
        prop_assert!(frf::magnitude(r, z) <= g * (1.0 + 1e-14));
    }
}

#[test]
fn stretched_logspace_ends_exactly_and_crowds_at_the_centre() {
    let g = frf::stretched_logspace(0.1, 10.0, 801, 5.0).unwrap();
    assert_eq!(g.len(), 801);
    assert!((g[0] - 0.1).abs() < 1e-15 && (g[800] - 10.0).abs() < 1e-14);
    assert!(g.windows(2).all(|w| w[1] > w[0]));
    // Symmetric in log r about r = 1: r_i·r_{n−1−i} = 1.
    for i in 0..401 {
        assert!((g[i] * g[800 - i] - 1.0).abs() < 1e-13, "{i}");
    }
    assert!((g[400] - 1.0).abs() < 1e-15);
    // Spacing in ln r at the centre: h·sinh(B·Δu)/sinh(B) with h = ln 10, Δu = 1/400,
    // i.e. about B/sinh B times the even spacing.
    let centre = g[401].ln() - g[400].ln();
    let expect = 10f64.ln() * (5.0f64 / 400.0).sinh() / 5f64.sinh();
    assert!(
        (centre - expect).abs() < 1e-12 * expect,
        "{centre} vs {expect}"
    );
    let near = g.iter().filter(|r| (**r - 1.0).abs() < 0.01).count();
    assert!(near >= 30, "{near} points within ±0.01 of r = 1");
    // A small stretch tends to the plain log grid.
    let flat = frf::stretched_logspace(0.1, 10.0, 5, 1e-6).unwrap();
    let log = frf::logspace(0.1, 10.0, 5).unwrap();
    for (a, b) in flat.iter().zip(&log) {
        assert!((a - b).abs() < 1e-9 * b);
    }
    assert!(frf::stretched_logspace(0.0, 10.0, 5, 5.0).is_err());
    assert!(frf::stretched_logspace(0.1, 10.0, 5, -1.0).is_err());
    assert!(frf::stretched_logspace(0.1, 10.0, 5, f64::NAN).is_err());
}

#[test]
fn half_power_width_is_two_sided_and_undefined_without_a_lower_point() {
    for &z in &[0.001, 0.01, 0.05, 0.1, 0.2, 0.3, 0.38] {
        let w = frf::half_power_width(z).unwrap();
        let s = (1.0f64 - z * z).sqrt();
        let (hi, lo) = (
            (1.0 - 2.0 * z * z + 2.0 * z * s).sqrt(),
            (1.0 - 2.0 * z * z - 2.0 * z * s).sqrt(),
        );
        assert!((w - (hi - lo)).abs() < 1e-12, "ζ = {z}");
        // Both ends sit at the peak gain over √2.
        let level = frf::peak(z).unwrap().gain * FRAC_1_SQRT_2;
        for r in [lo, hi] {
            assert!(
                (frf::magnitude(r, z) / level - 1.0).abs() < 1e-9,
                "ζ = {z}, r = {r}"
            );
        }
        // 2ζ + 2ζ³ + O(ζ⁵): within 0.1·ζ³ of the two-term series up to ζ = 0.1.
        if z <= 0.1 {
            assert!(
                (w - 2.0 * z - 2.0 * z.powi(3)).abs() < 0.1 * z.powi(3),
                "ζ = {z}"
            );
        }
        // Where both points exist it agrees with the continued `bandwidth`.
        assert!((w - frf::displacement_half_power_band(z).unwrap()).abs() < 1e-15);
    }
    // One-sided peak (0.3827 < ζ < 1/√2), no peak (ζ ≥ 1/√2), no steady state (ζ ≤ 0).
    for z in [
        0.383,
        0.5,
        0.7,
        FRAC_1_SQRT_2,
        0.8,
        2.0,
        0.0,
        -0.1,
        f64::NAN,
    ] {
        assert_eq!(frf::half_power_width(z), None, "ζ = {z}");
    }
    assert!(frf::half_power_width(0.3826).is_some());
}
