//! The nonlinear demo's own behaviour; its numbers at every preset are pinned by the
//! snapshot tests (`crates/app/tests/snapshots.rs`).

// Independent reference values (the linear closed form) are computed here by hand.
#![allow(clippy::disallowed_methods)]

use super::*;
use crate::demos::testing::{number, value, Tested};

#[test]
fn linear_settings_reproduce_the_linear_model() {
    let f = Nonlinear::preset("Linear (all off)");
    assert_eq!(value(&f, "effect"), "linear");
    assert!((number(&f, "period_ratio") - 1.0).abs() < 1e-6);
    // RK4 with ~720 steps per period against the closed form.
    let dev = number(&f, "max_deviation");
    assert!(dev < 1e-8, "{dev}");
    let wn = (24_000.0f64 / 300.0).sqrt();
    let c = 1_500.0 / (2.0 * (300.0f64 * 24_000.0).sqrt());
    let td = std::f64::consts::TAU / (wn * (1.0 - c * c).sqrt());
    assert!((number(&f, "period_linear") - td).abs() < 1e-4 * td);
}

#[test]
fn each_preset_shows_its_effect() {
    let hard = Nonlinear::preset("Hardening spring");
    assert_eq!(value(&hard, "effect"), "hardening spring");
    assert!(number(&hard, "period_ratio") < 0.95);
    let soft = Nonlinear::preset("Softening spring");
    assert_eq!(value(&soft, "effect"), "softening spring");
    assert!(number(&soft, "period_ratio") > 1.03);
    let fric = Nonlinear::preset("Friction stick–slip");
    assert_eq!(value(&fric, "effect"), "stick-slip");
    let x = number(&fric, "stick_position");
    // Held where the spring cannot overcome static friction: |k·x| ≤ F_static = 1.2·300 N.
    assert!(x.abs() <= 1.2 * 300.0 / 24_000.0 + 1e-9, "{x}");
    assert!(x.abs() > 1e-4, "{x}");
    let stop = Nonlinear::preset("Bump-stop impact");
    assert_eq!(value(&stop, "effect"), "bump-stop impact");
    let travel = number(&stop, "max_travel");
    let linear_reach = 1.5 / (24_000.0f64 / 300.0).sqrt();
    assert!(travel > 0.05 && travel < linear_reach, "{travel}");
    let asym = Nonlinear::preset("Asymmetric damper");
    assert_eq!(value(&asym, "effect"), "asymmetric damper");
    assert!(number(&asym, "max_deviation") > 1e-3);
    for f in [&hard, &soft, &fric, &stop, &asym] {
        assert!(f.figures.iter().all(|g| g.has_visible_data()));
    }
}

#[test]
fn a_softening_spring_past_its_limit_escapes_without_panicking() {
    let f = Nonlinear::run("k3=-4000000&x0=0.15&v0=2&c_comp=0&c_reb=0&k=5000");
    assert_eq!(value(&f, "effect"), "escaped");
    assert!(f.figures[0].description.contains("leaves the plot"));
    assert!(f.readouts.iter().all(|r| !r.data_value.contains("NaN")));
}

#[test]
fn the_schematic_follows_the_run() {
    let d = Nonlinear::live("");
    let (a, b) = (d.at(0.0), d.at(0.3));
    assert_ne!(a.description, b.description);
    assert!(a.description.contains("80.0 mm"), "{}", a.description);
}

#[test]
fn every_table_row_is_a_possible_effect() {
    let spec = Nonlinear::declare().spec();
    let table = spec.table.unwrap();
    for preset in &spec.presets {
        let e = value(&Nonlinear::preset(preset.label), "effect");
        assert!(table.rows.iter().any(|(k, _)| *k == e), "{e}");
    }
    // One cell per column in every row: the registry test checks it for every demo.
}

#[test]
fn the_defaults_are_a_plausible_car_corner() {
    // m = 300 kg, k = 24 kN/m, c = 1 500 N·s/m: ζ = c/(2√(mk)) ≈ 0.28, a typical car value.
    let f = Nonlinear::run("");
    assert_eq!(value(&f, "effect"), "hardening spring");
    let wn = (24_000.0f64 / 300.0).sqrt();
    let zeta = 1_500.0 / (2.0 * (300.0f64 * 24_000.0).sqrt());
    assert!(zeta > 0.2 && zeta < 0.4);
    let td = std::f64::consts::TAU / (wn * (1.0 - zeta * zeta).sqrt());
    assert!((number(&f, "period_linear") - td).abs() < 1e-3 * td);
}

#[test]
fn friction_holds_the_mass_for_good_once_it_stops() {
    // 1 500 N of sliding friction on the default car from 25 mm: it sticks, and the
    // schematic at the end of the window shows it exactly where it stuck (no creep).
    let d = Nonlinear::live("friction=1500&x0=0.025&k3=0");
    let f = &d.frame;
    assert_eq!(value(f, "effect"), "stick-slip");
    let x = number(f, "stick_position");
    assert!(x.abs() <= 1.2 * 1_500.0 / 24_000.0 + 1e-12, "{x}");
    let (_, t_end) = f.time_span.unwrap();
    let end = d.at(t_end);
    let shown = crate::format::si(x, "m", 3);
    assert!(
        end.description.contains(&shown),
        "{} vs {shown}",
        end.description
    );
}
