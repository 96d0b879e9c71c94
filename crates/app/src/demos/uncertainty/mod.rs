//! `uncertainty`: tolerances and robustness. The exact range of ζ, ω_n and Q when the
//! components sit anywhere within their tolerances, the band of free responses at the ends
//! of the range, and a seeded Monte Carlo run: histograms, percentiles and the yield against
//! a specification.
//!
//! `declaration.rs` declares the demo (parameters, readouts, plots and presets as data); this
//! file holds its model step (solver calls only) and the state kept between steps;
//! `cache.rs` keys and runs the Monte Carlo draws and `progressive.rs` runs them in slices
//! on a page; `ranges.rs` finds the exact ranges, `figures.rs` builds the plots and
//! `text.rs` holds the prose.

mod cache;
mod choices;
mod declaration;
mod figures;
mod progressive;
mod ranges;
mod text;

pub use choices::{Dist, HistOf, System};

use super::design::Stopwatch;
use super::progressive::{progressive_hooks, Progressive};
use super::Model;
use crate::declare::Declaration;
use crate::figure::Figure;
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
    /// Monte Carlo draws and seed, as set (the run rounds them to whole numbers).
    draws: f64,
    seed: f64,
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
            draws: self.draws.round().clamp(1.0, 100_000.0) as usize,
            seed: self.seed.round().max(0.0) as u64,
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
    /// The progressive run: the first draws at once on a page, the full run left to
    /// `refine` (see `progressive.rs`).
    progress: Progressive<progressive::McJob>,
    /// Buffers a full run fills next: the samples a finished run replaced, or those of a
    /// dropped run. Kept so that runs reuse two buffers instead of allocating each time.
    spare: McSamples,
}

impl Model for Uncertainty {
    type Params = P;
    type Results = Results;

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
                .progress
                .is_provisional()
                .then_some(self.key.map(|k| k.draws))
                .flatten(),
        })
    }

    progressive_hooks!(progressive::PROVISIONAL, refine_run);

    fn figure(&self, plot: usize, p: &P, r: &Results) -> Option<Figure> {
        let (of, pct, title) = match plot {
            0 => return Some(figures::band(p, r)),
            1 => (HistOf::Zeta, r.zeta_pct, t!("uncertainty-plot-zeta-hist")),
            2 => (
                p.hist,
                r.hist_pct,
                t!("uncertainty-hist-title", quantity = p.hist.label().0),
            ),
            _ => return None,
        };
        let mut fig = figures::histogram(p, &self.samples, of, pct, r.yield_pct, title);
        if let Some(full) = r.provisional_of {
            text::mark_provisional(&mut fig, r.draws, full);
        }
        Some(fig)
    }

    fn declare() -> Declaration<P, Results> {
        declaration::declaration()
    }
}

#[cfg(test)]
mod tests;
