//! The flutter demo's own behaviour; its numbers at every preset are pinned by the
//! snapshot tests (`crates/app/tests/snapshots.rs`).

use super::*;
use crate::demos::testing::{number, text, value, Tested};

#[test]
fn the_failure_day_grows_to_a_large_twist_within_the_plotted_window() {
    let f = Flutter::preset("Tacoma 1940, 19 m/s (failure day, ≈ 42 mph)");
    assert_eq!(value(&f, "regime"), "negatively damped");
    let uc = number(&f, "U_crit");
    assert!(uc > 17.0 && uc < 19.0, "{uc}");
    // Growth visible on the plot: from 2° to tens of degrees within the window, which
    // is minutes to an hour long.
    let end = number(&f, "amplitude_end_deg");
    assert!(end > 20.0, "{end}°");
    let window = f.time_span.unwrap().1;
    assert!(window > 600.0 && window < 3600.0, "{window} s");
    assert!(number(&f, "time_to_large") < window);
    assert!(
        text(&f, "doubling_time").ends_with("min"),
        "{}",
        text(&f, "doubling_time")
    );
    assert!(text(&f, "limit_deg").ends_with('°'));
    assert!(
        Flutter::plot(&f, "response")
            .description
            .contains("grows to"),
        "{}",
        Flutter::plot(&f, "response").description
    );
    assert!(Flutter::plot(&f, "response").x.title().contains("min"));
}

#[test]
fn below_the_critical_speed_a_twist_dies_away() {
    let f = Flutter::preset("Tacoma 1940, 10 m/s (stable)");
    assert_eq!(value(&f, "regime"), "underdamped");
    assert!(number(&f, "growth_rate") < 0.0);
    assert_eq!(value(&f, "doubling_time"), "");
    assert_eq!(value(&f, "limit_deg"), "");
    assert!(number(&f, "amplitude_end_deg") < 2.0);
    assert!(Flutter::plot(&f, "response")
        .description
        .contains("dies down to"));
}

#[test]
fn a_streamlined_box_never_flutters_and_the_h_section_does() {
    let boxed = Flutter::preset("Streamlined box deck, 40 m/s");
    assert_eq!(value(&boxed, "U_crit"), "");
    assert!(number(&boxed, "A2") < 0.0);
    assert!(Flutter::plot(&boxed, "damping")
        .description
        .contains("never crosses zero"));
    let h = Flutter::run("U=25");
    assert!(number(&h, "A2") > 0.0);
    // A₃* > 0 lowers the frequency below the still-air 0.2 Hz.
    assert!(number(&h, "frequency") < 0.2);
    // The current point sits on the plotted A₂* curve.
    let marker = &Flutter::plot(&h, "derivative").markers[0];
    assert!((marker.at.1 - number(&h, "A2")).abs() < 1e-12);
    assert!((marker.at.0 - number(&h, "reduced_velocity")).abs() < 1e-12);
}

#[test]
fn the_simplest_picture_is_the_old_linear_model() {
    let f = Flutter::preset("Simplest picture, 19 m/s (ζ_eff = ζ_s − g·U)");
    let uc = number(&f, "U_crit");
    assert!((uc - TACOMA_FAILURE_WIND).abs() < 1e-6, "{uc}");
    let z = number(&f, "zeta_eff");
    assert!((z - (TACOMA_STRUCTURAL_DAMPING - SIMPLEST_SLOPE * 19.0)).abs() < 1e-12);
    assert_eq!(number(&f, "A3"), 0.0);
}

#[test]
fn the_schematic_twists_with_the_deck() {
    let d = Flutter::live("");
    let a = d.at(0.0);
    let b = d.at(2.5); // about half a period later
    assert_ne!(a.series[1].points, b.series[1].points);
    assert!(a.description.contains("2.00°"), "{}", a.description);
    for t in [0.0, 100.0, 1e9] {
        let f = d.at(t);
        assert!(f
            .series
            .iter()
            .all(|s| s.points.iter().all(|q| q.0.is_finite() && q.1.is_finite())));
    }
}

#[test]
fn the_table_has_a_row_for_every_reachable_regime() {
    let table = Flutter::declare().spec().table.unwrap();
    for u in [5.0, 30.0] {
        let r = value(&Flutter::run(&format!("U={u}")), "regime");
        assert!(table.rows.iter().any(|(k, _)| *k == r), "{r}");
    }
    // One cell per column in every row: the registry test checks it for every demo.
}

#[test]
fn the_kept_critical_speed_and_locus_are_those_computed_afresh() {
    let moves = [("U", "30"), ("theta_s", "4"), ("f0", "0.3")];
    crate::demos::testing::assert_kept_is_fresh("flutter", "theta0=2", &moves);
}
