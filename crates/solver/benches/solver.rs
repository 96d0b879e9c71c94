//! Criterion benchmarks of the work a slider move triggers: `cargo bench -p zeta-solver`.
//!
//! - a closed-form free response of 1000 samples (what most plots draw);
//! - RK4 over 1000 fixed steps and Dormand–Prince to rtol 1e-8 (the integrators demo);
//! - the 100 × 100 (k, c) design sweep (the design explorer, target < 16 ms);
//! - 100 000 Monte Carlo draws (the uncertainty demo, target < 200 ms in the browser).

#![allow(missing_docs)] // criterion_group! generates undocumented functions
#![allow(clippy::unwrap_used)] // fixed, valid inputs

use criterion::{black_box, criterion_group, criterion_main, Criterion};
use zeta_solver::design::monte_carlo::{self, Distribution, McConfig, McSamples, Tolerance};
use zeta_solver::design::sensitivity::Components;
use zeta_solver::design::sweep::{sweep_kc_into, KcMaps, KcSweepConfig, RoadInput};
use zeta_solver::integrate::analysis::Amplification;
use zeta_solver::integrate::{Dopri5, Dopri5Config, FixedStep, Linear2, Rk4};
use zeta_solver::metrics::SettlingBand;
use zeta_solver::{linspace, FreeResponse, SecondOrder};

fn quarter_car() -> SecondOrder {
    SecondOrder::from_natural(8.944_271_909_999_16, 0.3).unwrap()
}

fn closed_form(c: &mut Criterion) {
    let resp = FreeResponse::new(quarter_car(), 0.06, 0.0);
    let t = linspace(0.0, 3.0, 1000);
    let mut out = vec![0.0; 1000];
    c.bench_function("free response, 1000 samples", |b| {
        b.iter(|| resp.sample_into(black_box(&t), &mut out))
    });
}

fn integrators(c: &mut Criterion) {
    let sys = Linear2::free(quarter_car());
    let mut buf = vec![[0.0; 2]; 1001];
    c.bench_function("RK4, 1000 steps", |b| {
        b.iter(|| Rk4.solve_into(&sys, black_box([0.06, 0.0]), 0.0, 3e-3, &mut buf))
    });
    let dp = Dopri5::new(Dopri5Config {
        rtol: 1e-8,
        atol: 1e-10,
        ..Dopri5Config::default()
    })
    .unwrap();
    c.bench_function("Dormand-Prince 5(4), 3 s at rtol 1e-8", |b| {
        b.iter(|| dp.solve(&sys, black_box([0.06, 0.0]), 0.0, 3.0))
    });
    // The integrators demo searches this on every move of ζ or ωₙ.
    let poles = quarter_car().poles();
    c.bench_function(
        "Dormand-Prince 5(4) largest stable step, underdamped pair",
        |b| b.iter(|| dp.step_limit(black_box(&poles))),
    );
}

fn design_sweep(c: &mut Criterion) {
    let k = linspace(5_000.0, 60_000.0, 100);
    let cc = linspace(200.0, 8_000.0, 100);
    let cfg = KcSweepConfig {
        mass: 300.0,
        band: SettlingBand::FREE_DEFAULT,
        road: RoadInput::new(1.0, 62.8).unwrap(),
    };
    let mut maps = KcMaps::default();
    c.bench_function("(k, c) sweep, 100 x 100", |b| {
        b.iter(|| sweep_kc_into(black_box(&k), &cc, &cfg, &mut maps))
    });
}

fn monte_carlo_draws(c: &mut Criterion) {
    let design = Components::Mechanical {
        m: 300.0,
        c: 2_000.0,
        k: 24_000.0,
    };
    let tol = Tolerance {
        fraction: 0.1,
        distribution: Distribution::Normal,
    };
    let cfg = McConfig {
        design,
        tolerances: [tol; 3],
        draws: 100_000,
        seed: 1,
        band: SettlingBand::FREE_DEFAULT,
    };
    let mut samples = McSamples::default();
    let mut group = c.benchmark_group("monte carlo");
    group.sample_size(20);
    group.bench_function("100 000 draws", |b| {
        b.iter(|| monte_carlo::run_into(black_box(&cfg), &mut samples))
    });
    group.finish();
}

criterion_group!(
    benches,
    closed_form,
    integrators,
    design_sweep,
    monte_carlo_draws
);
criterion_main!(benches);
