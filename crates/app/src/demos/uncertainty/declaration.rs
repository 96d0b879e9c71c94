//! The tolerance demo's declaration as data: parameters, readouts, plots and presets.

use super::{figures, text, Dist, HistOf, Results, System, P};
use crate::declare::{Choice, Declaration, Param};
use crate::demos::design::sprung_mass;
use crate::demos::rows::{self, readouts, sliders, Plot};
use crate::i18n::number;
use crate::spec::Preset;
use crate::t;

/// The range of every tolerance slider \[%\].
const TOLERANCE: (f64, f64, f64) = (0.0, 30.0, 0.5);

pub(super) fn declaration() -> Declaration<P, Results> {
    Declaration {
        equation_mathml: text::EQUATION,
        params: params(),
        readouts: readouts! { Results, |r|;
            number "zeta_min", "ζ, lowest (exact)", "", 4 => r.ranges.zeta.map(|(lo, _)| lo);
            number "zeta_max", "ζ, highest (exact)", "", 4 => r.ranges.zeta.map(|(_, hi)| hi);
            number "wn_min", "ωₙ, lowest (exact)", "rad/s", 4 => r.ranges.wn.map(|(lo, _)| lo);
            number "wn_max", "ωₙ, highest (exact)", "rad/s", 4 => r.ranges.wn.map(|(_, hi)| hi);
            number "Q_min", "Q, lowest (exact)", "", 4 => r.ranges.q.map(|(lo, _)| lo);
            number "Q_max", "Q, highest (exact)", "", 4 => r.ranges.q.map(|(_, hi)| hi);
            number "yield", "yield (meets spec)", "%", 3 => Some(r.yield_pct);
            number "zeta_p5", "ζ, 5th percentile", "", 4 => Some(r.zeta_pct[0]);
            number "zeta_p95", "ζ, 95th percentile", "", 4 => Some(r.zeta_pct[1]);
            number "Q_p5", "Q, 5th percentile", "", 4 => Some(r.q_pct[0]);
            number "Q_p95", "Q, 95th percentile", "", 4 => Some(r.q_pct[1]);
            formatted "draws", "draws", "" => {
                let n = r.draws as f64;
                Some(match r.provisional_of {
                    None => (n, number::fixed(n, 0)),
                    Some(full) => (
                        n,
                        t!("uncertainty-draws-provisional", draws = r.draws, full = full),
                    ),
                })
            };
            // Plain: the value is already in ms (an SI prefix would give "µms").
            plain "compute_time", "Monte Carlo compute time", "ms", 3 => Some(r.mc_ms);
        },
        plots: rows::plots(&PLOTS),
        presets: presets(),
        ..Declaration::new("uncertainty", "Tolerance analysis", text::SUMMARY)
    }
}

/// The parameters, in order.
fn params() -> Vec<Param<P>> {
    // Each system's sliders are shown only while it is chosen (the other's do nothing).
    let (suspension, rlc) = (System::Suspension.index(), System::Rlc.index());
    [
        vec![
            Param::<P>::choice("system", "system", System::default(), |p, v| p.system = v),
            sprung_mass("suspension: sprung mass", |p: &mut P, v| p.m = v).visible_when("system", suspension),
        ],
        sliders! { P;
            linear "k", "suspension: spring rate", "k", "N/m", (5_000.0, 100_000.0, 100.0), 24_000.0 => k, visible_when("system", suspension);
            linear "zeta", "suspension: design ζ at nominal mass", "ζ", "", (0.05, 2.0, 0.01), 0.7 => zeta, visible_when("system", suspension);
            linear "dm", "suspension: mass tolerance ±", "", "%", TOLERANCE, 10.0 => dm, visible_when("system", suspension);
            log "R", "RLC: resistance", "R", "Ω", (0.1, 1_000.0, 0.01), 7.0 => r, visible_when("system", rlc);
            log "L", "RLC: inductance", "L", "H", (0.001, 10.0, 0.001), 0.5 => l, visible_when("system", rlc);
            log "C", "RLC: capacitance", "C", "F", (1e-6, 1.0, 1e-6), 0.02 => cap, visible_when("system", rlc);
            linear "dR", "RLC: resistor tolerance ±", "", "%", TOLERANCE, 5.0 => dr, visible_when("system", rlc);
            linear "dL", "RLC: inductor tolerance ±", "", "%", TOLERANCE, 5.0 => dl, visible_when("system", rlc);
            linear "dC", "RLC: capacitor tolerance ±", "", "%", TOLERANCE, 5.0 => dc, visible_when("system", rlc);
        },
        vec![Param::choice("dist", "distribution of parts", Dist::default(), |p, v| p.dist = v)],
        sliders! { P;
            log "N", "Monte Carlo draws", "N", "", (100.0, 100_000.0, 1.0), 10_000.0 => draws;
            linear "seed", "random seed", "", "", (0.0, 999.0, 1.0), 1.0 => seed;
            linear "zeta_lo", "spec: lowest ζ", "ζ_lo", "", (0.0, 2.0, 0.01), 0.6 => zeta_lo;
            linear "zeta_hi", "spec: highest ζ", "ζ_hi", "", (0.0, 3.0, 0.01), 1.0 => zeta_hi;
            log "ts_max", "spec: longest settling time", "t_s,max", "s", (0.01, 10.0, 0.001), 0.5 => ts_max;
        },
        vec![Param::choice("hist", "second histogram", HistOf::default(), |p, v| p.hist = v)],
    ]
    .into_iter()
    .flatten()
    .collect()
}

/// The plots, in order: key, title and width / height.
const PLOTS: [Plot; 3] = [
    ("band", figures::BAND_TITLE, 2.0),
    ("zeta_hist", figures::ZETA_HIST_TITLE, 1.5),
    ("hist", "Monte Carlo: chosen quantity", 1.5),
];

/// The preset buttons.
fn presets() -> Vec<Preset> {
    let car = |label, zeta| Preset {
        label,
        values: vec![
            ("system", 0.0),
            ("m", 300.0),
            ("k", 24_000.0),
            ("zeta", zeta),
            ("dm", 10.0),
        ],
    };
    let rlc = |label, pct| Preset {
        label,
        values: vec![("system", 1.0), ("dR", pct), ("dL", pct), ("dC", pct)],
    };
    vec![
        car("ζ = 1 design under ±10 % mass", 1.0),
        car("ζ = 0.7 design under ±10 % mass", 0.7),
        rlc("RLC 5 % parts", 5.0),
        rlc("RLC 20 % parts", 20.0),
    ]
}
