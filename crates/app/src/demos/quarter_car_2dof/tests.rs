//! The two-DOF quarter car's own behaviour; its numbers at every preset are pinned by the
//! snapshot tests (`crates/app/tests/snapshots.rs`).

// Independent reference values (the characteristic polynomial) are computed here by hand.
#![allow(clippy::disallowed_methods)]

use super::run::{FRF_POINTS, MAX_STEPS};
use super::*;
use crate::demos::testing::{self, number, value};
use crate::demos::Frame;
use crate::params::{resolve_query, Params};

fn run(query: &str) -> Frame {
    testing::run("quarter-car-2dof", query)
}

#[test]
fn natural_frequencies_are_the_two_modes() {
    let f = run("");
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
        let f = run(&format!("road={road}"));
        assert!(number(&f, "rms_body_accel") > 0.0, "{road}");
        assert!(number(&f, "rms_tyre_deflection") > 0.0, "{road}");
        assert!(f.figures.iter().all(|g| g.has_visible_data()), "{road}");
        assert_eq!(value(&f, "rms_road").is_empty(), road != "random");
        assert_eq!(value(&f, "body_gain").is_empty(), road != "sine");
    }
}

#[test]
fn a_rougher_road_class_shakes_more() {
    let a = run("road=random&class=A&V=20");
    let e = run("road=random&class=E&V=20");
    // Each class quadruples the PSD: RMS road height and response double per class.
    let ratio = number(&e, "rms_road") / number(&a, "rms_road");
    assert!((ratio - 16.0).abs() < 1e-9, "{ratio}");
    let acc = number(&e, "rms_body_accel") / number(&a, "rms_body_accel");
    assert!((acc - 16.0).abs() < 1e-6, "{acc}");
}

#[test]
fn the_step_count_is_capped() {
    let mut d = QuarterCar2Dof::default();
    let decl = QuarterCar2Dof::declare();
    let (p, _) = resolve_query(&decl.spec(), "road=sine&f_road=30&kt=500000&mu=10&h=0.005");
    d.step(&decl.read(&p)).unwrap();
    assert!(d.run.states.len() <= MAX_STEPS + 1);
    assert_eq!(d.run.frf.len(), FRF_POINTS);
}

#[test]
fn the_schematic_moves_with_the_run() {
    let mut d = QuarterCar2Dof::default();
    let decl = QuarterCar2Dof::declare();
    let p = decl.read(&Params::defaults(&decl.spec()));
    d.step(&p).unwrap();
    let a = d.schematic(&p, 0.0).unwrap();
    let b = d.schematic(&p, 0.1).unwrap();
    assert_ne!(a.series[0].points, b.series[0].points);
    assert_ne!(a.description, b.description);
}
