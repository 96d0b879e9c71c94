//! The flutter demo's own behaviour; its numbers at every preset are pinned by the
//! snapshot tests (`crates/app/tests/snapshots.rs`).

use super::*;
use crate::demos::testing::{self, number, value};
use crate::demos::Frame;
use crate::params::Params;

fn run(query: &str) -> Frame {
    testing::run("flutter", query)
}

fn preset_slope() -> f64 {
    FlutterConfig::tacoma_1940().aero_slope
}

#[test]
fn defaults_are_the_1940_bridge_in_a_moderate_wind() {
    let f = run("");
    let uc = number(&f, "U_crit");
    assert!((uc - 18.775_68).abs() < 1e-9, "{uc}");
    let z = number(&f, "zeta_eff");
    assert!((z - (0.005 - preset_slope() * 10.0)).abs() < 1e-15);
    assert!(number(&f, "growth_rate") < 0.0);
    assert_eq!(value(&f, "regime"), "underdamped");
    assert_eq!(value(&f, "doubling_time"), "");
}

#[test]
fn the_poles_cross_at_the_critical_speed() {
    let at = run(&format!("U={TACOMA_FAILURE_WIND}"));
    assert_eq!(value(&at, "regime"), "undamped");
    assert!(number(&at, "zeta_eff").abs() < 1e-12);
    let above = run("U=19");
    assert_eq!(value(&above, "regime"), "negatively damped");
    let sigma = number(&above, "growth_rate");
    let omega = std::f64::consts::TAU * 0.2;
    assert!((sigma - (preset_slope() * 19.0 - 0.005) * omega).abs() < 1e-15);
    assert!((number(&above, "doubling_time") - std::f64::consts::LN_2 / sigma).abs() < 1e-6);
    assert!(above.figures[2].description.contains("grows by a factor"));
    assert!(run("U=10").figures[2].description.contains("decays to"));
}

#[test]
fn no_wind_effect_means_no_critical_speed() {
    let f = run("slope=0&U=40");
    assert_eq!(value(&f, "U_crit"), "");
    assert_eq!(value(&f, "regime"), "underdamped");
    assert!(f.figures[0].description.contains("never crosses zero"));
    assert!(f.figures.iter().all(|fig| fig.has_visible_data()));
}

#[test]
fn the_schematic_twists_with_the_deck() {
    let d = crate::demos::create("flutter").unwrap();
    let p = Params::defaults(&d.spec());
    let a = d.schematic(&p, 0.0).unwrap();
    let b = d.schematic(&p, 2.5).unwrap(); // about half a period later
    assert_ne!(a.series[1].points, b.series[1].points);
    assert!(a.description.contains("2.00 °"), "{}", a.description);
    for t in [0.0, 100.0, 1e9] {
        let f = d.schematic(&p, t).unwrap();
        assert!(f
            .series
            .iter()
            .all(|s| s.points.iter().all(|q| q.0.is_finite() && q.1.is_finite())));
    }
}

#[test]
fn the_table_has_a_row_for_every_reachable_regime() {
    let table = Flutter::declare().spec().table.unwrap();
    for u in [5.0, TACOMA_FAILURE_WIND, 30.0] {
        let r = value(&run(&format!("U={u}")), "regime");
        assert!(table.rows.iter().any(|(k, _)| *k == r), "{r}");
    }
    assert!(table
        .rows
        .iter()
        .all(|(_, c)| c.len() == table.columns.len()));
}
