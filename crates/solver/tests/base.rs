//! Base excitation: transmissibility identities and the closed-form bump response checked
//! against the ODE, limits, and an independent fine-step RK4 integration.

use zeta_solver::base::{self, Bump, BumpResponse};
use zeta_solver::forced::{HarmonicForce, HarmonicResponse};
use zeta_solver::{FreeResponse, SecondOrder};

/// Quarter-car corner: m = 300 kg, k = 24 000 N/m (ω_n = √80 = 8.944 rad/s).
const M: f64 = 300.0;
const K: f64 = 24_000.0;

fn car(zeta: f64) -> SecondOrder {
    let c = 2.0 * zeta * (M * K).sqrt();
    match SecondOrder::mechanical(M, c, K) {
        Ok(s) => s,
        Err(e) => unreachable!("{e}"),
    }
}

#[test]
fn transmissibility_equals_the_base_driven_steady_state() {
    // Independent route: road u = U cos ωt acts as the force k·u + c·u' = Re[U(k + icω)e^{iωt}];
    // the forced module's steady state divided by U must be T(r, ζ), with T's phase.
    for &zeta in &[0.05, 0.3, 1.0] {
        let sys = car(zeta);
        let wn = sys.natural_frequency().unwrap();
        for &r in &[0.2, 0.9, 1.0, 1.3, std::f64::consts::SQRT_2, 4.0] {
            let w = r * wn;
            let (fr, fi) = (K, sys.damping() * w);
            let f = HarmonicForce::with_phase(fr.hypot(fi), w, fi.atan2(fr)).unwrap();
            let ss = HarmonicResponse::new(sys, f, 0.0, 0.0)
                .steady_state()
                .unwrap();
            let t = base::transmissibility(r, zeta);
            assert!((ss.amplitude - t).abs() < 1e-13 * t, "ζ={zeta} r={r}");
            let phase = ss.phase + fi.atan2(fr);
            assert!(
                (phase - base::transmissibility_phase(r, zeta)).abs() < 1e-13,
                "ζ={zeta} r={r}"
            );
        }
    }
}

#[test]
fn all_curves_cross_at_root_two() {
    for &zeta in &[0.0, 0.01, 0.2, 0.7, 1.0, 5.0] {
        assert!((base::transmissibility(base::CROSSOVER_RATIO, zeta) - 1.0).abs() < 1e-15);
        // Below the crossover more damping helps isolation less; above it, it hurts.
        assert!(base::transmissibility(1.2, zeta) > 1.0);
        assert!(base::transmissibility(1.6, zeta) < 1.0);
    }
}

#[test]
fn peak_transmissibility_is_the_maximum() {
    for &zeta in &[0.01, 0.05, 0.1, 0.3, 0.7, 2.0] {
        let p = base::peak_transmissibility(zeta).unwrap();
        // Closed form r_p² = (√(1 + 8ζ²) − 1)/(4ζ²) (Rao, Mechanical Vibrations, §3.10),
        // evaluated directly: agrees to the cancellation error ~1e-16/ζ².
        let direct = (((1.0 + 8.0 * zeta * zeta).sqrt() - 1.0) / (4.0 * zeta * zeta)).sqrt();
        assert!((p.ratio - direct).abs() < 1e-15 / (zeta * zeta), "ζ={zeta}");
        // No point on a fine grid is higher.
        for i in 0..=20_000 {
            let r = i as f64 * 1e-4;
            assert!(
                base::transmissibility(r, zeta) <= p.gain * (1.0 + 1e-14),
                "ζ={zeta} r={r}"
            );
        }
    }
    // ζ = 0.1: r_p = 0.990334, T = 5.12277 (closed forms evaluated independently in Python).
    let p = base::peak_transmissibility(0.1).unwrap();
    assert!((p.ratio - 0.990_334).abs() < 1e-6, "{}", p.ratio);
    assert!((p.gain - 5.122_77).abs() < 1e-5, "{}", p.gain);
    assert!(base::peak_transmissibility(0.0).is_none());
}

#[test]
fn acceleration_transmissibility_grows_like_two_zeta_r() {
    let zeta = 0.3;
    let r = 1e5;
    let a = base::acceleration_transmissibility(r, zeta);
    assert!((a / (2.0 * zeta * r) - 1.0).abs() < 1e-6);
    assert_eq!(base::acceleration_transmissibility(0.0, zeta), 0.0);
}

/// Classic RK4 on `m x'' = c(u' − x') + k(u − x)`, `n` steps from 0 to `t_end`.
fn rk4(sys: SecondOrder, bump: Bump, t_end: f64, n: usize) -> [f64; 2] {
    let (m, c, k) = (sys.inertia(), sys.damping(), sys.stiffness());
    let f = |t: f64, y: [f64; 2]| {
        let (u, du) = (bump.profile(t), bump.profile_velocity(t));
        [y[1], (c * (du - y[1]) + k * (u - y[0])) / m]
    };
    let h = t_end / n as f64;
    let mut y = [0.0, 0.0];
    for i in 0..n {
        let t = i as f64 * h;
        let k1 = f(t, y);
        let k2 = f(
            t + 0.5 * h,
            [y[0] + 0.5 * h * k1[0], y[1] + 0.5 * h * k1[1]],
        );
        let k3 = f(
            t + 0.5 * h,
            [y[0] + 0.5 * h * k2[0], y[1] + 0.5 * h * k2[1]],
        );
        let k4 = f(t + h, [y[0] + h * k3[0], y[1] + h * k3[1]]);
        for j in 0..2 {
            y[j] += h / 6.0 * (k1[j] + 2.0 * k2[j] + 2.0 * k3[j] + k4[j]);
        }
    }
    y
}

#[test]
fn bump_response_matches_fine_step_rk4() {
    // RK4 with the bump duration split into 4000 steps (and the same step after it) has
    // global error ~(hω)⁴ ≈ 1e-12 relative; the right-hand side's kink at t = L/V costs
    // O(h²)·h per step there, still < 1e-9 of h. Tolerance: 1e-8·h.
    let bump = Bump::new(0.05, 2.0, 10.0).unwrap();
    for &zeta in &[0.0, 0.3, 1.0, 2.5] {
        let sys = car(zeta);
        let ride = BumpResponse::new(sys, bump).unwrap();
        let dt = bump.duration() / 4000.0;
        for &t in &[0.05, 0.2, 0.5, 1.3] {
            let n = (t / dt).round() as usize;
            let y = rk4(sys, bump, n as f64 * dt, n);
            let got = ride.state(n as f64 * dt);
            assert!(
                (got[0] - y[0]).abs() < 1e-8 * 0.05,
                "ζ={zeta} t={t}: {got:?} {y:?}"
            );
            assert!((got[1] - y[1]).abs() < 1e-8 * 0.05 * 9.0, "ζ={zeta} t={t}");
        }
    }
}

#[test]
fn bump_response_satisfies_the_ode() {
    // m x'' + c(x' − u') + k(x − u) = 0 with x'' by central differences (h = 1e-5 s;
    // truncation ~h²ω⁴|x|/12 and rounding ~1e-16|x|/h² both far below 1e-6 of the terms).
    let bump = Bump::new(0.08, 1.5, 12.0).unwrap();
    for &zeta in &[0.05, 0.4, 1.0] {
        let sys = car(zeta);
        let ride = BumpResponse::new(sys, bump).unwrap();
        for &t in &[0.01, 0.06, 0.11, 0.3, 0.9] {
            let h = 1e-5;
            let acc = (ride.displacement(t + h) - 2.0 * ride.displacement(t)
                + ride.displacement(t - h))
                / (h * h);
            let (x, v) = (ride.displacement(t), ride.velocity(t));
            let (u, du) = (bump.profile(t), bump.profile_velocity(t));
            let terms = [M * acc, sys.damping() * (v - du), K * (x - u)];
            let scale: f64 = terms.iter().map(|v| v.abs()).sum();
            assert!(
                terms.iter().sum::<f64>().abs() < 1e-6 * scale,
                "ζ={zeta} t={t}"
            );
            // Body acceleration agrees with the differenced one.
            assert!(
                (ride.acceleration(t) - acc).abs() < 1e-6 * scale / M,
                "ζ={zeta} t={t}"
            );
        }
    }
}

#[test]
fn state_is_continuous_when_the_wheel_leaves_the_bump() {
    let bump = Bump::new(0.05, 0.8, 15.0).unwrap();
    for &zeta in &[0.0, 0.25, 1.0, 3.0] {
        let ride = BumpResponse::new(car(zeta), bump).unwrap();
        let te = bump.duration();
        let eps = 1e-12 * te;
        let (before, after) = (ride.state(te - eps), ride.state(te + eps));
        // Over 2ε the state moves by (x', x'')·2ε; what is left is rounding of the two
        // closed forms: 1e-16 m and 1e-13 m/s on |x| ≈ 0.02 m, |x'| ≈ 1 m/s.
        let dx = after[0] - before[0] - 2.0 * eps * ride.velocity(te);
        let dv = after[1] - before[1] - 2.0 * eps * ride.acceleration(te);
        assert!(dx.abs() < 1e-16, "ζ={zeta} {before:?} {after:?}");
        assert!(dv.abs() < 1e-13, "ζ={zeta} {before:?} {after:?}");
        let acc_jump = (ride.acceleration(te - eps) - ride.acceleration(te + eps)).abs();
        assert!(
            acc_jump < 1e-9,
            "ζ={zeta}: body acceleration must be continuous, jump {acc_jump}"
        );
    }
}

#[test]
fn long_slow_bump_is_followed_quasi_statically() {
    // L/V = 100 natural periods (Ω/ω_n = 0.01): x − u ≈ −u''/ω_n², |u''| ≤ (h/2)Ω², so
    // |x − u| ≤ h·(Ω/ω_n)² with room for the start-up transient of the same size.
    let wn = (K / M).sqrt();
    let duration = 100.0 * std::f64::consts::TAU / wn;
    let bump = Bump::new(0.05, duration * 10.0, 10.0).unwrap();
    let ratio: f64 = bump.omega() / wn;
    let ride = BumpResponse::new(car(0.3), bump).unwrap();
    let mut worst: f64 = 0.0;
    for i in 0..=1000 {
        let t = duration * i as f64 / 1000.0;
        worst = worst.max((ride.displacement(t) - bump.profile(t)).abs());
    }
    assert!(worst < 0.05 * ratio * ratio, "{worst}");
    assert!(worst > 0.0);
}

#[test]
fn short_sharp_bump_acts_like_an_impulse() {
    // L/V = 1e-3 of a natural period: the road acts like u = A·δ(t), A = ∫u dt = hL/(2V),
    // i.e. the force c·A·δ' + k·A·δ. Integrating m x'' = c(u' − x') + k(u − x) over the
    // bump: m·x = c·∫u ⇒ x(0⁺) = c·A/m, and m·x'(0⁺) = c·(u − x) + k·∫u = k·A − c²A/m
    // (the damper passes the road's displacement, the spring its area). Afterwards the body
    // moves freely, so the response is the free response from that state, centred at the
    // bump's middle. Error O(ω_n·L/V) ≈ 6e-3 of the response amplitude: tolerance 1 %.
    let wn = (K / M).sqrt();
    let duration = 1e-3 * std::f64::consts::TAU / wn;
    let bump = Bump::new(0.05, duration * 20.0, 20.0).unwrap();
    for &zeta in &[0.1, 0.5] {
        let sys = car(zeta);
        let a = bump.area();
        let cm = sys.damping() / M;
        let kick = FreeResponse::new(sys, cm * a, (K / M - cm * cm) * a);
        let ride = BumpResponse::new(sys, bump).unwrap();
        let amp = (K * a / M) / wn;
        for &t in &[0.05, 0.2, 0.5, 1.0] {
            let want = kick.displacement(t - 0.5 * duration);
            assert!(
                (ride.displacement(t) - want).abs() < 0.01 * amp,
                "ζ={zeta} t={t} {} {want} {amp}",
                ride.displacement(t)
            );
        }
    }
}

#[test]
fn samplers_match_pointwise_values() {
    let bump = Bump::new(0.05, 2.0, 10.0).unwrap();
    let ride = BumpResponse::new(car(0.3), bump).unwrap();
    let t = [-0.1, 0.05, 0.1, 0.5];
    let mut out = [0.0; 4];
    ride.sample_into(&t, &mut out);
    assert_eq!(out, t.map(|ti| ride.displacement(ti)));
    ride.velocity_into(&t, &mut out);
    assert_eq!(out, t.map(|ti| ride.velocity(ti)));
    ride.acceleration_into(&t, &mut out);
    assert_eq!(out, t.map(|ti| ride.acceleration(ti)));
    ride.profile_into(&t, &mut out);
    assert_eq!(out, t.map(|ti| bump.profile(ti)));
    let mut tr = [0.0; 2];
    base::transmissibility_into(&[0.5, 2.0], 0.2, &mut tr);
    assert_eq!(
        tr,
        [
            base::transmissibility(0.5, 0.2),
            base::transmissibility(2.0, 0.2)
        ]
    );
}
