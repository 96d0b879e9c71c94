//! The tolerance demo's Monte Carlo cache: the draws are repeated only when the design,
//! tolerances, distribution, count or seed change (moving the spec or the histogram choice
//! reuses them), and percentiles are computed once per run.

use super::progressive::COARSE_DRAWS;
use super::{Dist, HistOf, Stopwatch, Uncertainty};
use crate::declare::Choice;
use zeta_solver::design::monte_carlo::{percentiles_into, run_into, McConfig, Tolerance};
use zeta_solver::design::sensitivity::Components;
use zeta_solver::metrics::SettlingBand;

/// Everything the Monte Carlo run depends on; it is repeated only when this changes.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct McKey {
    pub(super) design: Components,
    /// Tolerance of each component, a fraction.
    pub(super) tolerances: [f64; 3],
    pub(super) dist: Dist,
    pub(super) draws: usize,
    pub(super) seed: u64,
}

impl Uncertainty {
    pub(super) fn run_if_needed(&mut self, key: McKey) {
        if self.key == Some(key) {
            return;
        }
        // Inputs moved on: a run under way for other inputs is dropped unseen.
        self.drop_job();
        let watch = Stopwatch::start();
        let distribution = key.dist.0;
        let cfg = McConfig {
            design: key.design,
            tolerances: key.tolerances.map(|fraction| Tolerance {
                fraction,
                distribution,
            }),
            draws: key.draws,
            seed: key.seed,
            band: SettlingBand::FREE_DEFAULT,
        };
        let now = McConfig {
            draws: self.progress.size_now(key.draws, COARSE_DRAWS),
            ..cfg
        };
        run_into(&now, &mut self.samples);
        self.key = Some(key);
        self.finish_run(watch.elapsed_ms());
        match self.progress.is_provisional() {
            true => self.start_job(key, cfg),
            false => self.runs += 1,
        }
    }

    /// Percentiles and timing of freshly drawn samples.
    pub(super) fn finish_run(&mut self, ms: f64) {
        self.pct = [None; 5];
        self.percentiles(HistOf::Zeta);
        self.percentiles(HistOf::Q);
        self.mc_ms = ms;
    }

    /// `[p5, p95]` of a quantity over the current draws (cached per run).
    pub(super) fn percentiles(&mut self, h: HistOf) -> [f64; 2] {
        let i = h.index();
        if let Some(Some(p)) = self.pct.get(i) {
            return *p;
        }
        let mut out = [f64::NAN; 2];
        percentiles_into(
            h.data(&self.samples),
            &[0.05, 0.95],
            &mut self.scratch,
            &mut out,
        );
        if let Some(slot) = self.pct.get_mut(i) {
            *slot = Some(out);
        }
        out
    }
}
