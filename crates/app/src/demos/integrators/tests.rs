//! The integrators demo's own behaviour; its numbers at every preset are pinned by the
//! snapshot tests (`crates/app/tests/snapshots.rs`).

use crate::demos::testing::{number, run as run_demo, value};
use crate::demos::Frame;

fn run(query: &str) -> Frame {
    run_demo("integrators", query)
}

#[test]
fn preset_shows_euler_unstable_and_the_orders() {
    let f = run("");
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
    assert!((3.5..6.5).contains(&o("order_dp45")));
}

#[test]
fn stiff_dp45_gets_no_meaningless_order() {
    let f = run("zeta=2&wn=20&h=0.03&T=5");
    assert_eq!(value(&f, "order_dp45"), "");
    assert_eq!(value(&f, "stable_euler"), "no");
    assert_eq!(value(&f, "stable_rk4"), "yes");
}

#[test]
fn an_overflowing_run_says_so_without_a_number() {
    // RK4 at ωₙh = 6 multiplies by |R(6i)| ≈ 48 per step: 200 steps overflow.
    let f = run("zeta=0&wn=20&h=0.3&T=60");
    assert_eq!(value(&f, "max_err_rk4"), "");
    let text = crate::demos::testing::text(&f, "max_err_rk4");
    assert!(text.starts_with("overflow at t = "), "{text}");
}
