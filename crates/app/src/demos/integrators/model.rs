//! The integrators demo's model step: solver calls only. Runs each fixed-step method at
//! `h`, DP45 at `tol`, the (cached) convergence study and the stability analysis. On a page
//! the study is progressive (`progressive.rs`): a coarse one at once, the full one in slices.

use super::progressive::{self, StudyJob};
use super::runs::{FixedRuns, RunsCache};
use super::P;
use crate::demos::progressive::Progressive;
use std::cell::OnceCell;
use std::rc::Rc;
use zeta_solver::integrate::analysis::{error_norms, FitWindow, StepLimit};
use zeta_solver::integrate::convergence::{nested_study, NestedGrids, NestedStudy};
use zeta_solver::integrate::stability::{region_boundary, Stability, REGION_RAYS};
use zeta_solver::integrate::work_precision::{
    dopri5_point, fit_work_points, WorkPoint, WorkPrecision,
};
use zeta_solver::integrate::{
    Dopri5, Dopri5Config, Dopri5Solution, Euler, ExactStepGrid, Heun, IntegrationError, Linear2,
    Method, Rk4, Solution,
};
use zeta_solver::{Complex, FreeResponse, SecondOrder};

/// The fixed-step methods, in readout order.
pub(super) const FIXED: [Method; 4] = [
    Method::Euler,
    Method::SymplecticEuler,
    Method::Heun,
    Method::Rk4,
];
/// Step sizes of the convergence study (halving each time).
pub(super) const LEVELS: usize = 12;
/// Steps one method may spend on the whole study (summed over its step sizes); finer step
/// sizes beyond this budget are skipped, which keeps a ζ/ωₙ/T drag fast.
pub(super) const STUDY_BUDGET: usize = 24_000;
/// Forward Euler's budget: one evaluation per step, and the slowest to reach its
/// asymptotic range (on an undamped oscillator its error only becomes small below
/// h ≈ 0.01/ωₙ²T).
pub(super) const EULER_BUDGET: usize = 48_000;
/// Coarsest study step, as `h₀·max|λ|`.
const COARSEST_H_LAMBDA: f64 = 1.0;
/// Fewest common check points of the study.
const MIN_CHECKPOINTS: usize = 16;
/// Tolerances of the DP45 sweep.
pub(super) const DP45_TOLS: [f64; 9] = [1e-2, 1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10];
/// The asymptotic range: neighbouring local orders within this of the finest one.
pub(super) const SPREAD: f64 = 0.03;
/// Step budget of one DP45 run.
const DP45_MAX_STEPS: usize = 8_000;
/// The initial displacement the cached convergence study starts from (m): the study from
/// any other `x₀` is this one scaled ([`Study::scaled`]).
pub(super) const UNIT_X0: f64 = 1.0;

/// The `x₀` the cached study for displacement `x0` starts from: [`UNIT_X0`], scaled to
/// `x0` when shown. A first module (feature `first`), which draws only the first frames
/// and has a download budget, runs its study from `x0` itself and leaves the scaling out;
/// the two agree to rounding (see [`Study::scaled`]).
fn study_x0(x0: f64) -> f64 {
    match cfg!(feature = "first") {
        true => x0,
        false => UNIT_X0,
    }
}
/// Errors below this fraction of x₀ are rounding: left out of the fit.
pub(super) const FIT_FLOOR: f64 = 1e-10;
/// Errors above this fraction of x₀ are no longer small (or unstable): left out. Whether
/// the smaller ones are asymptotic is decided by their local orders ([`SPREAD`]).
pub(super) const FIT_CEILING: f64 = 0.5;

/// How much work a convergence study may spend: the full study's [`FULL`], or the coarse
/// stand-in shown at once on a page while the full one runs.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct Budget {
    /// Steps each fixed-step method but forward Euler may spend on the whole study.
    pub(super) steps: usize,
    /// Forward Euler's step budget.
    pub(super) euler: usize,
    /// Tolerances of the DP45 sweep, loosest first.
    pub(super) tols: &'static [f64],
}

/// The full study's budget.
pub(super) const FULL: Budget = Budget {
    steps: STUDY_BUDGET,
    euler: EULER_BUDGET,
    tols: &DP45_TOLS,
};

/// `(ζ, ωₙ, T, x₀ of the study)`: everything the cached convergence study depends on. The
/// study is from `x₀ = 1` ([`study_x0`]): the study from another `x₀` is that one scaled
/// ([`Study::scaled`]).
pub(super) type StudyKey = [f64; 4];

/// A convergence study: the fixed-step methods' and DP45's. The cache keeps the one from
/// [`study_x0`]; results carry it scaled to the current `x₀`.
#[derive(Debug, Clone)]
pub(super) struct Study {
    /// `(ζ, ωₙ, T, x₀)` it was computed for.
    pub(super) key: StudyKey,
    /// The budget it was computed with.
    pub(super) budget: Budget,
    /// The nested grids of the fixed-step studies.
    pub(super) grids: NestedGrids,
    /// One study per fixed-step method, in [`FIXED`] order.
    pub(super) fixed: Vec<NestedStudy>,
    /// DP45 over the tolerance sweep: error against f-evaluations.
    pub(super) dp45: WorkPrecision,
}

impl Study {
    /// The study from an initial displacement `x0` times this one's (this one's is
    /// [`UNIT_X0`] in the full module's cache): every error times `x0`, the steps,
    /// evaluations and orders unchanged. The oscillator and every method are linear in the
    /// initial state, and the study's fit window and DP45's absolute tolerance are
    /// proportional to `x₀`, so a rerun from `x0` measures the same up to rounding
    /// (`zeta-solver`'s `a_study_from_a_scaled_start_is_the_unit_study_scaled`); an `x₀`
    /// drag needs no new study.
    pub(super) fn scaled(&self, x0: f64) -> Self {
        Self {
            key: self.key,
            budget: self.budget,
            grids: self.grids,
            fixed: self.fixed.iter().map(|s| s.scaled(x0)).collect(),
            dp45: self.dp45.scaled(x0),
        }
    }

    /// Fitted order of fixed-step method `k`.
    pub fn order(&self, k: usize) -> Option<f64> {
        self.fixed.get(k).and_then(|s| s.study.order)
    }
}

/// What one step computes.
pub struct Results {
    pub(super) resp: FreeResponse,
    pub(super) poles: [Complex; 2],
    /// The step used (s): exactly the chosen `h`.
    pub(super) h: f64,
    /// The last step (s), shorter than `h` when `h` does not divide `T`.
    pub(super) h_last: f64,
    /// Number of steps.
    pub(super) n: usize,
    /// The exact state and the fixed-step runs on the grid, shared with the cache.
    pub(super) fixed: Rc<FixedRuns>,
    pub(super) growth: [f64; 4],
    pub(super) limit: [StepLimit; 4],
    pub(super) stable: [bool; 4],
    pub(super) dp45: Result<Dopri5Solution<2>, IntegrationError>,
    pub(super) dp45_err: Option<f64>,
    pub(super) study: Study,
    /// Whether `study` is the coarse stand-in while the full study runs.
    pub(super) provisional: bool,
}

/// What the demo keeps between steps.
#[derive(Debug, Default)]
pub(super) struct Cache {
    pub(super) study: Option<Study>,
    /// The stability regions' outlines: parameter-free, traced when first drawn.
    regions: OnceCell<[Vec<(f64, f64)>; 3]>,
    /// The stable steps of the system `(ζ, ωₙ)`, which moving h, T, x₀ or the tolerance
    /// leaves as they are.
    limits: Option<([f64; 2], Limits)>,
    /// The fixed-step runs of the last step, and those under way.
    pub(super) runs: RunsCache,
}

/// The largest stable steps of each fixed-step method (in [`FIXED`] order) and of DP45
/// (`None` if it cannot be set up) for one system: a search each.
#[derive(Debug, Clone, Copy)]
pub(super) struct Limits {
    fixed: [StepLimit; 4],
    dp45: Option<StepLimit>,
}

impl Limits {
    pub(super) fn of(sys: &SecondOrder) -> Self {
        Self {
            fixed: FIXED.map(|m| m.stable_steps(sys)),
            dp45: Dopri5::new(Dopri5Config::default())
                .ok()
                .map(|d| d.stable_steps(sys)),
        }
    }
}

impl Cache {
    /// The stability-region boundaries of Euler, Heun and RK4, traced on the first call
    /// (only the stability plot needs them: a page that does not draw it yet, such as a
    /// phone showing the first plot, does not wait for them).
    pub fn regions(&self) -> &[Vec<(f64, f64)>] {
        self.regions.get_or_init(|| {
            let outline = |pts: Vec<Complex>| pts.into_iter().map(|z| (z.re, z.im)).collect();
            [
                outline(region_boundary(&Euler, REGION_RAYS)),
                outline(region_boundary(&Heun, REGION_RAYS)),
                outline(region_boundary(&Rk4, REGION_RAYS)),
            ]
        })
    }

    /// One step for `p`; `progress` decides whether a new study is the full one or a
    /// coarse one now with the full one left to `refine`.
    pub fn step(&mut self, p: &P, progress: &mut Progressive<StudyJob>) -> Option<Results> {
        let sys = SecondOrder::from_natural(p.wn, p.zeta).ok()?;
        if !(p.x0.is_finite() && p.x0 > 0.0 && p.t_end.is_finite() && p.t_end > 0.0 && p.tol > 0.0)
        {
            return None;
        }
        let key = [
            sys.damping_ratio().unwrap_or(f64::NAN),
            sys.natural_frequency().unwrap_or(f64::NAN),
            p.t_end,
            study_x0(p.x0),
        ];
        let system = [key[0], key[1]];
        let limits = match self.limits {
            Some((of, limits)) if of == system => limits,
            _ => {
                let limits = Limits::of(&sys);
                self.limits = Some((system, limits));
                limits
            }
        };
        // The study is of the release from x₀ = 1, scaled to p.x0 below (a first module's
        // from p.x0 itself: `study_x0`).
        let unit = P {
            x0: study_x0(p.x0),
            ..*p
        };
        let problem = Problem::new(sys, &unit, limits);
        if self.study.as_ref().map(|st| st.key) != Some(key) {
            // Inputs moved on: a full study under way for other inputs is dropped unseen.
            progress.job = None;
            let coarse = match progress.is_held() {
                true => progressive::HELD,
                false => progressive::COARSE,
            };
            progress.size_now(FULL.steps, coarse.steps);
            let budget = match progress.is_provisional() {
                true => coarse,
                false => FULL,
            };
            // No study at all (no grids for these inputs) leaves nothing to refine either.
            self.study = compute_study(&problem, key, budget);
            // The first module leaves the full study to the full module, which takes over
            // within seconds (and leaves its slices out of its own download).
            match self.study.is_some() && progress.is_provisional() {
                true if !cfg!(feature = "first") => {
                    progress.job = StudyJob::start(sys, &unit, key, limits)
                }
                true => {}
                false => progress.finished(),
            }
        }
        let study = self.study.as_ref()?;
        // The study and the exact response at p.x0 (a first module's problem is from p.x0).
        let (study, resp) = match cfg!(feature = "first") {
            true => (study.clone(), problem.resp),
            false => (study.scaled(p.x0), FreeResponse::new(sys, p.x0, 0.0)),
        };
        let grid = ExactStepGrid::new(0.0, p.t_end, p.h).ok()?;
        // The runs depend on neither the tolerance nor which methods are shown.
        let runs_key = [key[0], key[1], p.h, p.t_end, p.x0];
        // On a page a step computes the first steps of long runs, the rest left to
        // `refine`. The first module has no slices (it runs them whole, as off a page, and
        // leaves the slicing out of its download).
        let sliced = progress.is_on() && !cfg!(feature = "first");
        let fixed = self
            .runs
            .get(runs_key, (resp, problem.lin), p, grid, sliced);
        run_current(
            sys,
            resp,
            &problem.lin,
            p,
            (grid, fixed),
            (study, limits.fixed),
            progress.is_provisional(),
        )
    }
}

fn dp45_config(tol: f64, x0: f64) -> Dopri5Config {
    Dopri5Config {
        rtol: tol,
        atol: tol * x0,
        max_steps: DP45_MAX_STEPS,
        ..Dopri5Config::default()
    }
}

fn run_dp45(
    lin: &Linear2<fn(f64) -> f64>,
    p: &P,
    tol: f64,
) -> Result<Dopri5Solution<2>, IntegrationError> {
    Dopri5::new(dp45_config(tol, p.x0))?.solve(lin, [p.x0, 0.0], 0.0, p.t_end)
}

/// Largest displacement error of a DP45 run over its accepted steps (NaN if any is NaN).
fn dp45_error(resp: &FreeResponse, sol: &Solution<2>) -> f64 {
    error_norms(sol, |t| resp.state(t))[0].max
}

pub(super) fn fit_window(x0: f64) -> FitWindow {
    FitWindow {
        floor: FIT_FLOOR * x0,
        ceiling: FIT_CEILING * x0,
    }
}

/// The nested grids of the full study for `p` on `sys` (the coarse study uses the same
/// grids with a smaller budget, so its step sizes are the full study's coarsest ones).
pub(super) fn study_grids(sys: &SecondOrder, p: &P) -> Option<NestedGrids> {
    let rho = sys.poles().iter().map(|q| q.abs()).fold(0.0f64, f64::max);
    NestedGrids::for_rate(
        p.t_end,
        rho,
        COARSEST_H_LAMBDA,
        MIN_CHECKPOINTS,
        LEVELS,
        STUDY_BUDGET,
    )
    .ok()
}

/// What the convergence studies are of: the oscillator of `p`, as a system, as the linear
/// right-hand side the integrators step, and as its exact free response.
pub(super) struct Problem<'p> {
    sys: SecondOrder,
    lin: Linear2<fn(f64) -> f64>,
    resp: FreeResponse,
    p: &'p P,
    /// DP45's largest stable step for the system (see [`Limits`]).
    dp45_stable: Option<StepLimit>,
}

impl<'p> Problem<'p> {
    pub(super) fn new(sys: SecondOrder, p: &'p P, limits: Limits) -> Self {
        Self {
            sys,
            lin: Linear2::free(sys),
            resp: FreeResponse::new(sys, p.x0, 0.0),
            p,
            dp45_stable: limits.dp45,
        }
    }
}

/// The convergence study of fixed-step method `FIXED[k]` on `grids` within `budget`.
pub(super) fn fixed_study(
    k: usize,
    problem: &Problem<'_>,
    grids: NestedGrids,
    budget: Budget,
) -> Option<NestedStudy> {
    let Problem { lin, resp, p, .. } = problem;
    let m = FIXED.get(k)?;
    let grids = match m {
        Method::Euler => grids.with_budget(budget.euler),
        _ => grids.with_budget(budget.steps),
    };
    let exact = |t: f64| resp.displacement(t);
    let mut out = nested_study(m, lin, [p.x0, 0.0], 0, exact, &grids, fit_window(p.x0));
    out.study.restrict_to_asymptotic(SPREAD);
    Some(out)
}

/// DP45 over the tolerances `tols`: error against f-evaluations (its runs, then their fit:
/// the solver's `dopri5_sweep`, a run at a time as a progressive study computes it).
pub(super) fn dp45_study(problem: &Problem<'_>, tols: &[f64]) -> Option<WorkPrecision> {
    let runs = tols.iter().map(|&tol| dp45_run(problem, tol));
    Some(dp45_fit(runs.collect::<Option<Vec<_>>>()?))
}

/// One run of [`dp45_study`]'s sweep, at `tol` (a slice of a progressive study; the runs
/// are fitted with [`dp45_fit`]).
pub(super) fn dp45_run(problem: &Problem<'_>, tol: f64) -> Option<WorkPoint> {
    let Problem {
        lin,
        resp,
        p,
        dp45_stable,
        ..
    } = problem;
    Some(dopri5_point(
        lin,
        [p.x0, 0.0],
        p.t_end,
        tol,
        |tol| dp45_config(tol, p.x0),
        |sol| dp45_error(resp, sol),
        (*dp45_stable)?,
        fit_window(p.x0),
    ))
}

/// [`dp45_study`] from its runs, loose to tight.
pub(super) fn dp45_fit(runs: Vec<WorkPoint>) -> WorkPrecision {
    fit_work_points(runs, SPREAD)
}

/// The whole convergence study of `key` within `budget`, at once.
pub(super) fn compute_study(problem: &Problem<'_>, key: StudyKey, budget: Budget) -> Option<Study> {
    let grids = study_grids(&problem.sys, problem.p)?;
    let fixed = (0..FIXED.len())
        .map(|k| fixed_study(k, problem, grids, budget))
        .collect::<Option<Vec<_>>>()?;
    let dp45 = dp45_study(problem, budget.tols)?;
    Some(Study {
        key,
        budget,
        grids: grids.with_budget(budget.steps),
        fixed,
        dp45,
    })
}

fn run_current(
    sys: SecondOrder,
    resp: FreeResponse,
    lin: &Linear2<fn(f64) -> f64>,
    p: &P,
    (grid, fixed): (ExactStepGrid, Rc<FixedRuns>),
    (study, limit): (Study, [StepLimit; 4]),
    provisional: bool,
) -> Option<Results> {
    let h = grid.h();
    let growth = FIXED.map(|m| m.growth_per_step(&sys, h));
    let stable = limit.map(|l| l.allows(h));
    let dp45 = run_dp45(lin, p, p.tol);
    let dp45_err = dp45
        .as_ref()
        .ok()
        .map(|o| dp45_error(&resp, &o.solution))
        .filter(|e| e.is_finite());
    Some(Results {
        resp,
        poles: sys.poles(),
        h,
        h_last: grid.last_step(),
        n: grid.steps(),
        fixed,
        growth,
        limit,
        stable,
        dp45,
        dp45_err,
        study,
        provisional,
    })
}
