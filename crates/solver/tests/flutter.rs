//! Flutter model: the critical speed, the sign change of damping and growth, poles crossing
//! the imaginary axis, and the envelope ratio per period on either side of U_crit.

use std::f64::consts::TAU;
use zeta_solver::flutter::{FlutterConfig, FlutterModel, LocusPoint};
use zeta_solver::{Regime, SecondOrder};

fn bridge() -> FlutterModel {
    FlutterModel::tacoma_1940()
}

#[test]
fn preset_uses_the_historical_numbers() {
    // ≈ 0.2 Hz torsion and ≈ 42 mph (18.78 m/s) at failure: approximate published values.
    let b = bridge();
    assert!((b.config().omega / TAU - 0.2).abs() < 1e-15);
    let u = b.critical_speed().unwrap();
    assert!((u - 18.775_68).abs() < 1e-9, "{u}");
}

#[test]
fn effective_damping_vanishes_exactly_at_the_critical_speed() {
    for cfg in [
        FlutterConfig::tacoma_1940(),
        FlutterConfig {
            omega: 3.0,
            structural_damping: 0.02,
            aero_slope: 7e-4,
        },
        FlutterConfig {
            omega: 1.0,
            structural_damping: 0.3,
            aero_slope: 0.1,
        },
    ] {
        let m = FlutterModel::new(cfg).unwrap();
        let uc = m.critical_speed().unwrap();
        // U_crit = ζ_s/g carries one rounding; ζ_s − g·U_crit (one fused rounding) is then
        // at most ~1 ulp of ζ_s. Tolerance 2 ulp.
        assert!(m.effective_damping(uc).abs() <= 2.0 * f64::EPSILON * cfg.structural_damping);
        assert!(m.effective_damping(uc * (1.0 - 1e-12)) > 0.0);
        assert!(m.effective_damping(uc * (1.0 + 1e-12)) < 0.0);
        assert_eq!(m.effective_damping(0.0), cfg.structural_damping);
        assert_eq!(m.regime(uc).unwrap(), Regime::Undamped);
    }
}

#[test]
fn growth_rate_changes_sign_at_the_critical_speed_and_matches_the_poles() {
    let b = bridge();
    let uc = b.critical_speed().unwrap();
    assert!(b.growth_rate(uc * (1.0 - 1e-9)) < 0.0);
    assert!(b.growth_rate(uc * (1.0 + 1e-9)) > 0.0);
    assert!(b.growth_rate(uc).abs() < 1e-17);
    let w = b.config().omega;
    // σ = −ζ_eff·ω while |ζ_eff| < 1; beyond, the largest real pole. Cross-check against the
    // independent quadratic solve in SecondOrder::poles, from calm air to ζ_eff = −5.
    for &u in &[0.0, 5.0, 18.0, 19.0, 40.0, 3000.0, 3800.0, 3780.0, 22_600.0] {
        let sigma = b.growth_rate(u);
        let p = b.poles(u).unwrap();
        let max_re = p[0].re.max(p[1].re);
        assert!(
            (sigma - max_re).abs() < 1e-12 * (1.0 + max_re.abs()),
            "U={u}: {sigma} {max_re}"
        );
        let z = b.effective_damping(u);
        if z.abs() < 1.0 {
            assert!((sigma + z * w).abs() < 1e-15, "U={u}");
        }
    }
}

#[test]
fn poles_cross_the_imaginary_axis_at_the_critical_speed() {
    let b = bridge();
    let uc = b.critical_speed().unwrap();
    let w = b.config().omega;
    let at = b.poles(uc).unwrap();
    assert!(at[0].re.abs() < 1e-16 * w && (at[0].im - w).abs() < 1e-15 * w);
    // Root locus from calm to 2·U_crit: the poles stay on the circle |s| = ω (their product
    // is ω²) and the real part changes sign once, between the samples bracketing U_crit.
    let mut locus = [LocusPoint::default(); 100]; // no sample lands on U_crit
    b.root_locus_into(0.0, 2.0 * uc, &mut locus).unwrap();
    assert_eq!((locus[0].speed, locus[99].speed), (0.0, 2.0 * uc));
    let mut crossings = 0;
    for pair in locus.windows(2) {
        for p in pair[0].poles {
            assert!((p.abs() - w).abs() < 1e-14 * w);
        }
        let (a, c) = (pair[0].poles[0].re, pair[1].poles[0].re);
        if a < 0.0 && c >= 0.0 {
            crossings += 1;
            assert!(pair[0].speed < uc && uc <= pair[1].speed);
        }
    }
    assert_eq!(crossings, 1);
    let mut untouched = [LocusPoint::default(); 2];
    assert!(b.root_locus_into(-1.0, 10.0, &mut untouched).is_err());
    assert!(b
        .root_locus_into(0.0, f64::INFINITY, &mut untouched)
        .is_err());
    assert_eq!(untouched, [LocusPoint::default(); 2]);
}

#[test]
fn below_critical_the_twist_decays_above_it_grows_by_the_stated_ratio() {
    // For a free underdamped response x(t + T_d) = e^{−ζω T_d}·x(t) exactly, with
    // T_d = 2π/(ω√(1−ζ²)), i.e. ratio exp(−2πζ/√(1−ζ²)) per period. Tolerance 1e-11
    // (rounding in e^{−αt} and the phase over ~20 periods).
    let b = bridge();
    for &u in &[0.0, 10.0, 18.0, 20.0, 30.0, 60.0] {
        let z = b.effective_damping(u);
        let resp = b.response(u, 0.02, 0.0).unwrap();
        let td = TAU / b.damped_frequency(u).unwrap();
        let want = (-TAU * z / (1.0 - z * z).sqrt()).exp();
        for k in 0..20 {
            let t = 0.37 + k as f64 * td;
            let ratio = resp.displacement(t + td) / resp.displacement(t);
            assert!(
                (ratio - want).abs() < 1e-11 * want,
                "U={u} k={k}: {ratio} {want}"
            );
        }
        let grows = resp.displacement(0.37 + 20.0 * td).abs() > resp.displacement(0.37).abs();
        assert_eq!(grows, u > b.critical_speed().unwrap(), "U={u}");
        assert_eq!(
            b.regime(u).unwrap().is_stable(),
            u < b.critical_speed().unwrap(),
            "U={u}"
        );
    }
}

#[test]
fn the_mode_is_the_normalised_second_order_system() {
    let b = bridge();
    let s = b.system(25.0).unwrap();
    let w = b.config().omega;
    let want = SecondOrder::from_natural(w, b.effective_damping(25.0)).unwrap();
    assert_eq!(s, want);
    assert!(b.system(f64::NAN).is_err());
}

#[test]
fn the_envelope_bounds_the_twist_and_touches_it_each_half_period() {
    // θ = A·e^{σt}·cos(ω_d t − φ): |θ| ≤ envelope everywhere, equal at the extrema, which
    // fall half a damped period apart. Tolerance 1e-12 relative (rounding only).
    let b = bridge();
    for &u in &[5.0, 19.0, 30.0] {
        let theta0 = 0.03;
        let resp = b.response(u, theta0, 0.0).unwrap();
        for i in 0..2000 {
            let t = 0.05 * i as f64;
            let env = b.envelope(u, theta0, t);
            assert!(
                resp.displacement(t).abs() <= env * (1.0 + 1e-12),
                "U={u} t={t}"
            );
        }
        assert!((b.envelope(u, theta0, 0.0) - b.envelope_amplitude(u, theta0)).abs() < 1e-18);
        let ratio = b.envelope(u, theta0, 100.0) / b.envelope(u, theta0, 0.0);
        assert!((ratio - b.growth_factor(u, 100.0)).abs() < 1e-12 * ratio);
    }
}

#[test]
fn the_doubling_time_is_ln2_over_sigma_only_while_growing() {
    let b = bridge();
    assert_eq!(b.doubling_time(10.0), None);
    assert_eq!(b.doubling_time(b.critical_speed().unwrap()), None);
    let sigma = b.growth_rate(25.0);
    let td = b.doubling_time(25.0).unwrap();
    assert!((b.growth_factor(25.0, td) - 2.0).abs() < 1e-12);
    assert!((td * sigma - std::f64::consts::LN_2).abs() < 1e-15);
    assert!((b.torsional_period() - 5.0).abs() < 1e-12); // 0.2 Hz
}

#[test]
fn angles_and_rotations() {
    use zeta_solver::flutter::{degrees, radians, rotate};
    assert!((degrees(std::f64::consts::PI) - 180.0).abs() < 1e-12);
    assert!((radians(90.0) - std::f64::consts::FRAC_PI_2).abs() < 1e-15);
    let (x, y) = rotate((1.0, 0.0), radians(90.0));
    assert!(x.abs() < 1e-15 && (y - 1.0).abs() < 1e-15);
    // A rotation keeps lengths.
    let (x, y) = rotate((3.0, 4.0), 0.7);
    assert!((x * x + y * y - 25.0).abs() < 1e-12);
}
