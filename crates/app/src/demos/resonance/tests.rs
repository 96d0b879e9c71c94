//! The resonance demo's own behaviour; its numbers at every preset are pinned by the
//! snapshot tests (`crates/app/tests/snapshots.rs`).

// Independent reference values are computed here by hand.
#![allow(clippy::disallowed_methods)]

use super::Resonance;
use crate::demos::testing::{self, number, value, Tested};
use crate::demos::{create, Frame};
use crate::figure::AxisScale;
use crate::params::resolve_query;

fn close(a: f64, b: f64, tol: f64) -> bool {
    (a - b).abs() <= tol * b.abs().max(1e-300)
}

#[test]
fn readouts_match_the_closed_forms() {
    let z = 0.05;
    let f = Resonance::run("zeta=0.05&r=1&wn=6&F0=10");
    assert!(close(number(&f, "Q"), 10.0, 1e-12));
    let g = 1.0 / (2.0 * z * (1.0f64 - z * z).sqrt());
    assert!(close(number(&f, "peak_gain"), g, 1e-12));
    assert!(close(
        number(&f, "peak_ratio"),
        (1.0f64 - 2.0 * z * z).sqrt(),
        1e-12
    ));
    assert!(close(number(&f, "gain_at_r"), 10.0, 1e-12));
    assert!(close(
        number(&f, "phase_at_r"),
        -std::f64::consts::FRAC_PI_2,
        1e-12
    ));
    // X = |H|·F0/k = 10 · 10/36 m.
    assert!(close(number(&f, "amplitude"), 100.0 / 36.0, 1e-9));
    let s = (1.0f64 - z * z).sqrt();
    let bw = (1.0 - 2.0 * z * z + 2.0 * z * s).sqrt() - (1.0 - 2.0 * z * z - 2.0 * z * s).sqrt();
    assert!(close(number(&f, "peak_width"), bw, 1e-9));
}

#[test]
fn no_peak_above_one_over_root_two() {
    let f = Resonance::run("zeta=0.8&r=2");
    assert_eq!(value(&f, "peak_gain"), "");
    assert_eq!(value(&f, "peak_ratio"), "");
    assert_eq!(testing::text(&f, "peak_gain"), "—");
    assert_eq!(value(&f, "peak_width"), "", "no peak, no peak width");
    let d = &f.figures[0].description;
    assert!(
        d.contains("no resonant peak") && d.contains("cut-off r = 0.871"),
        "{d}"
    );
}

#[test]
fn the_views_change_the_magnitude_axis_and_every_figure_is_drawable() {
    let lin = Resonance::run("view=linear&zeta=0.01");
    let db = Resonance::run("view=db&zeta=0.01");
    assert_eq!(lin.figures[0].y.unit, "");
    assert_eq!(db.figures[0].y.unit, "dB");
    for f in lin.figures.iter().chain(&db.figures) {
        assert!(f.has_visible_data());
        assert!(f.x.range.0 > 0.0 || f.x.scale == AxisScale::Linear);
    }
    // The ζ = 0.01 peak (50) is resolved by the grid: the drawn maximum is within 0.1 %.
    let drawn = lin.figures[0]
        .series
        .iter()
        .find(|s| s.label.starts_with("current"))
        .unwrap()
        .points
        .iter()
        .map(|p| p.1)
        .filter(|v| v.is_finite())
        .fold(0.0, f64::max);
    assert!(
        close(drawn, 1.0 / (0.02 * (1.0f64 - 1e-4).sqrt()), 1e-3),
        "{drawn}"
    );
}

#[test]
fn build_up_at_resonance_and_beats_off_it() {
    let res = Resonance::run("zeta=0.05&r=1");
    let d = &res.figures[2].description;
    assert!(d.contains("builds up"), "{d}");
    let x = &res.figures[2].series.last().unwrap().points;
    let early = x[..100].iter().map(|p| p.1.abs()).fold(0.0, f64::max);
    let late = x[900..].iter().map(|p| p.1.abs()).fold(0.0, f64::max);
    assert!(late > 3.0 * early);
    let beat = Resonance::run("zeta=0.01&r=0.9");
    let d = &beat.figures[2].description;
    assert!(d.contains("beat"), "{d}");
    assert!(!value(&beat, "beat_period").is_empty());
    let labels = |f: &Frame| -> Vec<String> {
        f.figures[2]
            .series
            .iter()
            .map(|s| s.label.clone())
            .collect()
    };
    assert!(labels(&beat).iter().any(|l| l.starts_with("envelope")));
    // Far from resonance the "envelope" would wobble faster than the motion: not drawn.
    assert!(!labels(&Resonance::run("zeta=0.1&r=0.2"))
        .iter()
        .any(|l| l.starts_with("envelope")));
}

#[test]
fn schematic_draws_the_force_and_stays_finite() {
    let d = create("resonance").unwrap();
    let spec = d.spec();
    for q in ["zeta=0.01&r=0.1", "zeta=2&r=10", "zeta=0.05&r=1&F0=0.1"] {
        let (p, _) = resolve_query(&spec, q);
        for t in [0.0, 0.3, 7.0] {
            let fig = d.schematic(&p, t).unwrap();
            assert!(fig.has_visible_data());
            assert!(fig
                .series
                .iter()
                .all(|s| s.points.iter().all(|p| p.0.is_finite() && p.1.is_finite())));
            assert!(fig.description.contains("force"));
        }
    }
}

#[test]
fn the_half_power_width_is_two_sided_or_undefined() {
    // Both half-power points exist below ζ = sin(π/8) ≈ 0.383.
    let narrow = Resonance::run("zeta=0.3");
    assert!(!value(&narrow, "peak_width").is_empty());
    assert!(narrow.figures[0].description.contains("peak width r₂ − r₁"));
    // Above it the peak is one-sided: |H| stays above |H|max/√2 down to r = 0.
    let broad = Resonance::run("zeta=0.5");
    assert!(!value(&broad, "peak_gain").is_empty(), "still a peak");
    assert_eq!(value(&broad, "peak_width"), "");
    let d = &broad.figures[0].description;
    assert!(d.contains("no lower half-power point"), "{d}");
    let legend: Vec<&str> = broad.figures[0]
        .series
        .iter()
        .map(|s| s.label.as_str())
        .collect();
    assert!(legend
        .iter()
        .any(|l| l.starts_with("|H| ≥ |H|max/√2 up to r = ")));
}

#[test]
fn no_beat_period_where_no_beat_shows() {
    // At resonance the amplitude builds up: the would-be period 2π/|ω − ω_d| (209 s here)
    // is far longer than the transient lasts.
    let at = Resonance::run("zeta=0.1&r=1");
    assert_eq!(value(&at, "beat_period"), "");
    assert_eq!(testing::text(&at, "beat_period"), "—");
    assert!(value(&at, "beats").starts_with("none (the free motion dies out"));
    // Far off resonance the "beat" is as fast as the motion.
    assert!(value(&Resonance::run("zeta=0.1&r=0.2"), "beats").starts_with("none (as fast as"));
    // Near resonance with light damping the beats show.
    let near = Resonance::run("zeta=0.01&r=0.9");
    assert_eq!(value(&near, "beats"), "visible");
    assert!(number(&near, "beat_period") > 0.0);
    assert_eq!(
        value(&Resonance::run("zeta=1.5&r=0.9"), "beats"),
        "none (no free oscillation, ζ ≥ 1)"
    );
}

#[test]
fn the_kept_family_is_the_one_computed_afresh() {
    let moves = [("r", "2"), ("zeta", "0.05"), ("view", "db")];
    crate::demos::testing::assert_kept_is_fresh("resonance", "wn=3", &moves);
}

#[test]
fn the_family_carries_its_peaks_whatever_the_current_zetas_axis() {
    // At ζ = 0.3 the magnitude axis ends at 2.5; a drag that started at ζ = 0.05 holds it
    // at 12 (the renderer keeps the wider range). The family's curves must still be their
    // own, peaks and all, for the renderer to cut at the axis drawn: the lightest member,
    // ζ = 0.01, peaks at 1/(2ζ√(1 − ζ²)) ≈ 50 near r = 1.
    let f = Resonance::run("zeta=0.3&r=1");
    let fig = &f.figures[0];
    assert!(fig.y.range.1 < 3.0, "{:?}", fig.y.range);
    let lightest = &fig.series[0];
    assert!(lightest.points.iter().all(|p| p.1.is_finite()));
    let top = lightest.points.iter().map(|p| p.1).fold(0.0, f64::max);
    let peak = 1.0 / (2.0 * 0.01 * (1.0f64 - 1e-4).sqrt());
    // The grid's nearest point to the peak is within a few parts in a thousand of it.
    assert!(close(top, peak, 5e-3), "{top} vs {peak}");
}
