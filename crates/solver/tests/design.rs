//! Design tools: ζ sweeps and their optimum, the quarter-car comfort metric, (k, c) maps,
//! Pareto fronts, sensitivity ranges and Monte Carlo.

// Helpers outside `#[test]` functions unwrap too: the whole file is test code.
#![cfg(test)]

use zeta_solver::design::sweep::{
    body_acceleration_rms, fastest_settling_zeta, iso_zeta_line_into, sweep_kc_into,
    sweep_zeta_into, KcMaps, KcSweepConfig, RoadInput, ZetaCurves, ZetaSweepConfig,
};
use zeta_solver::metrics::free::{settling_time, FreeMetrics};
use zeta_solver::metrics::SettlingBand;
use zeta_solver::{Complex, SecondOrder};

// ---------------------------------------------------------------- sweeps over ζ

fn brute_min(cfg: &ZetaSweepConfig, lo: f64, hi: f64, n: usize) -> (f64, f64) {
    let mut best = (f64::NAN, f64::INFINITY);
    for i in 0..n {
        let z = lo + (hi - lo) * i as f64 / (n - 1) as f64;
        let sys = SecondOrder::from_natural(cfg.wn, z).unwrap();
        if let Some(t) = settling_time(&sys, cfg.x0, cfg.v0, cfg.band) {
            if t < best.1 {
                best = (z, t);
            }
        }
    }
    best
}

#[test]
fn fastest_settling_zeta_matches_a_dense_brute_force_search() {
    // A dense search over 200 001 points finds a settling time no better than the refined
    // optimum, and its ζ lies within one dense step of it.
    let cases = [
        ZetaSweepConfig::release_from_rest(2.0),
        ZetaSweepConfig {
            band: SettlingBand::new(0.02).unwrap(),
            ..ZetaSweepConfig::release_from_rest(2.0)
        },
        ZetaSweepConfig {
            v0: 1.5,
            ..ZetaSweepConfig::release_from_rest(2.0)
        },
        ZetaSweepConfig {
            v0: -3.0,
            ..ZetaSweepConfig::release_from_rest(2.0)
        },
    ];
    let (lo, hi) = (0.2, 2.0);
    let n_dense = 200_001;
    let dense_step = (hi - lo) / (n_dense - 1) as f64;
    for cfg in &cases {
        let opt = fastest_settling_zeta(cfg, lo, hi, 100).unwrap();
        let (zb, tb) = brute_min(cfg, lo, hi, n_dense);
        assert!(
            opt.settling_time <= tb + 1e-12,
            "{cfg:?}: {opt:?} vs brute ({zb}, {tb})"
        );
        assert!(
            (opt.zeta - zb).abs() <= dense_step,
            "{cfg:?}: {opt:?} vs brute ({zb}, {tb})"
        );
        // And the reported time is the settling time at the reported ζ.
        let sys = SecondOrder::from_natural(cfg.wn, opt.zeta).unwrap();
        let t = settling_time(&sys, cfg.x0, cfg.v0, cfg.band).unwrap();
        assert!((t - opt.settling_time).abs() < 1e-9, "{cfg:?}");
    }
}

#[test]
fn optimum_from_rest_is_where_the_first_rebound_touches_the_band() {
    // ζ* = L/√(π² + L²), L = ln(1/band): 0.690106 for 5 %, 0.779703 for 2 %.
    for &band in &[0.05, 0.02] {
        let cfg = ZetaSweepConfig {
            band: SettlingBand::new(band).unwrap(),
            ..ZetaSweepConfig::release_from_rest(1.0)
        };
        let l = (1.0f64 / band).ln();
        let expect = l / (std::f64::consts::PI.powi(2) + l * l).sqrt();
        let opt = fastest_settling_zeta(&cfg, 0.3, 1.5, 50).unwrap();
        assert!(opt.at_jump);
        // The bisection lands on the jump to rounding, on the fast side.
        assert!(
            (opt.zeta - expect).abs() < 1e-9,
            "band {band}: {opt:?} vs {expect}"
        );
        let sys = SecondOrder::from_natural(1.0, expect + 1e-6).unwrap();
        let after = settling_time(&sys, 1.0, 0.0, cfg.band).unwrap();
        assert!(
            (opt.settling_time - after).abs() < 1e-4,
            "{opt:?} vs {after}"
        );
    }
}

#[test]
fn zeta_sweep_agrees_with_point_metrics_and_reuses_its_buffers() {
    let cfg = ZetaSweepConfig::release_from_rest(3.0);
    let zetas: Vec<f64> = (0..50).map(|i| -0.1 + 0.05 * i as f64).collect();
    let mut out = ZetaCurves::default();
    sweep_zeta_into(&zetas, &cfg, &mut out);
    let ptr = out.settling_time.as_ptr();
    sweep_zeta_into(&zetas, &cfg, &mut out);
    assert_eq!(
        ptr,
        out.settling_time.as_ptr(),
        "same grid size must not reallocate"
    );
    for (i, &z) in zetas.iter().enumerate() {
        let sys = SecondOrder::from_natural(3.0, z).unwrap();
        match FreeMetrics::exact(&sys, 1.0, 0.0, cfg.band) {
            Some(m) => {
                assert_eq!(out.settling_time[i], m.settling_time.unwrap());
                assert_eq!(out.peak_rebound[i], m.peak_rebound);
            }
            None => assert!(out.settling_time[i].is_nan() && z <= 0.0),
        }
    }
}

// ---------------------------------------------------------------- comfort metric

/// `(1/2π)∫|H(jω)|²dω·q` by Simpson's rule after `ω = s·tan θ` (maps [0, ∞) to [0, π/2)).
fn numeric_accel_variance(m: f64, c: f64, k: f64, road: &RoadInput) -> f64 {
    let wc = road.cutoff();
    let h2 = |w: f64| {
        let jw = Complex::new(0.0, w);
        let num = jw * (jw * c + Complex::real(k)) * wc;
        let den =
            (Complex::real(k - m * w * w) + Complex::new(0.0, c * w)) * (jw + Complex::real(wc));
        let h = num / den;
        h.abs() * h.abs()
    };
    let s = (k / m).sqrt();
    let n = 400_000; // even
    let a = 0.0;
    let b = std::f64::consts::FRAC_PI_2;
    let dt = (b - a) / n as f64;
    let f = |th: f64| {
        if th >= b {
            // |H|² → (c·ω_c/m)²/ω² ... times s·sec²θ: the limit is (c·ω_c/m)²/s.
            return (c * wc / m).powi(2) / s;
        }
        let w = s * th.tan();
        let sec2 = 1.0 / th.cos().powi(2);
        h2(w) * s * sec2
    };
    let mut sum = f(a) + f(b);
    for i in 1..n {
        let wgt = if i % 2 == 1 { 4.0 } else { 2.0 };
        sum += wgt * f(a + i as f64 * dt);
    }
    let half_line = sum * dt / 3.0; // ∫_0^∞ |H|² dω
    road.intensity() * 2.0 * half_line / (2.0 * std::f64::consts::PI)
}

#[test]
fn closed_form_acceleration_variance_matches_numerical_integration() {
    // 1e-6 relative, over damping from light to heavy and two cutoffs.
    let road = RoadInput::iso8608(64e-6, 20.0, 2.0 * std::f64::consts::PI * 10.0).unwrap();
    let slow = RoadInput::new(1e-3, 15.0).unwrap();
    for r in [&road, &slow] {
        for &(m, c, k) in &[
            (300.0, 1610.0, 24_000.0),
            (300.0, 400.0, 24_000.0),
            (250.0, 8000.0, 15_000.0),
            (1.0, 0.5, 4.0),
        ] {
            let exact = body_acceleration_rms(m, c, k, r).unwrap().powi(2);
            let numeric = numeric_accel_variance(m, c, k, r);
            assert!(
                ((exact - numeric) / numeric).abs() < 1e-6,
                "{m} {c} {k}: {exact} vs {numeric}"
            );
        }
    }
    assert!(body_acceleration_rms(300.0, 0.0, 24_000.0, &road).is_none());
}

#[test]
fn acceleration_rms_has_the_stated_limits() {
    let (m, k) = (300.0, 24_000.0);
    let road = RoadInput::new(1e-3, 60.0).unwrap();
    // Light damping: σ² → q·ω_c²·m·k²/(2mc(k + mω_c²)) ∝ 1/c.
    let a = body_acceleration_rms(m, 1.0, k, &road).unwrap();
    let b = body_acceleration_rms(m, 0.25, k, &road).unwrap();
    assert!((b / a - 2.0).abs() < 1e-3);
    // Unbounded input bandwidth: σ² ≈ q·ω_c·c²/(2m²).
    let wide = RoadInput::new(1e-3, 1e7).unwrap();
    let s2 = body_acceleration_rms(m, 1610.0, k, &wide).unwrap().powi(2);
    let asym = 1e-3 * 1e7 * 1610.0f64.powi(2) / (2.0 * m * m);
    assert!((s2 / asym - 1.0).abs() < 1e-3);
}

// ---------------------------------------------------------------- (k, c) maps

#[test]
fn kc_map_matches_pointwise_metrics_and_reuses_buffers() {
    let road = RoadInput::iso8608(64e-6, 20.0, 60.0).unwrap();
    let cfg = KcSweepConfig {
        mass: 300.0,
        band: SettlingBand::FREE_DEFAULT,
        road,
    };
    let k: Vec<f64> = (0..7).map(|i| 1.0e4 + 5.0e3 * i as f64).collect();
    let c: Vec<f64> = (0..5).map(|i| 500.0 * i as f64).collect(); // includes c = 0
    let mut maps = KcMaps::default();
    sweep_kc_into(&k, &c, &cfg, &mut maps);
    let ptr = maps.accel_rms.as_ptr();
    sweep_kc_into(&k, &c, &cfg, &mut maps);
    assert_eq!(ptr, maps.accel_rms.as_ptr());
    assert_eq!(maps.settling_time.len(), 35);
    for (ic, &ci) in c.iter().enumerate() {
        for (ik, &ki) in k.iter().enumerate() {
            let idx = ic * k.len() + ik;
            if ci == 0.0 {
                assert!(maps.settling_time[idx].is_nan() && maps.accel_rms[idx].is_nan());
                continue;
            }
            let sys = SecondOrder::mechanical(300.0, ci, ki).unwrap();
            let ts = settling_time(&sys, 1.0, 0.0, cfg.band).unwrap();
            assert_eq!(maps.settling_time[idx], ts);
            assert_eq!(
                maps.accel_rms[idx],
                body_acceleration_rms(300.0, ci, ki, &road).unwrap()
            );
            assert_eq!(maps.zeta[idx], sys.damping_ratio().unwrap());
        }
    }
}

#[test]
fn iso_zeta_lines_pass_through_the_grid_points_of_that_damping() {
    let k = [1.5e4, 2.4e4, 3.0e4];
    let mut c = [0.0; 3];
    iso_zeta_line_into(0.7, 300.0, &k, &mut c);
    for (ki, ci) in k.iter().zip(c) {
        let z = SecondOrder::mechanical(300.0, ci, *ki)
            .unwrap()
            .damping_ratio()
            .unwrap();
        assert!((z - 0.7).abs() < 1e-14);
    }
}
