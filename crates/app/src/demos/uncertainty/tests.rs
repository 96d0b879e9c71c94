//! The tolerance demo's own behaviour; its numbers at the defaults and every preset are
//! pinned by the snapshot tests (`crates/app/tests/snapshots.rs`).

// Independent reference values (ζ ∝ m^−½, ωₙ = √(k/m)) are computed here by hand.
#![allow(clippy::disallowed_methods)]

use super::*;
use crate::demos::progressive::{overtaken, shown};
use crate::demos::testing::{number, run, text, value, Tested};
use crate::params::resolve_query;

/// One model step of `d` for `query`, as the page would run it.
fn step(d: &mut Uncertainty, query: &str) -> Results {
    let decl = Uncertainty::declare();
    let (params, notices) = resolve_query(&decl.spec(), query);
    assert!(notices.is_empty(), "{notices:?}");
    d.step(&decl.read(&params)).expect("valid design")
}

#[test]
fn the_mass_range_of_zeta_is_exact() {
    let f = Uncertainty::run("zeta=1&dm=10");
    // ζ ∝ m^−½ at fixed c, k.
    assert!((number(&f, "zeta_min") - 1.0 / 1.1f64.sqrt()).abs() < 1e-12);
    assert!((number(&f, "zeta_max") - 1.0 / 0.9f64.sqrt()).abs() < 1e-12);
    let wn = (24_000.0f64 / 300.0).sqrt();
    assert!((number(&f, "wn_min") - wn / 1.1f64.sqrt()).abs() < 1e-12);
    // Q = 1/(2ζ).
    assert!((number(&f, "Q_max") - 1.1f64.sqrt() / 2.0).abs() < 1e-12);
    assert_eq!(number(&f, "draws"), 10_000.0);
    let band = &f.figures[0];
    assert_eq!(
        band.series.len(),
        5,
        "three masses and the band's two edges"
    );
    assert_eq!(band.markers.len(), 3, "where each settles");
    assert!(
        band.description.contains("RLC sliders are ignored"),
        "{}",
        band.description
    );
}

#[test]
fn the_rlc_range_uses_each_part_tolerance() {
    // ζ = (R/2)√(C/L): lowest at R(1 − dR), C(1 − dC), L(1 + dL).
    let f = Uncertainty::run("system=rlc&dR=20&dL=5&dC=10");
    let lo = 7.0 * 0.8 / 2.0 * (0.02f64 * 0.9 / (0.5 * 1.05)).sqrt();
    assert!((number(&f, "zeta_min") - lo).abs() < 1e-12);
    let band = &f.figures[0];
    assert!(band.series[2].label.starts_with("lowest-ζ corner (ζ = "));
}

#[test]
fn the_same_seed_gives_the_same_draws_and_others_differ() {
    let mut d = Uncertainty::default();
    let a = step(&mut d, "system=rlc&seed=3");
    let b = step(&mut d, "system=rlc&seed=4");
    let c = step(&mut d, "system=rlc&seed=3");
    assert_eq!(a.q_pct, c.q_pct);
    assert_ne!(a.q_pct, b.q_pct);
    assert_eq!(d.runs, 3);
    // Changing only the spec or the histogram reuses the draws.
    step(&mut d, "system=rlc&seed=3&zeta_lo=0.65&hist=f0");
    assert_eq!(d.runs, 3);
}

#[test]
fn percentiles_and_yield_follow_the_samples() {
    let mut d = Uncertainty::default();
    let r = step(&mut d, "system=rlc&dR=20&dL=20&dC=20&N=2000");
    let (zmin, zmax) = r.ranges.zeta.unwrap();
    let [p5, p95] = r.zeta_pct;
    assert!(zmin < p5 && p5 < 0.7 && 0.7 < p95 && p95 < zmax);
    // Uniform draws never leave the exact range.
    assert!(d
        .samples
        .zeta
        .iter()
        .all(|z| *z >= zmin - 1e-12 && *z <= zmax + 1e-12));
    let pass = d
        .samples
        .zeta
        .iter()
        .zip(&d.samples.settling_time)
        .filter(|(z, t)| (0.6..=1.0).contains(*z) && **t <= 0.5)
        .count();
    assert!((r.yield_pct - 100.0 * pass as f64 / 2000.0).abs() < 1e-9);
    // The second histogram follows the choice.
    let f = Uncertainty::run("system=rlc&dR=20&dL=20&dC=20&N=2000&hist=settling_time");
    assert!(f.figures[2].description.contains("settling time"));
    step(
        &mut d,
        "system=rlc&dR=20&dL=20&dC=20&N=2000&hist=settling_time",
    );
    assert_eq!(d.runs, 1);
}

#[test]
fn a_hundred_thousand_draws_run() {
    let f = Uncertainty::run("N=100000&dist=normal");
    assert_eq!(number(&f, "draws"), 100_000.0);
    assert!(f.figures.iter().all(|g| g.has_visible_data()));
}

#[test]
fn percentiles_and_yield_follow_the_distribution_of_the_parts() {
    // Sprung mass uniform on m0·[0.9, 1.1]: ζ = ζ0·√(m0/m), so ζ's 5th percentile is at the
    // mass's 95th, m0·1.09, and with the spec window [0.6, 1] on a ζ = 1 design exactly the
    // heavier half passes (ts_max = 10 s lets every draw settle in time). Sampling error of
    // a percentile with 10 000 draws: ~0.05 % of the value; of the yield, σ = 0.5 %.
    let close =
        |a: f64, b: f64, what: &str| assert!((a / b - 1.0).abs() < 2e-3, "{what}: {a} vs {b}");
    let f = Uncertainty::run("zeta=1&dm=10&ts_max=10&zeta_lo=0.6&zeta_hi=1");
    close(number(&f, "zeta_p5"), 1.0 / 1.09f64.sqrt(), "ζ p5");
    close(number(&f, "zeta_p95"), 1.0 / 0.91f64.sqrt(), "ζ p95");
    let y = number(&f, "yield");
    assert!((y - 50.0).abs() < 2.0, "yield {y} %");
    // Normal parts: tolerance = 3σ, so 90 % of masses lie within ±1.645σ = ±5.48 %.
    let f = Uncertainty::run("zeta=1&dm=10&dist=normal");
    close(
        number(&f, "zeta_p5"),
        1.0 / (1.0 + 0.1 * 1.6449 / 3.0f64).sqrt(),
        "normal ζ p5",
    );
}

#[test]
fn progressive_updates_show_the_first_draws_marked_then_exactly_the_full_run() {
    // Part of the run for ±15 %, then the tolerance moves on: that run is never shown.
    let mut ov = overtaken("uncertainty", "dm=15", "dm=12");
    let params = |q| crate::demos::testing::params("uncertainty", q);
    let first_draws = run("uncertainty", "dm=12&N=1000");
    assert!(ov.demo.provisional().contains(&"yield") && ov.demo.provisional().contains(&"hist"));
    assert_eq!(text(&ov.coarse, "draws"), "1000 (10000 on the way)");
    assert!(ov.coarse.figures[1].title.ends_with("(provisional)"));
    // The ov.coarse run is exactly the first 1000 draws of the full one.
    assert_eq!(value(&ov.coarse, "yield"), value(&first_draws, "yield"));
    assert_eq!(value(&ov.coarse, "zeta_min"), value(&ov.want, "zeta_min"));
    let mut slices = 0;
    while ov.demo.refine(0.0) != Some(1.0) {
        slices += 1;
        assert!(slices <= 200, "a slice of draws each time at least");
    }
    assert!(ov.demo.provisional().is_empty() && ov.demo.refine(5.0).is_none());
    let full = ov.demo.update(&params("dm=12"));
    // Debug text: the figures may hold NaN gaps, which `==` never equates.
    assert!(format!("{:?}", shown(&full)) == format!("{:?}", shown(&ov.want)));
}

#[test]
fn progressive_updates_keep_small_runs_and_spec_moves_immediate() {
    let spec = Uncertainty::declare().spec();
    let mut demo = crate::demos::create("uncertainty").unwrap();
    demo.set_progressive(true);
    demo.update(&crate::params::resolve_query(&spec, "N=800").0);
    assert!(demo.provisional().is_empty() && demo.refine(5.0).is_none());
    // Moving the spec reuses the draws: nothing to refine.
    demo.update(&crate::params::resolve_query(&spec, "N=800&ts_max=0.7").0);
    assert!(demo.provisional().is_empty() && demo.refine(5.0).is_none());
}
