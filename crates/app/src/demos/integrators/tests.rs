//! The integrators demo's own behaviour; its numbers at every preset are pinned by the
//! snapshot tests (`crates/app/tests/snapshots.rs`).

use super::Integrators;
use crate::demos::progressive::{overtaken, shown};
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

#[test]
fn progressive_updates_show_a_coarse_study_marked_then_exactly_the_full_one() {
    // Part of the full study for ζ = 0.3, then ζ moves on: that study is never shown.
    let mut ov = overtaken("integrators", "zeta=0.3", "zeta=0.1");
    let params = |q| crate::demos::testing::params("integrators", q);
    for key in [
        "order_euler",
        "order_rk4",
        "order_dp45",
        "convergence",
        "work",
    ] {
        assert!(ov.demo.provisional().contains(&key), "{key} marked");
    }
    // What does not come from the study is final at once.
    for key in ["max_err_rk4", "h_used", "stable_euler"] {
        assert!(!ov.demo.provisional().contains(&key), "{key} not marked");
        assert_eq!(value(&ov.coarse, key), value(&ov.want, key), "{key}");
    }
    assert!(
        !ov.demo.provisional().contains(&"response") && !ov.demo.provisional().contains(&"error")
    );
    assert_eq!(
        format!("{:?}", &ov.coarse.figures[..2]),
        format!("{:?}", &ov.want.figures[..2])
    );
    for (fig, final_fig) in ov.coarse.figures[2..4].iter().zip(&ov.want.figures[2..4]) {
        assert!(
            fig.description.starts_with(
                "Provisional: from a coarse study (at most 3000 steps per method, 6000 for \
                 forward Euler; DP45 down to 1e-4) while the full one (24000 and 48000 steps; \
                 DP45 down to 1e-10) runs."
            ),
            "{}",
            fig.description
        );
        assert_eq!(fig.title, final_fig.title);
    }
    // The ov.coarse study has fewer step sizes, but still about the textbook orders.
    let (o, full) = (
        number(&ov.coarse, "order_rk4"),
        number(&ov.want, "order_rk4"),
    );
    assert!((o - 4.0).abs() < 0.3 && o != full, "{o} vs {full}");
    let mut slices = 0;
    while ov.demo.refine(0.0) != Some(1.0) {
        slices += 1;
        // A slice a fixed-step method, then one a DP45 tolerance.
        assert!(slices < 4 + 9, "one method or tolerance per slice at least");
    }
    assert!(ov.demo.provisional().is_empty() && ov.demo.refine(5.0).is_none());
    let full = ov.demo.update(&params("zeta=0.1"));
    // Debug text: the figures may hold NaN gaps, which `==` never equates.
    assert!(format!("{:?}", shown(&full)) == format!("{:?}", shown(&ov.want)));
}

#[test]
fn a_held_control_gets_a_coarser_study_and_the_full_one_at_rest() {
    let params = |q| crate::demos::testing::params("integrators", q);
    let want = crate::demos::create("integrators")
        .unwrap()
        .update(&params("wn=3"));
    let mut demo = crate::demos::create("integrators").unwrap();
    demo.set_progressive(true);
    demo.update(&params(""));
    while demo.refine(5.0).is_some_and(|f| f < 1.0) {}
    demo.set_held(true);
    let held = demo.update(&params("wn=3"));
    assert!(demo.provisional().contains(&"convergence"));
    assert!(
        held.figures[2].description.starts_with(
            "Provisional: from a coarse study (at most 750 steps per method, 1500 for \
             forward Euler; DP45 down to 1e-3)"
        ),
        "{}",
        held.figures[2].description
    );
    // Still about the textbook order, from fewer step sizes.
    let o = number(&held, "order_rk4");
    assert!((o - 4.0).abs() < 0.5, "{o}");
    // Released: the full study replaces it, exactly as without progressive studies.
    demo.set_held(false);
    while demo.refine(5.0).is_some_and(|f| f < 1.0) {}
    let full = demo.update(&params("wn=3"));
    assert!(demo.provisional().is_empty());
    assert!(format!("{:?}", shown(&full)) == format!("{:?}", shown(&want)));
}

#[test]
fn progressive_updates_keep_h_tol_and_toggles_immediate() {
    let spec = crate::demos::create("integrators").unwrap().spec();
    let params = |q| crate::params::resolve_query(&spec, q).0;
    let mut reference = crate::demos::create("integrators").unwrap();
    let mut demo = crate::demos::create("integrators").unwrap();
    demo.set_progressive(true);
    demo.update(&params(""));
    while demo.refine(5.0).is_some_and(|f| f < 1.0) {}
    assert!(demo.provisional().is_empty());
    // Moving h, tol, x₀ or a toggle reuses the study (x₀ scales it): nothing to refine,
    // and the same frame as the step without progressive studies.
    for q in [
        "h=0.05",
        "h=0.05&tol=1e-8",
        "h=0.05&tol=1e-8&rk4=0",
        "h=0.05&tol=1e-8&rk4=0&x0=0.37",
    ] {
        let got = demo.update(&params(q));
        assert!(
            demo.provisional().is_empty() && demo.refine(5.0).is_none(),
            "{q}"
        );
        let want = reference.update(&params(q));
        assert!(
            format!("{:?}", shown(&got)) == format!("{:?}", shown(&want)),
            "{q}"
        );
    }
}

#[test]
fn the_study_shown_at_any_x0_is_what_a_study_from_that_x0_measures() {
    use super::model::{compute_study, Cache, Limits, Problem, FULL};
    use super::P;
    use crate::demos::progressive::Progressive;
    use zeta_solver::SecondOrder;
    // The cache holds the study from x₀ = 1 and scales it; a study run from x₀ itself
    // agrees within rounding: the same orders to 1e−4 (the fits reach down to errors of
    // 1e−10·x₀, where rounding is about 1e−4 of them) and errors to 1e−9 of themselves
    // plus 1e−14·x₀ (see zeta-solver's a_study_from_a_scaled_start_is_the_unit_study_scaled).
    let close = |a: Option<f64>, b: Option<f64>| match (a, b) {
        (Some(a), Some(b)) => (a - b).abs() < 1e-4,
        (a, b) => a == b,
    };
    for (zeta, wn, t_end, x0) in [
        (0.05, 2.0, 20.0, 0.37),
        (0.3, 5.0, 10.0, 1.9),
        (0.0, 2.0, 20.0, 0.05),
        (2.0, 20.0, 5.0, 0.05),
    ] {
        let p = P {
            zeta,
            wn,
            h: 0.1,
            t_end,
            x0,
            tol: 1e-6,
            show: [true; 5],
        };
        let sys = SecondOrder::from_natural(wn, zeta).unwrap();
        let problem = Problem::new(sys, &p, Limits::of(&sys));
        let rerun = compute_study(&problem, [zeta, wn, t_end, x0], FULL).unwrap();
        let shown = Cache::default()
            .step(&p, &mut Progressive::default())
            .unwrap()
            .study;
        let what = format!("ζ = {zeta}, ωₙ = {wn}, T = {t_end}, x₀ = {x0}");
        for k in 0..4 {
            assert!(close(shown.order(k), rerun.order(k)), "{what}: method {k}");
            for (a, b) in shown.fixed[k]
                .study
                .points
                .iter()
                .zip(&rerun.fixed[k].study.points)
            {
                assert_eq!((a.h, a.used), (b.h, b.used), "{what}");
                if b.error.is_finite() {
                    let gap = (a.error - b.error).abs();
                    assert!(gap <= 1e-9 * b.error + 1e-14 * x0, "{what}: {a:?} {b:?}");
                }
            }
        }
        assert!(
            close(shown.dp45.order(), rerun.dp45.order()),
            "{what}: DP45"
        );
        // The x₀ = 1 study really is scaled: its largest error is x₀ times the unit one's.
        assert_ne!(x0, 1.0);
        let unit = Cache::default()
            .step(&P { x0: 1.0, ..p }, &mut Progressive::default())
            .unwrap()
            .study;
        let first = |st: &super::model::Study| st.fixed[3].study.points[0].error;
        assert!(
            (first(&shown) - x0 * first(&unit)).abs() <= 1e-15 * first(&shown),
            "{what}"
        );
    }
}

#[test]
fn the_runs_are_kept_while_only_the_tolerance_or_the_methods_shown_move() {
    use crate::demos::Model;
    use std::rc::Rc;
    let decl = Integrators::declare();
    let p = |q: &str| decl.read(&crate::demos::testing::params("integrators", q));
    let mut m = Integrators::default();
    let first = m.step(&p("h=0.01")).unwrap();
    // Neither the tolerance nor a toggle changes a fixed-step run: the same runs, not
    // recomputed, and DP45 rerun at the new tolerance.
    let tol = m.step(&p("h=0.01&tol=1e-3&rk4=0")).unwrap();
    assert!(Rc::ptr_eq(&first.fixed, &tol.fixed));
    assert!(tol.dp45_err != first.dp45_err);
    // Each of the others does, with the numbers a fresh model computes.
    for q in [
        "h=0.02",
        "h=0.01&x0=0.5",
        "h=0.01&T=10",
        "h=0.01&zeta=0.3",
        "h=0.01&wn=3",
    ] {
        let moved = m.step(&p(q)).unwrap();
        assert!(!Rc::ptr_eq(&first.fixed, &moved.fixed), "{q}");
        let fresh = Integrators::default().step(&p(q)).unwrap();
        assert_eq!(moved.fixed.max_err, fresh.fixed.max_err, "{q}");
        assert_eq!(moved.fixed.exact, fresh.fixed.exact, "{q}");
    }
}

#[test]
fn long_runs_show_their_start_at_once_and_the_whole_runs_at_rest() {
    let params = |q| crate::demos::testing::params("integrators", q);
    let q = "h=0.001&T=20";
    let want = crate::demos::create("integrators")
        .unwrap()
        .update(&params(q));
    let mut demo = crate::demos::create("integrators").unwrap();
    demo.set_progressive(true);
    let first = demo.update(&params(q));
    // 20 000 steps of each method: the first 4096 at once (to t = 4.096 s), marked.
    let marked = demo.provisional();
    for key in ["response", "error", "max_err_euler", "max_err_rk4"] {
        assert!(marked.contains(&key), "{key}: {marked:?}");
    }
    assert!(
        first.figures[0]
            .description
            .starts_with("Provisional: the runs so far, to t = 4.10 s of 20.0 s"),
        "{}",
        first.figures[0].description
    );
    // The runs so far: fewer points drawn than of the whole runs.
    let so_far = &first.figures[0].series[1].points;
    let whole = &want.figures[0].series[1].points;
    assert!(so_far.len() < whole.len());
    // Moved on mid-way: the runs for the old inputs are dropped, never shown.
    assert!(demo.refine(0.0).is_some_and(|f| f < 1.0));
    let q2 = "h=0.001&T=25";
    let want2 = crate::demos::create("integrators")
        .unwrap()
        .update(&params(q2));
    demo.update(&params(q2));
    while demo.refine(5.0).is_some_and(|f| f < 1.0) {}
    while demo.refine(5.0).is_some_and(|f| f < 1.0) {}
    let done = demo.update(&params(q2));
    assert!(demo.provisional().is_empty(), "{:?}", demo.provisional());
    // Exactly what a step computes whole.
    assert!(format!("{:?}", shown(&done)) == format!("{:?}", shown(&want2)));
}
