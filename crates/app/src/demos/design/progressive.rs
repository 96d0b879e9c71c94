//! Progressive sweeps (issue 13): on a page, a moved map input gets a coarse
//! [`COARSE_CELLS`]² sweep at once ([`HELD_CELLS`]² while a control is held) and the full grid a few rows at a time in later short
//! tasks ([`DesignSpace::refine`]); the full maps replace the coarse ones only if they were
//! computed for the inputs still current. Off (native tests, snapshots) the full sweep runs
//! in the step, as before. The flags and the job live in the state both progressive demos
//! share, `demos/progressive.rs`.

use super::cache::SweepKey;
use super::comfort::{comfort_rows, Comfort};
use super::{DesignSpace, Stopwatch};
use crate::demos::progressive::StudyJob;
use std::cell::OnceCell;
use zeta_solver::design::sweep::{
    sweep_kc_into, sweep_kc_rows, sweep_kc_start, KcMaps, KcSweepConfig,
};
use zeta_solver::grid::cell_centre;
use zeta_solver::ride::Ride;

/// Cells per axis of the coarse sweep shown while the full one runs.
pub(super) const COARSE_CELLS: usize = 12;

/// Cells per axis of the coarse sweep while a control is held (a drag's frames): 100
/// cells instead of 144, about 3 of a held mass drag's 9-10 ms per event at 4x CPU on a
/// phone (the sweep is most of such an event); the full sweep follows at rest as always.
pub(super) const HELD_CELLS: usize = 10;

/// Readouts and plots drawn from the coarse sweep while the full one runs.
pub(super) const PROVISIONAL: [&str; 5] =
    ["grid_size", "compute_time", "map", "pareto", "response"];

/// A full sweep under way: its inputs, axes, maps so far and the next row to compute.
#[derive(Debug)]
pub(super) struct SweepJob {
    key: SweepKey,
    cfg: KcSweepConfig,
    ride: Ride,
    k_axis: Vec<f64>,
    c_axis: Vec<f64>,
    maps: KcMaps,
    /// The comfort map so far (see `comfort.rs`).
    comfort: Vec<f64>,
    next_row: usize,
    /// Compute time so far \[ms\].
    ms: f64,
}

impl StudyJob for SweepJob {
    /// The five maps, the comfort map and the compute time \[ms\].
    type Output = (KcMaps, Vec<f64>, f64);

    fn key_text(&self) -> String {
        format!("{:?}", self.key)
    }

    fn advance(&mut self, budget_ms: f64) -> f64 {
        let watch = Stopwatch::start();
        let rows = self.c_axis.len();
        while self.next_row < rows {
            let row = self.next_row;
            let axes = (&self.k_axis[..], &self.c_axis[..]);
            sweep_kc_rows(axes.0, axes.1, row..row + 1, &self.cfg, &mut self.maps);
            comfort_rows(&self.ride, &self.key, axes, row..row + 1, &mut self.comfort);
            self.next_row += 1;
            if watch.elapsed_ms() >= budget_ms {
                break;
            }
        }
        self.ms += watch.elapsed_ms();
        self.next_row as f64 / rows.max(1) as f64
    }

    fn finished(&self) -> bool {
        self.next_row >= self.c_axis.len()
    }

    fn output(&self) -> Self::Output {
        (self.maps.clone(), self.comfort.clone(), self.ms)
    }

    fn take_output(&mut self, (maps, comfort, ms): Self::Output) -> bool {
        let cells = self.k_axis.len() * self.c_axis.len();
        let sizes = [&maps.settling_time, &maps.peak_rebound, &maps.accel_rms];
        let more = [&maps.peak_transmissibility, &maps.zeta, &comfort];
        if sizes.iter().chain(&more).any(|v| v.len() != cells) {
            return false;
        }
        (self.maps, self.comfort, self.ms) = (maps, comfort, ms);
        self.next_row = self.c_axis.len();
        true
    }
}

/// Cell centres of `n` cells over `(lo, hi)`.
fn cells((lo, hi): (f64, f64), n: usize, out: &mut Vec<f64>) {
    out.clear();
    out.extend((0..n).map(|i| cell_centre(lo, hi, n, i)));
}

impl DesignSpace {
    /// The sweep for `key`: the cached one, the full one (not progressive, or a small
    /// grid), or a coarse one now with the full one left to [`DesignSpace::refine`].
    pub(super) fn sweep_for(&mut self, key: SweepKey, cfg: KcSweepConfig) {
        if self.key == Some(key) {
            return;
        }
        // Inputs moved on: a sweep under way for other inputs is dropped unseen.
        self.progress.job = None;
        let coarse = match self.progress.is_held() {
            true => HELD_CELLS,
            false => COARSE_CELLS,
        };
        let n = self.progress.size_now(key.n, coarse);
        let watch = Stopwatch::start();
        cells(key.k, n, &mut self.k_axis);
        cells(key.c, n, &mut self.c_axis);
        sweep_kc_into(&self.k_axis, &self.c_axis, &cfg, &mut self.maps);
        self.key = Some(key);
        // The comfort map of a coarse sweep waits for a figure that asks for it
        // (`comfort.rs`); a full one is computed here, as part of the sweep.
        self.comfort = OnceCell::new();
        if !self.progress.is_provisional() {
            self.comfort();
        }
        self.sweep_ms = watch.elapsed_ms();
        if self.progress.is_provisional() {
            let mut job = SweepJob {
                key,
                cfg,
                ride: Ride::w_k(),
                k_axis: Vec::new(),
                c_axis: Vec::new(),
                maps: KcMaps::default(),
                comfort: vec![f64::NAN; key.n * key.n],
                next_row: 0,
                ms: 0.0,
            };
            cells(key.k, key.n, &mut job.k_axis);
            cells(key.c, key.n, &mut job.c_axis);
            sweep_kc_start(&job.k_axis, &job.c_axis, &mut job.maps);
            self.progress.job = Some(job);
        } else {
            self.sweeps += 1;
        }
    }

    /// Computes rows of the pending full sweep for about `budget_ms` (at least one row),
    /// unless the page's worker computes it. Returns the fraction done, or `None` when no
    /// sweep is pending here; at 1 the full maps have replaced the coarse ones.
    pub(super) fn refine_sweep(&mut self, budget_ms: f64) -> Option<f64> {
        let done = self.progress.refine(budget_ms)?;
        if done < 1.0 {
            return Some(done);
        }
        let job = self.progress.job.take()?;
        // Shown only if computed for the inputs still current (always so here: a step
        // with other inputs drops the job), never as the answer to other inputs.
        if self.key != Some(job.key) {
            return None;
        }
        self.comfort = OnceCell::from(Comfort::new(job.comfort, &job.maps.settling_time));
        self.k_axis = job.k_axis;
        self.c_axis = job.c_axis;
        self.maps = job.maps;
        self.sweep_ms = job.ms;
        self.progress.finished();
        self.sweeps += 1;
        Some(1.0)
    }
}
