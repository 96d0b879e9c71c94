//! The two-DOF quarter car's own behaviour; its numbers at every preset are pinned by the
//! snapshot tests (`crates/app/tests/snapshots.rs`).

// Independent reference values (the characteristic polynomial) are computed here by hand.
#![allow(clippy::disallowed_methods)]

use super::run::FRF_POINTS;
use super::*;
use crate::demos::testing::{number, text, value, Tested};
use crate::params::resolve_query;

#[test]
fn natural_frequencies_are_the_two_modes() {
    let f = QuarterCar2Dof::run("");
    let fb = number(&f, "f_body");
    let fw = number(&f, "f_wheel");
    assert!(fb > 1.0 && fb < 1.5, "{fb}");
    assert!(fw > 10.0 && fw < 15.0, "{fw}");
    // det(K − ω²M) = 0: m_s·m_u·λ² − (k_s·m_u + (k_s + k_t)·m_s)·λ + k_s·k_t = 0.
    for f in [fb, fw] {
        let l = (TAU * f).powi(2);
        let det =
            300.0 * 40.0 * l * l - (24_000.0 * 40.0 + 224_000.0 * 300.0) * l + 24_000.0 * 200_000.0;
        assert!(det.abs() < 1e-9 * 24_000.0 * 200_000.0, "{det}");
    }
}

#[test]
fn every_road_runs_and_draws() {
    for road in ["bump", "step", "sine", "random"] {
        let f = QuarterCar2Dof::run(&format!("road={road}"));
        assert!(number(&f, "rms_body_accel") > 0.0, "{road}");
        assert!(number(&f, "rms_tyre_deflection") > 0.0, "{road}");
        assert!(f.figures.iter().all(|g| g.has_visible_data()), "{road}");
        assert_eq!(value(&f, "rms_road").is_empty(), road != "random");
        assert_eq!(value(&f, "body_gain").is_empty(), road != "sine");
    }
}

#[test]
fn a_rougher_road_class_shakes_more() {
    let a = QuarterCar2Dof::run("road=random&class=A&V=20");
    let c = QuarterCar2Dof::run("road=random&class=C&V=20");
    // Each class quadruples the PSD: RMS road height and response double per class, as
    // long as the wheel stays on the road (the only nonlinearity).
    let ratio = number(&c, "rms_road") / number(&a, "rms_road");
    assert!((ratio - 4.0).abs() < 1e-9, "{ratio}");
    assert_eq!(number(&c, "airborne_time"), 0.0);
    let acc = number(&c, "rms_body_accel") / number(&a, "rms_body_accel");
    assert!((acc - 4.0).abs() < 1e-6, "{acc}");
}

#[test]
fn a_short_fast_bump_gives_the_fine_step_reference() {
    // The audit's case: a 5 cm bump 0.1 m long at 40 m/s lasts 2.5 ms. Fine-step reference
    // (3 digits): 0.116 m/s² RMS body acceleration over the 2.5025 s run, 2.82 mm travel.
    let f = QuarterCar2Dof::run("road=bump&L=0.1&V=40");
    assert!((number(&f, "rms_body_accel") - 0.116).abs() < 5e-4);
    assert!((number(&f, "max_travel") - 2.82e-3).abs() < 5e-6);
    assert_eq!(number(&f, "window"), 0.1 / 40.0 + 2.5);
    assert!(text(&f, "rms_body_accel").ends_with("(0–2.50 s)"));
}

#[test]
fn the_tyre_cannot_pull_and_the_lift_off_is_shown() {
    let calm = QuarterCar2Dof::run("road=bump&h=0.02&L=2");
    assert_eq!(value(&calm, "lift_off"), "");
    assert_eq!(number(&calm, "airborne_time"), 0.0);
    assert!(calm.figures[3].description.contains("keeps contact"));
    // A 10 cm bump half a metre long at 20 m/s throws the wheel off the road.
    let thrown = QuarterCar2Dof::run("road=bump&h=0.1&L=0.5&V=20");
    let lift = number(&thrown, "lift_off");
    let air = number(&thrown, "airborne_time");
    assert!(lift > 0.0 && lift < 0.1 && air > 0.05, "{lift} {air}");
    let tyre = &thrown.figures[3];
    assert!(tyre.series.iter().any(|s| s.label == "off the road"));
    assert!(
        tyre.description.contains("leaves the road"),
        "{}",
        tyre.description
    );
    // While off the road the wheel is above the road by more than the static deflection.
    let d0 = number(&thrown, "static_tyre_deflection");
    let mut d = QuarterCar2Dof::default();
    let decl = QuarterCar2Dof::declare();
    let (p, _) = resolve_query(&decl.spec(), "road=bump&h=0.1&L=0.5&V=20");
    d.step(&decl.read(&p)).unwrap();
    let r = &d.run;
    for i in 0..r.times.len() - 1 {
        if !r.contact[i] && !r.contact[i + 1] {
            assert!(r.states[i + 1][1] - r.road_u[i + 1] >= d0 * (1.0 - 1e-9));
        }
    }
}

#[test]
fn the_run_stays_small_at_the_stiffest_tyre() {
    let mut d = QuarterCar2Dof::default();
    let decl = QuarterCar2Dof::declare();
    let (p, _) = resolve_query(&decl.spec(), "road=sine&f_road=0.2&kt=500000&mu=10&h=0.005");
    d.step(&decl.read(&p)).unwrap();
    assert!(d.run.states.len() < 50_000, "{}", d.run.states.len());
    assert_eq!(d.run.frf.len(), FRF_POINTS);
}

#[test]
fn the_schematic_moves_with_the_run() {
    let d = QuarterCar2Dof::live("");
    let (a, b) = (d.at(0.0), d.at(0.1));
    assert_ne!(a.series[0].points, b.series[0].points);
    assert_ne!(a.description, b.description);
}

#[test]
fn the_random_road_shows_the_stationary_comfort_values() {
    let f = QuarterCar2Dof::run("road=random&class=C&V=20");
    let a = number(&f, "stationary_accel");
    let aw = number(&f, "stationary_weighted_accel");
    // W_k weighs body bounce (≈ 1.3 Hz) by about one half: a_w is well below the
    // unweighted value, which is of the order of the run's own RMS.
    assert!(aw < 0.9 * a && aw > 0.3 * a, "{a} {aw}");
    assert!((a / number(&f, "rms_body_accel") - 1.0).abs() < 0.5);
    assert_eq!(
        value(&QuarterCar2Dof::run(""), "stationary_weighted_accel"),
        ""
    );
}

#[test]
fn a_kept_run_is_the_one_computed_afresh() {
    // The sine's frequency and the seed leave the bump's run as it was; the mass does not.
    let moves = [
        ("f_road", "3"),
        ("seed", "4"),
        ("ms", "420"),
        ("f_road", "2"),
    ];
    crate::demos::testing::assert_kept_is_fresh("quarter-car-2dof", "", &moves);
}
