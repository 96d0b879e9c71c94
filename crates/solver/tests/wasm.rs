//! The solver's reference checks, run again as WebAssembly (`wasm-pack test --node
//! crates/solver`): the same closed forms must give the same numbers in the browser's
//! floating-point environment as natively.
#![cfg(target_arch = "wasm32")]

use wasm_bindgen_test::wasm_bindgen_test;
use zeta_solver::{FreeResponse, Regime, SecondOrder};

#[wasm_bindgen_test]
fn quarter_car_natural_frequency() {
    let s = SecondOrder::mechanical(300.0, 0.0, 24_000.0).unwrap();
    assert!((s.natural_frequency().unwrap() - 8.944_271_909_999_16).abs() < 1e-12);
}

#[wasm_bindgen_test]
fn rlc_critical_resistance() {
    let s = SecondOrder::electrical(0.5, 10.0, 0.02).unwrap();
    assert!((s.critical_damping().unwrap() - 10.0).abs() < 1e-12);
    assert_eq!(s.regime(), Regime::CriticallyDamped);
}

#[wasm_bindgen_test]
fn free_response_satisfies_the_ode_across_regimes() {
    for zeta in [-0.3, 0.0, 0.2, 1.0, 1.000_001, 2.5] {
        let sys = SecondOrder::from_natural(6.0, zeta).unwrap();
        let r = FreeResponse::new(sys, 0.06, 0.1);
        for t in [0.0, 0.05, 0.4, 1.7] {
            let (x, v, a) = (r.displacement(t), r.velocity(t), r.acceleration(t));
            let res = a + sys.damping() * v + sys.stiffness() * x;
            let scale = a
                .abs()
                .max(sys.damping().abs() * v.abs())
                .max(sys.stiffness() * x.abs())
                .max(1e-300);
            assert!(res.abs() / scale < 1e-12, "ζ={zeta} t={t}");
        }
    }
}

#[wasm_bindgen_test]
fn continuity_across_critical_damping() {
    let x = |z: f64| {
        FreeResponse::new(SecondOrder::from_natural(6.0, z).unwrap(), 0.06, 0.0).displacement(0.3)
    };
    assert!((x(1.0 - 1e-6) - x(1.0)).abs() < 1e-7);
    assert!((x(1.0 + 1e-6) - x(1.0)).abs() < 1e-7);
}
