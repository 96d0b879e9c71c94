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
    for (zeta, k, tol) in [
        (0.3, [1.0e4, 2.4e4, 5.0e4], 1e-15),
        (0.7, [1.5e4, 2.4e4, 3.0e4], 1e-14),
    ] {
        let mut c = [0.0; 3];
        iso_zeta_line_into(zeta, 300.0, &k, &mut c);
        for (ki, ci) in k.iter().zip(c) {
            let z = SecondOrder::mechanical(300.0, ci, *ki)
                .unwrap()
                .damping_ratio()
                .unwrap();
            assert!((z - zeta).abs() < tol, "ζ = {zeta}: {z}");
        }
    }
}

// ---------------------------------------------------------------- Pareto front

use zeta_solver::design::pareto::{dominates, pareto_front};
use zeta_solver::design::rng::Rng;

#[test]
fn pareto_front_is_mutually_non_dominated_and_dominates_everything_else() {
    let mut rng = Rng::new(11);
    for round in 0..20 {
        let n = 50 + 37 * round;
        let mut f1: Vec<f64> = (0..n).map(|_| rng.uniform()).collect();
        // A quarter of the second objective on a coarse grid forces ties.
        let mut f2: Vec<f64> = (0..n)
            .map(|i| {
                if i % 4 == 0 {
                    (rng.uniform() * 5.0).floor()
                } else {
                    rng.uniform() * 5.0
                }
            })
            .collect();
        f1[3] = f64::NAN;
        f2[5] = f64::INFINITY;
        let front = pareto_front(&f1, &f2);
        assert!(!front.contains(&3) && !front.contains(&5));
        for w in front.windows(2) {
            assert!(
                f1[w[0]] <= f1[w[1]] && f2[w[0]] >= f2[w[1]],
                "not ordered along the front"
            );
        }
        for &a in &front {
            for &b in &front {
                assert!(
                    !dominates(f1[a], f2[a], f1[b], f2[b]),
                    "{a} dominates {b} on the front"
                );
            }
        }
        for i in (0..n).filter(|i| !front.contains(i) && f1[*i].is_finite() && f2[*i].is_finite()) {
            assert!(
                front.iter().any(|&p| dominates(f1[p], f2[p], f1[i], f2[i])),
                "{i} is off the front but not dominated"
            );
        }
    }
}

// ---------------------------------------------------------------- sensitivity

use zeta_solver::design::sensitivity::{spread, Components, Quantity, Varied};

#[test]
fn sensitivity_ranges_contain_interior_samples_and_equal_the_corners() {
    let designs = [
        Components::mechanical_for_zeta(300.0, 24_000.0, 0.7),
        Components::mechanical_for_zeta(300.0, 24_000.0, 1.0),
        Components::Electrical {
            l: 0.5,
            r: 4.0,
            cap: 0.02,
        },
    ];
    let x = 0.1;
    let mut rng = Rng::new(3);
    for d in &designs {
        for q in Quantity::ALL {
            for varied in [Varied::One(0), Varied::One(1), Varied::One(2), Varied::All] {
                let s = spread(d, q, varied, x).unwrap();
                let on = |p: usize| varied == Varied::All || varied == Varied::One(p);
                // Interior samples stay inside [min, max] (1e-12 relative for rounding).
                for _ in 0..300 {
                    let mut v = d.values();
                    for (p, vp) in v.iter_mut().enumerate() {
                        if on(p) {
                            *vp *= 1.0 + x * (2.0 * rng.uniform() - 1.0);
                        }
                    }
                    let val = q.of(&d.with_values(v).system().unwrap()).unwrap();
                    assert!(
                        val >= s.min * (1.0 - 1e-12) && val <= s.max * (1.0 + 1e-12),
                        "{q:?} {varied:?}"
                    );
                }
                // The extremes are the corners predicted by the signs of the exponents.
                let corner = |dir: f64| {
                    let mut v = d.values();
                    for (p, vp) in v.iter_mut().enumerate() {
                        let e = q.log_sensitivity(d, p).unwrap();
                        if on(p) && e != 0.0 {
                            *vp *= 1.0 + dir * e.signum() * x;
                        }
                    }
                    q.of(&d.with_values(v).system().unwrap()).unwrap()
                };
                assert!(
                    (corner(-1.0) - s.min).abs() <= 1e-14 * s.min,
                    "{q:?} {varied:?}"
                );
                assert!(
                    (corner(1.0) - s.max).abs() <= 1e-14 * s.max,
                    "{q:?} {varied:?}"
                );
                // Linearised ranges are first-order: within 3x² of the exact ones (ζ, all varied:
                // exact max 1.1/0.9 = 1.2222 vs linear 1.2).
                assert!(
                    (s.linear_max - s.max).abs() <= 3.0 * x * x * s.nominal,
                    "{q:?} {varied:?}"
                );
            }
        }
    }
}

#[test]
fn every_quantity_is_monotone_in_each_component_as_its_exponent_says() {
    let d = Components::Electrical {
        l: 0.5,
        r: 4.0,
        cap: 0.02,
    };
    for q in Quantity::ALL {
        for p in 0..3 {
            let e = q.log_sensitivity(&d, p).unwrap();
            let mut prev = f64::NAN;
            for i in 0..50 {
                let mut v = d.values();
                v[p] *= 0.5 + i as f64 / 49.0;
                let val = q.of(&d.with_values(v).system().unwrap()).unwrap();
                if !prev.is_nan() {
                    let step = val - prev;
                    match e.partial_cmp(&0.0).unwrap() {
                        std::cmp::Ordering::Greater => assert!(step > 0.0, "{q:?} p{p}"),
                        std::cmp::Ordering::Less => assert!(step < 0.0, "{q:?} p{p}"),
                        std::cmp::Ordering::Equal => {
                            assert!(step.abs() <= 1e-15 * val, "{q:?} p{p}")
                        }
                    }
                }
                prev = val;
            }
            // And the exponent is the numerical log-derivative (central difference, h = 1e-5).
            let at = |f: f64| {
                let mut v = d.values();
                v[p] *= f;
                q.of(&d.with_values(v).system().unwrap()).unwrap().ln()
            };
            let num =
                (at(1.0 + 1e-5) - at(1.0 - 1e-5)) / ((1.0f64 + 1e-5).ln() - (1.0f64 - 1e-5).ln());
            assert!((num - e).abs() < 1e-8, "{q:?} p{p}: {num} vs {e}");
        }
    }
}

#[test]
fn critical_design_turns_underdamped_with_ten_percent_more_mass() {
    // ζ ∝ m^−½: ±10 % sprung mass gives ζ ∈ [0.95346, 1.05409] for a ζ = 1 design and
    // ζ ∈ [0.66742, 0.73786] for ζ = 0.7; linearised ±5 % in both cases.
    let critical = Components::mechanical_for_zeta(300.0, 24_000.0, 1.0);
    let s = spread(&critical, Quantity::DampingRatio, Varied::One(0), 0.1).unwrap();
    assert!(
        (s.min - 0.953_462_589_245_592).abs() < 1e-12
            && (s.max - 1.054_092_553_389_459_6).abs() < 1e-12
    );
    assert!((s.linear_min - 0.95).abs() < 1e-12 && (s.linear_max - 1.05).abs() < 1e-12);
    let heavier = critical
        .with_values([330.0, critical.values()[1], 24_000.0])
        .system()
        .unwrap();
    assert_eq!(heavier.regime(), zeta_solver::Regime::Underdamped);
    let d07 = Components::mechanical_for_zeta(300.0, 24_000.0, 0.7);
    let s = spread(&d07, Quantity::DampingRatio, Varied::One(0), 0.1).unwrap();
    assert!(
        (s.min - 0.7 * 0.953_462_589_245_592).abs() < 1e-12
            && (s.max - 0.7 * 1.054_092_553_389_459_6).abs() < 1e-12
    );
}

// ---------------------------------------------------------------- Monte Carlo

use zeta_solver::design::monte_carlo::{
    histogram_into, percentiles_into, run_into, yield_percent, Distribution, McConfig, McSamples,
    Spec, Tolerance,
};

fn mc_config(dist: Distribution, fraction: f64, draws: usize, seed: u64) -> McConfig {
    McConfig {
        design: Components::mechanical_for_zeta(300.0, 24_000.0, 0.7),
        tolerances: [Tolerance {
            fraction,
            distribution: dist,
        }; 3],
        draws,
        seed,
        band: SettlingBand::FREE_DEFAULT,
    }
}

#[test]
fn same_seed_gives_identical_results_and_another_seed_does_not() {
    let mut a = McSamples::default();
    let mut b = McSamples::default();
    run_into(&mc_config(Distribution::Normal, 0.1, 5000, 42), &mut a);
    run_into(&mc_config(Distribution::Normal, 0.1, 5000, 42), &mut b);
    assert_eq!(a, b);
    run_into(&mc_config(Distribution::Normal, 0.1, 5000, 43), &mut b);
    assert_ne!(a.zeta, b.zeta);
}

#[test]
fn percentiles_of_a_uniform_draw_converge_to_the_theoretical_values() {
    // Only the mass varies, uniformly by ±20 %: ω_n = √(k/m) has the quantile function
    // ω_n(p) = √(k/(m0·(1.2 − 0.4p))) (ω_n falls with m). With n = 100 000 the standard error
    // of a sample quantile is √(p(1−p)/n)/density ≤ 0.0007·ω_n0·(range): we allow 0.3 %.
    let mut cfg = mc_config(Distribution::Uniform, 0.2, 100_000, 9);
    cfg.tolerances[1].fraction = 0.0;
    cfg.tolerances[2].fraction = 0.0;
    let mut s = McSamples::default();
    run_into(&cfg, &mut s);
    let mut scratch = Vec::new();
    let mut out = [0.0; 3];
    let ps = [0.05, 0.5, 0.95];
    percentiles_into(&s.wn, &ps, &mut scratch, &mut out);
    for (o, p) in out.iter().zip(ps) {
        let expect = (24_000.0 / (300.0 * (1.2 - 0.4 * p))).sqrt();
        assert!((o / expect - 1.0).abs() < 3e-3, "p{p}: {o} vs {expect}");
    }
    // And a histogram of the mass-driven ζ over its full range holds every draw.
    let mut counts = Vec::new();
    histogram_into(&s.zeta, 40, None, &mut counts).unwrap();
    assert_eq!(counts.iter().sum::<u64>(), 100_000);
}

#[test]
fn yield_of_an_all_inclusive_spec_is_100_and_of_an_impossible_one_is_0() {
    let mut s = McSamples::default();
    run_into(&mc_config(Distribution::Normal, 0.1, 20_000, 1), &mut s);
    assert_eq!(s.invalid, 0);
    let all = Spec {
        zeta: Some((0.0, 10.0)),
        f0: Some((0.0, 100.0)),
        q: Some((0.0, 100.0)),
        max_settling_time: Some(100.0),
    };
    assert_eq!(yield_percent(&s, &all), 100.0);
    let none = Spec {
        zeta: Some((2.0, 3.0)),
        ..Spec::default()
    };
    assert_eq!(yield_percent(&s, &none), 0.0);
    // ζ within ±5 % of 0.7 with ±10 % (3σ) normal parts: a proper fraction.
    let tight = Spec {
        zeta: Some((0.665, 0.735)),
        ..Spec::default()
    };
    let y = yield_percent(&s, &tight);
    assert!(y > 50.0 && y < 100.0, "{y}");
}

#[test]
fn wide_normal_tolerances_redraw_invalid_values_and_never_produce_negative_parts() {
    // 3σ = 150 %: σ = 50 %, so about 2.3 % of raw draws are non-positive and are re-drawn.
    let mut s = McSamples::default();
    run_into(&mc_config(Distribution::Normal, 1.5, 20_000, 5), &mut s);
    assert!(s.redraws > 500, "{}", s.redraws);
    assert_eq!(s.invalid, 0);
    assert!(s.zeta.iter().all(|z| z.is_finite() && *z >= 0.0));
    assert!(s.wn.iter().all(|w| w.is_finite() && *w > 0.0));
}

// ---------------------------------------------------------------- design-map helpers

mod map_helpers {
    use zeta_solver::design::pareto::{nearest_on_front, pareto_front};
    use zeta_solver::design::sweep::{
        iso_zeta_line_into, iso_zeta_span, iso_zeta_stiffness, rebound_from_rest, RoadInput,
    };
    use zeta_solver::metrics::free::FreeMetrics;
    use zeta_solver::metrics::SettlingBand;
    use zeta_solver::two_dof::IsoClass;
    use zeta_solver::SecondOrder;

    #[test]
    fn iso_zeta_stiffness_inverts_the_iso_zeta_line() {
        for zeta in [0.2, 0.7, 1.0] {
            let k = [12_345.0];
            let mut c = [0.0];
            iso_zeta_line_into(zeta, 300.0, &k, &mut c);
            let back = iso_zeta_stiffness(zeta, 300.0, c[0]).unwrap();
            assert!((back - k[0]).abs() < 1e-10 * k[0], "ζ = {zeta}");
        }
        assert!(iso_zeta_stiffness(0.0, 300.0, 1.0).is_none());
        assert!(iso_zeta_stiffness(0.5, 0.0, 1.0).is_none());
    }

    #[test]
    fn iso_zeta_span_is_the_part_inside_the_map() {
        // ζ = 0.5, m = 300: c = √(300·k); c = 500 at k = 833.3, c = 8 000 at k = 213 333.
        let (ka, kb) = iso_zeta_span(0.5, 300.0, (10_000.0, 60_000.0), (500.0, 8_000.0)).unwrap();
        assert_eq!((ka, kb), (10_000.0, 60_000.0));
        // ζ = 0.2: c = 0.4·√(300·k) reaches c = 500 only at k = 5 208.3 (< k0), and c = 2 000 at
        // k = 83 333.3 (> k1): the whole k range. With c1 = 2 000 and k1 = 100 000 it stops at
        // k = (2 000/0.4)²/300.
        let (_, kb) = iso_zeta_span(0.2, 300.0, (1_000.0, 100_000.0), (500.0, 2_000.0)).unwrap();
        assert!((kb - 5_000.0f64.powi(2) / 300.0).abs() < 1e-9);
        // ζ = 0.05 runs above the whole map: c = 0.1·√(300·k) ≤ 245 < c0 for k ≤ 20 000.
        assert!(iso_zeta_span(0.05, 300.0, (10_000.0, 20_000.0), (500.0, 800.0)).is_none());
    }

    #[test]
    fn rebound_from_rest_is_the_free_response_peak() {
        // The closed form against the solver's exact free-response metrics (1e-12).
        for zeta in [0.05, 0.2, 0.37, 0.7, 0.95] {
            let sys = SecondOrder::from_natural(8.0, zeta).unwrap();
            let m = FreeMetrics::exact(&sys, 0.06, 0.0, SettlingBand::FREE_DEFAULT).unwrap();
            let expect = rebound_from_rest(zeta).unwrap();
            assert!((m.peak_rebound - expect).abs() < 1e-12, "ζ = {zeta}");
        }
        // Undamped: it swings back to −x₀, a full rebound.
        assert_eq!(rebound_from_rest(0.0), Some(1.0));
        // ζ = 0.5: e^{−π/√3} = 0.163 033.
        assert!((rebound_from_rest(0.5).unwrap() - 0.163_033).abs() < 1e-6);
        assert!(rebound_from_rest(1.0).is_none());
        assert!(rebound_from_rest(-0.1).is_none());
        assert!(rebound_from_rest(f64::NAN).is_none());
    }

    #[test]
    fn road_classes_come_from_the_one_iso_8608_table() {
        // G_d(n0) of classes A–D: 16, 64, 256, 1 024 × 10⁻⁶ m³.
        for (class, gd) in [
            (IsoClass::A, 16e-6),
            (IsoClass::B, 64e-6),
            (IsoClass::C, 256e-6),
            (IsoClass::D, 1024e-6),
        ] {
            let a = RoadInput::iso_class(class, 20.0, 60.0).unwrap();
            let b = RoadInput::iso8608(gd, 20.0, 60.0).unwrap();
            assert_eq!(a, b);
        }
        assert!(RoadInput::iso_class(IsoClass::A, 0.0, 60.0).is_err());
    }

    #[test]
    fn the_nearest_front_point_is_measured_in_scaled_units() {
        let f1 = [1.0, 2.0, 3.0];
        let f2 = [30.0, 20.0, 10.0];
        let front = pareto_front(&f1, &f2);
        assert_eq!(
            nearest_on_front(&front, &f1, &f2, (1.1, 30.0), (1.0, 1.0)),
            Some(0)
        );
        // (2.9, 20): unscaled, point 1 is nearest; with f2 shrunk by 100, point 2 is.
        assert_eq!(
            nearest_on_front(&front, &f1, &f2, (2.9, 20.0), (1.0, 1.0)),
            Some(1)
        );
        assert_eq!(
            nearest_on_front(&front, &f1, &f2, (2.9, 20.0), (1.0, 100.0)),
            Some(2)
        );
        assert_eq!(
            nearest_on_front(&[], &f1, &f2, (0.0, 0.0), (1.0, 1.0)),
            None
        );
        assert_eq!(
            nearest_on_front(&[7], &f1, &f2, (0.0, 0.0), (1.0, 1.0)),
            None
        );
    }
}

// ---------------------------------------------------------------- tolerance boxes

mod tolerance_boxes {
    use zeta_solver::design::sensitivity::{spread, tolerance_box, Components, Quantity, Varied};

    const RLC: Components = Components::Electrical {
        l: 0.5,
        r: 7.0,
        cap: 0.02,
    };

    #[test]
    fn equal_tolerances_agree_with_spread() {
        for q in Quantity::ALL {
            let (lo, hi) = tolerance_box(&RLC, q, [0.1; 3]).unwrap();
            let s = spread(&RLC, q, Varied::All, 0.1).unwrap();
            assert!((lo.value - s.min).abs() <= 1e-12 * s.min.abs(), "{q:?}");
            assert!((hi.value - s.max).abs() <= 1e-12 * s.max.abs(), "{q:?}");
        }
    }

    #[test]
    fn separate_tolerances_reach_the_analytic_corners() {
        // ζ = (R/2)√(C/L): lowest at L(1 + dL), R(1 − dR), C(1 − dC), highest opposite.
        let (lo, hi) = tolerance_box(&RLC, Quantity::DampingRatio, [0.05, 0.2, 0.1]).unwrap();
        let z = |l: f64, r: f64, c: f64| r / 2.0 * (c / l).sqrt();
        assert!((lo.value - z(0.525, 5.6, 0.018)).abs() < 1e-12);
        assert!((hi.value - z(0.475, 8.4, 0.022)).abs() < 1e-12);
        for (v, e) in lo.design.values().iter().zip([0.525, 5.6, 0.018]) {
            assert!((v - e).abs() < 1e-12 * e);
        }
        for (v, e) in hi.design.values().iter().zip([0.475, 8.4, 0.022]) {
            assert!((v - e).abs() < 1e-12 * e);
        }
        // ω_n = 1/√(LC) does not depend on R: its range ignores dR.
        let (wlo, whi) = tolerance_box(&RLC, Quantity::NaturalFrequency, [0.05, 0.2, 0.1]).unwrap();
        assert!((wlo.value - 1.0 / (0.525f64 * 0.022).sqrt()).abs() < 1e-12);
        assert!((whi.value - 1.0 / (0.475f64 * 0.018).sqrt()).abs() < 1e-12);
    }

    #[test]
    fn a_zero_tolerance_holds_a_component_and_invalid_ones_are_none() {
        let (lo, hi) = tolerance_box(&RLC, Quantity::DampingRatio, [0.0; 3]).unwrap();
        assert_eq!(lo.value, hi.value);
        assert_eq!(lo.design, RLC);
        for bad in [1.0, -0.1, f64::NAN] {
            assert!(tolerance_box(&RLC, Quantity::DampingRatio, [bad, 0.0, 0.0]).is_none());
        }
        let undamped = Components::Mechanical {
            m: 1.0,
            c: 0.0,
            k: 1.0,
        };
        assert!(tolerance_box(&undamped, Quantity::QualityFactor, [0.1; 3]).is_none());
    }
}
