#![cfg(not(target_arch = "wasm32"))]
//! Forced responses: ODE residuals, initial conditions, resonance continuity, steady state,
//! impulse/step relation and superposition.

use proptest::prelude::*;
use zeta_solver::forced::{HarmonicForce, HarmonicResponse, ImpulseResponse, StepResponse};
use zeta_solver::{frf, FreeResponse, SecondOrder};

/// Quarter-car corner used throughout: m = 300 kg, k = 24 000 N/m, ω_n = √80 rad/s.
const WN: f64 = 8.944_271_909_999_16;

/// ODE residual `|a·x'' + b·x' + c·x − f|` with `x''` and `x'` from central differences of
/// the displacement, divided by its error budget: `1e-7·(|a·x''| + |b·x'| + |c·x| + |f|)`
/// for the truncation (step `h = 3e-4/scale`, so ~h²·scale²/12 ≈ 1e-8 relative) plus
/// `4·ε·(10 + scale·t)·a·m/h²` for rounding, with `m = max(|x|, |x'|/scale, size)` the size
/// of the components (x itself may be a small difference of them; `size` is the particular
/// solution's amplitude): each sample carries
/// ~10 ulp plus the rounding of the phase and decay arguments, which grows like `scale·t`
/// ulp. Also returns the
/// relative mismatch between the differenced and the returned velocity. A value ≤ 1 passes.
fn residuals(
    sys: SecondOrder,
    x: impl Fn(f64) -> f64,
    v: impl Fn(f64) -> f64,
    f: impl Fn(f64) -> f64,
    scale: f64,
    size: f64,
    t: f64,
) -> (f64, f64) {
    let h = 3e-4 / scale;
    let (xm, x0, xp) = (x(t - h), x(t), x(t + h));
    let acc = (xp - 2.0 * x0 + xm) / (h * h);
    let vel = (xp - xm) / (2.0 * h);
    let (a, b, c) = (sys.inertia(), sys.damping(), sys.stiffness());
    let terms = (a * acc).abs() + (b * vel).abs() + (c * x0).abs() + f(t).abs();
    let m = x0.abs().max(vel.abs() / scale).max(size);
    let noise = 4.0 * f64::EPSILON * (10.0 + scale * t) * a * m / (h * h);
    let budget = 1e-7 * terms + noise + 1e-300;
    let ode = (a * acc + b * vel + c * x0 - f(t)).abs() / budget;
    let vtol = v(t).abs().max(scale * x0.abs()).max(1e-300);
    (ode, (vel - v(t)).abs() / vtol)
}

/// Every regime: negative, vanishing, light, critical and heavy damping, no stiffness, and
/// negative stiffness. (A test helper: a bad constant here should stop the test loudly.)
#[allow(clippy::unwrap_used)]
fn systems() -> Vec<SecondOrder> {
    let mut out = Vec::new();
    for &z in &[
        -0.3, -1e-12, 0.0, 1e-12, 0.05, 0.3, 0.7, 0.72, 1.0, 1.5, 4.0,
    ] {
        out.push(SecondOrder::from_natural(WN, z).unwrap());
    }
    out.push(SecondOrder::new(2.0, 3.0, 0.0).unwrap()); // neutral, damped
    out.push(SecondOrder::new(2.0, 0.0, 0.0).unwrap()); // free mass
    out.push(SecondOrder::new(2.0, -1.0, 0.0).unwrap()); // neutral, negative damping
    out.push(SecondOrder::new(1.0, 1.0, -4.0).unwrap()); // divergent
    out.push(SecondOrder::new(1.0, 0.0, -4.0).unwrap()); // divergent, undamped
    out
}

#[test]
fn step_response_satisfies_ode_and_initial_conditions() {
    for sys in systems() {
        let r = StepResponse::new(sys, 1500.0, 0.04, -0.3);
        assert!((r.displacement(0.0) - 0.04).abs() < 1e-15, "{sys:?}");
        assert!((r.velocity(0.0) + 0.3).abs() < 1e-14, "{sys:?}");
        for &t in &[0.05, 0.3, 1.0, 2.7] {
            let size = r.equilibrium().unwrap_or(0.0).abs();
            let (ode, vel) = residuals(
                sys,
                |t| r.displacement(t),
                |t| r.velocity(t),
                |_| 1500.0,
                WN,
                size,
                t,
            );
            assert!(ode <= 1.0 && vel < 1e-7, "{sys:?} t={t}: {ode:e} {vel:e}");
            // The analytic acceleration agrees with the ODE.
            let acc =
                (1500.0 - sys.damping() * r.velocity(t) - sys.stiffness() * r.displacement(t))
                    / sys.inertia();
            assert!(
                (r.acceleration(t) - acc).abs() <= 1e-10 * (1.0 + acc.abs()),
                "{sys:?} t={t}"
            );
        }
    }
}

#[test]
fn step_without_stiffness_drifts_along_the_exact_ramp() {
    // a x'' + b x' = F0 from rest: x = (F0/b)·t − (F0·a/b²)·(1 − e^{−bt/a}).
    let (a, b, f0) = (2.0, 3.0, 6.0);
    let r = StepResponse::new(SecondOrder::new(a, b, 0.0).unwrap(), f0, 0.0, 0.0);
    assert_eq!(r.equilibrium(), None);
    for &t in &[0.5, 2.0, 10.0, 100.0] {
        let exact = f0 / b * t - f0 * a / (b * b) * (1.0 - (-b * t / a).exp());
        assert!((r.displacement(t) - exact).abs() < 1e-13 * exact, "t={t}");
    }
    // Tiny t: the series keeps the parabola F0 t²/(2a) exact where the closed form cancels.
    let t = 1e-6;
    assert!((r.displacement(t) / (f0 * t * t / (2.0 * a)) - 1.0).abs() < 1e-5);
}

#[test]
fn impulse_response_is_step_derivative_times_impulse_over_force() {
    for sys in systems() {
        let (f0, imp) = (800.0, 12.0);
        let step = StepResponse::new(sys, f0, 0.0, 0.0);
        let kick = ImpulseResponse::new(sys, imp, 0.0, 0.0);
        assert_eq!(kick.velocity_jump(), imp / sys.inertia());
        for &t in &[0.0, 0.1, 0.5, 1.7] {
            let want = step.velocity(t) * imp / f0;
            let tol = 1e-12 * (1.0 + want.abs()) + 1e-15 * kick.velocity_jump().abs();
            assert!((kick.displacement(t) - want).abs() < tol, "{sys:?} t={t}");
        }
    }
}

#[test]
fn impulse_from_a_moving_state_adds_the_jump() {
    let sys = SecondOrder::from_natural(WN, 0.3).unwrap();
    let r = ImpulseResponse::new(sys, 6.0, 0.02, 0.5);
    let free = FreeResponse::new(sys, 0.02, 0.5 + 6.0);
    assert_eq!(r.displacement(0.0), 0.02);
    assert_eq!(r.velocity(0.0), 6.5);
    assert_eq!(r.state(0.8), free.state(0.8));
}

/// Amplitude of the particular solution when the response is formed as particular + free
/// (`c ≤ 0` or `ζ² ≥ 1/2`; rounding then is ~ε·amplitude); 0 for the cancellation-free
/// undamped and lightly damped forms (see the module doc of `forced`).
fn particular_size(sys: SecondOrder, r: &HarmonicResponse) -> f64 {
    let alpha = sys.alpha();
    if sys.stiffness() > 0.0 && 2.0 * alpha * alpha < sys.omega_n_squared() {
        0.0
    } else {
        r.steady_state().map_or(0.0, |s| s.amplitude)
    }
}

/// Forcing frequencies: far below, near, at and above resonance, plus zero.
fn omegas() -> [f64; 6] {
    [0.0, 0.3 * WN, WN * (1.0 - 1e-3), WN, 1.7 * WN, 6.0 * WN]
}

#[test]
fn harmonic_response_satisfies_ode_and_initial_conditions() {
    for sys in systems() {
        for w in omegas() {
            let force = HarmonicForce::with_phase(900.0, w, 0.4).unwrap();
            let r = HarmonicResponse::new(sys, force, -0.01, 0.2);
            assert!((r.displacement(0.0) + 0.01).abs() < 1e-14, "{sys:?} ω={w}");
            assert!((r.velocity(0.0) - 0.2).abs() < 1e-13, "{sys:?} ω={w}");
            for &t in &[0.05, 0.4, 1.3, 3.1] {
                let (ode, vel) = residuals(
                    sys,
                    |t| r.displacement(t),
                    |t| r.velocity(t),
                    |t| force.at(t),
                    6.0 * WN,
                    particular_size(sys, &r),
                    t,
                );
                assert!(
                    ode <= 1.0 && vel < 1e-6,
                    "{sys:?} ω={w} t={t}: {ode:e} {vel:e}"
                );
            }
        }
    }
}

#[test]
fn undamped_resonance_is_the_secular_term() {
    // b = 0, ω = ω_n, from rest: x = F0/(2aω_n)·t·sin(ω_n t)  (textbook closed form).
    let (a, f0) = (300.0, 1000.0);
    let sys = SecondOrder::mechanical(a, 0.0, a * WN * WN).unwrap();
    let r = HarmonicResponse::new(sys, HarmonicForce::new(f0, WN).unwrap(), 0.0, 0.0);
    for &t in &[0.1, 1.0, 5.0, 40.0] {
        let exact = f0 / (2.0 * a * WN) * t * (WN * t).sin();
        assert!(
            (r.displacement(t) - exact).abs() < 1e-14 * f0 / (a * WN) * t,
            "t={t}"
        );
        // The envelope is F0 t/(2aω_n) exactly.
        let env = r.envelope(t).unwrap();
        assert!((env - f0 / (2.0 * a * WN) * t).abs() < 1e-14 * env);
    }
    assert!(r.steady_state().is_none());
    assert!(r.beat_period().is_none());
}

#[test]
fn undamped_response_is_continuous_as_forcing_approaches_resonance() {
    // x(ω_n(1 ± 1e-9)) − x(ω_n) ≈ ∂x/∂ω·Δω with |∂x/∂ω| ≤ (F0/(2aω_n))·t²·(1 + 1/(ω_n t)),
    // i.e. ≤ 1e-9·ω_n·t·(1 + ω_n t)·F0/(2aω_n). Tolerance: 4× that bound.
    let (a, f0) = (300.0, 1000.0);
    let sys = SecondOrder::mechanical(a, 0.0, a * WN * WN).unwrap();
    let at = |w: f64, t: f64| {
        HarmonicResponse::new(sys, HarmonicForce::new(f0, w).unwrap(), 0.01, -0.1).state(t)
    };
    for &t in &[0.01, 0.7, 3.0, 20.0] {
        let res = at(WN, t);
        for w in [WN * (1.0 - 1e-9), WN * (1.0 + 1e-9)] {
            let near = at(w, t);
            let bound = 4.0 * 1e-9 * WN * t * (1.0 + WN * t) * f0 / (2.0 * a * WN);
            assert!((near[0] - res[0]).abs() <= bound, "t={t} ω={w}");
            assert!((near[1] - res[1]).abs() <= bound * WN * 2.0, "t={t} ω={w}");
        }
    }
}

#[test]
fn beats_have_the_stated_period_and_envelope() {
    // From rest, b = 0: E(t) = F0/(a(ω+ω_n))·|sin(δt)/δ| vanishes at the beat period.
    let sys = SecondOrder::from_natural(WN, 0.0).unwrap();
    let w = 1.1 * WN;
    let r = HarmonicResponse::new(sys, HarmonicForce::new(1.0, w).unwrap(), 0.0, 0.0);
    let period = r.beat_period().unwrap();
    assert!((period - std::f64::consts::TAU / (0.1 * WN)).abs() < 1e-12 * period);
    assert!(r.envelope(period).unwrap() < 1e-15);
    // |x| ≤ E everywhere and touches it near the envelope maxima (within 2 %, as the carrier
    // is sampled every 1e-3 of a beat).
    let mut worst_touch: f64 = 0.0;
    for i in 0..=1000 {
        let t = period * i as f64 / 1000.0;
        let (x, e) = (r.displacement(t), r.envelope(t).unwrap());
        assert!(x.abs() <= e * (1.0 + 1e-12) + 1e-18, "t={t}");
        if (t - 0.5 * period).abs() < 0.05 * period {
            worst_touch = worst_touch.max(x.abs() / e);
        }
    }
    assert!(worst_touch > 0.98, "{worst_touch}");
}

#[test]
fn damped_envelope_bounds_the_response() {
    let sys = SecondOrder::from_natural(WN, 0.05).unwrap();
    let r = HarmonicResponse::new(sys, HarmonicForce::new(1.0, 0.9 * WN).unwrap(), 0.003, 0.0);
    let t: Vec<f64> = (0..2000).map(|i| i as f64 * 0.005).collect();
    let mut env = vec![0.0; t.len()];
    assert!(r.envelope_into(&t, &mut env));
    for (ti, e) in t.iter().zip(&env) {
        assert!(r.displacement(*ti).abs() <= e * (1.0 + 1e-12), "t={ti}");
    }
    // Non-oscillating systems have none.
    let over = SecondOrder::from_natural(WN, 2.0).unwrap();
    let r = HarmonicResponse::new(over, HarmonicForce::new(1.0, WN).unwrap(), 0.0, 0.0);
    assert!(r.envelope(1.0).is_none() && r.beat_period().is_none());
    assert!(!r.envelope_into(&t, &mut env));
}

#[test]
fn damped_response_settles_to_the_steady_state() {
    // After 40 time constants (e^{−40} ≈ 4e-18) only the particular solution is left.
    // Amplitude cross-checked against the frequency-response module: X = (F0/k)·|H(r)|.
    let (m, k, f0): (f64, f64, f64) = (300.0, 24_000.0, 1000.0);
    for &zeta in &[0.05, 0.3, 0.7, 1.0, 2.0] {
        let c = 2.0 * zeta * (m * k).sqrt();
        let sys = SecondOrder::mechanical(m, c, k).unwrap();
        for &r in &[0.5, 1.0, 1.3] {
            let w = r * WN;
            let resp = HarmonicResponse::new(sys, HarmonicForce::new(f0, w).unwrap(), 0.05, 1.0);
            let ss = resp.steady_state().unwrap();
            let amp = f0 / k * frf::magnitude(r, zeta);
            assert!((ss.amplitude - amp).abs() < 1e-12 * amp, "ζ={zeta} r={r}");
            assert!(
                (ss.phase - frf::phase(r, zeta)).abs() < 1e-12,
                "ζ={zeta} r={r}"
            );
            let slowest = sys.time_constants()[0].unwrap();
            let t0 = 40.0 * slowest;
            for i in 0..20 {
                let t = t0 + i as f64 * 0.037;
                let xss = ss.amplitude * (w * t + ss.phase).cos();
                assert!(
                    (resp.displacement(t) - xss).abs() < 1e-9 * amp,
                    "ζ={zeta} r={r} t={t}"
                );
            }
        }
    }
}

#[test]
fn light_damping_matches_the_textbook_particular_plus_transient() {
    // ζ = 0.1, ω = 0.8 ω_n (textbook form: X cos(ωt − θ) + free response of the remainder).
    let zeta = 0.1;
    let sys = SecondOrder::from_natural(WN, zeta).unwrap();
    let (f0, w, x0, v0) = (3.0, 0.8 * WN, 0.02, -0.4);
    let r = HarmonicResponse::new(sys, HarmonicForce::new(f0, w).unwrap(), x0, v0);
    let (re, im) = (WN * WN - w * w, 2.0 * zeta * WN * w);
    let amp = f0 / re.hypot(im);
    let theta = im.atan2(re);
    let free = FreeResponse::new(sys, x0 - amp * theta.cos(), v0 - amp * w * theta.sin());
    for &t in &[0.0, 0.2, 1.0, 4.0, 15.0] {
        let want = amp * (w * t - theta).cos() + free.displacement(t);
        assert!(
            (r.displacement(t) - want).abs() < 1e-14 * (amp + x0),
            "t={t}"
        );
    }
}

#[test]
fn vanishing_damping_joins_the_undamped_resonant_solution() {
    // ζ = 1e-12 at ω = ω_n: differs from b = 0 by ~ζ·ω_n·t relative (≤ 1e-9 here). The
    // naive particular-plus-transient form would lose ~1e-16/(ζ ω_n t) ≈ 1e-5 here.
    let force = HarmonicForce::new(1.0, WN).unwrap();
    let undamped =
        HarmonicResponse::new(SecondOrder::from_natural(WN, 0.0).unwrap(), force, 0.0, 0.0);
    for &z in &[1e-12, -1e-12] {
        let tiny =
            HarmonicResponse::new(SecondOrder::from_natural(WN, z).unwrap(), force, 0.0, 0.0);
        for &t in &[0.5, 3.0, 30.0] {
            let scale = t / (2.0 * WN);
            assert!(
                (tiny.displacement(t) - undamped.displacement(t)).abs() < 1e-9 * scale,
                "ζ={z} t={t}"
            );
        }
    }
}

#[test]
fn sampling_helpers_match_pointwise_values() {
    let sys = SecondOrder::from_natural(WN, 0.2).unwrap();
    let h = HarmonicResponse::new(sys, HarmonicForce::new(1.0, 5.0).unwrap(), 0.0, 0.0);
    let s = StepResponse::new(sys, 1.0, 0.0, 0.0);
    let t = [0.0, 0.5, 1.0];
    let mut out = [0.0; 3];
    h.sample_into(&t, &mut out);
    assert_eq!(out[2], h.displacement(1.0));
    h.velocity_into(&t, &mut out);
    assert_eq!(out[1], h.velocity(0.5));
    s.sample_into(&t, &mut out);
    assert_eq!(out[1], s.displacement(0.5));
    s.velocity_into(&t, &mut out[..2]);
    assert_eq!(out[1], s.velocity(0.5));
}

proptest! {
    #[test]
    fn superposition_holds(
        zeta in -0.5f64..3.0,
        w in 0.0f64..40.0,
        phase in -3.0f64..3.0,
        x0 in -0.1f64..0.1,
        v0 in -1.0f64..1.0,
        t in 0.0f64..5.0,
    ) {
        let sys = SecondOrder::from_natural(WN, zeta).unwrap();
        // Full response = free response + forced response from rest.
        let f = HarmonicForce::with_phase(2.0, w, phase).unwrap();
        let full = HarmonicResponse::new(sys, f, x0, v0).displacement(t);
        let rest = HarmonicResponse::new(sys, f, 0.0, 0.0).displacement(t);
        let free = FreeResponse::new(sys, x0, v0).displacement(t);
        let scale = 1.0 + rest.abs() + free.abs();
        prop_assert!((full - rest - free).abs() < 1e-10 * scale);
        // cos(ωt + φ) = cos φ·cos ωt − sin φ·sin ωt.
        let cos_part = HarmonicResponse::new(sys, HarmonicForce::new(2.0 * phase.cos(), w).unwrap(), 0.0, 0.0);
        let sin_part = HarmonicResponse::new(
            sys,
            HarmonicForce::with_phase(2.0 * phase.sin(), w, -std::f64::consts::FRAC_PI_2).unwrap(),
            0.0,
            0.0,
        );
        let sum = cos_part.displacement(t) - sin_part.displacement(t);
        prop_assert!((sum - rest).abs() < 1e-10 * (1.0 + rest.abs()));
        // Steps add: F1 + F2.
        let s = |f0: f64| StepResponse::new(sys, f0, 0.0, 0.0).displacement(t);
        prop_assert!((s(1.0) + s(2.5) - s(3.5)).abs() < 1e-12 * (1.0 + s(3.5).abs()));
    }
}

#[test]
fn beats_are_visible_only_while_slow_and_lasting() {
    use std::f64::consts::TAU;
    use zeta_solver::forced::Beats;
    let wn = 6.0;
    let resp = |zeta: f64, r: f64| {
        let sys = SecondOrder::from_natural(wn, zeta).unwrap();
        HarmonicResponse::new(sys, HarmonicForce::new(10.0, r * wn).unwrap(), 0.0, 0.0)
    };
    // Light damping near resonance: beats of period 2π/|ω − ω_d|.
    let wd = wn * (1.0f64 - 1e-4).sqrt();
    let near = resp(0.01, 0.9);
    assert_eq!(
        near.beats(),
        Beats::Visible {
            period: TAU / (wd - 0.9 * wn)
        }
    );
    assert_eq!(near.beats().period(), near.beat_period());
    // At resonance the transient dies long before half a beat: 2π/(ω_n(1 − √(1 − ζ²)))
    // against τ = 1/(ζω_n), for every damping ratio below 1 (heavier damping makes the
    // "beat" too fast to be one as well).
    assert!(matches!(resp(0.9, 1.0).beats(), Beats::TooFast { .. }));
    for zeta in [0.001, 0.01, 0.1, 0.5] {
        let b = resp(zeta, 1.0).beats();
        match b {
            Beats::DiesOut {
                period,
                time_constant,
            } => {
                let s = (1.0f64 - zeta * zeta).sqrt();
                assert!((period - TAU / (wn * (1.0 - s))).abs() < 1e-9 * period);
                assert!((time_constant - 1.0 / (zeta * wn)).abs() < 1e-12 * time_constant);
            }
            other => panic!("ζ = {zeta}: {other:?}"),
        }
        assert_eq!(b.period(), None);
    }
    // Far from resonance the "beat" is as fast as the oscillation itself.
    assert!(matches!(resp(0.1, 0.2).beats(), Beats::TooFast { .. }));
    assert!(matches!(resp(0.01, 3.0).beats(), Beats::TooFast { .. }));
    assert_eq!(resp(1.5, 0.9).beats(), Beats::NoFreeOscillation);
    // Undamped, driven exactly at ω_n: one frequency.
    assert_eq!(resp(0.0, 1.0).beats(), Beats::SameFrequency);
    // Undamped off resonance: the transient never dies, the beats last.
    assert!(matches!(resp(0.0, 0.95).beats(), Beats::Visible { .. }));
}
