#![cfg(not(target_arch = "wasm32"))]
// Helpers below are test code too; clippy only recognises `#[test]` functions as such.
#![allow(clippy::unwrap_used, clippy::panic)]
//! Nonlinear quarter car against closed forms and classic perturbation results.

use proptest::prelude::*;
use zeta_solver::nonlinear::{NonlinearConfig, NonlinearModel};
use zeta_solver::FreeResponse;

fn model(cfg: NonlinearConfig) -> NonlinearModel {
    NonlinearModel::new(cfg).unwrap()
}

/// Unit oscillator m = 1 kg, k = 1 N/m (ω0 = 1 rad/s), no damping unless set.
fn unit() -> NonlinearConfig {
    NonlinearConfig {
        mass: 1.0,
        k: 1.0,
        c_compression: 0.0,
        c_rebound: 0.0,
        ..Default::default()
    }
}

#[test]
fn with_every_nonlinearity_off_it_matches_the_linear_closed_form() {
    // Default quarter car (m = 300 kg, k = 24 000 N/m, c = 1 610 N·s/m, ζ = 0.3) with
    // k3 = 0, symmetric damper, no friction, no stops. RK4 at h = 2.5e-4 s: (hω)⁴ ≈ 2.5e-11.
    let m = model(NonlinearConfig::default());
    let lin = FreeResponse::new(m.linear_model().unwrap(), 0.06, -0.2);
    let sol = m.simulate(0.06, -0.2, 3.0, 2.5e-4).unwrap();
    for (&t, s) in sol.t.iter().zip(&sol.y) {
        let e = lin.state(t);
        assert!((s[0] - e[0]).abs() < 1e-8, "t={t}: {} vs {}", s[0], e[0]);
        assert!((s[1] - e[1]).abs() < 1e-7, "t={t}");
    }
    let cmp = m.compare(0.06, -0.2, 3.0, 2.5e-4).unwrap();
    assert!(cmp.max_deviation() < 1e-8);
}

#[test]
fn duffing_frequency_follows_lindstedt_poincare() {
    // First-order Lindstedt–Poincaré: ω = ω0(1 + 3ε/8), ε = k3·A²/k. The next term is
    // −21ε²/256 (Nayfeh & Mook, Nonlinear Oscillations, 1979, §4.1.1), so the first-order
    // formula is good to 0.1·ε²; the numerical period (RK4, 2000 steps per period, 20
    // periods) adds < 1e-7.
    for &(k3, amp) in &[
        (0.01, 1.0),
        (0.04, 0.5),
        (0.05, 1.0),
        (-0.03, 1.0),
        (2.0, 0.1),
    ] {
        let m = model(NonlinearConfig { k3, ..unit() });
        let eps = k3 * amp * amp / 1.0;
        let period = m.period_at_amplitude(amp, 20, 2000).unwrap();
        let omega = std::f64::consts::TAU / period;
        let lp = 1.0 + 3.0 * eps / 8.0;
        assert!(
            (omega / lp - 1.0).abs() <= 0.1 * eps * eps + 1e-7,
            "k3={k3} A={amp}: ω = {omega}, Lindstedt–Poincaré {lp}"
        );
        // And the second-order term is really what is left (sign and size within 20 %).
        if eps.abs() >= 0.03 {
            let rest = omega - lp;
            let second = -21.0 * eps * eps / 256.0;
            assert!(
                (rest - second).abs() < 0.2 * second.abs(),
                "k3={k3}: {rest} vs {second}"
            );
        }
    }
}

#[test]
fn hardening_shortens_and_softening_lengthens_the_period() {
    let hard = model(NonlinearConfig { k3: 0.5, ..unit() });
    let soft = model(NonlinearConfig { k3: -0.2, ..unit() });
    let r_hard = hard
        .compare(1.0, 0.0, 40.0, 1e-3)
        .unwrap()
        .period_ratio()
        .unwrap();
    let r_soft = soft
        .compare(1.0, 0.0, 40.0, 1e-3)
        .unwrap()
        .period_ratio()
        .unwrap();
    assert!(r_hard < 0.9 && r_soft > 1.05, "{r_hard} {r_soft}");
}

/// Positive peaks of x (local maxima on the grid).
fn peaks(x: &[f64]) -> Vec<f64> {
    x.windows(3)
        .filter_map(|w| (w[1] > w[0] && w[1] >= w[2] && w[1] > 0.0).then_some(w[1]))
        .collect()
}

#[test]
fn coulomb_friction_decays_the_amplitude_linearly_by_4fc_over_k_per_cycle() {
    // Classic result (Den Hartog, Mechanical Vibrations, §8.7): each half cycle loses
    // 2F_c/k of amplitude, each full cycle 4F_c/k, and the frequency stays ω0. Here
    // F_c/k = 0.02 m, so 0.08 m per cycle. Regularisation v_ε = 1e-5 m/s; tolerance 0.5 %.
    let fc = 0.02;
    let m = model(NonlinearConfig {
        friction: fc,
        friction_velocity: 1e-5,
        ..unit()
    });
    let sol = m.simulate(1.01, 0.0, 60.0, 5e-4).unwrap();
    let x: Vec<f64> = sol.y.iter().map(|s| s[0]).collect();
    let p = peaks(&x);
    assert!(p.len() >= 8, "{p:?}");
    for w in p.windows(2) {
        let dec = w[0] - w[1];
        assert!((dec - 4.0 * fc).abs() < 0.005 * 4.0 * fc, "decrement {dec}");
    }
    // 25 half cycles of π s bring the amplitude from 1.01 to |1.01 − 25·0.04| = 0.01 ≤ F_c/k,
    // on the negative side: the mass sticks at x ≈ −0.01 at t ≈ 25π.
    let long = m.simulate(1.01, 0.0, 100.0, 5e-4).unwrap();
    let stick = m.sticking(&long).unwrap();
    assert!(
        (stick.t - 25.0 * std::f64::consts::PI).abs() < 0.05,
        "{stick:?}"
    );
    assert!((stick.x + 0.01).abs() < 1e-3, "{stick:?}");
    assert!(m.elastic_force(stick.x).abs() <= fc);
}

#[test]
fn no_sticking_without_friction() {
    let m = model(unit());
    let sol = m.simulate(1.0, 0.0, 10.0, 1e-3).unwrap();
    assert_eq!(m.sticking(&sol), None);
}

#[test]
fn bump_stops_limit_the_travel() {
    // Released from 0.2 m (0.1 m into a stop 20× stiffer than the spring), undamped. The
    // potential is even, so energy conservation sends the mass exactly to −0.2 m.
    let cfg = NonlinearConfig {
        stop_gap: 0.1,
        stop_stiffness: 20.0,
        ..unit()
    };
    let m = model(cfg);
    let sol = m.simulate(0.2, 0.0, 20.0, 1e-3).unwrap();
    let min = sol.y.iter().map(|s| s[0]).fold(f64::INFINITY, f64::min);
    assert!(
        (min + 0.2).abs() < 1e-6,
        "symmetric potential: swing to −0.2, got {min}"
    );
    let e0 = m.energy([0.2, 0.0]);
    let drift = sol
        .y
        .iter()
        .map(|s| (m.energy(*s) - e0).abs() / e0)
        .fold(0.0, f64::max);
    // RK4's local error drops to O(h²)·Δk at each crossing of the stop's kink (force
    // continuous, stiffness not): ≈ 1.5e-6 over the ~12 crossings here at h = 1e-3 s.
    assert!(drift < 1e-5, "{drift:e}");
    // Period shorter than the linear 2π.
    let cmp = m.compare(0.2, 0.0, 20.0, 1e-3).unwrap();
    assert!(cmp.period_ratio().unwrap() < 0.9);
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(24))]

    #[test]
    fn energy_never_rises_when_every_dissipative_term_is_non_negative(
        k3 in 0.0f64..2.0,
        c_comp in 0.0f64..0.5,
        c_reb in 0.0f64..0.5,
        fc in 0.0f64..0.05,
        k_stop in 0.0f64..20.0,
        x0 in -1.0f64..1.0,
        v0 in -1.0f64..1.0,
    ) {
        let m = model(NonlinearConfig {
            k3, c_compression: c_comp, c_rebound: c_reb, friction: fc,
            friction_velocity: 1e-3, stop_gap: 0.5, stop_stiffness: k_stop, ..unit()
        });
        let sol = m.simulate(x0, v0, 20.0, 1e-3).unwrap();
        let e0 = m.energy([x0, v0]);
        let mut prev = e0;
        for s in &sol.y {
            let e = m.energy(*s);
            // RK4's local energy error (≈ (hω)⁵, ω ≤ √(1 + 3k3 + k_stop) < 6) is far below
            // this allowance.
            prop_assert!(e <= prev + 1e-10 * e0.max(1e-12), "energy rose from {} to {}", prev, e);
            prev = e;
        }
    }
}

#[test]
fn compare_steps_matches_compare_and_cuts_an_escaping_run() {
    // Same grid i·h as `compare` when t_end is a whole number of steps.
    let m = model(NonlinearConfig { k3: 0.3, ..unit() });
    let a = m.compare(0.5, 0.0, 10.0, 1e-2).unwrap();
    let b = m.compare_steps(0.5, 0.0, 1e-2, 1000, 1.0);
    assert_eq!(a.t.len(), b.t.len());
    assert!(!b.escaped);
    for (p, q) in a.nonlinear.iter().zip(&b.nonlinear) {
        assert!((p[0] - q[0]).abs() < 1e-12);
    }
    // A softening spring released beyond √(−k/k3) = 1 m runs away: cut at |x| > 1.5.
    let soft = model(NonlinearConfig { k3: -1.0, ..unit() });
    let run = soft.compare_steps(1.2, 0.0, 1e-2, 1000, 1.5);
    assert!(run.escaped && run.t.len() < 1001 && !run.t.is_empty());
    assert!(run.nonlinear.iter().all(|s| s[0].abs() <= 1.5));
    assert_eq!(run.linear.len(), run.t.len());
}

#[test]
fn deviation_interpolation_and_period_helpers() {
    let m = model(NonlinearConfig { k3: 0.5, ..unit() });
    let cmp = m.compare_steps(1.0, 0.0, 1e-2, 2000, 10.0);
    let (dev, at) = cmp.largest_deviation();
    assert!((dev - cmp.max_deviation()).abs() < 1e-15);
    let i = cmp.t.iter().position(|&t| t == at).unwrap();
    assert!(((cmp.nonlinear[i][0] - cmp.linear[i][0]).abs() - dev).abs() < 1e-15);
    // Interpolation hits grid values and holds the ends.
    assert_eq!(cmp.nonlinear_at(cmp.t[7]), Some(cmp.nonlinear[7][0]));
    assert_eq!(cmp.nonlinear_at(-1.0), Some(1.0));
    let mid = cmp.nonlinear_at(0.5 * (cmp.t[3] + cmp.t[4])).unwrap();
    assert!((mid - 0.5 * (cmp.nonlinear[3][0] + cmp.nonlinear[4][0])).abs() < 1e-15);
    // T = 2π√(m/k).
    let t = zeta_solver::nonlinear::undamped_period(300.0, 24_000.0).unwrap();
    assert!((t - std::f64::consts::TAU * (300.0f64 / 24_000.0).sqrt()).abs() < 1e-15);
    assert_eq!(zeta_solver::nonlinear::undamped_period(300.0, 0.0), None);
    assert_eq!(zeta_solver::nonlinear::undamped_period(-1.0, 1.0), None);
}
