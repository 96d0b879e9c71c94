//! The RLC demo's own behaviour; its numbers at every preset are pinned by the snapshot
//! tests (`crates/app/tests/snapshots.rs`).

// Independent reference values are computed here by hand.
#![allow(clippy::disallowed_methods)]

use super::text::ohms;
use super::Rlc;
use crate::demos::regime_cases::each_regime;
use crate::demos::testing::{close, number, value, Tested};

#[test]
fn readouts_match_the_textbook_circuit() {
    // L = 0.5 H, C = 20 mF: ω₀ = 10 rad/s, R_crit = 10 Ω; R = 4 Ω → ζ = 0.4, Q = 1.25.
    let f = Rlc::run("R=4&L=0.5&C=0.02&V0=12");
    for (key, want) in [
        ("w0", 10.0),
        ("R_crit", 10.0),
        ("zeta", 0.4),
        ("Q", 1.25),
        ("alpha", 4.0),
        ("bandwidth", 8.0),
        ("wd", (100.0f64 - 16.0).sqrt()),
    ] {
        assert!(close(number(&f, key), want, 1e-14), "{key}");
    }
    assert_eq!(value(&f, "regime"), "underdamped");
}

#[test]
fn every_preset_reaches_its_regime_and_the_plots_start_right() {
    for (r, regime, f) in each_regime("rlc", "", "R", [0.0, 2.0, 10.0, 20.0]) {
        // i(0) = 0 and v_C(0) = V₀ on the design's curve (the last series).
        let i0 = f.figures[0].series.last().unwrap().points[0].1;
        let v0 = f.figures[1].series.last().unwrap().points[0].1;
        assert_eq!(i0, 0.0);
        assert!(close(v0, 12.0, 1e-14));
        for fig in &f.figures {
            assert!(
                fig.description.starts_with(&format!("R = {}", ohms(r))),
                "{}",
                fig.description
            );
            assert!(fig.description.contains(regime.split(' ').next().unwrap()));
        }
    }
    let lossless = Rlc::run("R=0");
    assert_eq!(
        value(&lossless, "Q"),
        "",
        "Q is infinite without resistance"
    );
    assert_eq!(value(&lossless, "settling_time"), "");
}

#[test]
fn the_current_never_exceeds_the_energy_bound() {
    for r in [0.0, 1.0, 4.0, 10.0, 30.0] {
        let f = Rlc::run(&format!("R={r}"));
        // V₀·√(C/L): all the initial energy ½CV₀² in the inductor, ½Li².
        let bound = 12.0 * (0.02f64 / 0.5).sqrt();
        let peak = f.figures[0]
            .series
            .last()
            .unwrap()
            .points
            .iter()
            .map(|p| p.1.abs())
            .fold(0.0, f64::max);
        assert!(peak <= bound * (1.0 + 1e-12), "R={r}: {peak} > {bound}");
        assert!(peak > 0.05 * bound);
    }
}

#[test]
fn the_envelopes_bound_the_ringing_and_touch_it() {
    // R = 2 Ω: ζ = 0.2; the envelope of the current is V₀/(L·ω_d)·e^(−αt).
    let f = Rlc::run("R=2");
    let wd = (100.0f64 - 4.0).sqrt();
    for (fig, amp) in [
        (&f.figures[0], 12.0 / (0.5 * wd)),
        (&f.figures[1], 12.0 * 10.0 / wd),
    ] {
        let env = &fig.series[0];
        assert_eq!(env.label, "envelope");
        assert!(
            close(env.points[0].1, amp, 1e-13),
            "{} vs {amp}",
            env.points[0].1
        );
        let t = env.points[60].0;
        assert!(close(env.points[60].1, amp * (-2.0 * t).exp(), 1e-13));
        // The design's curve stays inside and reaches the envelope.
        let own = &fig.series.last().unwrap().points;
        let ratio = own
            .iter()
            .map(|&(t, y)| y.abs() / (amp * (-2.0 * t).exp()))
            .fold(0.0, f64::max);
        assert!(ratio <= 1.0 + 1e-12 && ratio > 0.99, "{ratio}");
    }
    assert!(
        Rlc::run("R=20").figures[0]
            .series
            .iter()
            .all(|s| s.label != "envelope"),
        "no envelope without ringing"
    );
}

#[test]
fn the_voltage_text_counts_reversals() {
    let ringing = Rlc::run("R=2").figures[1].description.clone();
    assert!(ringing.contains("reverses polarity"), "{ringing}");
    let slight = Rlc::run("R=8").figures[1].description.clone();
    assert!(slight.contains("reverses only slightly"), "{slight}");
    let crit = Rlc::run("R=10").figures[1].description.clone();
    assert!(crit.contains("without reversing"), "{crit}");
}

#[test]
fn the_schematic_follows_the_current() {
    use crate::demos::create;
    use crate::params::Params;
    let demo = create("rlc").unwrap();
    let p = Params::defaults(&demo.spec());
    let fig = demo.schematic(&p, 0.1).unwrap();
    assert!(fig.description.contains("current -"), "{}", fig.description);
    // Discharging (i < 0): the current arrow points left along the bottom wire.
    let shaft = fig
        .series
        .iter()
        .find(|s| s.style.ink == crate::plot::Ink::Purple)
        .expect("a current arrow");
    assert!(shaft.points[1].0 < shaft.points[0].0, "{:?}", shaft.points);
}
