//! The analogy demo's own behaviour; its numbers at every preset are pinned by the
//! snapshot tests (`crates/app/tests/snapshots.rs`).

use super::figures::CIRCUIT_OFFSET;
use super::*;
use crate::demos::create;
use crate::demos::regime_cases::each_regime;
use crate::demos::testing::{number, value, Tested};
use crate::figure::finite_extent;
use crate::params::Params;

#[test]
fn the_circuit_mirrors_the_mechanism() {
    let f = Analogy::run("m=4&c=2&k=25&x0=0.02");
    assert_eq!(number(&f, "L"), 4.0);
    assert_eq!(number(&f, "R"), 2.0);
    assert!((number(&f, "C") - 0.04).abs() < 1e-15);
    assert_eq!(number(&f, "q0"), 0.02);
    let wn = number(&f, "wn");
    assert!((wn - 2.5).abs() < 1e-12);
    assert!((number(&f, "w0") - wn).abs() < 1e-12);
    assert!((number(&f, "zeta") - 0.1).abs() < 1e-12);
    assert!((number(&f, "Q") - 5.0).abs() < 1e-12);
    assert_eq!(value(&f, "regime"), "underdamped");
    // ½kx₀² = ½·25·0.02² = 5 mJ.
    assert!((number(&f, "energy") - 0.005).abs() < 1e-15);
}

#[test]
fn normalised_curves_coincide_in_every_regime() {
    for (_, regime, f) in each_regime("analogy", "m=1&k=100", "c", [0.0, 1.0, 20.0, 40.0]) {
        let s = &f.figures[0].series;
        for (a, b) in s[0].points.iter().zip(&s[1].points) {
            assert!((a.1 - b.1).abs() < 1e-12);
        }
        let e = &f.figures[1].series;
        for (a, b) in e[0].points.iter().zip(&e[1].points) {
            assert!((a.1 - b.1).abs() < 1e-12 * e[0].points[0].1);
        }
        assert!(f.figures[0].description.starts_with(regime));
    }
}

#[test]
fn energy_is_conserved_without_damping_and_lost_with_it() {
    let free = Analogy::run("c=0");
    let tot = &free.figures[1].series[4].points;
    let e0 = tot[0].1;
    assert!(tot.iter().all(|p| (p.1 - e0).abs() < 1e-9 * e0));
    let damped = Analogy::run("c=2");
    let tot = &damped.figures[1].series[4].points;
    assert!(tot.last().unwrap().1 < 0.5 * tot[0].1);
}

#[test]
fn the_schematic_shows_both_machines_side_by_side() {
    let d = create("analogy").unwrap();
    let p = Params::defaults(&d.spec());
    let fig = d.schematic(&p, 0.1).unwrap();
    let labels: Vec<&str> = fig.markers.iter().map(|m| m.label.as_str()).collect();
    for l in ["m", "k", "c", "L", "R", "C", "mechanical", "electrical"] {
        assert!(labels.contains(&l), "{l} in {labels:?}");
    }
    let xs = fig.series.iter().flat_map(|s| s.points.iter().map(|p| p.0));
    let (lo, hi) = finite_extent(xs).unwrap();
    assert!(lo < 0.0 && hi > CIRCUIT_OFFSET.0, "both drawings present");
    assert!(hi <= fig.x.range.1 && lo >= fig.x.range.0);
    assert!(fig.description.contains("capacitor"));
}

#[test]
fn table_rows_have_every_column() {
    let t = Analogy::declare().spec().table.unwrap();
    for (_, cells) in &t.rows {
        assert_eq!(cells.len(), t.columns.len());
    }
}

#[test]
fn the_live_table_shows_equal_numbers_in_both_machines() {
    let table = Analogy::declare().spec().table.unwrap();
    let live = table.live_cells();
    assert_eq!(live.len(), 18, "{live:?}");
    for query in ["", "m=4&c=2&k=25&x0=0.02", "m=0.37&c=13.1&k=731&x0=0.093"] {
        let f = Analogy::run(query);
        for row in [
            "inertia",
            "dissipation",
            "stiffness",
            "compliance",
            "coordinate",
        ] {
            let keys: Vec<&str> = live
                .iter()
                .filter(|(r, _, _)| *r == row)
                .map(|(_, _, k)| *k)
                .collect();
            let [mech, elec] = keys[..] else {
                panic!("{row}: {keys:?}")
            };
            let (a, b) = (number(&f, mech), number(&f, elec));
            assert!(
                (a - b).abs() <= 1e-12 * a.abs(),
                "{query}: {mech} {a} ≠ {elec} {b}"
            );
        }
    }
}
