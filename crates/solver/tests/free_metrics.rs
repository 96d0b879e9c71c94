//! Free-response metrics: exact settling time against brute-force dense sampling, rebound and
//! decrement against closed forms, and the discontinuities of settling time in ζ.

// Helpers outside `#[test]` functions unwrap too: the whole file is test code.
#![cfg(test)]

use std::f64::consts::PI;
use zeta_solver::metrics::free::{settling_time, FreeMetrics};
use zeta_solver::metrics::SettlingBand;
use zeta_solver::{FreeResponse, SecondOrder};

const WN: f64 = 1.0;

fn sys(zeta: f64) -> SecondOrder {
    SecondOrder::from_natural(WN, zeta).unwrap()
}

/// Brute force: the last of `n` samples on `[0, horizon]` with `|x| > h`, and the next one.
fn brute_force_bracket(r: &FreeResponse, h: f64, horizon: f64, n: usize) -> (f64, f64) {
    let dt = horizon / (n - 1) as f64;
    let mut last = 0;
    for i in 0..n {
        if r.displacement(i as f64 * dt).abs() > h {
            last = i;
        }
    }
    assert!(last < n - 1, "horizon too short");
    (last as f64 * dt, (last + 1) as f64 * dt)
}

#[test]
fn exact_settling_time_agrees_with_a_million_samples_for_zeta_from_0_05_to_3() {
    // Agreement to the sampling resolution: the exact time lies in the brute-force bracket
    // (widened by 1e-9 s for rounding at the band edge).
    let band = SettlingBand::FREE_DEFAULT;
    let zetas = [
        0.05, 0.1, 0.2, 0.3, 0.45, 0.6, 0.69, 0.7, 0.8, 0.9, 0.97, 1.0, 1.03, 1.3, 2.0, 3.0,
    ];
    for &zeta in &zetas {
        for &(x0, v0) in &[(1.0, 0.0), (-0.3, 1.2)] {
            let s = sys(zeta);
            let ts = settling_time(&s, x0, v0, band).unwrap();
            let r = FreeResponse::new(s, x0, v0);
            // Horizon 120 s ≥ 1.3 × the slowest settling time here (ζ = 0.05, v0 ≠ 0: ≈ 88 s).
            let (lo, hi) = brute_force_bracket(&r, 0.05 * f64::abs(x0), 120.0, 1_000_000);
            assert!(
                ts >= lo - 1e-9 && ts <= hi + 1e-9,
                "ζ={zeta} x0={x0}: {ts} not in [{lo}, {hi}]"
            );
        }
    }
}

#[test]
fn peak_rebound_from_rest_is_the_textbook_overshoot() {
    for &zeta in &[0.01, 0.1, 0.3, 0.5, 0.7, 0.9, 0.999] {
        let m = FreeMetrics::exact(&sys(zeta), 0.06, 0.0, SettlingBand::FREE_DEFAULT).unwrap();
        let expect = (-PI * zeta / (1.0 - zeta * zeta).sqrt()).exp();
        assert!(
            (m.peak_rebound - expect).abs() <= 1e-13 * expect,
            "ζ={zeta}"
        );
        let wd = WN * (1.0 - zeta * zeta).sqrt();
        assert!(
            (m.rebound_time.unwrap() - PI / wd).abs() < 1e-12 * PI / wd,
            "ζ={zeta}"
        );
        let delta = 2.0 * PI * zeta / (1.0 - zeta * zeta).sqrt();
        assert!(
            (m.log_decrement.unwrap() - delta).abs() <= 1e-13 * delta,
            "ζ={zeta}"
        );
    }
    // From rest, a critically or over-damped system never crosses equilibrium.
    for &zeta in &[1.0, 1.5, 5.0] {
        let m = FreeMetrics::exact(&sys(zeta), 0.06, 0.0, SettlingBand::FREE_DEFAULT).unwrap();
        assert_eq!(
            (m.peak_rebound, m.rebound_time, m.log_decrement),
            (0.0, None, None)
        );
        assert_eq!(m.zero_crossings, 0);
    }
}

#[test]
fn overdamped_release_towards_equilibrium_rebounds_once() {
    // x0 = 1, v0 = −5 with ζ = 1.5 crosses zero once; the rebound is the single extremum,
    // where the velocity vanishes.
    let s = sys(1.5);
    let m = FreeMetrics::exact(&s, 1.0, -5.0, SettlingBand::FREE_DEFAULT).unwrap();
    let te = m.rebound_time.unwrap();
    let r = FreeResponse::new(s, 1.0, -5.0);
    assert!(r.velocity(te).abs() < 1e-12);
    assert!((m.peak_rebound + r.displacement(te)).abs() < 1e-15);
    assert!(m.peak_rebound > 0.05, "this case rebounds outside the band");
    assert_eq!(m.zero_crossings, 1);
}

#[test]
fn zero_crossings_count_the_swings_before_settling() {
    // From rest the extrema are |x_k| = e^{−kπζ/√(1−ζ²)}; the swings before settling are the
    // extrema after t = 0 still outside the band, each preceded by one zero crossing.
    for &zeta in &[0.02, 0.1, 0.3, 0.6] {
        let m = FreeMetrics::exact(&sys(zeta), 1.0, 0.0, SettlingBand::FREE_DEFAULT).unwrap();
        let d = PI * zeta / (1.0 - zeta * zeta).sqrt();
        let outside = (1..10_000)
            .filter(|&k| (-(k as f64) * d).exp() > 0.05)
            .count() as u64;
        assert_eq!(m.zero_crossings, outside, "ζ={zeta}");
    }
}

#[test]
fn settling_time_jumps_where_a_peak_leaves_the_band() {
    // From rest the k-th extremum equals the band when kπζ/√(1−ζ²) = L, L = ln(1/band):
    // ζ_k = L/√(k²π² + L²). Just below ζ_k that extremum is outside the band and the settling
    // time is just after it, t_k = kπ/ω_d; just above, the response settles on the way down
    // from extremum k−1, before the zero crossing at (k − 1/2)π/ω_d + ψ/ω_d < t_k.
    let band = SettlingBand::FREE_DEFAULT;
    let l = 20f64.ln();
    for k in 1..=3 {
        let kf = k as f64;
        let zk = l / (kf * kf * PI * PI + l * l).sqrt();
        for &(zeta, above) in &[(zk - 1e-7, false), (zk + 1e-7, true)] {
            let ts = settling_time(&sys(zeta), 1.0, 0.0, band).unwrap();
            let tk = kf * PI / (WN * (1.0 - zeta * zeta).sqrt());
            if above {
                assert!(ts < tk - 0.3, "k={k} ζ={zeta}: {ts} vs t_k {tk}");
            } else {
                assert!(
                    ts > tk && ts < tk + 0.05,
                    "k={k} ζ={zeta}: {ts} vs t_k {tk}"
                );
            }
            // Both sides agree with brute force.
            let r = FreeResponse::new(sys(zeta), 1.0, 0.0);
            let (lo, hi) = brute_force_bracket(&r, 0.05, 40.0, 1_000_000);
            assert!(ts >= lo - 1e-9 && ts <= hi + 1e-9, "k={k} ζ={zeta}");
        }
    }
}

#[test]
fn settling_time_is_continuous_through_critical_damping() {
    // No extremum leaves the band near ζ = 1 from rest (the first rebound there is
    // e^{−π·ζ/√(1−ζ²)} ≈ 0), so the settling time is continuous; check both sides and a
    // start with velocity.
    let band = SettlingBand::FREE_DEFAULT;
    for &(x0, v0) in &[(1.0, 0.0), (1.0, 2.0), (1.0, -0.5)] {
        let t1 = settling_time(&sys(1.0), x0, v0, band).unwrap();
        for &eps in &[1e-3, 1e-5, 1e-7] {
            let below = settling_time(&sys(1.0 - eps), x0, v0, band).unwrap();
            let above = settling_time(&sys(1.0 + eps), x0, v0, band).unwrap();
            // dT_s/dζ is O(1) s here, so the gap shrinks like eps.
            assert!(
                (below - t1).abs() < 10.0 * eps,
                "x0={x0} v0={v0} eps={eps}: {below} vs {t1}"
            );
            assert!(
                (above - t1).abs() < 10.0 * eps,
                "x0={x0} v0={v0} eps={eps}: {above} vs {t1}"
            );
        }
    }
    // ζ = 1 from rest: the root of (1 + u)e^{−u} = 0.05, u = 4.743864518390578
    // (SciPy brentq, xtol 1e-16).
    let t1 = settling_time(&sys(1.0), 1.0, 0.0, band).unwrap();
    assert!((t1 - 4.743_864_518_390_578).abs() < 1e-12);
}

#[test]
fn data_path_matches_the_exact_path_on_a_fine_grid() {
    let band = SettlingBand::FREE_DEFAULT;
    for &zeta in &[0.1, 0.4, 0.7, 1.0, 2.0] {
        let s = sys(zeta);
        let exact = FreeMetrics::exact(&s, 1.0, 0.0, band).unwrap();
        let t = zeta_solver::linspace(0.0, 60.0, 60_001);
        let mut x = vec![0.0; t.len()];
        FreeResponse::new(s, 1.0, 0.0).sample_into(&t, &mut x);
        let data = FreeMetrics::from_samples(&t, &x, band).unwrap();
        // Linear interpolation over dt = 1e-3 s: error ≤ dt²·max|x''|/(8·|x'|) ≪ 1e-4 s.
        assert!(
            (data.settling_time.unwrap() - exact.settling_time.unwrap()).abs() < 1e-4,
            "ζ={zeta}"
        );
        assert!(
            (data.peak_rebound - exact.peak_rebound).abs() < 1e-6,
            "ζ={zeta}"
        );
        assert_eq!(data.zero_crossings, exact.zero_crossings, "ζ={zeta}");
        match (data.log_decrement, exact.log_decrement) {
            (Some(a), Some(b)) => assert!((a - b).abs() < 1e-4, "ζ={zeta}"),
            (None, None) => {}
            other => panic!("ζ={zeta}: {other:?}"),
        }
    }
}

#[test]
fn settling_time_is_finite_and_positive_across_ten_thousand_dampings() {
    // The app's design grid evaluates this many systems per frame, with a non-zero v0.
    let band = SettlingBand::FREE_DEFAULT;
    for i in 0..10_000 {
        let zeta = 0.01 + 3.0 * i as f64 / 10_000.0;
        let ts = settling_time(&sys(zeta), 1.0, 0.3, band).unwrap();
        assert!(ts.is_finite() && ts > 0.0, "ζ={zeta}: {ts}");
    }
}

#[test]
fn settling_time_jumps_are_the_closed_form_zetas_from_rest() {
    use zeta_solver::metrics::free::{settling_time_jumps, settling_time_jumps_from_rest};
    // From rest the k-th extremum is e^{−kπζ/√(1−ζ²)}; it meets the band b at
    // ζ_k = L/√((kπ)² + L²), L = ln(1/b).
    for &b in &[0.05, 0.02, 0.2] {
        let band = SettlingBand::new(b).unwrap();
        let zetas: Vec<f64> = (0..400).map(|i| 0.02 + 2.0 * i as f64 / 399.0).collect();
        let jumps = settling_time_jumps(3.0, 0.06, 0.0, band, &zetas);
        let closed = settling_time_jumps_from_rest(band, zetas[0], zetas[399]);
        assert_eq!(closed.len(), jumps.len(), "band {b}: {closed:?}");
        for (c, j) in closed.iter().zip(&jumps) {
            assert!((c - j).abs() < 1e-13 * j, "band {b}: {c} vs {j}");
        }
        let l = (1.0 / b).ln();
        let mut expect: Vec<f64> = (1..200)
            .map(|k| l / ((k as f64 * PI).powi(2) + l * l).sqrt())
            .filter(|z| (0.02..=2.02).contains(z))
            .collect();
        expect.reverse();
        assert_eq!(jumps.len(), expect.len(), "band {b}: {jumps:?}");
        for (j, e) in jumps.iter().zip(&expect) {
            // Located to adjacent doubles; the closed form itself rounds at ~1e-15.
            assert!((j - e).abs() < 1e-13 * e, "band {b}: {j} vs {e}");
            // And the settling time really jumps there, by more than a tenth of a period.
            let below = settling_time(&sys(j * (1.0 - 1e-9)), 1.0, 0.0, band).unwrap();
            let above = settling_time(&sys(j * (1.0 + 1e-9)), 1.0, 0.0, band).unwrap();
            assert!(below - above > 0.1 * PI / WN, "band {b} at ζ = {j}");
        }
    }
}

#[test]
fn settling_time_jumps_find_every_jump_inside_one_coarse_interval() {
    use zeta_solver::metrics::free::settling_time_jumps;
    let band = SettlingBand::FREE_DEFAULT;
    let fine: Vec<f64> = (0..2000).map(|i| 0.05 + 0.9 * i as f64 / 1999.0).collect();
    let coarse = [0.05, 0.95];
    for &(x0, v0) in &[(1.0, 0.0), (-0.3, 1.2)] {
        let a = settling_time_jumps(WN, x0, v0, band, &fine);
        let b = settling_time_jumps(WN, x0, v0, band, &coarse);
        assert!(a.len() >= 3, "{a:?}");
        assert_eq!(a.len(), b.len());
        for (x, y) in a.iter().zip(&b) {
            assert!((x - y).abs() < 1e-13 * x, "{x} vs {y}");
        }
    }
    assert!(settling_time_jumps(WN, 1.0, 0.0, band, &[0.5]).is_empty());
    assert!(settling_time_jumps(WN, 1.0, 0.0, band, &[-0.5, 0.0]).is_empty());
}
