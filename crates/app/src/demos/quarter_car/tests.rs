//! The quarter-car demo's own behaviour; its numbers at every preset are pinned by the
//! snapshot tests (`crates/app/tests/snapshots.rs`).

// Independent reference values are computed here by hand.
#![allow(clippy::disallowed_methods)]

use super::*;
use crate::demos::create;
use crate::demos::testing::{close, number, value, Tested};
use crate::params::Params;

#[test]
fn defaults_of_c_and_zeta_agree() {
    assert!(close(
        C_DEFAULT,
        2.0 * ZETA_DEFAULT * (M_DEFAULT * K_DEFAULT).sqrt(),
        1e-15
    ));
    assert!(close(number(&QuarterCar::run(""), "zeta"), 0.3, 1e-14));
}

#[test]
fn readouts_match_closed_forms() {
    let f = QuarterCar::run("c=1610");
    let wn = 80.0f64.sqrt();
    let zeta = 1610.0 / (2.0 * 7.2e6f64.sqrt());
    assert!(close(number(&f, "wn"), wn, 1e-14));
    assert!(close(number(&f, "fn"), wn / std::f64::consts::TAU, 1e-14));
    assert!(close(number(&f, "zeta"), zeta, 1e-14));
    assert!(close(
        number(&f, "wd"),
        wn * (1.0 - zeta * zeta).sqrt(),
        1e-12
    ));
    let rebound = (-std::f64::consts::PI * zeta / (1.0 - zeta * zeta).sqrt()).exp();
    assert!(close(number(&f, "overshoot"), 100.0 * rebound, 1e-10));
    assert!(close(
        number(&f, "peak_time"),
        std::f64::consts::PI / (wn * (1.0 - zeta * zeta).sqrt()),
        1e-12
    ));
    // 5 % band from rest: the optimum is ln 20/√(π² + ln² 20).
    let l = 20.0f64.ln();
    let z_opt = l / (std::f64::consts::PI.powi(2) + l * l).sqrt();
    assert!(close(number(&f, "zeta_argmin"), z_opt, 1e-6));
    // ±10 % mass: ζ ∝ m^−½.
    assert!(close(number(&f, "zeta_lo"), zeta / 1.1f64.sqrt(), 1e-12));
    assert!(close(number(&f, "zeta_hi"), zeta / 0.9f64.sqrt(), 1e-12));
    let ts = number(&f, "settling_time");
    assert!(ts > 1.105 && ts < 1.2, "{ts}");
}

#[test]
fn moving_zeta_sets_c_and_moving_c_sets_zeta() {
    let mut d = create("quarter-car").unwrap();
    let s = d.spec();
    let mut p = Params::defaults(&s);
    d.update(&p);
    p.set_raw(&s, "zeta", "0.7");
    let f = d.update(&p);
    let crit = 2.0 * 7.2e6f64.sqrt();
    assert!(close(number(&f, "c"), 0.7 * crit, 1e-14));
    assert!(close(number(&f, "zeta"), 0.7, 1e-14));
    assert_eq!(d.derived_params()[0], ("c", number(&f, "c")));
    // Without a write-back the c parameter is stale; moving m keeps the damper.
    p.set_raw(&s, "m", "400");
    let f = d.update(&p);
    assert!(close(number(&f, "c"), 0.7 * crit, 1e-14));
    let z = 0.7 * crit / (2.0 * (400.0f64 * 24_000.0).sqrt());
    assert!(close(number(&f, "zeta"), z, 1e-14));
    // Moving c wins over the (unchanged) ζ slider.
    p.set_raw(&s, "c", "3000");
    let f = d.update(&p);
    assert_eq!(number(&f, "c"), 3000.0);
    // With a write-back of the derived values the next update sees no move.
    for (k, v) in d.derived_params() {
        p.set_raw(&s, k, &format!("{v}"));
    }
    let again = d.update(&p);
    assert_eq!(number(&again, "c"), 3000.0);
    assert_eq!(again.readouts, f.readouts);
    // And a later ζ move after the write-back still counts.
    p.set_raw(&s, "zeta", "1");
    let f = d.update(&p);
    assert!(close(number(&f, "zeta"), 1.0, 1e-14));
}

#[test]
fn url_rule_c_wins_when_both_are_given() {
    assert_eq!(number(&QuarterCar::run("zeta=0.9&c=3000"), "c"), 3000.0);
    assert_eq!(number(&QuarterCar::run("c=3000&zeta=0.9"), "c"), 3000.0);
    assert!(close(
        number(&QuarterCar::run("zeta=0.9"), "zeta"),
        0.9,
        1e-14
    ));
}

#[test]
fn presets_give_consistent_c_and_zeta() {
    for preset in QuarterCar::declare().spec().presets {
        let f = QuarterCar::preset(preset.label);
        let z = preset.values.iter().find(|(k, _)| *k == "zeta").unwrap().1;
        assert!(close(number(&f, "zeta"), z, 1e-12), "{}", preset.label);
    }
    assert_eq!(
        value(&QuarterCar::run("zeta=1"), "regime"),
        "critically damped",
        "ζ = 1 from the slider is exactly critical"
    );
}

#[test]
fn settling_curve_breaks_at_jumps_and_marks_the_minimum() {
    let f = QuarterCar::run("");
    let fig = &f.figures[1];
    let breaks = fig.series[0].points.iter().filter(|p| p.0.is_nan()).count();
    assert!(breaks >= 3, "{breaks}");
    assert!(fig.markers.iter().any(|m| m.label.starts_with("fastest")));
    assert!(fig.description.contains("0.690"), "{}", fig.description);
}

#[test]
fn descriptions_follow_the_design() {
    let light = QuarterCar::run("zeta=0.2").figures[0].description.clone();
    let heavy = QuarterCar::run("zeta=2").figures[0].description.clone();
    assert!(light.contains("crosses equilibrium"), "{light}");
    assert!(
        heavy.contains("overdamped") && heavy.contains("no rebound"),
        "{heavy}"
    );
    let none = QuarterCar::run("c=0").figures[0].description.clone();
    assert!(none.contains("oscillates forever"), "{none}");
    let past_jump = QuarterCar::run("zeta=0.7");
    let d = &past_jump.figures[0].description;
    assert!(d.contains("settles before crossing"), "{d}");
    let strip = &past_jump.figures[2].description;
    assert!(strip.contains("inside this range"), "{strip}");
}

#[test]
fn the_rescaled_sweep_is_the_sweep_at_this_natural_frequency() {
    use zeta_solver::design::sweep::{fastest_settling_zeta, sweep_zeta_into, ZetaCurves};
    use zeta_solver::grid::linspace;
    // Moved away from the first car, so that the cached unit sweep is rescaled.
    let mut live = QuarterCar::live("band=2");
    let s = live.demo.spec();
    for (m, k) in [(550.0f64, 61_000.0f64), (120.0, 9_000.0)] {
        live.params.set_raw(&s, "m", &m.to_string());
        live.params.set_raw(&s, "k", &k.to_string());
        let f = live.demo.update(&live.params);
        let cfg = ZetaSweepConfig {
            wn: (k / m).sqrt(),
            x0: X0_DEFAULT,
            v0: 0.0,
            band: SettlingBand::new(0.02).unwrap(),
        };
        let best = fastest_settling_zeta(&cfg, OPTIMUM_RANGE.0, OPTIMUM_RANGE.1, OPTIMUM_GRID);
        let best = best.unwrap();
        assert!(close(number(&f, "zeta_argmin"), best.zeta, 1e-12));
        assert!(close(number(&f, "settling_min"), best.settling_time, 1e-12));
        let zeta = number(&f, "zeta");
        let zetas = linspace(
            (0.9 * zeta).clamp(0.02, 0.1),
            (1.3 * zeta).clamp(2.0, 15.0),
            SWEEP_POINTS,
        );
        let mut curves = ZetaCurves::default();
        sweep_zeta_into(&zetas, &cfg, &mut curves);
        let direct: Vec<(f64, f64)> = zetas.into_iter().zip(curves.settling_time).collect();
        let shown = &f.figures[1].series[0].points;
        let mut compared = 0;
        for (z, t) in shown.iter().filter(|p| p.1.is_finite()) {
            let at = direct.iter().find(|d| d.0 == *z).unwrap();
            assert!(close(*t, at.1, 1e-12), "ζ = {z}: {t} vs {}", at.1);
            compared += 1;
        }
        assert!(compared > SWEEP_POINTS / 2, "{compared}");
    }
}
