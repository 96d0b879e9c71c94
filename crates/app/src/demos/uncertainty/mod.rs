//! `uncertainty`: tolerances and robustness. The exact range of ζ, ω_n and Q when the
//! components sit anywhere within their tolerances, the band of free responses at the ends
//! of the range, and a seeded Monte Carlo run: histograms, percentiles and the yield against
//! a specification.
//!
//! This file declares the demo and holds its model step (solver calls only) and the Monte
//! Carlo cache; `ranges.rs` finds the exact ranges, `figures.rs` builds the plots and
//! `text.rs` holds the prose.

mod cache;
mod choices;
mod figures;
mod progressive;
mod ranges;
mod text;

pub use choices::{Dist, HistOf, System};

use super::design::Stopwatch;
use super::Model;
use crate::declare::{Declaration, Param, ReadoutDef};
use crate::figure::Figure;
use crate::i18n::number;
use crate::spec::PlotSpec;
use crate::t;
use cache::McKey;
use ranges::Ranges;
use zeta_solver::design::monte_carlo::{yield_percent, McSamples, Spec};
use zeta_solver::design::sensitivity::Components;

/// Typed parameters, filled from the declaration.
#[derive(Debug, Default, Clone, Copy, PartialEq)]
pub struct P {
    system: System,
    /// Suspension: sprung mass \[kg\], spring \[N/m\], design ζ at nominal mass, mass
    /// tolerance \[%\].
    m: f64,
    k: f64,
    zeta: f64,
    dm: f64,
    /// RLC: resistance \[Ω\], inductance \[H\], capacitance \[F\] and their tolerances \[%\].
    r: f64,
    l: f64,
    cap: f64,
    dr: f64,
    dl: f64,
    dc: f64,
    dist: Dist,
    /// Monte Carlo draws and seed.
    draws: usize,
    seed: u64,
    /// Spec: ζ window and longest settling time \[s\].
    zeta_lo: f64,
    zeta_hi: f64,
    ts_max: f64,
    hist: HistOf,
}

impl P {
    /// The nominal design and the tolerance of each component (fractions, in the order of
    /// [`Components::values`]).
    fn design(&self) -> (Components, [f64; 3]) {
        match self.system {
            System::Suspension => (
                Components::mechanical_for_zeta(self.m, self.k, self.zeta),
                [self.dm / 100.0, 0.0, 0.0],
            ),
            System::Rlc => (
                Components::Electrical {
                    l: self.l,
                    r: self.r,
                    cap: self.cap,
                },
                [self.dl / 100.0, self.dr / 100.0, self.dc / 100.0],
            ),
        }
    }

    /// The spec's ζ window, lower end first.
    fn zeta_window(&self) -> (f64, f64) {
        (
            self.zeta_lo.min(self.zeta_hi),
            self.zeta_lo.max(self.zeta_hi),
        )
    }

    fn mc_key(&self) -> McKey {
        let (design, tolerances) = self.design();
        McKey {
            design,
            tolerances,
            dist: self.dist,
            draws: self.draws,
            seed: self.seed,
        }
    }
}

/// What one step computes (the draws themselves stay in [`Uncertainty`]'s cache).
pub struct Results {
    ranges: Ranges,
    /// Share of draws meeting the spec \[%\].
    yield_pct: f64,
    /// 5th and 95th percentiles of ζ, Q and the second histogram's quantity.
    zeta_pct: [f64; 2],
    q_pct: [f64; 2],
    hist_pct: [f64; 2],
    draws: usize,
    /// Duration of the last Monte Carlo run \[ms\] (wall clock).
    mc_ms: f64,
    /// Draws of the full run when the samples shown are its coarse start, else `None`.
    provisional_of: Option<usize>,
}

/// The tolerance demo. Keeps the Monte Carlo samples and percentiles between updates.
#[derive(Debug, Default)]
pub struct Uncertainty {
    samples: McSamples,
    key: Option<McKey>,
    mc_ms: f64,
    runs: u64,
    scratch: Vec<f64>,
    /// 5th and 95th percentiles per [`HistOf`] index, filled lazily after each run.
    pct: [Option<[f64; 2]>; 5],
    /// Whether moved inputs get a coarse run first (on a page; see `progressive.rs`).
    progressive: bool,
    /// Whether the samples held are the coarse stand-in for `key`.
    provisional: bool,
    /// The full run under way, if any.
    job: Option<progressive::McJob>,
    /// Buffers a full run fills next: the samples a finished run replaced, or those of a
    /// dropped run. Kept so that runs reuse two buffers instead of allocating each time.
    spare: McSamples,
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

impl Model for Uncertainty {
    type Params = P;
    type Results = Results;

    fn declare() -> Declaration<P, Results> {
        let (linear, log) = (Param::linear, Param::log);
        Declaration {
            equation_mathml: text::EQUATION,
            params: vec![
                Param::choice("system", "system", System::Suspension, |p, v| p.system = v),
                linear(
                    "m",
                    "suspension: sprung mass",
                    "m",
                    "kg",
                    (100.0, 800.0, 1.0),
                    300.0,
                    |p, v| p.m = v,
                ),
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
                ReadoutDef::number("zeta_min", "ζ, lowest (exact)", "", 4, |r| {
                    r.ranges.zeta.map(|v| v.0)
                }),
                ReadoutDef::number("zeta_max", "ζ, highest (exact)", "", 4, |r| {
                    r.ranges.zeta.map(|v| v.1)
                }),
                ReadoutDef::number("wn_min", "ωₙ, lowest (exact)", "rad/s", 4, |r| {
                    r.ranges.wn.map(|v| v.0)
                }),
                ReadoutDef::number("wn_max", "ωₙ, highest (exact)", "rad/s", 4, |r| {
                    r.ranges.wn.map(|v| v.1)
                }),
                ReadoutDef::number("Q_min", "Q, lowest (exact)", "", 4, |r| {
                    r.ranges.q.map(|v| v.0)
                }),
                ReadoutDef::number("Q_max", "Q, highest (exact)", "", 4, |r| {
                    r.ranges.q.map(|v| v.1)
                }),
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
            presets: text::presets(),
            ..Declaration::new("uncertainty", "Tolerance analysis", text::SUMMARY)
        }
    }

    fn step(&mut self, p: &P) -> Option<Results> {
        self.run_if_needed(p.mc_key());
        let spec = Spec {
            zeta: Some(p.zeta_window()),
            max_settling_time: Some(p.ts_max),
            ..Spec::default()
        };
        Some(Results {
            ranges: Ranges::new(p),
            yield_pct: yield_percent(&self.samples, &spec),
            zeta_pct: self.percentiles(HistOf::Zeta),
            q_pct: self.percentiles(HistOf::Q),
            hist_pct: self.percentiles(p.hist),
            draws: self.samples.zeta.len(),
            mc_ms: self.mc_ms,
            provisional_of: self
                .provisional
                .then_some(self.key.map(|k| k.draws))
                .flatten(),
        })
    }

    fn set_progressive(&mut self, on: bool) {
        self.progressive = on;
    }

    fn refine(&mut self, budget_ms: f64) -> Option<f64> {
        self.refine_run(budget_ms)
    }

    fn provisional(&self) -> Vec<&'static str> {
        match self.provisional {
            true => progressive::PROVISIONAL.to_vec(),
            false => Vec::new(),
        }
    }

    fn figures(&self, p: &P, r: &Results) -> Vec<Figure> {
        let mut figs = vec![
            figures::band(p, r),
            figures::histogram(
                p,
                &self.samples,
                HistOf::Zeta,
                r.zeta_pct,
                r.yield_pct,
                t!("uncertainty-plot-zeta-hist"),
            ),
            figures::histogram(
                p,
                &self.samples,
                p.hist,
                r.hist_pct,
                r.yield_pct,
                t!("uncertainty-hist-title", quantity = p.hist.label().0),
            ),
        ];
        if let Some(full) = r.provisional_of {
            for f in &mut figs[1..] {
                text::mark_provisional(f, r.draws, full);
            }
        }
        figs
    }
}

#[cfg(test)]
mod tests;
