//! The integrators demo's own behaviour; its numbers at every preset are pinned by the
//! snapshot tests (`crates/app/tests/snapshots.rs`).

use super::Integrators;
use crate::demos::testing::{number, value, Tested};

#[test]
fn preset_shows_euler_unstable_and_the_orders() {
    let f = Integrators::run("");
    assert_eq!(value(&f, "stable_euler"), "no");
    assert_eq!(value(&f, "stable_rk4"), "yes");
    let (e, h, r) = (
        number(&f, "max_err_euler"),
        number(&f, "max_err_heun"),
        number(&f, "max_err_rk4"),
    );
    assert!(r < h && h < e, "{r} {h} {e}");
    let o = |k| number(&f, k);
    assert!((0.8..1.3).contains(&o("order_euler")));
    assert!((0.8..1.3).contains(&o("order_symplectic_euler")));
    assert!((1.7..2.3).contains(&o("order_heun")));
    assert!((3.6..4.4).contains(&o("order_rk4")));
    // DP45: minus the slope of error against f-evaluations, fitted where the tolerance
    // sets its steps.
    assert!((4.8..5.3).contains(&o("order_dp45")), "{}", o("order_dp45"));
}

#[test]
fn the_step_is_exactly_the_chosen_h() {
    // T = 20 s, h = 0.3 s: 66 steps of 0.3 s and a last one of 0.2 s ending at T.
    let f = Integrators::run("h=0.3");
    assert_eq!(number(&f, "h_used"), 0.3);
    assert!((number(&f, "h_last") - 0.2).abs() < 1e-12);
    assert!(
        f.figures[0]
            .description
            .contains("with h = 300 ms (67 steps"),
        "{}",
        f.figures[0].description
    );
    // When h divides T every step is h.
    let f = Integrators::run("h=0.1");
    assert_eq!(number(&f, "h_last"), 0.1);
}

#[test]
fn every_preset_has_every_fixed_step_order_near_its_textbook_value() {
    let spec = crate::demos::create("integrators").unwrap().spec();
    for preset in &spec.presets {
        let f = Integrators::preset(preset.label);
        for (key, p) in [
            ("order_euler", 1.0),
            ("order_symplectic_euler", 1.0),
            ("order_heun", 2.0),
            ("order_rk4", 4.0),
        ] {
            // Fitted over the asymptotic range only: within 5 % of p, also for the stiff
            // overdamped preset (where a fit over coarse steps read Heun 2.35, RK4 4.35).
            let o = number(&f, key);
            assert!((o - p).abs() < 0.05 * p, "{}: {key} = {o}", preset.label);
        }
    }
}

#[test]
fn dp45_has_an_order_only_where_its_tolerance_sets_the_steps() {
    // A long decaying run: after the transient, stability sets DP45's steps.
    let f = Integrators::run("zeta=0.5&T=60");
    assert_eq!(value(&f, "order_dp45"), "");
    assert!(f.figures[3]
        .description
        .contains("DP45 has no observed order"));
    let f = Integrators::run("zeta=0&h=0.1");
    assert!((number(&f, "order_dp45") - 5.0).abs() < 0.2);
}

#[test]
fn stiff_dp45_gets_no_meaningless_order() {
    let f = Integrators::run("zeta=2&wn=20&h=0.03&T=5");
    for (key, want) in [
        ("order_dp45", ""),
        ("stable_euler", "no"),
        ("stable_rk4", "yes"),
    ] {
        assert_eq!(value(&f, key), want, "{key}");
    }
}

#[test]
fn an_overflowing_run_says_so_without_a_number() {
    // RK4 at ωₙh = 6 multiplies by |R(6i)| ≈ 48 per step: 200 steps overflow.
    let f = Integrators::run("zeta=0&wn=20&h=0.3&T=60");
    assert_eq!(value(&f, "max_err_rk4"), "");
    let text = crate::demos::testing::text(&f, "max_err_rk4");
    assert!(text.starts_with("overflow at t = "), "{text}");
}
