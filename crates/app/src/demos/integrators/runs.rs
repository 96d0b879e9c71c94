//! The integrators demo's fixed-step runs at `h`: each method from x₀ over [0, T] on the
//! exact-step grid, and the exact state at its points. At a small `h` they are the bulk of a
//! step's work (T = 60 s at h = 1 ms is 60 000 steps of each method, 60–90 ms at 4× CPU
//! slowdown), so on a page a step computes the first [`STEPS_NOW`] steps and the rest
//! follows in slices ([`RunsJob`], from `Integrators::refine`); meanwhile the plots and the
//! errors are of the runs so far, marked provisional ([`FixedRuns::until`]). Off (native
//! tests, snapshots) a step computes the whole runs, as before.

use super::model::FIXED;
use super::P;
use crate::demos::design::Stopwatch;
use std::rc::Rc;
use zeta_solver::integrate::analysis::error_norms_at;
use zeta_solver::integrate::{
    ExactStepGrid, FixedStep, IntegrationError, Linear2, Solution, Stats,
};
use zeta_solver::FreeResponse;

/// The unforced oscillator the methods step.
type Free = Linear2<fn(f64) -> f64>;

/// Steps of each method a step computes at once on a page (about 3–5 ms at 4× CPU
/// slowdown): every run of up to this many steps is whole at once.
pub(super) const STEPS_NOW: usize = 4096;

/// Steps of each method per slice of [`RunsJob::advance`] between checks of the clock.
pub(super) const SLICE_STEPS: usize = 1024;

/// Readouts and plots drawn from the runs while they are under way.
pub(super) const PROVISIONAL: [&str; 6] = [
    "max_err_euler",
    "max_err_symplectic_euler",
    "max_err_heun",
    "max_err_rk4",
    "response",
    "error",
];

/// One fixed-step run at the current `h`.
#[derive(Debug, Clone)]
pub(super) struct Run {
    pub(super) sol: Solution<2>,
    /// Time at which the numbers overflowed, if they did.
    pub(super) overflow: Option<f64>,
}

/// The fixed-step runs at the current step and their errors, whole or so far. Kept across
/// steps that move only the tolerance or the methods shown (and the step again at a study's
/// end), which change none of them.
#[derive(Debug, Clone)]
pub(super) struct FixedRuns {
    /// What the runs are of: ζ, ωₙ (rad/s), h (s), T (s) and x₀ (m).
    pub(super) key: [f64; 5],
    /// The exact state at each grid point computed.
    pub(super) exact: Vec<[f64; 2]>,
    /// The fixed-step runs, in [`FIXED`] order.
    pub(super) runs: Vec<Run>,
    /// Each run's largest displacement error (m) over its points so far, `None` if it
    /// overflowed.
    pub(super) max_err: [Option<f64>; 4],
    /// `None` when the runs reach T; else the time they have reached (s), the rest on the
    /// way.
    pub(super) until: Option<f64>,
}

/// The fixed-step runs of the last step, whole, and those under way on a page.
#[derive(Debug, Default)]
pub(super) struct RunsCache {
    whole: Option<Rc<FixedRuns>>,
    /// The runs under way: the last step showed them so far.
    job: Option<RunsJob>,
    /// How many runs were started in slices (see [`crate::demos::Demo::study_round`]). Wraps.
    rounds: u32,
}

impl RunsCache {
    /// The runs of `key` (from `p.x0` on `grid`, for the system `lin` whose free response
    /// is `resp`): the kept ones if they are of `key`; else computed, whole, or when
    /// `sliced` their first [`STEPS_NOW`] steps (or as many more of the runs under way for
    /// `key`), the rest left to [`RunsCache::refine`]. Runs under way for another key are
    /// dropped unseen.
    pub(super) fn get(
        &mut self,
        key: [f64; 5],
        (resp, lin): (FreeResponse, Free),
        p: &P,
        grid: ExactStepGrid,
        sliced: bool,
    ) -> Rc<FixedRuns> {
        if let Some(whole) = self.whole.as_ref().filter(|w| w.key == key) {
            self.job = None;
            return whole.clone();
        }
        let mut job = match (sliced, self.job.take()) {
            (true, Some(job)) if job.key == key => job,
            _ => {
                self.rounds = self.rounds.wrapping_add(u32::from(sliced));
                RunsJob::start(key, resp, lin, p, grid)
            }
        };
        job.advance(match sliced {
            true => STEPS_NOW,
            false => usize::MAX,
        });
        if sliced && !job.finished() {
            let so_far = Rc::new(job.snapshot());
            self.job = Some(job);
            return so_far;
        }
        let whole = Rc::new(job.into_runs());
        self.whole = Some(whole.clone());
        whole
    }

    /// A count that moves on each time runs start in slices.
    pub(super) fn rounds(&self) -> u32 {
        self.rounds
    }

    /// Whether the last step showed the runs so far, the rest under way.
    pub(super) fn pending(&self) -> bool {
        !cfg!(feature = "first") && self.job.is_some()
    }

    /// Continues the runs under way for about `budget_ms` (at least one slice): `None`
    /// when none are, else the fraction done; at 1 they are whole and kept, for the step
    /// that shows them.
    pub(super) fn refine(&mut self, budget_ms: f64) -> Option<f64> {
        if cfg!(feature = "first") {
            return None;
        }
        let job = self.job.as_mut()?;
        let watch = Stopwatch::start();
        while !job.finished() {
            job.advance(SLICE_STEPS);
            if watch.elapsed_ms() >= budget_ms {
                break;
            }
        }
        if !job.finished() {
            return Some(job.fraction());
        }
        let whole = self.job.take()?.into_runs();
        self.whole = Some(Rc::new(whole));
        Some(1.0)
    }
}

/// The fixed-step runs of one key under way: every method and the exact state, a slice
/// of grid points at a time.
#[derive(Debug)]
struct RunsJob {
    key: [f64; 5],
    grid: ExactStepGrid,
    resp: FreeResponse,
    lin: Free,
    exact: Vec<[f64; 2]>,
    runs: Vec<Run>,
}

impl RunsJob {
    /// The runs of `key` for `p` (from `p.x0`, at rest) on `grid`: only the start point yet.
    fn start(key: [f64; 5], resp: FreeResponse, lin: Free, p: &P, grid: ExactStepGrid) -> Self {
        let t0 = grid.time(0);
        let run = || Run {
            sol: Solution {
                t: vec![t0],
                y: vec![[p.x0, 0.0]],
                stats: Stats::default(),
            },
            overflow: None,
        };
        Self {
            key,
            grid,
            exact: vec![resp.state(t0)],
            resp,
            lin,
            runs: FIXED.map(|_| run()).into(),
        }
    }

    /// Grid points computed so far (the start point counts).
    fn points(&self) -> usize {
        self.exact.len()
    }

    fn finished(&self) -> bool {
        self.points() > self.grid.steps()
    }

    /// Computes up to `steps` more steps of every method, and the exact state there.
    fn advance(&mut self, steps: usize) {
        let from = self.points() - 1;
        let end = self.grid.steps().min(from.saturating_add(steps));
        if end <= from {
            return;
        }
        let (grid, resp) = (&self.grid, &self.resp);
        self.exact
            .extend((from + 1..=end).map(|i| resp.state(grid.time(i))));
        for (m, run) in FIXED.iter().zip(&mut self.runs) {
            run.sol.t.extend((from + 1..=end).map(|i| grid.time(i)));
            // An overflowed run stays undefined (NaN) from where it went.
            run.sol.y.resize(end + 1, [f64::NAN; 2]);
            if run.overflow.is_some() {
                continue;
            }
            match m.resume_exact_step_into(&self.lin, grid, from, &mut run.sol.y) {
                Ok(s) => {
                    run.sol.stats.n_rhs += s.n_rhs;
                    run.sol.stats.n_accepted += s.n_accepted;
                }
                Err(e) => {
                    run.overflow = Some(match e {
                        IntegrationError::NonFinite { t } => t,
                        _ => 0.0,
                    });
                    // As a run in one go reports it: no work counted for a failed run.
                    run.sol.stats = Stats::default();
                }
            }
        }
    }

    /// The fraction of the grid computed.
    fn fraction(&self) -> f64 {
        self.points() as f64 / (self.grid.steps() + 1) as f64
    }

    /// The runs so far, with their errors so far.
    fn snapshot(&self) -> FixedRuns {
        let until = match self.finished() {
            true => None,
            false => Some(self.grid.time(self.points() - 1)),
        };
        with_errors(self.key, self.exact.clone(), self.runs.clone(), until)
    }

    /// The whole runs: call when [`RunsJob::finished`].
    fn into_runs(self) -> FixedRuns {
        with_errors(self.key, self.exact, self.runs, None)
    }
}

/// The runs with each one's largest displacement error against `exact`.
fn with_errors(
    key: [f64; 5],
    exact: Vec<[f64; 2]>,
    runs: Vec<Run>,
    until: Option<f64>,
) -> FixedRuns {
    let mut max_err = [None; 4];
    for (slot, run) in max_err.iter_mut().zip(&runs) {
        if run.overflow.is_none() {
            // Every run is on one grid: `exact[i]` is the exact state at its point `i`.
            let e = error_norms_at(&run.sol, &exact)[0].max;
            *slot = e.is_finite().then_some(e);
        }
    }
    FixedRuns {
        key,
        exact,
        runs,
        max_err,
        until,
    }
}
