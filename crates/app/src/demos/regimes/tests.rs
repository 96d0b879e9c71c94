//! The regimes demo's own behaviour; its numbers at every preset are pinned by the
//! snapshot tests (`crates/app/tests/snapshots.rs`).

// Independent reference values are computed here by hand.
#![allow(clippy::disallowed_methods)]

use super::*;
use crate::demos::testing;

use crate::demos::testing::Tested;
use testing::value;

#[test]
fn readouts_come_from_the_solver() {
    const WN: f64 = 8.944_271_909_999_16; // √80 rad/s: m = 300 kg, k = 24 000 N/m
    let f = Regimes::run(&format!("wn={WN}&zeta=0.2"));
    assert_eq!(value(&f, "wn").parse::<f64>().unwrap(), WN);
    assert_eq!(value(&f, "regime"), "underdamped");
    let wd: f64 = value(&f, "wd").parse().unwrap();
    assert!((wd - WN * (1.0f64 - 0.04).sqrt()).abs() < 1e-12);
    let re: f64 = value(&f, "pole_re").parse().unwrap();
    assert!((re + 0.2 * WN).abs() < 1e-12);
}

#[test]
fn every_regime_is_reachable_from_the_sliders() {
    for (z, name) in [
        (0.0, "undamped"),
        (0.5, "underdamped"),
        (1.0, "critically damped"),
        (2.0, "overdamped"),
        (-0.3, "negatively damped"),
    ] {
        let f = Regimes::run(&format!("zeta={z}"));
        assert_eq!(value(&f, "regime"), name);
        assert!(f.figures.iter().all(|fig| fig.has_visible_data()));
        assert!(
            f.figures[0].description.starts_with(name),
            "{}",
            f.figures[0].description
        );
    }
    assert_eq!(
        value(&Regimes::run("zeta=2"), "wd"),
        "",
        "no damped frequency when overdamped"
    );
}

#[test]
fn the_text_alternative_follows_the_response() {
    let light = Regimes::run("zeta=0.1").figures[0].description.clone();
    let heavy = Regimes::run("zeta=0.6").figures[0].description.clone();
    assert_ne!(light, heavy);
    assert!(
        light.contains("swings past equilibrium 9 times") && light.contains("within 5 %"),
        "{light}"
    );
    // ζ = 0.6 from rest: rebound e^{−πζ/√(1−ζ²)} = 9.48 %.
    assert!(heavy.contains("9.48 %"), "{heavy}");
}

#[test]
fn every_table_row_matches_a_regime_key() {
    let spec = Regimes::declare().spec();
    let keys: Vec<&str> = Regime::ALL.iter().map(|r| r.key()).collect();
    for (key, cells) in &spec.table.unwrap().rows {
        assert!(keys.contains(key));
        assert_eq!(cells.len(), 5);
    }
}
