//! The nonlinear demo's figures: both responses over time, the phase plane, the spring and
//! damper force laws, and the animated quarter car.

use super::{text, Results, ESCAPE};
use crate::figure::{finite_extent, padded, Axis, Figure, LineStyle, Marker};
use crate::format::si;
use crate::plot::Ink;
use crate::schematic::{mass_spring_damper, MassLabels};
use crate::t;
use zeta_solver::nonlinear::NonlinearConfig;

/// Every `STRIDE`-th state is plotted (≤ ~1000 points per curve).
const STRIDE: usize = 4;
/// Points of the force curves.
const CURVE: usize = 241;

/// Every [`STRIDE`]-th point of `pick(i)` for `i < n`, always including the last.
fn strided(n: usize, pick: impl Fn(usize) -> (f64, f64)) -> Vec<(f64, f64)> {
    let mut out: Vec<(f64, f64)> = (0..n).step_by(STRIDE).map(&pick).collect();
    if n > 0 && !(n - 1).is_multiple_of(STRIDE) {
        out.push(pick(n - 1));
    }
    out
}

/// `(t, x)` of a run.
fn displacement(t: &[f64], states: &[[f64; 2]]) -> Vec<(f64, f64)> {
    strided(t.len().min(states.len()), |i| (t[i], states[i][0]))
}

/// `(x, v)` of a run.
fn phase_points(states: &[[f64; 2]]) -> Vec<(f64, f64)> {
    strided(states.len(), |i| (states[i][0], states[i][1]))
}

/// `f` at [`CURVE`] points evenly spread over `[-reach, reach]`, both ends included.
fn symmetric(reach: f64, f: impl Fn(f64) -> f64) -> Vec<(f64, f64)> {
    (0..CURVE)
        .map(|i| {
            let x = -reach + 2.0 * reach * i as f64 / (CURVE - 1) as f64;
            (x, f(x))
        })
        .collect()
}

/// A range padded by 8 % with 30 % more on top for the legend.
fn with_legend_room((lo, hi): (f64, f64)) -> (f64, f64) {
    let mut y = padded((lo, hi.max(lo + 1e-6)), 0.08);
    y.1 += 0.3 * (y.1 - y.0);
    y
}

/// x(t) of the nonlinear run against the linear model, with the bump stops and the moment
/// friction holds the mass.
pub(super) fn response(r: &Results) -> Figure {
    let cfg = r.model.config();
    let nl = displacement(&r.cmp.t, &r.cmp.nonlinear);
    let lin = displacement(&r.cmp.t, &r.cmp.linear);
    let (lo, hi) =
        finite_extent(nl.iter().chain(&lin).map(|p| p.1).chain([0.0])).unwrap_or((-0.1, 0.1));
    let mut y = padded((lo, hi.max(lo + 1e-6)), 0.1);
    y.1 += 0.25 * (y.1 - y.0); // room for the legend
    let mut fig = Figure::plot(
        t!("nonlinear-plot-response"),
        Axis::linear(t!("axis-time"), "s", (0.0, r.t_end)),
        Axis::linear(t!("axis-extension"), "m", y),
    );
    if cfg.stop_stiffness > 0.0 {
        let stop = LineStyle::dotted(Ink::Purple, 1.5);
        let gap = cfg.stop_gap;
        fig = fig
            .with_line(
                t!("nonlinear-series-stops", gap = si(gap, "m", 3)),
                vec![(0.0, gap), (r.t_end, gap)],
                stop,
            )
            .with_line("", vec![(0.0, -gap), (r.t_end, -gap)], stop);
    }
    fig = both_runs(fig, lin, nl, 2.5);
    if let Some(st) = r.cmp.sticking {
        fig = fig.with_marker(Marker::dot(
            t!("nonlinear-marker-sticks"),
            (st.t, st.x),
            Ink::Green,
        ));
    }
    fig.with_origin_lines()
        .described(text::describe_response(r))
}

/// The trajectories in the (x, v) plane.
pub(super) fn phase(r: &Results) -> Figure {
    let nl = phase_points(&r.cmp.nonlinear);
    let lin = phase_points(&r.cmp.linear);
    let xs = finite_extent(nl.iter().chain(&lin).map(|p| p.0).chain([0.0])).unwrap_or((-0.1, 0.1));
    let vs = finite_extent(nl.iter().chain(&lin).map(|p| p.1).chain([0.0])).unwrap_or((-1.0, 1.0));
    let x = padded((xs.0, xs.1.max(xs.0 + 1e-6)), 0.08);
    let description = text::describe_phase(&nl, &lin);
    let start = nl.first().copied();
    let plot = Figure::plot(
        t!("nonlinear-plot-phase"),
        Axis::linear(t!("axis-extension"), "m", x),
        Axis::linear(t!("axis-velocity"), "m/s", with_legend_room(vs)),
    );
    let mut fig = both_runs(plot, lin, nl, 2.0);
    if let Some(p) = start {
        fig = fig.with_marker(Marker::dot(t!("nonlinear-marker-start"), p, Ink::Black));
    }
    fig.with_origin_lines().described(description)
}

/// Spring plus bump-stop force against extension, beside the linear spring.
pub(super) fn spring(r: &Results) -> Figure {
    let model = &r.model;
    let cfg = model.config();
    let max_travel = r.max_travel.unwrap_or(0.0);
    let mut reach = max_travel.max(0.02);
    if cfg.stop_stiffness > 0.0 {
        reach = reach.max(1.3 * cfg.stop_gap);
    }
    let reach = reach.min(ESCAPE) * 1.15;
    force_plot(
        t!("nonlinear-plot-spring"),
        (t!("axis-extension"), "m", reach),
        (t!("nonlinear-series-linear-spring"), &|x| cfg.k * x),
        (t!("nonlinear-series-spring"), &|x| model.elastic_force(x)),
    )
    .described(text::describe_spring(model, reach, max_travel))
}

/// One force against `x` over `±reach` (the x axis's label and unit given): the linear
/// model's force (dashed) under the nonlinear one, each with its legend label.
fn force_plot(
    title: String,
    (x_label, x_unit, reach): (String, &'static str, f64),
    (linear_label, linear): (String, &dyn Fn(f64) -> f64),
    (label, nonlinear): (String, &dyn Fn(f64) -> f64),
) -> Figure {
    let nl = symmetric(reach, nonlinear);
    let lin = symmetric(reach, linear);
    let extent =
        finite_extent(nl.iter().chain(&lin).map(|p| p.1).chain([0.0])).unwrap_or((-1.0, 1.0));
    let plot = Figure::plot(
        title,
        Axis::linear(x_label, x_unit, (-reach, reach)),
        Axis::linear(t!("axis-force"), "N", with_legend_room(extent)),
    );
    against_linear(plot, (linear_label, lin), (label, nl), 2.5).with_origin_lines()
}

/// `fig` with the linear model's curve (dashed) under the nonlinear one (solid, `width`
/// wide), each with its legend label.
fn against_linear(
    fig: Figure,
    (linear_label, linear): (String, Vec<(f64, f64)>),
    (label, nonlinear): (String, Vec<(f64, f64)>),
    width: f64,
) -> Figure {
    fig.with_line(
        linear_label,
        linear,
        LineStyle::dashed(Ink::Vermillion, 2.0),
    )
    .with_line(label, nonlinear, LineStyle::solid(Ink::Blue, width))
}

/// `fig` with the linear and the nonlinear run (see [`against_linear`]).
fn both_runs(
    fig: Figure,
    linear: Vec<(f64, f64)>,
    nonlinear: Vec<(f64, f64)>,
    width: f64,
) -> Figure {
    against_linear(
        fig,
        (t!("nonlinear-series-linear"), linear),
        (t!("nonlinear-series-nonlinear"), nonlinear),
        width,
    )
}

/// Damper plus friction force against velocity, beside the linear model's mean damper.
pub(super) fn damper(r: &Results) -> Figure {
    let model = &r.model;
    let cfg = model.config();
    let cmp = &r.cmp;
    let vmax = finite_extent(cmp.nonlinear.iter().chain(&cmp.linear).map(|p| p[1].abs()))
        .map_or(0.5, |e| e.1)
        .clamp(0.05, 10.0)
        * 1.15;
    let c_mean = 0.5 * (cfg.c_compression + cfg.c_rebound);
    force_plot(
        t!("nonlinear-plot-damper"),
        (t!("nonlinear-axis-velocity-rebound"), "m/s", vmax),
        (t!("nonlinear-series-linear-damper"), &|v| c_mean * v),
        (t!("nonlinear-series-damper"), &|v| {
            model.dissipative_force(v)
        }),
    )
    .described(text::describe_damper(model, vmax, c_mean))
}

/// The quarter car extended `x` \[m\] at time `t` \[s\], drawn at `x / reach` of full travel.
pub(super) fn schematic(cfg: &NonlinearConfig, x: f64, reach: f64, t: f64) -> Figure {
    let labels = MassLabels {
        mass: "m",
        spring: "k, k₃",
        damper: "c_c/c_r",
        base: "",
    };
    let stops = if cfg.stop_stiffness <= 0.0 {
        "none"
    } else if x.abs() > cfg.stop_gap {
        "pressing"
    } else {
        "clear"
    };
    let description = t!(
        "nonlinear-schematic",
        time = si(t, "s", 3),
        extension = si(x, "m", 3),
        stops = stops
    );
    mass_spring_damper(x / reach, 0.0, &labels, description)
}
