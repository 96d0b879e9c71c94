//! Property tests of the model and the closed-form free response over the parameter space.
//! Tolerances are relative to the size of the terms involved, stated per property.
#![cfg(not(target_arch = "wasm32"))]
#![allow(clippy::unwrap_used)]

use proptest::prelude::*;
use zeta_solver::{FreeResponse, SecondOrder};

fn system() -> impl Strategy<Value = SecondOrder> {
    (0.1f64..100.0, -1.0f64..5.0)
        .prop_map(|(wn, zeta)| SecondOrder::from_natural(wn, zeta).unwrap())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(400))]

    /// a·x'' + b·x' + c·x = 0 from independently derived x, x', x'' (relative 1e-9 of the
    /// largest term), for every regime, over five time constants of the slowest mode.
    #[test]
    fn free_response_satisfies_the_ode(sys in system(), x0 in -1.0f64..1.0, v0 in -10.0f64..10.0, f in 0.0f64..1.0) {
        let r = FreeResponse::new(sys, x0, v0);
        let wn = sys.natural_frequency().unwrap();
        let t = f * 5.0 / wn;
        let (x, v, a) = (r.displacement(t), r.velocity(t), r.acceleration(t));
        let scale = a.abs().max(sys.damping().abs() * v.abs()).max(sys.stiffness() * x.abs()).max(1e-300);
        prop_assert!((a + sys.damping() * v + sys.stiffness() * x).abs() / scale < 1e-9);
    }

    /// x(0) = x0 and x'(0) = v0 exactly.
    #[test]
    fn initial_conditions_hold(sys in system(), x0 in -1.0f64..1.0, v0 in -10.0f64..10.0) {
        let r = FreeResponse::new(sys, x0, v0);
        prop_assert_eq!(r.displacement(0.0), x0);
        prop_assert_eq!(r.velocity(0.0), v0);
    }

    /// With b ≥ 0 the energy ½v² + ½ωₙ²x² never rises (relative slack 1e-12 for rounding).
    #[test]
    fn energy_never_rises_without_negative_damping(wn in 0.1f64..50.0, zeta in 0.0f64..4.0, x0 in -1.0f64..1.0, v0 in -5.0f64..5.0) {
        let sys = SecondOrder::from_natural(wn, zeta).unwrap();
        let r = FreeResponse::new(sys, x0, v0);
        let energy = |t: f64| { let [x, v] = r.state(t); 0.5 * v * v + 0.5 * wn * wn * x * x };
        let e0 = energy(0.0);
        let mut last = e0;
        for i in 1..200 {
            let e = energy(i as f64 * 0.05 / wn);
            prop_assert!(e <= last * (1.0 + 1e-12) + 1e-300);
            last = e;
        }
    }

    /// The response is linear in the initial state: x(−x0, −v0) = −x(x0, v0), and the sum of
    /// two responses is the response to the summed state (relative 1e-12).
    #[test]
    fn response_is_linear_in_the_initial_state(sys in system(), x0 in -1.0f64..1.0, v0 in -5.0f64..5.0, f in 0.0f64..1.0) {
        let t = f * 3.0 / sys.natural_frequency().unwrap();
        let x = |a: f64, b: f64| FreeResponse::new(sys, a, b).displacement(t);
        let scale = x(x0, 0.0).abs() + x(0.0, v0).abs() + 1e-300;
        prop_assert!((x(-x0, -v0) + x(x0, v0)).abs() <= 1e-12 * scale);
        prop_assert!((x(x0, 0.0) + x(0.0, v0) - x(x0, v0)).abs() <= 1e-12 * scale);
    }

    /// Crossing ζ = 1 from either side changes x(t) by O(ζ − 1): within 1e-6·(|x0| + |v0|/ωₙ)
    /// at |ζ − 1| = 1e-7.
    #[test]
    fn continuous_across_critical_damping(wn in 0.1f64..50.0, x0 in -1.0f64..1.0, v0 in -5.0f64..5.0, f in 0.0f64..1.0) {
        let t = f * 8.0 / wn;
        let x = |z: f64| FreeResponse::new(SecondOrder::from_natural(wn, z).unwrap(), x0, v0).displacement(t);
        let tol = 1e-6 * (x0.abs() + v0.abs() / wn + 1e-300);
        prop_assert!((x(1.0 - 1e-7) - x(1.0)).abs() <= tol);
        prop_assert!((x(1.0 + 1e-7) - x(1.0)).abs() <= tol);
    }

    /// Poles: s₁ + s₂ = −b/a and s₁·s₂ = c/a (relative 1e-12).
    #[test]
    fn poles_match_vieta(a in 0.1f64..10.0, b in -10.0f64..100.0, c in -50.0f64..500.0) {
        let sys = SecondOrder::new(a, b, c).unwrap();
        let [p, q] = sys.poles();
        let sum = p + q;
        let prod = p * q;
        let scale = (b / a).abs() + (c / a).abs().sqrt() + 1e-12;
        prop_assert!((sum.re + b / a).abs() <= 1e-12 * scale && sum.im.abs() <= 1e-12 * scale);
        prop_assert!((prod.re - c / a).abs() <= 1e-11 * scale * scale && prod.im.abs() <= 1e-11 * scale * scale);
    }

    /// Mechanical → electrical → mechanical gives back the same coefficients, and ζ, ωₙ, Q
    /// agree between the twins (relative 1e-14).
    #[test]
    fn analogy_round_trips(m in 0.1f64..1000.0, c in 0.0f64..10_000.0, k in 1.0f64..1e6) {
        let mech = SecondOrder::mechanical(m, c, k).unwrap();
        let (l, r, cap) = mech.as_electrical().unwrap();
        let elec = SecondOrder::electrical(l, r, cap).unwrap();
        prop_assert!((elec.stiffness() - k).abs() <= 1e-14 * k);
        prop_assert!((elec.damping_ratio().unwrap() - mech.damping_ratio().unwrap()).abs() <= 1e-14 * (1.0 + mech.damping_ratio().unwrap()));
        prop_assert!((elec.natural_frequency().unwrap() - mech.natural_frequency().unwrap()).abs() <= 1e-14 * mech.natural_frequency().unwrap());
    }
}
