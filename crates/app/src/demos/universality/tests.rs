//! The universality demo's own behaviour; its numbers at every preset are pinned by the
//! snapshot tests (`crates/app/tests/snapshots.rs`).

use super::*;
use crate::demos::testing::{number, text, value, Tested};
use crate::params::Params;

#[test]
fn each_machine_shows_its_coefficients_in_its_own_units() {
    let f = Universality::run("A=servo&B=thermal");
    assert_eq!(text(&f, "a_A"), "0.001000 kg·m²");
    assert_eq!(text(&f, "b_A"), "10.00 mN·m·s/rad");
    assert_eq!(text(&f, "c_A"), "1.000 N·m/rad");
    // C₁ = 5 J/K, R₁ = 0.5 K/W, C₂ = 1 J/K, R₂ = 2 K/W: a = 2.5·2 = 5 s², b = 2.5 + 2 + 0.5 s.
    assert_eq!(number(&f, "a_B"), 5.0);
    assert_eq!(number(&f, "b_B"), 5.0);
    assert_eq!(text(&f, "c_B"), "1.000");
    assert_eq!(value(&f, "regime_B"), "overdamped");
}

#[test]
fn match_tunes_b_to_a_and_publishes_the_tuned_sliders() {
    let mut d = Universality::live("A=mass-spring&B=rlc&match=1");
    let f = d.frame.clone();
    assert_eq!(value(&f, "match"), "on: B has the ωₙ and ζ of A");
    let rel = |a: f64, b: f64| (a - b).abs() <= 1e-12 * b.abs();
    assert!(rel(number(&f, "wn_B"), number(&f, "wn_A")));
    assert!(rel(number(&f, "zeta_B"), number(&f, "zeta_A")));
    // L = 0.1 H kept: C = 1/(Lωₙ²) = 0.1 F, R = 2ζLωₙ = 0.2 Ω.
    let derived = d.demo.derived_params();
    let keys: Vec<&str> = derived.iter().map(|d| d.0).collect();
    assert_eq!(keys, ["B_C", "B_R"]);
    assert!(rel(derived[0].1, 0.1) && rel(derived[1].1, 0.2));
    // The normalised curves of A and B coincide.
    let s = &f.figures[0].series;
    for (a, b) in s[1].points.iter().zip(&s[2].points) {
        assert!((a.1 - b.1).abs() < 1e-12);
    }
    assert!(f.figures[0].description.contains("coincide"));
    // Writing the derived values back changes nothing.
    let spec = d.demo.spec();
    for (k, v) in derived {
        d.params.set_raw(&spec, k, &format!("{v}"));
    }
    assert_eq!(d.demo.update(&d.params), f);
}

#[test]
fn a_thermal_system_cannot_be_tuned_to_an_oscillator() {
    let f = Universality::run("A=mass-spring&B=thermal&match=1");
    let status = value(&f, "match");
    // √(1 + C₂/C₁) = √1.2 = 1.095.
    assert!(
        status.starts_with("not reachable") && status.contains("1.095"),
        "{status}"
    );
    assert!(f.figures[0].description.contains("cannot oscillate"));
    assert!(number(&f, "zeta_B") > 1.0);
}

#[test]
fn tuned_values_outside_the_sliders_are_reported_not_applied() {
    // A storey at ωₙ ≈ 30 rad/s would need a U-tube column of 2g/ωₙ² = 22 mm.
    let d = Universality::live("A=storey&B=u-tube&match=1");
    let f = &d.frame;
    assert!(
        value(f, "match").contains("within the sliders"),
        "{}",
        value(f, "match")
    );
    assert!(d.demo.derived_params().is_empty());
}

#[test]
fn hidden_sliders_belong_to_their_machine_and_slot() {
    let spec = Universality::declare().spec();
    // Per slot the machine and the 23 sliders of the six machines (none dropped), then "match".
    assert_eq!(spec.params.len(), 2 * (1 + 23) + 1);
    for p in &spec.params {
        match p.key {
            "A" | "B" | "match" => assert_eq!(p.visible_when, None),
            key => {
                let (slot, _) = key.split_once('_').unwrap();
                let (on, index) = p.visible_when.unwrap();
                assert_eq!(on, slot, "{key}");
                assert!(index < 6);
            }
        }
    }
    let defaults = Params::defaults(&spec);
    assert_eq!(defaults.get("A"), 0.0);
    assert_eq!(defaults.get("B"), 1.0);
}

#[test]
fn every_machine_draws_in_both_slots() {
    for kind in ["mass-spring", "rlc", "u-tube", "servo", "storey", "thermal"] {
        let d = Universality::live(&format!("A={kind}&B={kind}"));
        let f = &d.frame;
        assert!(f.figures.iter().all(|fig| fig.has_visible_data()), "{kind}");
        let (t0, t1) = f.time_span.unwrap();
        let fig = d.at(0.5 * (t0 + t1));
        assert!(fig.has_visible_data() && fig.description.starts_with("At t ="));
    }
}
