//! One equation, many machines: each machine's `(a, b, c)` against values derived by hand
//! from its formula (computed independently, to the digits shown); matched machines give
//! the same normalised response; the two-capacity thermal system never oscillates.
#![cfg(not(target_arch = "wasm32"))]
#![allow(clippy::unwrap_used, clippy::panic)]

use proptest::prelude::*;
use zeta_solver::machines::{
    DcServo, Machine, MassSpringDamper, MatchError, SeriesRlc, Storey, Target, TwoCapacityThermal,
    UTube,
};
use zeta_solver::{FreeResponse, Regime, SecondOrder};

fn close(got: f64, want: f64, rel: f64) -> bool {
    (got - want).abs() <= rel * want.abs().max(1e-300)
}

fn coefficients(sys: SecondOrder) -> (f64, f64, f64) {
    (sys.inertia(), sys.damping(), sys.stiffness())
}

fn assert_coefficients(name: &str, sys: SecondOrder, want: (f64, f64, f64)) {
    let got = coefficients(sys);
    for (g, w) in [(got.0, want.0), (got.1, want.1), (got.2, want.2)] {
        assert!(close(g, w, 1e-14), "{name}: got {got:?}, want {want:?}");
    }
}

#[test]
fn each_machine_maps_to_its_hand_derived_coefficients() {
    // m = 2 kg, c = 3 N·s/m, k = 50 N/m: a = m, b = c, c = k.
    let msd = MassSpringDamper::new(2.0, 3.0, 50.0).unwrap();
    assert_coefficients("mass–spring", msd.system(), (2.0, 3.0, 50.0));
    // L = 0.5 H, R = 4 Ω, C = 20 mF: a = L, b = R, c = 1/C = 50 1/F.
    let rlc = SeriesRlc::new(0.5, 4.0, 0.02).unwrap();
    assert_coefficients("RLC", rlc.system(), (0.5, 4.0, 50.0));
    // Water column L = 0.5 m in a 10 mm bore: A = π·(0.01)²/4 = 7.853 981 6e-5 m²;
    // a = ρAL = 0.039 269 908 2 kg, b = 8πμL = 0.012 566 370 6 N·s/m,
    // c = 2ρgA = 1.540 424 980 N/m; ωₙ = √(2g/L) = 6.263 114 241 rad/s.
    let tube = UTube::new(0.5, 0.01, 1000.0, 1e-3).unwrap();
    assert_coefficients(
        "U-tube",
        tube.system(),
        (
            0.039_269_908_169_872_414,
            0.012_566_370_614_359_173,
            1.540_424_979_816_317_2,
        ),
    );
    assert!(close(
        tube.system().natural_frequency().unwrap(),
        6.263_114_241_333_938_5,
        1e-14
    ));
    // ζ = 16μ/(ρd²ωₙ) = 0.016/(0.1·6.263 114 241) = 0.025 545 468.
    assert!(close(
        tube.system().damping_ratio().unwrap(),
        0.016 / (0.1 * 6.263_114_241_333_938_5),
        1e-14
    ));
    // J = 1 g·m², K_t = 0.1 N·m/A, R = 2 Ω, K_p = 20 V/rad, K_d = 0.1 V·s/rad:
    // b = 0.1·(0.1 + 0.1)/2 = 0.01 N·m·s/rad, c = 0.1·20/2 = 1 N·m/rad.
    let servo = DcServo::new(1e-3, 0.1, 2.0, 20.0, 0.1).unwrap();
    assert_coefficients("servo", servo.system(), (1e-3, 0.01, 1.0));
    // 20 t floor on four columns of EI = 10 MN·m², 3 m high, c = 60 kN·s/m:
    // k = 12·4·1e7/27 = 17 777 777.78 N/m.
    let storey = Storey::new(2e4, 3.0, 1e7, 4.0, 6e4).unwrap();
    assert_coefficients(
        "storey",
        storey.system(),
        (2e4, 6e4, 17_777_777.777_777_776),
    );
    // C₁ = 1000 J/K, R₁ = 1 K/W, C₂ = 100 J/K, R₂ = 1 K/W: τ₁ = 1000 s, τ₂ = 100 s,
    // R₁C₂ = 100 s: a = 1e5 s², b = 1200 s, c = 1; ζ = 1200/(2·316.227 766) = 1.897 366 6.
    let thermal = TwoCapacityThermal::new(1000.0, 1.0, 100.0, 1.0).unwrap();
    assert_coefficients("thermal", thermal.system(), (1e5, 1200.0, 1.0));
    assert!(close(
        thermal.system().damping_ratio().unwrap(),
        1.897_366_596_101_027_6,
        1e-14
    ));
    // b² − 4ac = 1200² − 4e5 = 1 040 000 s².
    assert!(close(thermal.discriminant(), 1_040_000.0, 1e-15));
}

/// One machine of each kind, at the demo's defaults (a fast thermocouple for the thermal
/// system, so that its ωₙ is within reach of the others).
fn sources() -> Vec<(&'static str, SecondOrder)> {
    vec![
        (
            "mass–spring",
            MassSpringDamper::new(1.0, 2.0, 100.0).unwrap().system(),
        ),
        ("RLC", SeriesRlc::new(0.1, 10.0, 1e-3).unwrap().system()),
        (
            "U-tube",
            UTube::new(0.5, 0.01, 1000.0, 1e-3).unwrap().system(),
        ),
        (
            "servo",
            DcServo::new(1e-3, 0.1, 2.0, 20.0, 0.1).unwrap().system(),
        ),
        (
            "storey",
            Storey::new(2e4, 3.0, 1e7, 4.0, 6e4).unwrap().system(),
        ),
        (
            "thermal",
            TwoCapacityThermal::new(0.05, 2.0, 0.01, 5.0)
                .unwrap()
                .system(),
        ),
    ]
}

/// The largest difference between the normalised free responses `y(t)/y₀` (released from
/// rest) of `a` and `b` over five slow time constants or four periods of `a`.
fn largest_gap(a: SecondOrder, b: SecondOrder) -> f64 {
    let (ra, rb) = (
        FreeResponse::new(a, 1.0, 0.0),
        FreeResponse::new(b, 1.0, 0.0),
    );
    let wn = a.natural_frequency().unwrap();
    let slow = a.time_constants()[0].unwrap_or(1.0 / wn);
    let t_end = (8.0 * std::f64::consts::PI / wn).max(5.0 * slow);
    (0..=2000)
        .map(|i| {
            let t = t_end * i as f64 / 2000.0;
            (ra.displacement(t) - rb.displacement(t)).abs()
        })
        .fold(0.0, f64::max)
}

/// Tunes `machine` to each source; checks ωₙ, ζ and the responses, or that the failure is
/// the documented one. Returns how many matched.
fn match_all<M: Machine>(name: &str, machine: &M) -> usize {
    let mut matched = 0;
    for (source, sys) in sources() {
        let target = Target::of(&sys).unwrap();
        match machine.matched(target) {
            Ok(tuned) => {
                let t = tuned.system();
                assert!(close(t.natural_frequency().unwrap(), target.wn(), 1e-12));
                assert!(close(t.damping_ratio().unwrap(), target.zeta(), 1e-12));
                let gap = largest_gap(sys, t);
                assert!(gap < 1e-12, "{name} tuned to {source}: gap {gap}");
                matched += 1;
            }
            Err(MatchError::DampingTooLow { zeta_min, zeta }) => {
                assert!(zeta_min > zeta, "{name} ← {source}: {zeta_min} ≤ {zeta}");
            }
            Err(e) => panic!("{name} ← {source}: {e}"),
        }
    }
    matched
}

#[test]
fn matched_machines_give_identical_normalised_responses() {
    // Machines with free damping reach every source.
    assert_eq!(
        match_all(
            "mass–spring",
            &MassSpringDamper::new(5.0, 1.0, 10.0).unwrap()
        ),
        6
    );
    assert_eq!(match_all("RLC", &SeriesRlc::new(1.0, 1.0, 1.0).unwrap()), 6);
    assert_eq!(
        match_all("U-tube", &UTube::new(1.0, 0.005, 13_534.0, 1.5e-3).unwrap()),
        6
    );
    assert_eq!(
        match_all("storey", &Storey::new(5e4, 3.5, 1e8, 4.0, 1e5).unwrap()),
        6
    );
    // The motor's back-EMF alone gives ζ ≥ K_t²/(2ωₙRJ) = 0.25/ωₙ: the U-tube (ζ = 0.026
    // at ωₙ = 6.26 rad/s, which needs ζ ≥ 0.040) would need K_d < 0.
    assert_eq!(
        match_all("servo", &DcServo::new(1e-3, 0.05, 5.0, 10.0, 0.0).unwrap()),
        5
    );
    // A thermal system reaches only the overdamped source (ζ ≥ √(1 + C₂/C₁) = 1.095).
    assert_eq!(
        match_all(
            "thermal",
            &TwoCapacityThermal::new(1.0, 1.0, 0.2, 1.0).unwrap()
        ),
        1
    );
}

#[test]
fn matching_twice_changes_nothing() {
    let target = Target::new(14.0, 1.3).unwrap();
    let once = TwoCapacityThermal::new(0.05, 2.0, 0.01, 5.0)
        .unwrap()
        .matched(target)
        .unwrap();
    let twice = once.matched(target).unwrap();
    let (a, b) = (once.params(), twice.params());
    for (x, y) in [(a.1, b.1), (a.3, b.3)] {
        assert!(close(x, y, 1e-13), "{a:?} {b:?}");
    }
}

fn log_uniform(lo: f64, hi: f64) -> impl Strategy<Value = f64> {
    (lo.log10()..hi.log10()).prop_map(|e| 10f64.powf(e))
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(2000))]

    /// ζ = (τ₁ + τ₂ + R₁C₂)/(2√(τ₁τ₂)) ≥ 1 for every positive C₁, R₁, C₂, R₂ over twelve
    /// decades each (to rounding: 4 ulp), and the system never oscillates.
    #[test]
    fn a_two_capacity_thermal_system_never_oscillates(
        c1 in log_uniform(1e-6, 1e6),
        r1 in log_uniform(1e-6, 1e6),
        c2 in log_uniform(1e-6, 1e6),
        r2 in log_uniform(1e-6, 1e6),
    ) {
        let th = TwoCapacityThermal::new(c1, r1, c2, r2).unwrap();
        let sys = th.system();
        prop_assert!(sys.damping_ratio().unwrap() >= 1.0 - 4.0 * f64::EPSILON);
        prop_assert!(th.discriminant() > 0.0);
        prop_assert!(sys.damped_frequency().is_none());
        prop_assert!(matches!(sys.regime(), Regime::Overdamped | Regime::CriticallyDamped));
    }

    /// Tuning hits any reachable target to 1e-12 in ωₙ and ζ.
    #[test]
    fn tuning_reaches_the_target(
        wn in log_uniform(1e-3, 1e4),
        zeta in 0.0f64..5.0,
        m in log_uniform(1e-2, 1e4),
        d in log_uniform(1e-3, 0.1),
    ) {
        let target = Target::new(wn, zeta).unwrap();
        let systems = [
            MassSpringDamper::new(m, 1.0, 1.0).unwrap().matched(target).unwrap().system(),
            SeriesRlc::new(m, 1.0, 1.0).unwrap().matched(target).unwrap().system(),
            UTube::new(1.0, d, 1000.0, 1e-3).unwrap().matched(target).unwrap().system(),
            Storey::new(m, 3.0, 1e6, 4.0, 1.0).unwrap().matched(target).unwrap().system(),
        ];
        for sys in systems {
            prop_assert!(close(sys.natural_frequency().unwrap(), wn, 1e-12));
            prop_assert!((sys.damping_ratio().unwrap() - zeta).abs() <= 1e-12 * zeta.max(1e-3));
        }
    }
}
