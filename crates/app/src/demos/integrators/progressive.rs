//! Progressive convergence study (issue 13): on a page, a moved ζ, ωₙ or T gets a coarse
//! study at once ([`COARSE`]: the same nested grids with an eighth of the step budgets, so
//! the finest three step sizes are left out, and DP45 down to 10⁻⁴ only; [`HELD`], coarser
//! still, while the control is held) and the full study
//! one method per slice in later short tasks ([`Integrators::refine_study`]): the four
//! fixed-step methods, then the DP45 tolerance sweep. The full study replaces the coarse one
//! only if it was computed for the inputs still current. A moved x₀ needs no study: the
//! study is of the release from x₀ = 1, scaled (`Study::scaled`). Off (native tests,
//! snapshots) the full study runs in the step, as before. The flags and the job live in the
//! state every progressive demo shares, `demos/progressive.rs`. A first module (feature
//! `first`) starts no full study: the full module computes it behind the page and takes
//! over with it.

use super::model::{
    dp45_fit, dp45_run, fixed_study, study_grids, Budget, Limits, Problem, Study, StudyKey,
    EULER_BUDGET, FIXED, FULL, STUDY_BUDGET,
};
use super::{Integrators, P};
use crate::demos::design::Stopwatch;
use zeta_solver::integrate::convergence::{NestedGrids, NestedStudy};
use zeta_solver::integrate::work_precision::WorkPoint;
use zeta_solver::SecondOrder;

/// DP45 tolerances of the coarse study: the full sweep's, down to 10⁻⁴ (the tighter ones
/// take the most steps: about 10^(1/5) times more for each tenth).
const COARSE_TOLS: [f64; 3] = [1e-2, 1e-3, 1e-4];

/// The coarse study shown at once while the full one runs.
pub(super) const COARSE: Budget = Budget {
    steps: STUDY_BUDGET / 8,
    euler: EULER_BUDGET / 8,
    tols: &COARSE_TOLS,
};

/// DP45 tolerances of the study while a control is held.
const HELD_TOLS: [f64; 2] = [1e-2, 1e-3];

/// The coarse study while a control is held (each event a frame of the drag): a quarter
/// of [`COARSE`]'s budgets, so its two finest step sizes are left out too, and DP45 down
/// to 10⁻³ only; about half [`COARSE`]'s time. The full study follows at rest as after
/// any coarse one.
pub(super) const HELD: Budget = Budget {
    steps: COARSE.steps / 4,
    euler: COARSE.euler / 4,
    tols: &HELD_TOLS,
};

/// Readouts and plots drawn from the coarse study while the full one runs.
pub(super) const PROVISIONAL: [&str; 7] = [
    "order_euler",
    "order_symplectic_euler",
    "order_heun",
    "order_rk4",
    "order_dp45",
    "convergence",
    "work",
];

/// Slices of the full study: one per fixed-step method, then one per DP45 tolerance (the
/// sweep in one slice was a task of up to ~100 ms at 4× CPU slowdown).
const SLICES: usize = FIXED.len() + FULL.tols.len();

/// A full study under way: its inputs, the fixed-step studies so far and the next slice.
#[derive(Debug)]
pub(super) struct StudyJob {
    key: StudyKey,
    sys: SecondOrder,
    p: P,
    limits: Limits,
    grids: NestedGrids,
    fixed: Vec<NestedStudy>,
    /// DP45's runs so far, loose to tight; `None` once one could not be set up.
    dp45: Option<Vec<WorkPoint>>,
    next: usize,
}

impl StudyJob {
    /// The full study of `key` (for `sys` and `p`), nothing computed yet.
    pub(super) fn start(sys: SecondOrder, p: &P, key: StudyKey, limits: Limits) -> Option<Self> {
        Some(Self {
            key,
            sys,
            p: *p,
            limits,
            grids: study_grids(&sys, p)?,
            fixed: Vec::with_capacity(FIXED.len()),
            dp45: Some(Vec::with_capacity(FULL.tols.len())),
            next: 0,
        })
    }

    /// Computes the next slice: one fixed-step method's study, or one DP45 run.
    fn step(&mut self) {
        let problem = Problem::new(self.sys, &self.p, self.limits);
        if self.next < FIXED.len() {
            if let Some(s) = fixed_study(self.next, &problem, self.grids, FULL) {
                self.fixed.push(s);
            }
        } else if let Some(&tol) = FULL.tols.get(self.next - FIXED.len()) {
            let run = dp45_run(&problem, tol);
            self.dp45 = self.dp45.take().zip(run).map(|(mut runs, run)| {
                runs.push(run);
                runs
            });
        }
        self.next += 1;
    }

    /// The finished full study, exactly as the step computes it when not progressive.
    fn into_study(self) -> Option<Study> {
        if self.fixed.len() != FIXED.len() {
            return None;
        }
        Some(Study {
            key: self.key,
            budget: FULL,
            grids: self.grids.with_budget(FULL.steps),
            fixed: self.fixed,
            dp45: dp45_fit(self.dp45?),
        })
    }
}

impl crate::demos::progressive::StudyJob for StudyJob {
    /// Each fixed-step method's study and DP45's runs.
    type Output = (Vec<NestedStudy>, Option<Vec<WorkPoint>>);

    fn key_text(&self) -> String {
        format!("{:?}", self.key)
    }

    fn advance(&mut self, budget_ms: f64) -> f64 {
        let watch = Stopwatch::start();
        while !self.finished() {
            self.step();
            if watch.elapsed_ms() >= budget_ms {
                break;
            }
        }
        self.next.min(SLICES) as f64 / SLICES as f64
    }

    fn finished(&self) -> bool {
        self.next >= SLICES
    }

    fn output(&self) -> Self::Output {
        (self.fixed.clone(), self.dp45.clone())
    }

    fn take_output(&mut self, (fixed, dp45): Self::Output) -> bool {
        let fits = dp45
            .as_ref()
            .is_none_or(|runs| runs.len() <= FULL.tols.len());
        if fixed.len() != FIXED.len() || !fits {
            return false;
        }
        (self.fixed, self.dp45, self.next) = (fixed, dp45, SLICES);
        true
    }
}

impl Integrators {
    /// Continues the pending full study for about `budget_ms` (at least one slice), unless
    /// the page's worker computes it. Returns the fraction done, or `None` when no study is
    /// pending here; at 1 the full study has replaced the coarse one.
    pub(super) fn refine_study(&mut self, budget_ms: f64) -> Option<f64> {
        if cfg!(feature = "first") {
            return None;
        }
        let done = self.progress.refine(budget_ms)?;
        if done < 1.0 {
            return Some(done);
        }
        let study = self.progress.job.take()?.into_study()?;
        // Shown only if computed for the inputs still current (a step with other inputs
        // drops the job), never as the answer to other inputs.
        if self.cache.study.as_ref().map(|s| s.key) != Some(study.key) {
            return None;
        }
        self.cache.study = Some(study);
        self.progress.finished();
        Some(1.0)
    }
}
