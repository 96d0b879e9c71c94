//! The design demo's own behaviour; its numbers at the defaults and every preset are pinned
//! by the snapshot tests (`crates/app/tests/snapshots.rs`).

use super::figures::ISO_ZETAS;
use super::*;
use crate::demos::progressive::shown;
use crate::demos::testing::{number, Tested};
use crate::params::resolve_query;
use zeta_solver::design::sweep::rebound_from_rest;

/// One model step of `d` for `query`, as the page would run it.
fn step(d: &mut DesignSpace, query: &str) -> (P, Results) {
    let decl = DesignSpace::declare();
    let (params, notices) = resolve_query(&decl.spec(), query);
    assert!(notices.is_empty(), "{notices:?}");
    let p = decl.read(&params);
    let r = d.step(&p).expect("valid design");
    (p, r)
}

#[test]
fn readouts_are_the_selected_design_from_the_solver() {
    let f = DesignSpace::run("m=300&k=24000&c=2000");
    let sys = SecondOrder::mechanical(300.0, 2000.0, 24_000.0).unwrap();
    let zeta = sys.damping_ratio().unwrap();
    assert_eq!(number(&f, "zeta"), zeta);
    let m = FreeMetrics::exact(&sys, X0, 0.0, SettlingBand::FREE_DEFAULT).unwrap();
    assert_eq!(number(&f, "settling_time"), m.settling_time.unwrap());
    // Release from rest: the rebound is the textbook overshoot e^{−πζ/√(1−ζ²)}.
    let rebound = 100.0 * rebound_from_rest(zeta).unwrap();
    assert!((number(&f, "overshoot") - rebound).abs() < 1e-9);
    assert_eq!(number(&f, "grid_size"), 10_000.0);
    let map = f.figures[0].heatmap.as_ref().unwrap();
    assert_eq!((map.nx, map.ny, map.values.len()), (100, 100, 10_000));
    assert!(f.figures[0]
        .description
        .contains("into ±5 % of x₀, over k 10–60 kN/m"));
}

#[test]
fn the_map_is_recomputed_only_when_its_inputs_change() {
    let mut d = DesignSpace::default();
    step(&mut d, "k=24000");
    step(&mut d, "k=30000&c=3000");
    step(&mut d, "k=30000&c=3000&metric=accel_rms");
    assert_eq!(d.sweeps, 1, "selection and metric reuse the sweep");
    step(&mut d, "m=400");
    step(&mut d, "m=400&n=40");
    assert_eq!(d.sweeps, 3);
    assert_eq!(d.maps.zeta.len(), 1600);
}

#[test]
fn the_map_cells_hold_the_solver_metrics_at_their_centres() {
    let f = DesignSpace::run("n=20&metric=peak_rebound");
    let map = f.figures[0].heatmap.as_ref().unwrap();
    // Cell (ix, iy) = (3, 7): k = 10 000 + 3.5·2 500, c = 500 + 7.5·375.
    let sys = SecondOrder::mechanical(300.0, 3_312.5, 18_750.0).unwrap();
    let expect = 100.0 * rebound_from_rest(sys.damping_ratio().unwrap()).unwrap();
    assert!((map.values[7 * 20 + 3] - expect).abs() < 1e-9);
}

#[test]
fn clicking_picks_a_design_and_the_front_is_non_dominated() {
    let mut d = DesignSpace::default();
    step(&mut d, "");
    assert_eq!(
        d.pick("map", 31.234, 4.3214),
        vec![("k", 31_230.0), ("c", 4_321.0)]
    );
    assert!(d.pick("map", 70.0, 4.0).is_empty(), "outside the map");
    assert!(d.pick("response", 1.0, 0.0).is_empty());
    // The Pareto plot as the page draws it before a click on it (its axes are the pick's).
    let (p, r) = step(&mut d, "");
    d.figure(1, &p, &r).unwrap();
    let comfort = d.comfort().clone();
    assert!(comfort.front.len() > 3);
    let (ts, acc) = (&d.maps.settling_time.clone(), &comfort.accel_rms);
    for w in comfort.front.windows(2) {
        assert!(ts[w[0]] <= ts[w[1]] && acc[w[0]] >= acc[w[1]]);
    }
    // Picking next to the front's first point chooses that design.
    let first = comfort.front[0];
    let (t, a) = (ts[first], acc[first]);
    let picked = d.pick("pareto", t, a);
    let (k, c) = d.design_at(first).unwrap();
    assert_eq!(picked, vec![("k", k), ("c", c)]);
}

#[test]
fn iso_zeta_lines_lie_on_their_damping_ratio() {
    let f = DesignSpace::run("");
    let map = &f.figures[0];
    assert_eq!(map.series.len(), 5);
    for (s, zeta) in map.series.iter().zip(ISO_ZETAS) {
        let (k, c) = s.points[s.points.len() / 2];
        let sys = SecondOrder::mechanical(300.0, c * KILO, k * KILO).unwrap();
        assert!((sys.damping_ratio().unwrap() - zeta).abs() < 1e-9);
    }
    assert!(map.markers.iter().any(|m| m.label == "ζ=0.7"));
}

#[test]
fn a_map_cell_and_the_two_dof_demo_agree_on_comfort_for_the_same_car() {
    // Cell (ix, iy) = (3, 7) of a 20 × 20 map: k = 10 000 + 3.5·2 500 = 18 750 N/m,
    // c = 500 + 7.5·375 = 3 312.5 N·s/m. The same car in quarter-car-2dof (random road,
    // no tyre damping in both): a_w and the unweighted RMS agree to 1e-9 relative (the
    // map's block solves against the full 13-state Lyapunov equation; both are exact to
    // rounding, at most 2e-12 apart over the sliders' ranges).
    for (design, two_dof) in [
        ("", "class=C&V=10"),
        (
            "m=420&mu=60&kt=150000&road=d&V=25",
            "ms=420&mu=60&kt=150000&class=D&V=25",
        ),
    ] {
        let query = format!("n=20&metric=accel_rms&{design}");
        let car = crate::demos::testing::run(
            "quarter-car-2dof",
            &format!("road=random&ks=18750&cs=3312.5&{two_dof}"),
        );
        let a_w = number(&car, "stationary_weighted_accel");
        let mut d = DesignSpace::default();
        step(&mut d, &query);
        let cell = d.comfort().accel_rms[7 * 20 + 3];
        assert_eq!(d.design_at(7 * 20 + 3), Some((18_750.0, 3_312.5)));
        assert!(
            (cell - a_w).abs() <= 1e-9 * a_w,
            "{design}: {cell} vs {a_w}"
        );
        // The page's map shows that cell as ln(a_w) on its logarithmic colour bar.
        let map = DesignSpace::run(&query)
            .figures
            .swap_remove(0)
            .heatmap
            .unwrap();
        let ln_a_w = zeta_solver::grid::log10(a_w) * std::f64::consts::LN_10;
        assert!(map.log && (map.values[7 * 20 + 3] - ln_a_w).abs() < 1e-9);
        // The selected design's readouts call the very function the two-DOF demo calls.
        let sel = DesignSpace::run(&format!("k=18750&c=3312.5&{design}"));
        assert_eq!(number(&sel, "accel_rms"), a_w);
        let unweighted = number(&car, "stationary_accel");
        assert_eq!(number(&sel, "accel_unweighted"), unweighted);
        assert!(a_w < unweighted, "W_k attenuates outside 4–12 Hz");
    }
}

#[test]
fn comfort_labels_say_weighted_two_dof_and_which_road() {
    let spec = DesignSpace::declare().spec();
    let label = |key: &str| spec.readouts.iter().find(|r| r.key == key).unwrap().label;
    assert!(label("accel_rms").contains("weighted by ISO 2631-1 W_k"));
    assert!(label("accel_unweighted").contains("unweighted"));
    let f = DesignSpace::run("metric=accel_rms&road=c&V=20");
    let bar = &f.figures[0].heatmap.as_ref().unwrap().label;
    assert!(bar.contains("W_k-weighted"), "{bar}");
    assert!(f.figures[1].y.label.contains("W_k-weighted"));
    // The road beside the value, in the map's caption and in the front's.
    let shown = crate::demos::testing::text(&f, "accel_rms");
    assert!(shown.ends_with("m/s² (class C road, 20 m/s)"), "{shown}");
    for fig in &f.figures[..2] {
        assert!(fig.description.contains("ISO 8608 class C road at 20 m/s"));
    }
    // The two-DOF demo's defaults: class C at 10 m/s, 40 kg wheel, 200 kN/m tyre.
    let f = DesignSpace::run("metric=accel_rms");
    assert!(f.figures[0]
        .description
        .contains("wheel 40 kg, tyre 200 kN/m"));
    assert!(f.figures[0].description.contains("class C road at 10 m/s"));
}

#[test]
fn the_road_class_scales_only_the_comfort_metric() {
    // ISO 8608: each class has 4× the roughness of the one before, so 2× the RMS.
    let b = DesignSpace::run("road=b");
    let c = DesignSpace::run("road=c");
    for key in ["accel_rms", "accel_unweighted"] {
        assert!((number(&c, key) / number(&b, key) - 2.0).abs() < 1e-12);
    }
    assert_eq!(number(&c, "settling_time"), number(&b, "settling_time"));
}

#[test]
fn settling_and_rebound_labels_say_free_response_relative_to_x0() {
    let spec = DesignSpace::declare().spec();
    for key in ["settling_time", "overshoot"] {
        let r = spec.readouts.iter().find(|r| r.key == key).unwrap();
        assert!(
            r.label.contains("x₀") && r.label.contains("free response"),
            "{}",
            r.label
        );
    }
    let band = spec.param("band").unwrap();
    assert!(band.label.contains("x₀") && band.label.contains("free response"));
    let f = DesignSpace::run("band=2");
    assert!(f.figures[0].title.contains("±2 % of x₀"));
    assert!(f.figures[2].description.contains("not a step"));
    // The colour bar names its unit for every metric.
    for (metric, unit) in [
        ("settling_time", "[s]"),
        ("peak_rebound", "[% of x₀]"),
        ("accel_rms", "[m/s²]"),
        ("peak_transmissibility", "[m/m]"),
    ] {
        let f = DesignSpace::run(&format!("metric={metric}"));
        let label = &f.figures[0].heatmap.as_ref().unwrap().label;
        assert!(label.contains(unit), "{metric}: {label}");
    }
}

#[test]
fn progressive_updates_show_a_marked_coarse_sweep_then_exactly_the_full_one() {
    let spec = DesignSpace::declare().spec();
    let params = |q| resolve_query(&spec, q).0;
    let mut reference = crate::demos::create("design").unwrap();
    let want = reference.update(&params("m=500"));
    let mut demo = crate::demos::create("design").unwrap();
    demo.set_progressive(true);
    let coarse = demo.update(&params("m=420"));
    let cells = super::progressive::COARSE_CELLS;
    assert_eq!(number(&coarse, "grid_size"), (cells * cells) as f64);
    assert!(demo.provisional().contains(&"map") && demo.provisional().contains(&"grid_size"));
    assert!(coarse.figures[0]
        .description
        .starts_with(&format!("Provisional: from a coarse {cells} × {cells}")));
    // Part of the sweep for m = 420, then the mass moves on: that sweep is never shown.
    assert!(matches!(demo.refine(0.0), Some(f) if f < 1.0));
    let moved = demo.update(&params("m=500"));
    assert_eq!(number(&moved, "grid_size"), (cells * cells) as f64);
    let mut slices = 0;
    while demo.refine(0.0) != Some(1.0) {
        slices += 1;
        assert!(slices <= 100, "one row per slice at least");
    }
    assert!(demo.provisional().is_empty());
    // Before the page's next update a figure built now (an export) shows the full sweep
    // with the results it belongs to, not the full maps read on the coarse grid.
    let early: Vec<_> = (0..).map_while(|i| demo.figure(i)).collect();
    assert!(format!("{early:?}") == format!("{:?}", want.figures));
    assert_eq!(demo.refine(5.0), None, "nothing left to do");
    let full = demo.update(&params("m=500"));
    // Debug text: the figures hold NaN gaps, which `==` never equates.
    assert!(format!("{:?}", shown(&full)) == format!("{:?}", shown(&want)));
    // The selected design's own readouts never wait for the sweep.
    for key in [
        "zeta",
        "settling_time",
        "overshoot",
        "accel_rms",
        "accel_unweighted",
    ] {
        assert_eq!(number(&moved, key), number(&want, key), "{key}");
    }
}

#[test]
fn a_held_control_gets_a_coarser_stand_in_and_the_same_full_sweep() {
    let spec = DesignSpace::declare().spec();
    let params = |q| resolve_query(&spec, q).0;
    let mut reference = crate::demos::create("design").unwrap();
    let want = reference.update(&params("m=420"));
    let mut demo = crate::demos::create("design").unwrap();
    demo.set_progressive(true);
    demo.set_held(true);
    let held = demo.update(&params("m=420"));
    let cells = super::progressive::HELD_CELLS;
    assert!(cells < super::progressive::COARSE_CELLS);
    assert_eq!(number(&held, "grid_size"), (cells * cells) as f64);
    assert!(held.figures[0]
        .description
        .starts_with(&format!("Provisional: from a coarse {cells} × {cells}")));
    // Released: the full sweep at rest is the one a non-progressive model computes.
    demo.set_held(false);
    while demo.refine(5.0).is_some_and(|done| done < 1.0) {}
    assert!(demo.provisional().is_empty());
    let full = demo.update(&params("m=420"));
    assert!(format!("{:?}", shown(&full)) == format!("{:?}", shown(&want)));
    // Not held, a move gets the usual coarse grid.
    let moved = demo.update(&params("m=430"));
    let coarse = super::progressive::COARSE_CELLS;
    assert_eq!(number(&moved, "grid_size"), (coarse * coarse) as f64);
}

#[test]
fn progressive_updates_keep_unmoved_maps_immediate() {
    let spec = DesignSpace::declare().spec();
    let mut demo = crate::demos::create("design").unwrap();
    demo.set_progressive(true);
    demo.update(&resolve_query(&spec, "n=25").0);
    while demo.refine(5.0).is_some_and(|done| done < 1.0) {}
    assert!(demo.provisional().is_empty() && demo.refine(5.0).is_none());
    // Moving the selected design reuses the map: nothing to refine.
    demo.update(&resolve_query(&spec, "n=25&k=30000&c=2500").0);
    assert!(demo.provisional().is_empty() && demo.refine(5.0).is_none());
}

#[test]
fn a_coarse_sweep_leaves_comfort_to_the_first_figure_that_needs_it() {
    // On a page, a moved map input gets a coarse sweep; with only the settling map in view
    // (a phone during a drag) nothing computes the comfort map. The Pareto plot, a comfort
    // map or a pick on the Pareto plot compute it then, the same as a full step would.
    let decl = DesignSpace::declare();
    let p = |q| decl.read(&resolve_query(&decl.spec(), q).0);
    let cells = super::progressive::COARSE_CELLS;
    let mut d = DesignSpace::default();
    d.set_progressive(true);
    let pq = p("m=420");
    let r = d.step(&pq).unwrap();
    assert!(r.provisional && d.comfort.get().is_none());
    d.figure(0, &pq, &r).unwrap();
    d.figure(2, &pq, &r).unwrap();
    assert!(
        d.comfort.get().is_none(),
        "the settling map and the response need none"
    );
    let pareto = d.figure(1, &pq, &r).unwrap();
    assert_eq!(
        d.comfort.get().map(|c| c.accel_rms.len()),
        Some(cells * cells)
    );
    // Every cell is the two-DOF car's a_w from the function the selected design's readout
    // calls (to 1e−9 relative: the map's block solves, as in the test above), and the
    // front drawn is the front over them.
    let comfort = d.comfort();
    for i in [0, 5, 77, cells * cells - 1] {
        let (k_s, c_s) = d.design_at(i).unwrap();
        let car = TwoDof::new(TwoDofConfig {
            k_s,
            c_s,
            ..r.key.car()
        })
        .unwrap();
        let a_w = stationary(&car, r.key.road.0, r.key.v)
            .unwrap()
            .rms_weighted_body_acceleration;
        let cell = comfort.accel_rms[i];
        assert!(
            (cell - a_w).abs() <= 1e-9 * a_w,
            "cell {i}: {cell} vs {a_w}"
        );
    }
    let front: Vec<(f64, f64)> = comfort
        .front
        .iter()
        .map(|&i| (d.maps.settling_time[i], comfort.accel_rms[i]))
        .collect();
    assert!(front.len() > 3);
    assert_eq!(pareto.series[1].points, front, "the front drawn");
    // The comfort map shown as the metric asks for it alike.
    let mut d = DesignSpace::default();
    d.set_progressive(true);
    let pc = p("m=420&metric=accel_rms");
    let r = d.step(&pc).unwrap();
    assert!(d.comfort.get().is_none());
    let map = d.figure(0, &pc, &r).unwrap();
    assert!(map.heatmap.unwrap().log && d.comfort.get().is_some());
}
