#![cfg(not(target_arch = "wasm32"))]
// Helpers below are test code too; clippy only recognises `#[test]` functions as such.
#![allow(clippy::unwrap_used, clippy::panic)]
//! Exact runs of the two-DOF car: against RK4 on the same road, the frequency response, a
//! fine-step reference for a short bump and for a wheel that leaves the road, and
//! convergence as the road sampling and the pieces shrink.

use proptest::prelude::*;
use std::f64::consts::TAU;
use zeta_solver::integrate::{FixedStep, Rk4, System};
use zeta_solver::road::SampledRoad;
use zeta_solver::two_dof::{Road, TwoDof, TwoDofConfig, G};
use zeta_solver::two_dof_exact::{ExactConfig, ExactError, ExactMetrics, Tyre};

fn car(cfg: TwoDofConfig) -> TwoDof {
    TwoDof::new(cfg).unwrap()
}

fn ride(two: &TwoDof, road: &Road, t_end: f64, tyre: Tyre) -> ExactMetrics {
    let mut s = SampledRoad::default();
    two.ride_exact(road, t_end, tyre, &mut s).unwrap().metrics
}

/// The car on the analytic road with the tyre force `max(0, P − k_t·(z_u − u))`
/// (no tyre damping), for a fine-step RK4 reference written independently of the exact
/// solver.
struct Unilateral<'a> {
    car: &'a TwoDof,
    road: &'a Road,
}

impl System<4> for Unilateral<'_> {
    fn rhs(&self, t: f64, y: &[f64; 4], dy: &mut [f64; 4]) {
        let c = self.car.config();
        let weight = (c.sprung_mass + c.unsprung_mass) * G;
        let u = self.road.at(t).0;
        let susp = c.k_s * (y[0] - y[1]) + c.c_s * (y[2] - y[3]);
        let tyre = (weight - c.k_t * (y[1] - u)).max(0.0);
        dy[0] = y[2];
        dy[1] = y[3];
        dy[2] = -susp / c.sprung_mass;
        dy[3] = (susp + tyre - weight) / c.unsprung_mass;
    }
}

/// RMS body acceleration and tyre deflection (trapezoid rule), peak travel and time off
/// the road of an RK4 run with step `h` on the analytic road.
fn rk4_reference(two: &TwoDof, road: &Road, t_end: f64, h: f64, unilateral: bool) -> [f64; 4] {
    let sol = if unilateral {
        Rk4.solve(&Unilateral { car: two, road }, [0.0; 4], 0.0, t_end, h)
    } else {
        two.simulate(road, t_end, h)
    }
    .unwrap();
    let d0 = two.static_tyre_deflection();
    let (mut a2, mut d2, mut travel, mut air) = (0.0, 0.0, 0.0f64, 0.0);
    let n = sol.t.len();
    for i in 0..n {
        let y = &sol.y[i];
        let a = two.body_acceleration(y);
        let d = y[1] - road.at(sol.t[i]).0;
        let w = if i == 0 || i == n - 1 { 0.5 } else { 1.0 };
        a2 += w * a * a;
        d2 += w * d * d;
        travel = travel.max((y[0] - y[1]).abs());
        if i + 1 < n && d > d0 {
            air += sol.t[i + 1] - sol.t[i];
        }
    }
    let dt = sol.t[1] - sol.t[0];
    [
        (a2 * dt / t_end).sqrt(),
        (d2 * dt / t_end).sqrt(),
        travel,
        air,
    ]
}

fn assert_close(got: f64, want: f64, rel: f64, what: &str) {
    assert!(
        (got - want).abs() <= rel * want.abs(),
        "{what}: {got} vs {want} (rel {})",
        (got - want).abs() / want.abs()
    );
}

/// The ride metrics `m` against an [`rk4_reference`] `r`, to relative tolerances
/// `[RMS acceleration, RMS tyre deflection, peak travel]`.
fn assert_ride_matches(m: &ExactMetrics, r: &[f64; 4], rel: [f64; 3]) {
    assert_close(m.rms_body_acceleration, r[0], rel[0], "RMS acceleration");
    assert_close(m.rms_tyre_deflection, r[1], rel[1], "RMS tyre deflection");
    assert_close(m.max_suspension_travel, r[2], rel[2], "peak travel");
}

/// The default car over one bump, for the demo's window: the bump's duration `L/V` and
/// 2.5 s after it.
struct BumpCrossing {
    two: TwoDof,
    road: Road,
    t_end: f64,
}

impl BumpCrossing {
    /// A bump of `height` and `length` (m) crossed at `speed` (m/s).
    fn new(height: f64, length: f64, speed: f64) -> Self {
        Self {
            two: car(TwoDofConfig::default()),
            road: Road::bump(height, length, speed),
            t_end: length / speed + 2.5,
        }
    }

    /// The exact solver's ride metrics with `tyre`.
    fn ride(&self, tyre: Tyre) -> ExactMetrics {
        ride(&self.two, &self.road, self.t_end, tyre)
    }

    /// The unilateral tyre's [`rk4_reference`] at step `h` (s).
    fn reference(&self, h: f64) -> [f64; 4] {
        rk4_reference(&self.two, &self.road, self.t_end, h, true)
    }
}

#[test]
fn a_short_bump_gives_the_audits_fine_step_reference() {
    // ?demo=quarter-car-2dof&road=bump&L=0.1&V=40: a 5 cm bump lasting 2.5 ms, over the
    // demo's window L/V + 2.5 s. The audit's fine-step reference: 0.116 m/s² RMS body
    // acceleration and 2.82 mm peak travel (3 digits).
    let crossing = BumpCrossing::new(0.05, 0.1, 40.0);
    let m = crossing.ride(Tyre::Unilateral);
    assert_eq!(m.window, crossing.t_end);
    assert!((m.rms_body_acceleration - 0.116).abs() < 5e-4, "{m:?}");
    assert!((m.max_suspension_travel - 2.82e-3).abs() < 5e-6, "{m:?}");
    assert_eq!(m.airborne_time, 0.0);
    // Our own reference: RK4 at h = 2 µs (800 steps per bump) on the analytic road,
    // trapezoid rule; agreement to 1e-5 (observed ≈ 2e-6: the chords of the bump and the
    // reference's own step error).
    let r = crossing.reference(2e-6);
    assert_ride_matches(&m, &r, [1e-5, 1e-4, 1e-5]);
}

#[test]
fn a_wheel_thrown_off_the_road_flies_as_the_fine_step_reference_does() {
    // A 10 cm bump half a metre long at 20 m/s throws the default wheel off the road for
    // about 64 ms.
    let crossing = BumpCrossing::new(0.1, 0.5, 20.0);
    let m = crossing.ride(Tyre::Unilateral);
    assert!(m.lift_offs == 1 && m.airborne_time > 0.05, "{m:?}");
    let r = crossing.reference(5e-6);
    assert_ride_matches(&m, &r, [1e-4; 3]);
    // Time off the road: the reference counts whole steps of 5 µs.
    assert!(
        (m.airborne_time - r[3]).abs() < 2e-5 * m.lift_offs as f64 + 1e-5,
        "{m:?} {r:?}"
    );
    // The bilateral tyre pulls the wheel back: it gives another answer.
    let b = crossing.ride(Tyre::Bilateral);
    assert!((b.rms_tyre_deflection / m.rms_tyre_deflection - 1.0).abs() > 0.01);
}

#[test]
fn without_lift_off_the_two_tyre_models_agree_and_match_rk4_on_the_same_chords() {
    let two = car(TwoDofConfig {
        c_t: 120.0,
        ..Default::default()
    });
    let road = Road::bump(0.02, 2.0, 10.0);
    let mut s = SampledRoad::default();
    s.fill_uniform(&road, 1000.0, 1.0);
    let cfg = |tyre| ExactConfig {
        tyre,
        max_step: 1e-3,
    };
    let uni = two.run_exact(&s, cfg(Tyre::Unilateral)).unwrap();
    let bi = two.run_exact(&s, cfg(Tyre::Bilateral)).unwrap();
    assert_eq!(uni, bi);
    assert_eq!(uni.metrics.airborne_time, 0.0);
    // RK4 at 1e-5 s on each chord in turn (the road u = u_i + s_i·(t − t_i) and its slope
    // u' = s_i for every stage of the chord's steps): states at every sample agree to 1e-9
    // of the largest excursion.
    let reach = uni
        .y
        .iter()
        .map(|y| y[0].abs().max(y[1].abs()))
        .fold(0.0, f64::max);
    let mut y = [0.0; 4];
    for i in 0..s.len() - 1 {
        let (t0, u0) = (s.times()[i], s.heights()[i]);
        let slope = (s.heights()[i + 1] - u0) / (s.times()[i + 1] - t0);
        let chord = Chord {
            car: &two,
            t0,
            u0,
            slope,
        };
        for j in 0..100 {
            Rk4.step(&chord, t0 + j as f64 * 1e-5, 1e-5, &mut y)
                .unwrap();
        }
        let e = &uni.y[i + 1];
        for k in 0..2 {
            assert!(
                (e[k] - y[k]).abs() < 1e-9 * reach,
                "t={} {e:?} {y:?}",
                uni.t[i + 1]
            );
        }
    }
}

/// The car on one chord of the road, `u = u0 + slope·(t − t0)`, `u' = slope`.
struct Chord<'a> {
    car: &'a TwoDof,
    t0: f64,
    u0: f64,
    slope: f64,
}

impl System<4> for Chord<'_> {
    fn rhs(&self, t: f64, y: &[f64; 4], dy: &mut [f64; 4]) {
        let c = self.car.config();
        let u = self.u0 + self.slope * (t - self.t0);
        let susp = c.k_s * (y[0] - y[1]) + c.c_s * (y[2] - y[3]);
        let tyre = c.k_t * (y[1] - u) + c.c_t * (y[3] - self.slope);
        dy[0] = y[2];
        dy[1] = y[3];
        dy[2] = -susp / c.sprung_mass;
        dy[3] = (susp - tyre) / c.unsprung_mass;
    }
}

#[test]
fn a_sine_road_settles_on_the_frequency_response() {
    // Sine 1 cm at 2 Hz for 15 s: after the transient (e^-18), the body and tyre-deflection
    // amplitudes are |H|·1 cm. The road's chords (100 per period) lower the fundamental
    // by 3.3e-4; sampling the peak every 1/100 period misses it by ≤ 5e-4.
    let two = car(TwoDofConfig::default());
    let (amp, f) = (0.01, 2.0);
    let road = Road::sine(amp, f);
    let mut s = SampledRoad::default();
    let run = two
        .ride_exact(&road, 15.0, Tyre::Bilateral, &mut s)
        .unwrap();
    let (mut body, mut tyre) = (0.0f64, 0.0f64);
    for ((t, y), u) in run.t.iter().zip(&run.y).zip(&run.u) {
        if *t >= 12.0 {
            body = body.max(y[0].abs());
            tyre = tyre.max((y[1] - u).abs());
        }
    }
    let h = two.frf(TAU * f);
    assert_close(body, h.body.abs() * amp, 1e-3, "body amplitude");
    assert_close(tyre, h.tyre_deflection.abs() * amp, 1e-3, "tyre amplitude");
    // RMS of a sinusoid of amplitude A over many periods: A/√2 (the 3 s transient and the
    // part period shift it by under 1 %).
    let acc = h.body_acceleration.abs() * amp;
    assert_close(
        run.metrics.rms_body_acceleration,
        acc / 2f64.sqrt(),
        0.01,
        "RMS",
    );
}

#[test]
fn invalid_input_is_a_typed_error() {
    let two = car(TwoDofConfig::default());
    let mut s = SampledRoad::default();
    let cfg = ExactConfig {
        tyre: Tyre::Unilateral,
        max_step: 1e-3,
    };
    assert_eq!(two.run_exact(&s, cfg), Err(ExactError::InvalidRoad));
    s.fill_uniform(&Road::Flat, 100.0, 1.0);
    assert!(matches!(
        two.run_exact(
            &s,
            ExactConfig {
                max_step: 0.0,
                ..cfg
            }
        ),
        Err(ExactError::InvalidStep { .. })
    ));
    assert!(matches!(
        two.run_exact(
            &s,
            ExactConfig {
                max_step: 1e-9,
                ..cfg
            }
        ),
        Err(ExactError::TooManySteps { .. })
    ));
    assert!(two
        .ride_exact(&Road::Flat, f64::NAN, Tyre::Bilateral, &mut s)
        .is_err());
    // A flat road leaves the car at rest.
    let m = two.run_exact(&s, cfg).unwrap().metrics;
    assert_eq!(m.rms_body_acceleration, 0.0);
}

/// Metrics of a bump run at resolution level `k`: `16·k` chords over the bump and chords
/// of at most a `25·k`-th of the wheel-hop period after it (`k = 8` is [`TwoDof::ride_exact`]'s
/// resolution).
fn bump_metrics(two: &TwoDof, road: &Road, on: f64, k: usize) -> [f64; 3] {
    let h = 1.0 / (25.0 * k as f64 * two.natural_frequencies_hz()[1]);
    let chords = (16 * k).max((on / h).ceil() as usize);
    let t_end = on + 0.5;
    let mut s = SampledRoad::default();
    s.fill_segments(
        road,
        &[(on, chords), (t_end, ((t_end - on) / h).ceil() as usize)],
    );
    let m = two
        .run_exact(
            &s,
            ExactConfig {
                tyre: Tyre::Unilateral,
                max_step: h,
            },
        )
        .unwrap()
        .metrics;
    [
        m.rms_body_acceleration,
        m.rms_tyre_deflection,
        m.max_suspension_travel,
    ]
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(12))]

    /// As the road's chords and the pieces shrink, every metric converges: the difference
    /// from a run 4× finer than the demo's falls at least 3× per halving (the chord error is
    /// O(Δt²)), and at the demo's resolution it is below 3e-4 of the value.
    #[test]
    fn metrics_converge_as_the_step_shrinks(
        ms in 150.0f64..700.0, mu in 15.0f64..120.0, ks in 8e3f64..6e4, kt in 8e4f64..4e5,
        cs in 300.0f64..5000.0, height in 0.01f64..0.1, length in 0.1f64..3.0, speed in 3.0f64..40.0,
    ) {
        let two = car(TwoDofConfig { sprung_mass: ms, unsprung_mass: mu, k_s: ks, k_t: kt, c_s: cs, c_t: 0.0 });
        let road = Road::bump(height, length, speed);
        let on = length / speed;
        let levels = [2, 4, 8].map(|k| bump_metrics(&two, &road, on, k));
        let fine = bump_metrics(&two, &road, on, 32);
        for m in 0..3 {
            let e: Vec<f64> = levels.iter().map(|l| (l[m] - fine[m]).abs()).collect();
            let floor = 1e-9 * fine[m];
            prop_assert!(e[1] <= e[0] / 3.0 + floor, "metric {m}: {levels:?} {fine:?}");
            prop_assert!(e[2] <= e[1] / 3.0 + floor, "metric {m}: {levels:?} {fine:?}");
            prop_assert!(e[2] <= 3e-4 * fine[m], "metric {m}: {levels:?} vs {fine:?}");
        }
    }
}
