//! The tolerance demo's declaration as data: parameters, readouts, plots and presets.

use super::{figures, text, Dist, HistOf, Results, System, P};
use crate::declare::{Declaration, Param, ReadoutDef};
use crate::demos::design::sprung_mass;
use crate::i18n::number;
use crate::spec::{PlotSpec, Preset};
use crate::t;

pub(super) fn declaration() -> Declaration<P, Results> {
    let (linear, log) = (Param::linear, Param::log);
    Declaration {
        equation_mathml: text::EQUATION,
        params: vec![
            Param::choice("system", "system", System::Suspension, |p, v| p.system = v),
            sprung_mass("suspension: sprung mass", |p, v| p.m = v),
            linear(
                "k",
                "suspension: spring rate",
                "k",
                "N/m",
                (5_000.0, 100_000.0, 100.0),
                24_000.0,
                |p, v| p.k = v,
            ),
            linear(
                "zeta",
                "suspension: design ζ at nominal mass",
                "ζ",
                "",
                (0.05, 2.0, 0.01),
                0.7,
                |p, v| p.zeta = v,
            ),
            tolerance("dm", "suspension: mass tolerance ±", 10.0, |p, v| p.dm = v),
            log(
                "R",
                "RLC: resistance",
                "R",
                "Ω",
                (0.1, 1_000.0, 0.01),
                7.0,
                |p, v| p.r = v,
            ),
            log(
                "L",
                "RLC: inductance",
                "L",
                "H",
                (0.001, 10.0, 0.001),
                0.5,
                |p, v| p.l = v,
            ),
            log(
                "C",
                "RLC: capacitance",
                "C",
                "F",
                (1e-6, 1.0, 1e-6),
                0.02,
                |p, v| p.cap = v,
            ),
            tolerance("dR", "RLC: resistor tolerance ±", 5.0, |p, v| p.dr = v),
            tolerance("dL", "RLC: inductor tolerance ±", 5.0, |p, v| p.dl = v),
            tolerance("dC", "RLC: capacitor tolerance ±", 5.0, |p, v| p.dc = v),
            Param::choice("dist", "distribution of parts", Dist::Uniform, |p, v| {
                p.dist = v
            }),
            log(
                "N",
                "Monte Carlo draws",
                "N",
                "",
                (100.0, 100_000.0, 1.0),
                10_000.0,
                |p, v| p.draws = v.round().clamp(1.0, 100_000.0) as usize,
            ),
            linear(
                "seed",
                "random seed",
                "",
                "",
                (0.0, 999.0, 1.0),
                1.0,
                |p, v| p.seed = v.round().max(0.0) as u64,
            ),
            linear(
                "zeta_lo",
                "spec: lowest ζ",
                "ζ_lo",
                "",
                (0.0, 2.0, 0.01),
                0.6,
                |p, v| p.zeta_lo = v,
            ),
            linear(
                "zeta_hi",
                "spec: highest ζ",
                "ζ_hi",
                "",
                (0.0, 3.0, 0.01),
                1.0,
                |p, v| p.zeta_hi = v,
            ),
            log(
                "ts_max",
                "spec: longest settling time",
                "t_s,max",
                "s",
                (0.01, 10.0, 0.001),
                0.5,
                |p, v| p.ts_max = v,
            ),
            Param::choice("hist", "second histogram", HistOf::Q, |p, v| p.hist = v),
        ],
        readouts: vec![
            ReadoutDef::number("zeta_min", "ζ, lowest (exact)", "", 4, exact::<0, false>),
            ReadoutDef::number("zeta_max", "ζ, highest (exact)", "", 4, exact::<0, true>),
            ReadoutDef::number(
                "wn_min",
                "ωₙ, lowest (exact)",
                "rad/s",
                4,
                exact::<1, false>,
            ),
            ReadoutDef::number(
                "wn_max",
                "ωₙ, highest (exact)",
                "rad/s",
                4,
                exact::<1, true>,
            ),
            ReadoutDef::number("Q_min", "Q, lowest (exact)", "", 4, exact::<2, false>),
            ReadoutDef::number("Q_max", "Q, highest (exact)", "", 4, exact::<2, true>),
            ReadoutDef::number("yield", "yield (meets spec)", "%", 3, |r| Some(r.yield_pct)),
            ReadoutDef::number("zeta_p5", "ζ, 5th percentile", "", 4, |r| {
                Some(r.zeta_pct[0])
            }),
            ReadoutDef::number("zeta_p95", "ζ, 95th percentile", "", 4, |r| {
                Some(r.zeta_pct[1])
            }),
            ReadoutDef::number("Q_p5", "Q, 5th percentile", "", 4, |r| Some(r.q_pct[0])),
            ReadoutDef::number("Q_p95", "Q, 95th percentile", "", 4, |r| Some(r.q_pct[1])),
            ReadoutDef::formatted("draws", "draws", "", |r| {
                Some(match r.provisional_of {
                    None => (r.draws as f64, number::fixed(r.draws as f64, 0)),
                    Some(full) => (
                        r.draws as f64,
                        t!(
                            "uncertainty-draws-provisional",
                            draws = r.draws,
                            full = full
                        ),
                    ),
                })
            }),
            // Plain: the value is already in ms (an SI prefix would give "µms").
            ReadoutDef::plain("compute_time", "Monte Carlo compute time", "ms", 3, |r| {
                Some(r.mc_ms)
            }),
        ],
        plots: vec![
            PlotSpec {
                key: "band",
                title: figures::BAND_TITLE,
                aspect: 2.0,
            },
            PlotSpec {
                key: "zeta_hist",
                title: figures::ZETA_HIST_TITLE,
                aspect: 1.5,
            },
            PlotSpec {
                key: "hist",
                title: "Monte Carlo: chosen quantity",
                aspect: 1.5,
            },
        ],
        presets: presets(),
        ..Declaration::new("uncertainty", "Tolerance analysis", text::SUMMARY)
    }
}

/// The readouts of the exact ranges: the lowest (`HIGH` false) or highest end of the range
/// of ζ (`WHICH` 0), ωₙ (1) or Q (2).
fn exact<const WHICH: usize, const HIGH: bool>(r: &Results) -> Option<f64> {
    let ranges = [r.ranges.zeta, r.ranges.wn, r.ranges.q];
    let (lo, hi) = ranges.get(WHICH).copied().flatten()?;
    Some(if HIGH { hi } else { lo })
}

/// A tolerance slider in percent.
fn tolerance(
    key: &'static str,
    label: &'static str,
    default: f64,
    set: fn(&mut P, f64),
) -> Param<P> {
    Param::linear(key, label, "", "%", (0.0, 30.0, 0.5), default, set)
}

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
