#![cfg(not(target_arch = "wasm32"))]
// Helpers below are test code too; clippy only recognises `#[test]` functions as such.
#![allow(clippy::unwrap_used, clippy::panic)]
//! Two-DOF quarter car: natural frequencies, frequency responses, energy balance, roads.

use std::f64::consts::TAU;
use zeta_solver::base::transmissibility;
use zeta_solver::integrate::{FixedStep, Rk4};
use zeta_solver::two_dof::{
    IsoClass, RandomRoad, RandomRoadConfig, Road, TwoDof, TwoDofConfig, ISO_N0,
};

fn car(cfg: TwoDofConfig) -> TwoDof {
    TwoDof::new(cfg).unwrap()
}

/// The default car with tyre damping `c_t` (N·s/m).
fn car_with_tyre_damping(c_t: f64) -> TwoDof {
    car(TwoDofConfig {
        c_t,
        ..Default::default()
    })
}

#[test]
fn natural_frequencies_are_roots_of_the_characteristic_polynomial() {
    let c = TwoDofConfig::default();
    let [w1, w2] = car(c).natural_frequencies();
    let a = c.sprung_mass * c.unsprung_mass;
    let b = c.k_s * c.unsprung_mass + (c.k_s + c.k_t) * c.sprung_mass;
    let p = c.k_s * c.k_t;
    for w in [w1, w2] {
        // det(K − ω²M) written out from the matrices, not from the quadratic's coefficients.
        let l = w * w;
        let det =
            (c.k_s - l * c.sprung_mass) * (c.k_s + c.k_t - l * c.unsprung_mass) - c.k_s * c.k_s;
        assert!(det.abs() < 1e-12 * p, "ω={w}: det {det}");
    }
    // Vieta: sum b/a and product p/a of the roots λ = ω².
    assert!((w1 * w1 + w2 * w2 - b / a).abs() < 1e-12 * b / a);
    assert!((w1 * w1 * w2 * w2 - p / a).abs() < 1e-12 * p / a);
    // Typical car: body bounce 1–1.5 Hz, wheel hop 10–15 Hz; and the classic decoupled
    // estimates √(k_s k_t/(k_s + k_t)/m_s) and √((k_s + k_t)/m_u) are within 2 %.
    let [f1, f2] = car(c).natural_frequencies_hz();
    assert!(
        (1.0..1.5).contains(&f1) && (10.0..15.0).contains(&f2),
        "{f1} {f2}"
    );
    let body = (c.k_s * c.k_t / (c.k_s + c.k_t) / c.sprung_mass).sqrt();
    let hop = ((c.k_s + c.k_t) / c.unsprung_mass).sqrt();
    assert!((w1 / body - 1.0).abs() < 0.02 && (w2 / hop - 1.0).abs() < 0.02);
}

#[test]
fn at_zero_frequency_the_body_follows_the_road() {
    let f = car_with_tyre_damping(100.0).frf(1e-9);
    assert!((f.body.re - 1.0).abs() < 1e-12 && f.body.im.abs() < 1e-6);
    assert!(f.tyre_deflection.abs() < 1e-9 && f.body_acceleration.abs() < 1e-15);
}

#[test]
fn tiny_wheel_on_a_rigid_tyre_reduces_to_base_excitation() {
    // m_u → 0, k_t → ∞: z_u = u and the body sees 1-DOF base excitation with
    // ω_n = √(k_s/m_s), ζ = c_s/(2√(k_s m_s)). Residual coupling ~ m_u/m_s and k_s/k_t ≈ 1e-5.
    let c = TwoDofConfig {
        unsprung_mass: 1e-3,
        k_t: 1e10,
        ..Default::default()
    };
    let two = car(c);
    let wn = (c.k_s / c.sprung_mass).sqrt();
    let zeta = c.c_s / (2.0 * (c.k_s * c.sprung_mass).sqrt());
    for i in 1..=60 {
        let r = 0.05 * i as f64;
        let t = transmissibility(r, zeta);
        let got = two.frf(r * wn).body.abs();
        assert!((got - t).abs() < 1e-4 * t.max(1.0), "r={r}: {got} vs {t}");
    }
}

#[test]
fn frequency_response_matches_the_time_simulation() {
    // Sine road 0.01 m at 2 Hz: after the transient (slowest decay rate ≈ 1.5 1/s, 12 s ⇒
    // e^-18), the body amplitude equals |Z_s/U|·0.01 and the tyre deflection |(Z_u−U)/U|·0.01.
    let two = car(TwoDofConfig::default());
    let (amp, f) = (0.01, 2.0);
    let road = Road::sine(amp, f);
    let sol = two.simulate(&road, 15.0, 1e-3).unwrap();
    let tail = sol.t.iter().zip(&sol.y).filter(|(t, _)| **t >= 12.0);
    let (mut body, mut tyre) = (0.0f64, 0.0f64);
    for (&t, y) in tail {
        body = body.max(y[0].abs());
        tyre = tyre.max((y[1] - road.at(t).0).abs());
    }
    let h = two.frf(TAU * f);
    // Sampling a sine every 1/500 period misses its peak by ≤ 1 − cos(π/500) ≈ 2e-5.
    assert!((body / (h.body.abs() * amp) - 1.0).abs() < 1e-4, "{body}");
    assert!(
        (tyre / (h.tyre_deflection.abs() * amp) - 1.0).abs() < 1e-4,
        "{tyre}"
    );
}

/// `E(T) − E(0)`, `∫(P_road − P_diss) dt` (composite Simpson rule on the uniform grid, error
/// ∝ (hω)⁴ for the wheel-hop content) and the largest |running work| as a scale.
fn energy_balance(two: &TwoDof, road: &Road, t_end: f64, h: f64) -> (f64, f64, f64) {
    let sol = two.simulate(road, t_end, h).unwrap();
    assert_eq!(
        (sol.t.len() - 1) % 2,
        0,
        "Simpson needs an even number of steps"
    );
    let net = |i: usize| {
        let (u, du) = road.at(sol.t[i]);
        two.road_power(&sol.y[i], u, du) - two.dissipated_power(&sol.y[i], du)
    };
    let mut work = 0.0;
    let mut scale = 0.0f64;
    for i in (2..sol.t.len()).step_by(2) {
        let dt = sol.t[i] - sol.t[i - 2];
        work += dt / 6.0 * (net(i - 2) + 4.0 * net(i - 1) + net(i));
        scale = scale.max(work.abs());
    }
    let last = sol.y.len() - 1;
    let de =
        two.energy(&sol.y[last], road.at(sol.t[last]).0) - two.energy(&sol.y[0], road.at(0.0).0);
    (de, work, scale)
}

#[test]
fn energy_change_equals_road_work_minus_damper_losses() {
    // 5 cm bump, 0.5 m long at 10 m/s, with tyre damping too. RK4 at h = 1e-4 s and
    // Simpson's rule. The road puts in and the dampers take out ≈ 245 J while the net
    // change is only 0.034 J; the balance holds to ≈ 1.3e-10 of the work that flowed
    // (observed), asserted at 1e-9.
    let two = car_with_tyre_damping(150.0);
    let road = Road::bump(0.05, 0.5, 10.0);
    let (de, work, scale) = energy_balance(&two, &road, 1.0, 1e-4);
    assert!(
        (de - work).abs() < 1e-9 * scale,
        "ΔE {de} vs work {work} (scale {scale})"
    );
}

#[test]
fn with_the_road_held_fixed_energy_only_decays_or_is_conserved() {
    // Step road: after t = 0 the road is fixed at 2 cm and the car starts 2 cm too low.
    // The first RK4 step still sees u(0) = 0 in its first stage, so the energy is
    // followed from the end of that step.
    let road = Road::Step { height: 0.02 };
    let two = car(TwoDofConfig::default());
    let sol = two.simulate(&road, 5.0, 1e-4).unwrap();
    let e: Vec<f64> = sol.y.iter().skip(1).map(|y| two.energy(y, 0.02)).collect();
    assert!(e.windows(2).all(|w| w[1] <= w[0] * (1.0 + 1e-12)));
    assert!(e[e.len() - 1] < 1e-3 * e[0]);

    // Undamped: conserved by a fine-step RK4 (hω_hop ≈ 7.5e-3, local energy error
    // ∝ (hω)⁶ per step) to 1e-9.
    let free = car(TwoDofConfig {
        c_s: 0.0,
        c_t: 0.0,
        ..Default::default()
    });
    let sol = free.simulate(&road, 5.0, 1e-4).unwrap();
    let e0 = free.energy(&sol.y[1], 0.02);
    for y in &sol.y[1..] {
        assert!((free.energy(y, 0.02) / e0 - 1.0).abs() < 1e-9);
    }
}

#[test]
fn random_road_has_the_iso_8608_variance() {
    // ∫ G_d(n0)(n0/n)² dn over [n_min, n_max] = G_d(n0)·n0²·(1/n_min − 1/n_max).
    let cfg = RandomRoadConfig {
        components: 4096,
        ..Default::default()
    };
    let fine = RandomRoad::new(cfg).unwrap();
    let exact = IsoClass::C.g_d_n0() * ISO_N0 * ISO_N0 * (1.0 / cfg.n_min - 1.0 / cfg.n_max);
    // Midpoint sum vs integral: the 1/n² weight is steepest in the first band; 1 % suffices
    // at 4096 bands.
    let v = fine.variance();
    assert!((v / exact - 1.0).abs() < 0.01, "{v} vs {exact}");
    // The profile itself (256 components) over 2 km (22 periods of the longest wave) has its
    // nominal variance to within 10 % (random phases leave cross terms of order
    // 1/(record length · Δn)).
    let road = RandomRoad::new(RandomRoadConfig::default()).unwrap();
    let n = 20_000;
    let dt = 100.0 / n as f64;
    let (mut s, mut s2) = (0.0, 0.0);
    for i in 0..n {
        let u = road.at(i as f64 * dt).0;
        s += u;
        s2 += u * u;
    }
    let var = s2 / n as f64 - (s / n as f64).powi(2);
    let nominal = road.variance();
    assert!((var / nominal - 1.0).abs() < 0.1, "{var} vs {nominal}");
}

#[test]
fn random_road_is_reproducible_and_scales_by_class() {
    let c = RandomRoadConfig::default();
    let a = RandomRoad::new(c).unwrap();
    let b = RandomRoad::new(c).unwrap();
    let other = RandomRoad::new(RandomRoadConfig { seed: 2, ..c }).unwrap();
    assert_eq!(a.at(3.7), b.at(3.7));
    assert_ne!(a.at(3.7), other.at(3.7));
    // One class up quadruples G_d, so doubles every amplitude (same seed ⇒ same phases),
    // and the linear car's RMS responses double exactly.
    let d = RandomRoad::new(RandomRoadConfig {
        class: IsoClass::D,
        ..c
    })
    .unwrap();
    assert!((d.at(3.7).0 / a.at(3.7).0 - 2.0).abs() < 1e-12);
    let two = car(TwoDofConfig::default());
    let metrics = |r: RandomRoad| {
        let road = Road::Random(r);
        let sol = two.simulate(&road, 5.0, 1e-3).unwrap();
        two.metrics(&road, &sol).unwrap()
    };
    let (mc, md) = (metrics(a), metrics(d));
    assert!((md.rms_body_acceleration / mc.rms_body_acceleration - 2.0).abs() < 1e-9);
    assert!((md.rms_tyre_deflection / mc.rms_tyre_deflection - 2.0).abs() < 1e-9);
    // Class C at 20 m/s gives a body acceleration of the order of 1 m/s² (ride-comfort
    // literature: 0.3–3 m/s² for passenger cars on average roads).
    assert!((0.3..3.0).contains(&mc.rms_body_acceleration), "{mc:?}");
}

#[test]
fn rk4_step_matches_simulate_for_the_driven_car() {
    // `simulate` is RK4 from rest; driving the same System by hand gives the same states.
    let two = car(TwoDofConfig::default());
    let road = Road::bump(0.05, 0.5, 10.0);
    let sol = two.simulate(&road, 0.2, 1e-3).unwrap();
    let mut y = [0.0; 4];
    for i in 0..200 {
        Rk4.step(&two.driven(&road), i as f64 * 1e-3, 1e-3, &mut y)
            .unwrap();
    }
    let last = sol.y.last().unwrap();
    assert!(y.iter().zip(last).all(|(a, b)| (a - b).abs() < 1e-12));
    assert!(last[0].abs() > 1e-4, "the bump moved the body: {last:?}");
}
