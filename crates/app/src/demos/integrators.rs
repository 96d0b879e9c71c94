//! `integrators`: numerical error of five integrators on the free oscillator
//! `x'' + 2ζωₙ·x' + ωₙ²·x = 0`, `x(0) = x₀`, `x'(0) = 0`.
//!
//! Four fixed-step methods (forward Euler, symplectic Euler, Heun, RK4) run at the step `h`
//! and Dormand–Prince 5(4) runs adaptively to the tolerance `tol`. Plots: each method
//! against the exact solution, the error over time, a log–log convergence study with fitted
//! orders, and the stability regions `|R(z)| ≤ 1` with the system's `z = hλ`.
//!
//! Choices documented here (and in the figures' text alternatives):
//! - **Readouts of switched-off methods are still computed**; the toggles hide curves only.
//! - `max_err_<method>` is `max |x_num − x_exact|` over the run's own grid points in
//!   `[0, T]` (for DP45, its accepted steps). A run that overflows shows `overflow` with an
//!   empty `data-value`; a run that grows but stays finite reports its (huge) error.
//! - The convergence study uses nested grids `h_j = T/(n₀·2ʲ)`, measuring the error at the
//!   `n₀ + 1` points common to all of them; it depends on ζ, ωₙ, T and x₀ only and is cached,
//!   so dragging `h`, `tol` or a toggle does not rerun it.
//! - `order_dp45` is the slope of error against the *mean* step `T/steps` over a sweep of
//!   tolerances 10⁻² … 10⁻¹⁰ (an adaptive method has no single `h`).
//! - Symplectic Euler is not a scalar map `R(z)`: its stability comes from the spectral
//!   radius of its 2×2 step matrix and is described in words, not drawn as a region.

// Not yet reshaped: still does maths the solver should do (issue "one shape").
#![allow(clippy::disallowed_methods)]

use super::{Demo, Frame, Readout};
use crate::figure::{Axis, AxisScale, Dash, Figure, LineStyle, Marker, MarkerShape, Series};
use crate::format::si;
use crate::params::Params;
use crate::plot::Ink;
use crate::spec::{DemoSpec, ParamSpec, PlotSpec, Preset, ReadoutSpec, Table};
use zeta_solver::integrate::analysis::{
    convergence_study, error_norms, fit_order, symplectic_euler_spectral_radius,
    symplectic_euler_step_limit, Amplification, ConvergenceStudy, FitWindow, StepLimit,
};
use zeta_solver::integrate::{
    Dopri5, Dopri5Config, Dopri5Solution, Euler, FixedStep, Grid, Heun, IntegrationError, Linear2,
    Method, Rk4, Solution, Stats,
};
use zeta_solver::{Complex, FreeResponse, SecondOrder};

/// Samples of the exact curve and of DP45's dense output.
const SAMPLES: usize = 1000;
/// Most points of one drawn series.
const MAX_DRAWN: usize = 1000;
/// Most step markers drawn per method.
const MAX_MARKS: usize = 60;
/// Step sizes of the convergence study (halving each time).
const LEVELS: usize = 10;
/// Steps one method may spend on the whole study (summed over its step sizes); finer step
/// sizes beyond this budget are skipped, which keeps a ζ/ωₙ/T/x₀ drag fast.
const STUDY_BUDGET: usize = 24_000;
/// Coarsest study step, as `h₀·max|λ|`.
const COARSEST_H_LAMBDA: f64 = 1.0;
/// Fewest common check points of the study.
const MIN_CHECKPOINTS: usize = 16;
/// Tolerances of the DP45 sweep.
const DP45_TOLS: [f64; 9] = [1e-2, 1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10];
/// DP45's order is fitted to this many of its finest usable runs.
const DP45_FIT_POINTS: usize = 4;
/// Smallest ratio of largest to smallest mean step for a DP45 fit.
const DP45_MIN_SPAN: f64 = 1.5;
/// Step budget of one DP45 run.
const DP45_MAX_STEPS: usize = 8_000;
/// Errors below this fraction of x₀ are rounding: left out of the fit.
const FIT_FLOOR: f64 = 1e-10;
/// Errors above this fraction of x₀ are not yet asymptotic (or unstable): left out.
const FIT_CEILING: f64 = 0.05;
/// Half-height of the response plot, in units of the exact solution's largest |x|.
const RESPONSE_RANGE: f64 = 2.0;
/// Largest error drawn, in units of x₀ (larger values are clipped at the top).
const ERROR_CLIP: f64 = 1e8;

/// The MathML of the model problem.
const EQUATION: &str = "<math display=\"block\"><mrow>\
<mover><mi>x</mi><mo>¨</mo></mover><mo>+</mo><mn>2</mn><mi>ζ</mi><msub><mi>ω</mi><mi>n</mi></msub>\
<mover><mi>x</mi><mo>˙</mo></mover><mo>+</mo><msubsup><mi>ω</mi><mi>n</mi><mn>2</mn></msubsup><mi>x</mi>\
<mo>=</mo><mn>0</mn><mo>,</mo><mspace width=\"1em\"/><mi>x</mi><mo>(</mo><mn>0</mn><mo>)</mo><mo>=</mo>\
<msub><mi>x</mi><mn>0</mn></msub><mo>,</mo><mspace width=\"0.5em\"/>\
<mover><mi>x</mi><mo>˙</mo></mover><mo>(</mo><mn>0</mn><mo>)</mo><mo>=</mo><mn>0</mn></mrow></math>";

/// One fixed-step method as the demo presents it.
#[derive(Debug, Clone, Copy)]
struct Fixed {
    method: Method,
    name: &'static str,
    max_key: &'static str,
    order_key: &'static str,
    stable_key: &'static str,
    growth_key: &'static str,
    style: LineStyle,
    /// Marker drawn on the curve so it is told apart without colour.
    mark: Option<MarkerShape>,
    legend: &'static str,
}

const FIXED: [Fixed; 4] = [
    Fixed {
        method: Method::Euler,
        name: "forward Euler",
        max_key: "max_err_euler",
        order_key: "order_euler",
        stable_key: "stable_euler",
        growth_key: "growth_euler",
        style: LineStyle {
            ink: Ink::Vermillion,
            dash: Dash::Dashed,
            width: 2.0,
        },
        mark: None,
        legend: "Euler",
    },
    Fixed {
        method: Method::SymplecticEuler,
        name: "symplectic Euler",
        max_key: "max_err_symplectic_euler",
        order_key: "order_symplectic_euler",
        stable_key: "stable_symplectic_euler",
        growth_key: "growth_symplectic_euler",
        style: LineStyle {
            ink: Ink::Purple,
            dash: Dash::Dashed,
            width: 1.5,
        },
        mark: Some(MarkerShape::Cross),
        legend: "sympl. Euler ×",
    },
    Fixed {
        method: Method::Heun,
        name: "Heun",
        max_key: "max_err_heun",
        order_key: "order_heun",
        stable_key: "stable_heun",
        growth_key: "growth_heun",
        style: LineStyle {
            ink: Ink::Orange,
            dash: Dash::Dotted,
            width: 2.5,
        },
        mark: None,
        legend: "Heun",
    },
    Fixed {
        method: Method::Rk4,
        name: "RK4",
        max_key: "max_err_rk4",
        order_key: "order_rk4",
        stable_key: "stable_rk4",
        growth_key: "growth_rk4",
        style: LineStyle {
            ink: Ink::Blue,
            dash: Dash::Solid,
            width: 1.8,
        },
        mark: None,
        legend: "RK4",
    },
];

const EXACT_STYLE: LineStyle = LineStyle {
    ink: Ink::Black,
    dash: Dash::Solid,
    width: 3.5,
};
const DP45_STYLE: LineStyle = LineStyle {
    ink: Ink::Green,
    dash: Dash::Dotted,
    width: 2.0,
};
const DP45_LEGEND: &str = "DP45 ● steps";
const DP45_MARK: MarkerShape = MarkerShape::Dot;

/// How one run of the convergence study ended.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum RunStatus {
    Measured,
    /// The numbers overflowed (the method is violently unstable at this `h`).
    Overflow,
    /// Not run: too many steps, or a coarser run already reached rounding level.
    Skipped,
}

/// A convergence study and how each of its runs ended.
#[derive(Debug, Clone)]
struct Sweep {
    study: ConvergenceStudy,
    status: Vec<RunStatus>,
}

/// The cached convergence studies.
#[derive(Debug, Clone)]
struct Study {
    /// `(ζ, ωₙ, T, x₀)` it was computed for.
    key: [f64; 4],
    /// Number of common check points minus one.
    n0: usize,
    fixed: Vec<Sweep>,
    dp45: Sweep,
}

/// One fixed-step run at the current `h`.
#[derive(Debug, Clone)]
struct Run {
    sol: Solution<2>,
    /// Time at which the numbers overflowed, if they did.
    overflow: Option<f64>,
}

impl Default for Run {
    fn default() -> Self {
        Self {
            sol: Solution {
                t: Vec::new(),
                y: Vec::new(),
                stats: Stats::default(),
            },
            overflow: None,
        }
    }
}

/// The integrators demo. Keeps buffers between updates and caches the convergence study
/// and the (parameter-free) stability-region boundaries.
#[derive(Debug, Clone, Default)]
pub struct Integrators {
    study: Option<Study>,
    regions: Option<[Vec<(f64, f64)>; 3]>,
    exact: Vec<[f64; 2]>,
    runs: [Run; 4],
}

/// Everything the parameters describe.
struct Setup {
    sys: SecondOrder,
    lin: Linear2<fn(f64) -> f64>,
    resp: FreeResponse,
    poles: [Complex; 2],
    x0: f64,
    t_end: f64,
    h: f64,
    tol: f64,
    show: [bool; 5],
}

fn setup(params: &Params) -> Option<Setup> {
    let sys = SecondOrder::from_natural(params.get("wn"), params.get("zeta")).ok()?;
    let x0 = params.get("x0");
    let t_end = params.get("T");
    let h = params.get("h");
    let tol = params.get("tol");
    if !(x0.is_finite() && x0 > 0.0 && t_end.is_finite() && t_end > 0.0 && tol > 0.0) {
        return None;
    }
    let on = |k: &str| params.get(k) != 0.0;
    Some(Setup {
        lin: Linear2::free(sys),
        resp: FreeResponse::new(sys, x0, 0.0),
        poles: sys.poles(),
        sys,
        x0,
        t_end,
        h,
        tol,
        show: [
            on("euler"),
            on("symplectic_euler"),
            on("heun"),
            on("rk4"),
            on("dp45"),
        ],
    })
}

/// `|R(hλ)|` for the worse pole, or the spectral radius for symplectic Euler: the factor
/// by which the slowest-decaying mode is multiplied each step.
fn growth(m: Method, s: &Setup, h: f64) -> f64 {
    let worst = |amp: &dyn Fn(Complex) -> Complex| {
        s.poles
            .iter()
            .map(|&p| amp(p * h).abs())
            .fold(0.0f64, f64::max)
    };
    match m {
        Method::Euler => worst(&|z| Euler.amplification(z)),
        Method::Heun => worst(&|z| Heun.amplification(z)),
        Method::Rk4 => worst(&|z| Rk4.amplification(z)),
        Method::SymplecticEuler => symplectic_euler_spectral_radius(&s.sys, h),
        Method::Trapezoid => f64::NAN,
    }
}

fn step_limit(m: Method, s: &Setup) -> StepLimit {
    match m {
        Method::Euler => Euler.step_limit(&s.poles),
        Method::Heun => Heun.step_limit(&s.poles),
        Method::Rk4 => Rk4.step_limit(&s.poles),
        Method::SymplecticEuler => symplectic_euler_step_limit(&s.sys),
        Method::Trapezoid => StepLimit::Unconditional,
    }
}

fn limit_text(l: StepLimit) -> String {
    match l {
        StepLimit::UpTo(h) => format!("stable for h ≤ {}", si(h, "s", 3)),
        StepLimit::Unconditional => "stable for every h".into(),
        StepLimit::NoStableStep => "unstable for every h".into(),
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

fn run_dp45(s: &Setup, tol: f64) -> Result<Dopri5Solution<2>, IntegrationError> {
    Dopri5::new(dp45_config(tol, s.x0))?.solve(&s.lin, [s.x0, 0.0], 0.0, s.t_end)
}

/// Largest displacement error of a DP45 run over its accepted steps (NaN if any is NaN).
fn dp45_error(s: &Setup, sol: &Solution<2>) -> f64 {
    error_norms(sol, |t| s.resp.state(t))[0].max
}

/// Error at the `n₀ + 1` common check points of a run of `n = n₀·stride` steps of `h`;
/// `None` if the numbers overflow.
fn checkpoint_error(m: Method, s: &Setup, h: f64, stride: usize, exact: &[f64]) -> Option<f64> {
    let mut y = [s.x0, 0.0];
    let mut err = 0.0f64;
    let n = (exact.len() - 1) * stride;
    for i in 1..=n {
        m.step(&s.lin, (i - 1) as f64 * h, h, &mut y).ok()?;
        if i.is_multiple_of(stride) {
            let d = (y[0] - exact.get(i / stride)?).abs();
            if !d.is_finite() {
                return None;
            }
            err = err.max(d);
        }
    }
    Some(err)
}

fn fit_window(x0: f64) -> FitWindow {
    FitWindow {
        floor: FIT_FLOOR * x0,
        ceiling: FIT_CEILING * x0,
    }
}

fn compute_study(s: &Setup, key: [f64; 4]) -> Study {
    let rho = s.poles.iter().map(|p| p.abs()).fold(0.0f64, f64::max);
    let n0 = ((s.t_end * rho / COARSEST_H_LAMBDA).ceil() as usize).max(MIN_CHECKPOINTS);
    let dt = s.t_end / n0 as f64;
    let exact: Vec<f64> = (0..=n0)
        .map(|k| s.resp.displacement(k as f64 * dt))
        .collect();
    let window = fit_window(s.x0);
    let steps: Vec<f64> = (0..LEVELS)
        .map(|j| s.t_end / (n0 as f64 * (1u64 << j) as f64))
        .collect();
    let fixed = FIXED
        .iter()
        .map(|f| {
            let mut status = Vec::with_capacity(LEVELS);
            let mut level = 0usize;
            let mut resolved = false;
            let mut spent = 0usize;
            let study = convergence_study(&steps, window, |h| {
                let stride = 1usize << level;
                level += 1;
                spent = spent.saturating_add(n0.saturating_mul(stride));
                if resolved || spent > STUDY_BUDGET {
                    status.push(RunStatus::Skipped);
                    return Err(());
                }
                match checkpoint_error(f.method, s, h, stride, &exact) {
                    Some(e) => {
                        resolved = e <= window.floor;
                        status.push(RunStatus::Measured);
                        Ok((h, e))
                    }
                    None => {
                        status.push(RunStatus::Overflow);
                        Err(())
                    }
                }
            });
            Sweep { study, status }
        })
        .collect();
    let mut status = Vec::with_capacity(DP45_TOLS.len());
    let mut study = convergence_study(&DP45_TOLS, window, |tol| match run_dp45(s, tol) {
        Ok(out) => {
            let n = out.solution.stats.n_accepted.max(1);
            status.push(RunStatus::Measured);
            Ok((s.t_end / n as f64, dp45_error(s, &out.solution)))
        }
        Err(e) => {
            status.push(RunStatus::Skipped);
            Err(e)
        }
    });
    refit_finest(&mut study);
    Study {
        key,
        n0,
        fixed,
        dp45: Sweep { study, status },
    }
}

/// Restricts DP45's fit to its [`DP45_FIT_POINTS`] finest usable runs, and drops it when
/// their mean steps span less than [`DP45_MIN_SPAN`]: when stability rather than accuracy
/// limits the step (a stiff pole), loosening the tolerance no longer lengthens the steps
/// and a slope of error against the mean step would be meaningless.
fn refit_finest(study: &mut ConvergenceStudy) {
    let mut used: Vec<(usize, f64)> = study
        .points
        .iter()
        .enumerate()
        .filter(|(_, p)| p.used)
        .map(|(i, p)| (i, p.h))
        .collect();
    used.sort_by(|a, b| a.1.total_cmp(&b.1));
    let keep: Vec<usize> = used.iter().take(DP45_FIT_POINTS).map(|u| u.0).collect();
    for (i, p) in study.points.iter_mut().enumerate() {
        p.used = p.used && keep.contains(&i);
    }
    let fit: Vec<(f64, f64)> = study
        .points
        .iter()
        .filter(|p| p.used)
        .map(|p| (p.h, p.error))
        .collect();
    let (lo, hi) = fit.iter().fold((f64::INFINITY, 0.0f64), |(lo, hi), p| {
        (lo.min(p.0), hi.max(p.0))
    });
    study.order = if hi >= DP45_MIN_SPAN * lo {
        fit_order(&fit)
    } else {
        for p in study.points.iter_mut() {
            p.used = false;
        }
        None
    };
}

/// Outer boundary `|R(z)| = 1` of a stability region, traced along 360 rays from
/// `z = −1` (inside every region here): on each ray the outermost stable radius is
/// bracketed by an inward scan and refined by bisection. Presentation of the solver's
/// amplification factor; the regions do not depend on the parameters.
fn region_boundary(amp: impl Fn(Complex) -> f64) -> Vec<(f64, f64)> {
    const RAYS: usize = 360;
    const R_MAX: f64 = 4.0;
    const SCAN: usize = 400;
    let centre = Complex::real(-1.0);
    let stable = |z: Complex| amp(z) <= 1.0;
    (0..=RAYS)
        .map(|k| {
            let th = std::f64::consts::TAU * k as f64 / RAYS as f64;
            let dir = Complex::new(th.cos(), th.sin());
            let mut hi = R_MAX;
            let mut lo = 0.0;
            for i in (0..SCAN).rev() {
                let r = R_MAX * i as f64 / SCAN as f64;
                if stable(centre + dir * r) {
                    lo = r;
                    break;
                }
                hi = r;
            }
            for _ in 0..50 {
                let mid = 0.5 * (lo + hi);
                if stable(centre + dir * mid) {
                    lo = mid;
                } else {
                    hi = mid;
                }
            }
            let z = centre + dir * lo;
            (z.re, z.im)
        })
        .collect()
}

fn regions() -> [Vec<(f64, f64)>; 3] {
    [
        region_boundary(|z| Euler.amplification(z).abs()),
        region_boundary(|z| Heun.amplification(z).abs()),
        region_boundary(|z| Rk4.amplification(z).abs()),
    ]
}

/// Results at the current step, per fixed method.
struct Current {
    h: f64,
    n: usize,
    max_err: [Option<f64>; 4],
    growth: [f64; 4],
    limit: [StepLimit; 4],
    stable: [bool; 4],
    dp45: Result<Dopri5Solution<2>, IntegrationError>,
    dp45_err: Option<f64>,
}

impl Integrators {
    /// A demo with empty buffers.
    pub fn new() -> Self {
        Self::default()
    }

    fn run_current(&mut self, s: &Setup) -> Current {
        // h ≥ 1e−3 s and T ≤ 60 s keep this within 60 000 steps.
        let grid = Grid::new(0.0, s.t_end, s.h).unwrap_or(Grid {
            t0: 0.0,
            h: s.t_end,
            n: 1,
        });
        let n = grid.n.max(1);
        let h = if grid.n == 0 { s.t_end } else { grid.h };
        self.exact.clear();
        self.exact
            .extend((0..=n).map(|i| s.resp.state(i as f64 * h)));
        let exact = &self.exact;
        let lookup = |t: f64| {
            let i = ((t / h).round().max(0.0) as usize).min(n);
            exact.get(i).copied().unwrap_or([f64::NAN; 2])
        };
        let mut max_err = [None; 4];
        for (k, f) in FIXED.iter().enumerate() {
            let run = &mut self.runs[k];
            run.sol.t.clear();
            run.sol.t.extend((0..=n).map(|i| i as f64 * h));
            run.sol.y.clear();
            run.sol.y.resize(n + 1, [f64::NAN; 2]);
            run.overflow = None;
            match f
                .method
                .solve_into(&s.lin, [s.x0, 0.0], 0.0, h, &mut run.sol.y)
            {
                Ok(stats) => run.sol.stats = stats,
                Err(IntegrationError::NonFinite { t }) => run.overflow = Some(t),
                Err(_) => run.overflow = Some(0.0),
            }
            if run.overflow.is_none() {
                let e = error_norms(&run.sol, lookup)[0].max;
                max_err[k] = e.is_finite().then_some(e);
            }
        }
        let growth = FIXED.map(|f| growth(f.method, s, h));
        let limit = FIXED.map(|f| step_limit(f.method, s));
        let stable = limit.map(|l| l.allows(h));
        let dp45 = run_dp45(s, s.tol);
        let dp45_err = dp45
            .as_ref()
            .ok()
            .map(|o| dp45_error(s, &o.solution))
            .filter(|e| e.is_finite());
        Current {
            h,
            n,
            max_err,
            growth,
            limit,
            stable,
            dp45,
            dp45_err,
        }
    }

    fn frame(&mut self, s: &Setup) -> Frame {
        let key = [
            s.sys.damping_ratio().unwrap_or(f64::NAN),
            s.sys.natural_frequency().unwrap_or(f64::NAN),
            s.t_end,
            s.x0,
        ];
        if self.study.as_ref().map(|st| st.key) != Some(key) {
            self.study = Some(compute_study(s, key));
        }
        if self.regions.is_none() {
            self.regions = Some(regions());
        }
        let cur = self.run_current(s);
        let (Some(study), Some(regions)) = (self.study.as_ref(), self.regions.as_ref()) else {
            return invalid_frame();
        };
        let mut readouts = vec![Readout::number("h_used", Some(cur.h), "s", 4)];
        for (k, f) in FIXED.iter().enumerate() {
            readouts.push(match (cur.max_err[k], self.runs[k].overflow) {
                (_, Some(t)) => Readout {
                    key: f.max_key,
                    text: format!("overflow at t = {}", si(t, "s", 3)),
                    data_value: String::new(),
                },
                (e, None) => Readout::number(f.max_key, e, "m", 3),
            });
        }
        readouts.push(match &cur.dp45 {
            Ok(_) => Readout::number("max_err_dp45", cur.dp45_err, "m", 3),
            Err(_) => Readout {
                key: "max_err_dp45",
                text: "failed".into(),
                data_value: String::new(),
            },
        });
        for (k, f) in FIXED.iter().enumerate() {
            readouts.push(Readout::number(
                f.order_key,
                study.fixed.get(k).and_then(|sw| sw.study.order),
                "",
                3,
            ));
        }
        readouts.push(Readout::number("order_dp45", study.dp45.study.order, "", 3));
        for (k, f) in FIXED.iter().enumerate() {
            readouts.push(Readout::text(
                f.stable_key,
                if cur.stable[k] { "yes" } else { "no" },
            ));
        }
        for (k, f) in FIXED.iter().enumerate() {
            readouts.push(Readout::number(f.growth_key, Some(cur.growth[k]), "", 4));
        }
        readouts.push(Readout::number(
            "steps_dp45",
            cur.dp45
                .as_ref()
                .ok()
                .map(|o| o.solution.stats.n_accepted as f64),
            "",
            3,
        ));
        let figures = vec![
            self.response_figure(s, &cur),
            self.error_figure(s, &cur),
            convergence_figure(s, study, &cur),
            stability_figure(s, &cur, regions),
        ];
        Frame {
            readouts,
            figures,
            time_span: None,
        }
    }

    fn response_figure(&self, s: &Setup, cur: &Current) -> Figure {
        let exact: Vec<(f64, f64)> = (0..SAMPLES)
            .map(|i| {
                let t = s.t_end * i as f64 / (SAMPLES - 1) as f64;
                (t, s.resp.displacement(t))
            })
            .collect();
        let amp = exact
            .iter()
            .map(|p| p.1.abs())
            .fold(0.0f64, f64::max)
            .max(1e-12 * s.x0);
        let y_range = (-RESPONSE_RANGE * amp, RESPONSE_RANGE * amp);
        let inside = |y: f64| y.is_finite() && y.abs() <= RESPONSE_RANGE * amp;
        let mut series = vec![Series {
            label: "exact".into(),
            points: exact,
            style: EXACT_STYLE,
        }];
        let mut markers = Vec::new();
        let mut words = Vec::new();
        for (k, f) in FIXED.iter().enumerate() {
            let sol = &self.runs[k].sol;
            let clipped = sol.y.iter().any(|y| !inside(y[0]));
            words.push(method_words(f, cur, k, &self.runs[k], clipped));
            if !s.show[k] {
                continue;
            }
            let stride = sol.t.len().div_ceil(MAX_DRAWN).max(1);
            let pts: Vec<(f64, f64)> = strided(sol.t.len(), stride)
                .map(|i| (sol.t[i], sol.y[i][0]))
                .collect();
            if let Some(shape) = f.mark {
                let every = sol.t.len().div_ceil(MAX_MARKS / 2).max(1);
                markers.extend(
                    strided(sol.t.len(), every)
                        .filter(|&i| inside(sol.y[i][0]))
                        .map(|i| mark(shape, f.style.ink, (sol.t[i], sol.y[i][0]))),
                );
            }
            let mut label = f.legend.to_string();
            if cur.growth[k] > 1.0 && clipped {
                label.push_str(&format!(" ×{}/step ↑", si(cur.growth[k], "", 3)));
            }
            series.push(Series {
                label,
                points: pts,
                style: f.style,
            });
        }
        match &cur.dp45 {
            Ok(out) => {
                let steps = &out.solution;
                words.push(format!(
                    "DP45 took {} steps (tolerance {}), max error {}",
                    steps.stats.n_accepted,
                    sci(s.tol),
                    cur.dp45_err.map_or("—".into(), |e| si(e, "m", 3))
                ));
                if s.show[4] {
                    let pts = (0..SAMPLES)
                        .filter_map(|i| {
                            let t = s.t_end * i as f64 / (SAMPLES - 1) as f64;
                            out.dense.eval(t).map(|y| (t, y[0]))
                        })
                        .collect();
                    series.push(Series {
                        label: DP45_LEGEND.into(),
                        points: pts,
                        style: DP45_STYLE,
                    });
                    let every = steps.t.len().div_ceil(MAX_MARKS).max(1);
                    markers.extend(
                        strided(steps.t.len(), every)
                            .filter(|&i| inside(steps.y[i][0]))
                            .map(|i| mark(DP45_MARK, DP45_STYLE.ink, (steps.t[i], steps.y[i][0]))),
                    );
                }
            }
            Err(e) => words.push(format!("DP45 failed: {e}")),
        }
        let description = format!(
            "Each method against the exact decaying oscillation over {} with h = {} ({} steps). {}. \
             The plot shows ±{} of the exact amplitude; curves beyond it are clipped at the edge.",
            si(s.t_end, "s", 3),
            si(cur.h, "s", 3),
            cur.n,
            words.join("; "),
            RESPONSE_RANGE
        );
        Figure {
            description,
            series,
            markers,
            origin_lines: true,
            ..Figure::plot(
                "Numerical solutions and the exact x(t)",
                Axis::linear("time t", "s", (0.0, s.t_end)),
                Axis::linear("displacement x", "m", y_range),
            )
        }
    }

    fn error_figure(&self, s: &Setup, cur: &Current) -> Figure {
        let mut series = Vec::new();
        let mut markers = Vec::new();
        let mut lo = f64::INFINITY;
        let mut hi = 0.0f64;
        let mut parts = Vec::new();
        let clip = ERROR_CLIP * s.x0;
        for (k, f) in FIXED.iter().enumerate() {
            if !s.show[k] {
                continue;
            }
            let sol = &self.runs[k].sol;
            let errs = |i: usize| {
                let e = (sol.y[i][0] - self.exact.get(i).map_or(f64::NAN, |x| x[0])).abs();
                if e > 0.0 {
                    e
                } else {
                    f64::NAN
                }
            };
            let pts = bucket_max(sol.t.len(), |i| (sol.t[i], errs(i)));
            for p in pts.iter().filter(|p| p.1.is_finite()) {
                lo = lo.min(p.1);
                hi = hi.max(p.1);
            }
            if let Some(shape) = f.mark {
                let every = sol.t.len().div_ceil(MAX_MARKS / 2).max(1);
                markers.extend(
                    strided(sol.t.len(), every)
                        .map(|i| (sol.t[i], errs(i)))
                        .filter(|p| p.1.is_finite() && p.1 <= clip)
                        .map(|p| mark(shape, f.style.ink, p)),
                );
            }
            parts.push(error_words(f.name, &pts, cur.growth[k]));
            series.push(Series {
                label: f.legend.into(),
                points: pts,
                style: f.style,
            });
        }
        if let (true, Ok(out)) = (s.show[4], &cur.dp45) {
            let sol = &out.solution;
            let pts: Vec<(f64, f64)> = sol
                .t
                .iter()
                .zip(&sol.y)
                .map(|(&t, y)| {
                    let e = (y[0] - s.resp.displacement(t)).abs();
                    (t, if e > 0.0 { e } else { f64::NAN })
                })
                .collect();
            for p in pts.iter().filter(|p| p.1.is_finite()) {
                lo = lo.min(p.1);
                hi = hi.max(p.1);
            }
            let every = pts.len().div_ceil(MAX_MARKS).max(1);
            markers.extend(
                strided(pts.len(), every)
                    .map(|i| pts[i])
                    .filter(|p| p.1.is_finite())
                    .map(|p| mark(DP45_MARK, DP45_STYLE.ink, p)),
            );
            parts.push(error_words("DP45", &pts, 1.0));
            series.push(Series {
                label: DP45_LEGEND.into(),
                points: pts,
                style: DP45_STYLE,
            });
        }
        let floor = 1e-16 * s.x0;
        let (lo, hi) = if lo.is_finite() && hi > 0.0 {
            (
                (lo.max(floor)) / 3.0,
                (hi * 3.0).min(clip).max(lo.max(floor) * 10.0),
            )
        } else {
            (floor, s.x0)
        };
        let description = if parts.is_empty() {
            "No method is switched on.".to_string()
        } else {
            format!(
                "Error |x_num − x_exact| on a logarithmic scale at each method's grid points \
                 (h = {}): {}.{}",
                si(cur.h, "s", 3),
                parts.join("; "),
                if hi >= clip {
                    format!(" Errors above {} are clipped at the top.", si(clip, "m", 2))
                } else {
                    String::new()
                }
            )
        };
        Figure {
            description,
            series,
            markers,
            ..Figure::plot(
                "Error over time",
                Axis::linear("time t", "s", (0.0, s.t_end)),
                log_axis("error |x_num − x_exact|", "m", (lo, hi)),
            )
        }
    }
}

fn invalid_frame() -> Frame {
    Frame {
        readouts: Vec::new(),
        figures: Vec::new(),
        time_span: None,
    }
}

/// Indices `0, stride, 2·stride, …` and always the last one.
fn strided(len: usize, stride: usize) -> impl Iterator<Item = usize> {
    let stride = stride.max(1);
    (0..len)
        .step_by(stride)
        .chain((len > 0 && !(len - 1).is_multiple_of(stride)).then(|| len - 1))
}

/// At most [`MAX_DRAWN`] points: each bucket of consecutive points keeps its largest
/// value (so an error's peaks survive the thinning); a NaN value in a bucket is kept as a
/// line break.
fn bucket_max(len: usize, point: impl Fn(usize) -> (f64, f64)) -> Vec<(f64, f64)> {
    let size = len.div_ceil(MAX_DRAWN).max(1);
    (0..len)
        .step_by(size)
        .map(|start| {
            let mut best = point(start);
            for i in start + 1..(start + size).min(len) {
                let p = point(i);
                if !best.1.is_finite() || p.1 > best.1 {
                    best = p;
                }
            }
            best
        })
        .collect()
}

fn mark(shape: MarkerShape, color: Ink, at: (f64, f64)) -> Marker {
    Marker {
        label: String::new(),
        at,
        shape,
        ink: color,
    }
}

/// Length of the longest of plotters' tick labels for this log range (6 requested,
/// printed with `{:?}` as the renderer does): long ones carry rounding tails such as
/// `1.0000000000000002e-6`.
fn log_tick_width(lo: f64, hi: f64) -> usize {
    use plotters::coord::combinators::IntoLogRange;
    use plotters::coord::ranged1d::Ranged;
    let coord: plotters::coord::combinators::LogCoord<f64> = (lo..hi).log_scale().into();
    coord
        .key_points(6usize)
        .iter()
        .map(|v| format!("{v:?}").len())
        .max()
        .unwrap_or(0)
}

/// Longest tick label accepted as free of rounding tails (`1e-11`, `10000.0`).
const CLEAN_TICK: usize = 8;

/// A logarithmic axis over whole decades, widened by up to three decades at either end
/// when that gives tick labels without rounding tails (the renderer prints ticks with
/// `{:?}`, and the rounding of `powf` differs between native code and wasm).
fn log_axis(label: &str, unit: &'static str, range: (f64, f64)) -> Axis {
    let (lo, hi) = crate::figure::sane_range(range, AxisScale::Log);
    let (dlo, dhi) = (lo.log10().floor(), hi.log10().ceil());
    let mut best = (usize::MAX, 0.0, 0.0);
    'search: for widen in 0..=6 {
        for a in 0..=widen.min(3) {
            let b = widen - a;
            if b > 3 {
                continue;
            }
            let (a, b) = (f64::from(a), f64::from(b));
            let w = log_tick_width(10f64.powf(dlo - a), 10f64.powf(dhi + b));
            if w < best.0 {
                best = (w, a, b);
            }
            if w <= CLEAN_TICK {
                break 'search;
            }
        }
    }
    let (lo, hi) = (10f64.powf(dlo - best.1), 10f64.powf(dhi + best.2));
    Axis {
        range: crate::figure::sane_range((lo, hi), AxisScale::Log),
        scale: AxisScale::Log,
        ..Axis::linear(label, unit, (0.0, 1.0))
    }
}

/// `1e-6` style for tolerances.
fn sci(v: f64) -> String {
    format!("{v:.0e}")
}

fn method_words(f: &Fixed, cur: &Current, k: usize, run: &Run, clipped: bool) -> String {
    let g = cur.growth[k];
    let state = if let Some(t) = run.overflow {
        format!(
            "overflows at t = {} (×{} per step)",
            si(t, "s", 3),
            si(g, "", 3)
        )
    } else if g > 1.0 && !cur.stable[k] {
        format!(
            "diverges (×{} per step{}), max error {}",
            si(g, "", 4),
            if clipped { ", clipped" } else { "" },
            cur.max_err[k].map_or("—".into(), |e| si(e, "m", 3))
        )
    } else {
        format!(
            "stays bounded (×{} per step), max error {}",
            si(g, "", 4),
            cur.max_err[k].map_or("—".into(), |e| si(e, "m", 3))
        )
    };
    format!("{} {}", f.name, state)
}

fn error_words(name: &str, pts: &[(f64, f64)], growth: f64) -> String {
    let peak =
        pts.iter()
            .filter(|p| p.1.is_finite())
            .fold(None::<(f64, f64)>, |acc, &p| match acc {
                Some(a) if a.1 >= p.1 => Some(a),
                _ => Some(p),
            });
    match peak {
        Some((t, e)) => format!(
            "{name} largest {} at t = {}{}",
            si(e, "m", 3),
            si(t, "s", 3),
            if growth > 1.0 { ", growing" } else { "" }
        ),
        None => format!("{name} has no finite error"),
    }
}

/// A fitted line `e = C·hᵖ` through the used points of a sweep: `(h_lo, h_hi, C)`.
fn fit_line(study: &ConvergenceStudy) -> Option<(f64, f64, f64, f64)> {
    let p = study.order?;
    let used: Vec<(f64, f64)> = study
        .points
        .iter()
        .filter(|q| q.used)
        .map(|q| (q.h, q.error))
        .collect();
    let n = used.len() as f64;
    let mx = used.iter().map(|q| q.0.ln()).sum::<f64>() / n;
    let my = used.iter().map(|q| q.1.ln()).sum::<f64>() / n;
    let lo = used.iter().map(|q| q.0).fold(f64::INFINITY, f64::min);
    let hi = used.iter().map(|q| q.0).fold(0.0f64, f64::max);
    Some((lo, hi, (my - p * mx).exp(), p))
}

fn convergence_figure(s: &Setup, study: &Study, cur: &Current) -> Figure {
    let mut series = Vec::new();
    let mut markers = Vec::new();
    let clip = ERROR_CLIP * s.x0;
    let (mut xlo, mut xhi) = (cur.h, cur.h);
    let (mut ylo, mut yhi) = (f64::INFINITY, 0.0f64);
    let mut words = Vec::new();
    let mut add = |sweep: &Sweep,
                   name: &str,
                   legend: &str,
                   style: LineStyle,
                   shape: Option<MarkerShape>,
                   show: bool,
                   words: &mut Vec<String>| {
        let pts: Vec<(f64, f64)> = sweep
            .study
            .points
            .iter()
            .filter(|p| p.error.is_finite() && p.error > 0.0)
            .map(|p| (p.h, p.error))
            .collect();
        let overflowed = sweep
            .status
            .iter()
            .zip(&sweep.study.points)
            .filter(|(st, _)| **st == RunStatus::Overflow)
            .map(|(_, p)| p.h)
            .fold(0.0f64, f64::max);
        let order = sweep.study.order.map_or(
            "no fit (too few points in the asymptotic range)".into(),
            |p| format!("fitted slope {}", si(p, "", 3)),
        );
        let mut w = format!("{name} {order}");
        if overflowed > 0.0 {
            w.push_str(&format!(", overflows for h ≥ {}", si(overflowed, "s", 3)));
        }
        words.push(w);
        if !show {
            return;
        }
        for &(h, e) in &pts {
            xlo = xlo.min(h);
            xhi = xhi.max(h);
            ylo = ylo.min(e);
            yhi = yhi.max(e);
        }
        if let Some(shape) = shape {
            markers.extend(
                pts.iter()
                    .filter(|p| p.1 <= clip)
                    .map(|&p| mark(shape, style.ink, p)),
            );
        }
        if let Some((lo, hi, c, p)) = fit_line(&sweep.study) {
            series.push(Series {
                label: String::new(),
                points: vec![(lo, c * lo.powf(p)), (hi, c * hi.powf(p))],
                style: LineStyle::solid(style.ink, 1.0),
            });
        }
        let label = match sweep.study.order {
            Some(p) => format!("{legend}: {}", si(p, "", 3)),
            None => format!("{legend}: no fit"),
        };
        series.push(Series {
            label,
            points: pts,
            style,
        });
    };
    for (k, f) in FIXED.iter().enumerate() {
        if let Some(sw) = study.fixed.get(k) {
            add(sw, f.name, f.legend, f.style, f.mark, s.show[k], &mut words);
        }
    }
    add(
        &study.dp45,
        "DP45 (against the mean step T/steps over tolerances 1e-2 … 1e-10, its 4 finest usable runs; no fit when stability, not accuracy, sets its steps)",
        "DP45 (mean step)",
        DP45_STYLE,
        Some(DP45_MARK),
        s.show[4],
        &mut words,
    );
    if !(ylo.is_finite() && yhi > 0.0) {
        ylo = FIT_FLOOR * s.x0;
        yhi = s.x0;
    }
    let yhi = yhi.min(clip).max(ylo * 100.0);
    let x_range = (xlo / 1.6, xhi * 1.6);
    let y_range = (ylo / 4.0, yhi * 1000.0);
    // Reference slopes 1 and 4 through the geometric middle of the drawn data.
    let xm = (x_range.0 * x_range.1).sqrt();
    let ym = (ylo * yhi).sqrt();
    for p in [1.0, 4.0] {
        let (a, b) = (x_range.0, x_range.1);
        let line = |h: f64| ym * 0.1 * (h / xm).powf(p);
        series.push(Series {
            label: String::new(),
            points: (0..=40)
                .map(|i| {
                    let h = a * (b / a).powf(i as f64 / 40.0);
                    (h, line(h))
                })
                .filter(|q| q.1 >= y_range.0 && q.1 <= y_range.1)
                .collect(),
            style: LineStyle {
                ink: Ink::Black,
                dash: Dash::Dotted,
                width: 1.2,
            },
        });
        // Name the line where it leaves the plot on the left (or at its lowest point).
        let h_at = (a * 1.15).max(xm * (y_range.0 * 3.0 / (ym * 0.1)).powf(1.0 / p));
        if h_at < b {
            markers.push(Marker {
                label: format!("slope {p}"),
                at: (h_at, line(h_at)),
                shape: MarkerShape::Label,
                ink: Ink::Black,
            });
        }
    }
    markers.push(Marker {
        label: format!("h = {}", si(cur.h, "s", 3)),
        at: (cur.h * 1.1, y_range.0 * 30.0),
        shape: MarkerShape::Label,
        ink: Ink::Sky,
    });
    series.push(Series {
        label: String::new(),
        points: vec![(cur.h, y_range.0), (cur.h, y_range.1)],
        style: LineStyle {
            ink: Ink::Sky,
            dash: Dash::Dashed,
            width: 1.2,
        },
    });
    let description = format!(
        "Largest error at {} common check points against the step h, for up to {} step sizes \
         halving from {} (at most {} steps per method in all; finer steps are skipped). {}. Points \
         with error above {} % or below 1e-10 of x₀ are left out of the fit; reference \
         slopes 1 and 4 are dotted; the current h is the dashed vertical line.",
        study.n0 + 1,
        LEVELS,
        si(
            study
                .fixed
                .first()
                .and_then(|s| s.study.points.first())
                .map_or(0.0, |p| p.h),
            "s",
            3
        ),
        STUDY_BUDGET,
        words.join("; "),
        FIT_CEILING * 100.0
    );
    Figure {
        description,
        series,
        markers,
        ..Figure::plot(
            "Convergence: max error against step h",
            log_axis("step h", "s", x_range),
            log_axis("max error", "m", y_range),
        )
    }
}

fn stability_figure(s: &Setup, cur: &Current, regions: &[Vec<(f64, f64)>; 3]) -> Figure {
    let names = ["forward Euler", "Heun", "RK4"];
    let index = [0usize, 2, 3];
    let mut series = Vec::new();
    for (r, &k) in regions.iter().zip(&index) {
        if !s.show[k] {
            continue;
        }
        series.push(Series {
            label: FIXED[k].legend.into(),
            points: r.clone(),
            style: LineStyle {
                width: 2.0,
                ..FIXED[k].style
            },
        });
    }
    let z: Vec<Complex> = s.poles.iter().map(|&p| p * cur.h).collect();
    // Base window holds every region; it grows to show hλ, up to a limit.
    const LIMIT: f64 = 12.0;
    let mut x = (-3.2f64, 1.0f64);
    let mut y = (-3.2f64, 3.2f64);
    for p in &z {
        x = (
            x.0.min(p.re * 1.15).max(-LIMIT),
            x.1.max(p.re * 1.15).min(LIMIT),
        );
        y = (
            y.0.min(p.im * 1.15).max(-LIMIT),
            y.1.max(p.im * 1.15).min(LIMIT),
        );
    }
    // Keep the scales roughly equal on both axes (the canvas is 1.3 : 1).
    let (w, hgt) = (x.1 - x.0, y.1 - y.0);
    if w < 1.3 * hgt {
        let pad = 0.5 * (1.3 * hgt - w);
        // Most of the widening goes right, where the legend sits.
        x = (x.0 - pad * 0.2, x.1 + pad * 1.8);
    } else {
        let pad = 0.5 * (w / 1.3 - hgt);
        y = (y.0 - pad, y.1 + pad);
    }
    let mut markers = Vec::new();
    let same = z.len() == 2 && z[0] == z[1];
    for (i, p) in z.iter().enumerate() {
        if same && i == 1 {
            continue;
        }
        let off = p.re < x.0 || p.re > x.1 || p.im < y.0 || p.im > y.1;
        let at = (p.re.clamp(x.0, x.1), p.im.clamp(y.0, y.1));
        let name = if same {
            "hλ₁,₂"
        } else if i == 0 {
            "hλ₁"
        } else {
            "hλ₂"
        };
        markers.push(Marker {
            label: if off {
                format!("{name} = {} (off scale)", si(p.re, "", 3))
            } else {
                name.into()
            },
            at,
            shape: MarkerShape::Cross,
            ink: Ink::Black,
        });
        // The path z = h'λ for 0 < h' ≤ h, along which z moves as h grows.
        series.push(Series {
            label: if i == 0 {
                "hλ as h grows".into()
            } else {
                String::new()
            },
            points: (0..=50)
                .map(|j| {
                    let q = *p * (j as f64 / 50.0);
                    (q.re, q.im)
                })
                .collect(),
            style: LineStyle {
                ink: Ink::Sky,
                dash: Dash::Dotted,
                width: 1.5,
            },
        });
    }
    let zs = if same {
        format!("z = hλ = {}", si(z[0].re, "", 3))
    } else if z[0].im.abs() > 0.0 {
        format!(
            "z = hλ = {} ± {}i",
            si(z[0].re, "", 3),
            si(z[0].im.abs(), "", 3)
        )
    } else {
        // Two real poles: no imaginary unit.
        format!("z = hλ = {} and {}", si(z[0].re, "", 3), si(z[1].re, "", 3))
    };
    let mut words = Vec::new();
    for (name, &k) in names.iter().zip(&index) {
        words.push(format!(
            "{name}: {} its region, |R| = {}, {}",
            if cur.growth[k] <= 1.0 {
                "inside"
            } else {
                "outside"
            },
            si(cur.growth[k], "", 4),
            limit_text(cur.limit[k])
        ));
    }
    let description = format!(
        "Stability regions |R(z)| ≤ 1 in the complex plane of z = hλ (inside each closed curve; \
         forward Euler's is the disk |1 + z| ≤ 1). The system's two poles at h = {} give {}. {}. \
         Symplectic Euler is not a scalar map R(z): its 2×2 step matrix has spectral radius {} \
         here, {}. DP45 chooses its own steps and keeps them stable.",
        si(cur.h, "s", 3),
        zs,
        words.join("; "),
        si(cur.growth[1], "", 4),
        limit_text(cur.limit[1])
    );
    Figure {
        description,
        series,
        markers,
        origin_lines: true,
        ..Figure::plot(
            "Stability regions and z = hλ",
            Axis::linear("real part Re(hλ)", "", x),
            Axis::linear("imaginary part Im(hλ)", "", y),
        )
    }
}

impl Demo for Integrators {
    fn spec(&self) -> DemoSpec {
        let readouts = [
            ("h_used", "step used, T/⌈T/h⌉", "s"),
            ("max_err_euler", "max error, forward Euler", "m"),
            (
                "max_err_symplectic_euler",
                "max error, symplectic Euler",
                "m",
            ),
            ("max_err_heun", "max error, Heun", "m"),
            ("max_err_rk4", "max error, RK4", "m"),
            ("max_err_dp45", "max error, DP45", "m"),
            ("order_euler", "fitted order, forward Euler", ""),
            (
                "order_symplectic_euler",
                "fitted order, symplectic Euler",
                "",
            ),
            ("order_heun", "fitted order, Heun", ""),
            ("order_rk4", "fitted order, RK4", ""),
            ("order_dp45", "fitted order, DP45 (vs mean step)", ""),
            ("stable_euler", "stable at this h, forward Euler", ""),
            (
                "stable_symplectic_euler",
                "stable at this h, symplectic Euler",
                "",
            ),
            ("stable_heun", "stable at this h, Heun", ""),
            ("stable_rk4", "stable at this h, RK4", ""),
            ("growth_euler", "growth per step |R(hλ)|, forward Euler", ""),
            (
                "growth_symplectic_euler",
                "growth per step (spectral radius), symplectic Euler",
                "",
            ),
            ("growth_heun", "growth per step |R(hλ)|, Heun", ""),
            ("growth_rk4", "growth per step |R(hλ)|, RK4", ""),
            ("steps_dp45", "DP45 accepted steps", ""),
        ]
        .into_iter()
        .map(|(key, label, unit)| ReadoutSpec { key, label, unit })
        .collect();
        DemoSpec {
            id: "integrators",
            title: "Numerical integrators and their error",
            summary: "The free oscillator integrated by forward Euler, symplectic Euler, Heun \
                      (RK2) and classical RK4 at a fixed step h, and by Dormand–Prince 5(4) with \
                      adaptive steps, each compared with the exact solution. A one-step method \
                      multiplies each mode by R(hλ) per step: when |R| > 1 the numbers grow no \
                      matter how well the method fits the equation, which is why forward Euler \
                      blows up a lightly damped oscillator unless h < 2ζ/ωₙ. When it is stable, \
                      halving h divides the error by 2^p, where p is the method's order: the \
                      convergence plot measures p. Switching a method off hides its curves; its \
                      readouts are still computed.",
            equation_mathml: EQUATION,
            params: vec![
                ParamSpec::linear("zeta", "damping ratio", "ζ", "", (0.0, 2.0, 0.01), 0.05),
                ParamSpec::linear(
                    "wn",
                    "natural frequency",
                    "ωₙ",
                    "rad/s",
                    (0.5, 20.0, 0.01),
                    2.0,
                ),
                ParamSpec::log("h", "step size", "h", "s", (1e-3, 2.0, 1e-4), 0.3),
                ParamSpec::linear("T", "duration", "T", "s", (1.0, 60.0, 0.5), 20.0),
                ParamSpec::linear(
                    "x0",
                    "initial displacement",
                    "x₀",
                    "m",
                    (0.05, 2.0, 0.01),
                    1.0,
                ),
                ParamSpec::log(
                    "tol",
                    "DP45 tolerance (relative; absolute tol·x₀)",
                    "tol",
                    "",
                    (1e-10, 1e-2, 1e-10),
                    1e-6,
                ),
                ParamSpec::toggle("euler", "forward Euler", true),
                ParamSpec::toggle("symplectic_euler", "symplectic Euler", true),
                ParamSpec::toggle("heun", "Heun (RK2)", true),
                ParamSpec::toggle("rk4", "RK4", true),
                ParamSpec::toggle("dp45", "Dormand–Prince 5(4), adaptive", true),
            ],
            readouts,
            plots: vec![
                PlotSpec {
                    key: "response",
                    title: "Numerical solutions and the exact x(t)",
                    aspect: 1.6,
                },
                PlotSpec {
                    key: "error",
                    title: "Error over time",
                    aspect: 1.2,
                },
                PlotSpec {
                    key: "convergence",
                    title: "Convergence: max error against step h",
                    aspect: 1.25,
                },
                PlotSpec {
                    key: "stability",
                    title: "Stability regions and z = hλ",
                    aspect: 1.3,
                },
            ],
            primary_plot: "",
            presets: vec![
                Preset {
                    label: "Lightly damped, h = 0.3 s",
                    values: vec![("zeta", 0.05), ("wn", 2.0), ("h", 0.3)],
                },
                Preset {
                    label: "Euler just stable, h = 0.04 s",
                    values: vec![("zeta", 0.05), ("wn", 2.0), ("h", 0.04)],
                },
                Preset {
                    label: "RK4 beyond its limit, h = 1.6 s",
                    values: vec![("zeta", 0.05), ("wn", 2.0), ("h", 1.6)],
                },
                Preset {
                    label: "Undamped, h = 0.1 s",
                    values: vec![("zeta", 0.0), ("wn", 2.0), ("h", 0.1)],
                },
                Preset {
                    label: "Stiff overdamped ζ = 2, ωₙ = 20",
                    values: vec![("zeta", 2.0), ("wn", 20.0), ("h", 0.03), ("T", 5.0)],
                },
            ],
            table: Some(Table {
                caption: "The methods",
                columns: vec![
                    "method",
                    "order p",
                    "f-evaluations per step",
                    "amplification R(z)",
                    "on an undamped oscillator",
                ],
                rows: vec![
                    (
                        "euler",
                        vec![
                            "forward Euler",
                            "1",
                            "1",
                            "1 + z",
                            "always grows: |R(iωh)| = √(1 + ω²h²) > 1",
                        ],
                    ),
                    (
                        "symplectic_euler",
                        vec![
                            "symplectic Euler",
                            "1",
                            "2",
                            "2×2 matrix, not a scalar R",
                            "bounded energy error while ωh ≤ 2",
                        ],
                    ),
                    (
                        "heun",
                        vec![
                            "Heun (RK2)",
                            "2",
                            "2",
                            "1 + z + z²/2",
                            "slowly grows: |R(iy)|² = 1 + y⁴/4",
                        ],
                    ),
                    (
                        "rk4",
                        vec![
                            "classical RK4",
                            "4",
                            "4",
                            "1 + z + z²/2 + z³/6 + z⁴/24",
                            "slightly damps while ωh ≤ 2√2",
                        ],
                    ),
                    (
                        "dp45",
                        vec![
                            "Dormand–Prince 5(4)",
                            "5",
                            "6 (first same as last)",
                            "adaptive: h follows the error estimate",
                            "stable: rejected steps shrink h",
                        ],
                    ),
                ],
                highlight_readout: "",
            }),
            schematic: false,
        }
    }

    fn update(&mut self, params: &Params) -> Frame {
        match setup(params) {
            Some(s) => self.frame(&s),
            None => {
                let spec = self.spec();
                Frame {
                    readouts: spec
                        .readouts
                        .iter()
                        .map(|r| Readout::number(r.key, None, r.unit, 3))
                        .collect(),
                    figures: Vec::new(),
                    time_span: None,
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn run(query: &str) -> Frame {
        let mut d = Integrators::new();
        let spec = d.spec();
        let (p, _) = crate::params::resolve_query(&spec, query);
        d.update(&p)
    }

    fn value(f: &Frame, key: &str) -> String {
        f.readouts
            .iter()
            .find(|r| r.key == key)
            .map(|r| r.data_value.clone())
            .unwrap()
    }

    fn num(f: &Frame, key: &str) -> f64 {
        value(f, key).parse().unwrap()
    }

    #[test]
    fn preset_shows_euler_unstable_and_the_orders() {
        let f = run("");
        for fig in &f.figures {
            println!("{}: {}", fig.title, fig.description);
        }
        for r in &f.readouts {
            println!("{} = {} ({})", r.key, r.data_value, r.text);
        }
        assert_eq!(value(&f, "stable_euler"), "no");
        assert_eq!(value(&f, "stable_rk4"), "yes");
        let (e, h, r) = (
            num(&f, "max_err_euler"),
            num(&f, "max_err_heun"),
            num(&f, "max_err_rk4"),
        );
        assert!(r < h && h < e, "{r} {h} {e}");
        let o = |k| num(&f, k);
        assert!((0.8..1.3).contains(&o("order_euler")));
        assert!((0.8..1.3).contains(&o("order_symplectic_euler")));
        assert!((1.7..2.3).contains(&o("order_heun")));
        assert!((3.6..4.4).contains(&o("order_rk4")));
        assert!((3.5..6.5).contains(&o("order_dp45")));
    }

    #[test]
    fn stiff_dp45_gets_no_meaningless_order() {
        let f = run("zeta=2&wn=20&h=0.03&T=5");
        assert_eq!(value(&f, "order_dp45"), "");
        assert_eq!(value(&f, "stable_euler"), "no");
        assert_eq!(value(&f, "stable_rk4"), "yes");
    }
}

#[cfg(test)]
mod axes {
    use super::*;
    #[test]
    fn log_axes_get_clean_tick_labels() {
        for (lo, hi) in [
            (3e-13, 1e5),
            (1e-12, 1e0),
            (2e-9, 1e3),
            (1e-10, 1e4),
            (1e-6, 1e2),
        ] {
            let a = log_axis("y", "", (lo, hi));
            assert!(a.range.0 <= lo && a.range.1 >= hi);
            assert!(
                log_tick_width(a.range.0, a.range.1) <= CLEAN_TICK,
                "{lo:e}..{hi:e} -> {:?}",
                a.range
            );
        }
    }
}
