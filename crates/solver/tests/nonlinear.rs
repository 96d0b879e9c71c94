#![cfg(not(target_arch = "wasm32"))]
// Helpers below are test code too; clippy only recognises `#[test]` functions as such.
#![allow(clippy::unwrap_used, clippy::panic)]
//! Nonlinear quarter car against closed forms and classic perturbation results.

use proptest::prelude::*;
use zeta_solver::nonlinear::{period_from_zero_crossings, NonlinearConfig, NonlinearModel};
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
        .period_ratio(period_from_zero_crossings)
        .unwrap();
    let r_soft = soft
        .compare(1.0, 0.0, 40.0, 1e-3)
        .unwrap()
        .period_ratio(period_from_zero_crossings)
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
    // F_c/k = 0.02 m, so 0.08 m per cycle. Exact stick–slip switch: tolerance 0.1 %.
    let fc = 0.02;
    let m = model(NonlinearConfig {
        friction: fc,
        ..unit()
    });
    let sol = m.simulate(1.01, 0.0, 60.0, 5e-4).unwrap();
    let x: Vec<f64> = sol.y.iter().map(|s| s[0]).collect();
    let p = peaks(&x);
    assert!(p.len() >= 8, "{p:?}");
    for w in p.windows(2) {
        let dec = w[0] - w[1];
        assert!((dec - 4.0 * fc).abs() < 0.001 * 4.0 * fc, "decrement {dec}");
    }
    // 25 half cycles of π s bring the amplitude from 1.01 to |1.01 − 25·0.04| = 0.01 ≤ F_c/k,
    // on the negative side: the mass sticks at x ≈ −0.01 at t ≈ 25π.
    // Each half cycle lasts exactly π s (the friction only shifts the centre), so the stop
    // is at 25π s to the accuracy of the event location (RK4 at h = 5e-4 s: < 1e-6 s).
    let mut out = vec![[0.0; 2]; 200_001];
    let stick = m.simulate_into(1.01, 0.0, 5e-4, &mut out).unwrap().unwrap();
    assert!(
        (stick.t - 25.0 * std::f64::consts::PI).abs() < 1e-6,
        "{stick:?}"
    );
    assert!((stick.x + 0.01).abs() < 1e-9, "{stick:?}");
    assert!(m.elastic_force(stick.x).abs() <= fc);
    // Stuck means stuck: no creep afterwards, to the last bit.
    let after = (stick.t / 5e-4).ceil() as usize;
    assert!(out[after..].iter().all(|s| *s == [stick.x, 0.0]));
    let long = m.simulate(1.01, 0.0, 100.0, 5e-4).unwrap();
    let grid = m.sticking(&long).unwrap();
    assert!(grid.t >= stick.t && grid.t - stick.t <= 5e-4 && grid.x == long.y[long.y.len() - 1][0]);
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
    assert!(cmp.period_ratio(period_from_zero_crossings).unwrap() < 0.9);
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(24))]

    #[test]
    fn energy_never_rises_when_every_dissipative_term_is_non_negative(
        k3 in 0.0f64..2.0,
        c_comp in 0.0f64..0.5,
        c_reb in 0.0f64..0.5,
        fc in 0.0f64..0.3,
        k_stop in 0.0f64..20.0,
        x0 in -1.0f64..1.0,
        v0 in -1.0f64..1.0,
    ) {
        let m = model(NonlinearConfig {
            k3, c_compression: c_comp, c_rebound: c_reb, friction: fc,
            static_friction: 1.3 * fc, stop_gap: 0.5, stop_stiffness: k_stop, ..unit()
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

#[test]
fn a_block_released_inside_the_static_band_stays_stuck() {
    // k = 1 N/m, F_c = 0.1 N kinetic, F_static = 0.15 N. Released at rest from x0 with
    // |k·x0| ≤ F_static the block never moves — also between F_c and F_static, where only
    // the static/kinetic switch holds it; beyond F_static it breaks away.
    let m = model(NonlinearConfig {
        friction: 0.1,
        static_friction: 0.15,
        ..unit()
    });
    for x0 in [0.0, 0.05, -0.099, 0.12, -0.15] {
        let mut out = vec![[9.0; 2]; 2001];
        let stick = m.simulate_into(x0, 0.0, 1e-2, &mut out).unwrap();
        assert_eq!(
            stick,
            Some(zeta_solver::nonlinear::Sticking { t: 0.0, x: x0 })
        );
        assert!(out.iter().all(|s| *s == [x0, 0.0]), "x0 = {x0}");
    }
    let sol = m.simulate(0.2, 0.0, 1.0, 1e-3).unwrap();
    assert!(
        sol.y.last().unwrap()[0] < 0.19,
        "breaks away beyond F_static"
    );
    // Static below kinetic counts as kinetic: a block at |k·x| = 0.1 N is held.
    let weak = model(NonlinearConfig {
        friction: 0.1,
        static_friction: 0.0,
        ..unit()
    });
    assert_eq!(weak.static_limit(), 0.1);
    assert!(weak.holds_at(0.1) && !weak.holds_at(0.1001));
}

#[test]
fn the_asymmetric_damper_switches_exactly_at_each_reversal() {
    // Undamped in compression, c = 0.2 in rebound, no friction: energy is constant while
    // compressing (v < 0) and falls while rebounding. Check the compression half-cycles
    // keep the energy to 1e-10 (RK4 at h = 1e-3, reversals located by bisection).
    let m = model(NonlinearConfig {
        c_compression: 0.0,
        c_rebound: 0.2,
        ..unit()
    });
    let sol = m.simulate(1.0, 0.0, 20.0, 1e-3).unwrap();
    for w in sol.y.windows(2) {
        if w[0][1] < 0.0 && w[1][1] < 0.0 {
            let (e0, e1) = (m.energy(w[0]), m.energy(w[1]));
            assert!((e1 - e0).abs() < 1e-10 * e0.max(1e-9), "{e0} {e1}");
        }
    }
    assert!(m.energy(*sol.y.last().unwrap()) < 0.5 * m.energy([1.0, 0.0]));
}

#[test]
fn the_first_swing_period_of_a_damped_sinusoid_is_its_damped_period() {
    // x = e^{−0.3t}·cos(2t − 0.4): zero crossings every π/2 s, so three of them span π s,
    // whatever the decay. Grid 1e-4 s, linear interpolation: error O(h²·decay) < 1e-8.
    let t: Vec<f64> = (0..=100_000).map(|i| i as f64 * 1e-4).collect();
    let x: Vec<f64> = t
        .iter()
        .map(|&t| (-0.3 * t).exp() * (2.0 * t - 0.4).cos())
        .collect();
    let p = zeta_solver::nonlinear::first_swing_period(&t, &x).unwrap();
    assert!((p - std::f64::consts::PI).abs() < 1e-8, "{p}");
    assert_eq!(
        zeta_solver::nonlinear::first_swing_period(&t[..100], &x[..100]),
        None
    );
    // A hardening spring at large amplitude swings faster in its first cycle.
    let m = model(NonlinearConfig {
        k3: 0.5,
        c_compression: 0.3,
        c_rebound: 0.3,
        ..unit()
    });
    let cmp = m.compare(1.0, 0.0, 30.0, 1e-3).unwrap();
    let r = cmp.first_swing_ratio().unwrap();
    assert!(r < 0.95, "{r}");
}
