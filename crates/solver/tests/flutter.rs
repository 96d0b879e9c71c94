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

// ---- The deck on Scanlan's flutter derivatives -------------------------------------------

mod scanlan {
    use std::f64::consts::TAU;
    use zeta_solver::flutter::scanlan::Aerodynamics;
    use zeta_solver::flutter::{
        degrees, radians, DeckSection, FlutterModel, ScanlanConfig, ScanlanModel,
    };

    /// An independent p–k solution of the same equations: iterate ω ← Im λ of
    /// λ² + c(ω)λ + k(ω) = 0 (roots of the companion matrix [[0, 1], [−k, −c]] by the
    /// 2 × 2 eigenvalue formula), 400 times. Returns (Re λ, Im λ).
    fn direct(cfg: &ScanlanConfig, u: f64) -> (f64, f64) {
        let Aerodynamics::Derivatives(section) = cfg.aerodynamics else {
            unreachable!()
        };
        let w0 = TAU * cfg.frequency;
        let q = cfg.air_density * cfg.width.powi(4) / (2.0 * cfg.inertia);
        let mut w = w0;
        let mut eig = (0.0, w0);
        for _ in 0..400 {
            let vr = if u > 0.0 {
                u / (w / TAU * cfg.width)
            } else {
                0.0
            };
            let c = 2.0 * cfg.structural_damping * w0 - q * w * section.a2(vr);
            let k = w0 * w0 - q * w * w * section.a3(vr);
            // Eigenvalues of [[0, 1], [−k, −c]]: trace −c, determinant k.
            let (tr, det) = (-c, k);
            let disc = tr * tr / 4.0 - det;
            assert!(disc < 0.0, "U = {u}: the mode must oscillate");
            eig = (tr / 2.0, (-disc).sqrt());
            w = eig.1;
        }
        eig
    }

    #[test]
    fn growth_rate_and_frequency_match_a_direct_eigenvalue_computation() {
        // Tolerances: the model stops iterating at |Δω| ≤ 1e-12·ω₀; the direct loop runs to
        // its fixed point. Both round at ~1e-16.
        for cfg in [
            ScanlanConfig::tacoma_1940(),
            ScanlanConfig::streamlined_box(),
        ] {
            let m = ScanlanModel::new(cfg).unwrap();
            let w0 = m.still_air_omega();
            for i in 0..=40 {
                let u = i as f64;
                let s = m.state(u).unwrap();
                let (re, im) = direct(&cfg, u);
                assert!(
                    (s.growth_rate() - re).abs() < 1e-11 * w0,
                    "U={u}: {s:?} {re}"
                );
                assert!((s.omega - im).abs() < 1e-10 * w0, "U={u}: {} {im}", s.omega);
                let [p, q] = s.poles();
                assert_eq!((p.re, p.im, q.im), (s.growth_rate(), s.omega, -s.omega));
            }
        }
    }

    #[test]
    fn the_critical_speed_is_where_the_direct_eigenvalue_crosses_the_axis() {
        let cfg = ScanlanConfig::tacoma_1940();
        let m = ScanlanModel::new(cfg).unwrap();
        let uc = m.critical_speed().unwrap();
        // At U_crit the real part vanishes (to the bisection width times its slope).
        assert!(direct(&cfg, uc).0.abs() < 1e-9, "{}", direct(&cfg, uc).0);
        assert!(direct(&cfg, uc - 0.01).0 < 0.0 && direct(&cfg, uc + 0.01).0 > 0.0);
        // And it is the first crossing: a brute-force scan at 5 cm/s finds none before it.
        let first = (0..)
            .map(|i| 0.05 * i as f64)
            .find(|&u| direct(&cfg, u).0 > 0.0)
            .unwrap();
        assert!(first >= uc && first - uc <= 0.05, "{first} {uc}");
        // To first order, ζ_s·ω₀/ω = ρB⁴A₂*/(4I) there.
        let s = m.state(uc).unwrap();
        let lhs = cfg.structural_damping * m.still_air_omega() / s.omega;
        let rhs = cfg.air_density * cfg.width.powi(4) * s.a2 / (4.0 * cfg.inertia);
        assert!((lhs - rhs).abs() < 1e-9, "{lhs} {rhs}");
    }

    #[test]
    fn the_tabulated_derivatives_reproduce_their_source_table() {
        // H-section: the rule documented in `flutter::derivatives` (a teaching
        // approximation, see there): the listed A₂* nodes and A₃* = C_M′·(V_r/2π)² with
        // C_M′ = 0.3.
        let h_a2 = [
            0.0, -0.01, -0.02, -0.03, -0.035, -0.03, 0.0, 0.08, 0.2, 0.33, 0.46, 0.59, 0.72, 0.85,
            0.98, 1.11, 1.24, 1.37, 1.5, 1.63, 1.76, 1.89, 2.02, 2.15, 2.28, 2.41, 2.54, 2.67, 2.8,
            2.93, 3.06, 3.19, 3.32, 3.45, 3.58, 3.71, 3.84, 3.97, 4.1, 4.23, 4.36,
        ];
        let (h, b) = (DeckSection::HSection, DeckSection::StreamlinedBox);
        for (i, &a2) in h_a2.iter().enumerate() {
            let v = i as f64;
            assert_eq!(h.a2(v), a2, "H-section A2* at {v}");
            let k_inv2 = (v / TAU).powi(2);
            assert!((h.a3(v) - 0.3 * k_inv2).abs() <= 1e-15 * (1.0 + k_inv2));
            assert_eq!(h.table().a2[i], a2);
        }
        // Linear between nodes, the end value held beyond the table.
        assert!((h.a2(7.5) - 0.14).abs() < 1e-15);
        assert_eq!(h.a2(50.0), 4.36);
        // Box: Theodorsen's flat plate, A₂* = −π/(8K)(1 − F − 4G/K), A₃* = π/(2K²)(F − KG/4)
        // with C(K/2) = F + iG. Reference (K, F, G, A₂*, A₃*) at the tabulated reduced
        // frequencies k = K/2 = 0.1, 0.2, 0.5, 1 (mpmath 1.3, Bessel functions at 30 digits,
        // rounded to 10 significant digits); tolerance 10⁻⁹ relative.
        let reference = [
            (0.2, 0.8319241050, -0.1723022287, -7.096308948, 33.00789784),
            (0.4, 0.7275799213, -0.1886242121, -2.119261659, 7.328180561),
            (
                1.0,
                0.5979360643,
                -0.1507095032,
                -0.3946240723,
                0.9984192569,
            ),
            (
                2.0,
                0.5394348711,
                -0.1002729029,
                -0.1298088285,
                0.2315241169,
            ),
        ];
        for (big_k, f, g, a2, a3) in reference {
            let v = TAU / big_k;
            let c = zeta_solver::flutter::theodorsen::theodorsen(0.5 * big_k).unwrap();
            assert!(
                (c.re - f).abs() < 1e-9 && (c.im - g).abs() < 1e-9,
                "K = {big_k}"
            );
            assert!(
                (b.a2(v) / a2 - 1.0).abs() < 1e-9,
                "box A2* at K = {big_k}: {}",
                b.a2(v)
            );
            assert!(
                (b.a3(v) / a3 - 1.0).abs() < 1e-9,
                "box A3* at K = {big_k}: {}",
                b.a3(v)
            );
        }
        // The shapes the literature describes: the H-section changes sign, the box never.
        for i in 1..60 {
            let v = 0.1 * i as f64;
            assert!(h.a2(v) < 0.0, "H-section A2* negative below V_r = 6 ({v})");
            assert!(b.a2(v) < 0.0);
        }
        for i in 61..400 {
            let v = 0.1 * i as f64;
            assert!(h.a2(v) > 0.0, "H-section A2* positive above V_r = 6 ({v})");
            assert!(b.a2(v) < 0.0);
        }
    }

    #[test]
    fn the_1940_deck_flutters_near_the_failure_wind_and_the_box_does_not() {
        let deck = ScanlanModel::new(ScanlanConfig::tacoma_1940()).unwrap();
        let uc = deck.critical_speed().unwrap();
        assert!(uc > 17.0 && uc < 19.0, "U_crit = {uc} m/s");
        // 19 m/s (≈ 42 mph): doubling every few minutes, a limit cycle of tens of degrees,
        // reached from 2° within the hour — the time scale of the record.
        let s = deck.state(19.0).unwrap();
        let doubling = s.doubling_time().unwrap();
        assert!(doubling > 120.0 && doubling < 600.0, "{doubling} s");
        let lc = deck.limit_cycle(19.0).unwrap();
        assert!(degrees(lc) > 20.0 && degrees(lc) < 40.0, "{}°", degrees(lc));
        let t90 = deck.time_between(19.0, radians(2.0), 0.9 * lc).unwrap();
        assert!(t90 > 600.0 && t90 < 3600.0, "{t90} s");
        // A3* > 0 lowers the frequency a little.
        assert!(s.frequency_hz() < 0.2 && s.frequency_hz() > 0.19);
        // Below U_crit there is no limit cycle: the twist dies away.
        assert_eq!(deck.limit_cycle(10.0), None);
        let modern = ScanlanModel::new(ScanlanConfig::streamlined_box()).unwrap();
        assert_eq!(modern.critical_speed(), None);
        assert!(modern.state(40.0).unwrap().damping_ratio() > 0.005);
    }

    #[test]
    fn the_simulated_twist_follows_the_averaged_amplitude_equation() {
        // RK4 at 40 steps per period against the closed-form cycle average. Averaging is
        // exact to first order in the damping (|ζ| < 0.01 here): tolerance 2 %.
        let deck = ScanlanModel::new(ScanlanConfig::tacoma_1940()).unwrap();
        let (u, a0) = (19.0, radians(2.0));
        let lc = deck.limit_cycle(u).unwrap();
        let t90 = deck.time_between(u, a0, 0.9 * lc).unwrap();
        let run = deck.simulate(u, a0, 2.5 * t90, 40).unwrap();
        let reached = run.t[run.amplitude.iter().position(|&a| a >= 0.9 * lc).unwrap()];
        assert!((reached / t90 - 1.0).abs() < 0.02, "{reached} vs {t90}");
        let end = *run.amplitude.last().unwrap();
        assert!(
            (end / lc - 1.0).abs() < 0.01,
            "{} vs {}",
            degrees(end),
            degrees(lc)
        );
        assert!((run.theta_at(0.0) - a0).abs() < 1e-15);
        // From above the limit cycle it decays onto it.
        let from_above = deck.simulate(u, 1.5 * lc, 4.0 * t90, 40).unwrap();
        assert!((from_above.amplitude.last().unwrap() / lc - 1.0).abs() < 0.01);
        // Below U_crit the amplitude never rises (the damping is positive at every a).
        let calm = deck.simulate(10.0, a0, 600.0, 40).unwrap();
        assert!(calm
            .amplitude
            .windows(2)
            .all(|w| w[1] <= w[0] * (1.0 + 1e-9)));
        // The window fits the growth: it ends near the limit cycle, not long after.
        let w = deck.window(u, a0);
        let t95 = deck.time_between(u, a0, 0.95 * lc).unwrap();
        assert!((w - 1.25 * t95).abs() < 1e-6 * w);
    }

    #[test]
    fn the_simplest_picture_is_the_linear_model() {
        let linear = FlutterModel::tacoma_1940();
        let g = linear.config().aero_slope;
        let m = ScanlanModel::new(ScanlanConfig {
            aerodynamics: Aerodynamics::SimplestPicture { slope: g },
            ..ScanlanConfig::tacoma_1940()
        })
        .unwrap();
        let uc = m.critical_speed().unwrap();
        assert!((uc - linear.critical_speed().unwrap()).abs() < 1e-6, "{uc}");
        for u in [0.0, 10.0, 19.0, 30.0] {
            let s = m.state(u).unwrap();
            assert!((s.damping_ratio() - linear.effective_damping(u)).abs() < 1e-15);
            assert!((s.growth_rate() - linear.growth_rate(u)).abs() < 1e-15);
            assert_eq!(s.a3, 0.0);
        }
    }
}
