//! The two-DOF quarter car's plots: motion of body, wheel and road; body acceleration;
//! tyre deflection; and the frequency responses per unit road height.

use super::run::{Run, FRF_RANGE};
use super::{text, RoadKind};
use crate::figure::{finite_extent, padded, Axis, Figure, LineStyle, Marker};
use crate::plot::Ink;
use crate::t;
use std::f64::consts::TAU;
use zeta_solver::two_dof::{TwoDof, G};
use zeta_solver::two_dof_exact::ExactMetrics;

/// Every `stride`-th state is plotted once a run exceeds this many points.
const PLOT_POINTS: usize = 1000;

/// The look of each line that draws the road, the wheel or the body (the body the same
/// in the motion and the frequency response; the tyre's gain a little heavier than the
/// wheel's motion).
const ROAD: LineStyle = LineStyle::dotted(Ink::Black, 2.0);
const WHEEL: LineStyle = LineStyle::dashed(Ink::Vermillion, 1.8);
const TYRE: LineStyle = LineStyle::dashed(Ink::Vermillion, 2.0);
const BODY: LineStyle = LineStyle::solid(Ink::Blue, 2.5);
/// The one trace of a plot over the run (body acceleration, tyre deflection).
const TRACE: LineStyle = LineStyle::solid(Ink::Blue, 2.0);

fn stride(run: &Run) -> usize {
    run.states.len().div_ceil(PLOT_POINTS).max(1)
}

/// `(t, f(state, road height))` at every [`stride`]-th grid point.
fn sampled(run: &Run, f: impl Fn(&[f64; 4], f64) -> f64) -> Vec<(f64, f64)> {
    run.times
        .iter()
        .zip(&run.states)
        .zip(&run.road_u)
        .step_by(stride(run))
        .map(|((&t, y), &u)| (t, f(y, u)))
        .collect()
}

/// The point of largest |y| (the first one on a tie; `(0, 0)` when empty).
fn peak(s: &[(f64, f64)]) -> (f64, f64) {
    s.iter().fold(
        (0.0, 0.0),
        |acc: (f64, f64), p| {
            if p.1.abs() > acc.1.abs() {
                *p
            } else {
                acc
            }
        },
    )
}

/// A range over `values` and 0, padded by 8 %, with `headroom` of its span added on top
/// for the legend.
fn range_with_legend(values: impl Iterator<Item = f64>, empty: f64, headroom: f64) -> (f64, f64) {
    let (lo, hi) = finite_extent(values.chain([0.0])).unwrap_or((-empty, empty));
    let mut y = padded((lo, hi.max(lo + 1e-6)), 0.08);
    y.1 += headroom * (y.1 - y.0);
    y
}

/// An empty plot against time over the run, `0 … t_end` \[s\], with this y axis.
fn over_run(title: String, t_end: f64, y: Axis) -> Figure {
    Figure::plot(title, Axis::linear(t!("axis-time"), "s", (0.0, t_end)), y)
}

/// Body, wheel and road heights over the run.
pub(super) fn motion(run: &Run, t_end: f64, kind: RoadKind) -> Figure {
    let road = sampled(run, |_, u| u);
    let body = sampled(run, |y, _| y[0]);
    let wheel = sampled(run, |y, _| y[1]);
    let all = road.iter().chain(&body).chain(&wheel).map(|p| p.1);
    let y = range_with_legend(all, 0.05, 0.35);
    let description = text::describe_motion(kind, peak(&road).1, peak(&body), peak(&wheel));
    over_run(
        t!("quarter-car-2dof-plot-motion"),
        t_end,
        Axis::linear(t!("quarter-car-2dof-axis-height"), "m", y),
    )
    .with_line(t!("quarter-car-2dof-series-road"), road, ROAD)
    .with_line(t!("quarter-car-2dof-series-wheel"), wheel, WHEEL)
    .with_line(t!("quarter-car-2dof-series-body"), body, BODY)
    .with_origin_lines()
    .described(description)
}

/// Body acceleration over the run, with ± its RMS.
pub(super) fn acceleration(
    run: &Run,
    car: Option<&TwoDof>,
    t_end: f64,
    m: Option<ExactMetrics>,
) -> Figure {
    let acc = match car {
        Some(car) => sampled(run, |y, _| car.body_acceleration(y)),
        None => Vec::new(),
    };
    let (lo, hi) = finite_extent(acc.iter().map(|p| p.1).chain([0.0])).unwrap_or((-1.0, 1.0));
    let y = range_with_legend(acc.iter().map(|p| p.1), 1.0, 0.2);
    let peak = lo.abs().max(hi.abs());
    let rms = m.map(|m| m.rms_body_acceleration);
    let description = text::describe_acceleration(peak, peak / G, m);
    let mut fig = over_run(
        t!("quarter-car-2dof-plot-accel"),
        t_end,
        Axis::linear(t!("quarter-car-2dof-axis-acceleration"), "m/s²", y),
    )
    .with_line(t!("quarter-car-2dof-series-body-acceleration"), acc, TRACE);
    if let Some(r) = rms {
        let style = LineStyle::dashed(Ink::Purple, 1.5);
        fig = fig
            .with_line(
                t!("quarter-car-2dof-series-rms"),
                vec![(0.0, r), (t_end, r)],
                style,
            )
            .with_line("", vec![(0.0, -r), (t_end, -r)], style);
    }
    fig.with_origin_lines().described(description)
}

/// The intervals `(from, to)` \[s\] during which the wheel is off the road.
fn airborne(run: &Run) -> Vec<(f64, f64)> {
    let mut out = Vec::new();
    let mut from = None;
    for (&t, &contact) in run.times.iter().zip(&run.contact) {
        match (from, contact) {
            (None, false) => from = Some(t),
            (Some(f), true) => {
                out.push((f, t));
                from = None;
            }
            _ => {}
        }
    }
    if let (Some(f), Some(&last)) = (from, run.times.last()) {
        out.push((f, last));
    }
    out
}

/// Tyre deflection `z_u − u` over the run, with the static deflection (beyond which the
/// wheel leaves the road) when the deflection comes near it, and the times off the road.
pub(super) fn tyre(run: &Run, t_end: f64, static_tyre: f64, m: Option<ExactMetrics>) -> Figure {
    let defl = sampled(run, |y, u| y[1] - u);
    let (lo, hi) = finite_extent(defl.iter().map(|p| p.1).chain([0.0])).unwrap_or((-0.01, 0.01));
    let shows_limit = hi > 0.5 * static_tyre;
    let top = if shows_limit { hi.max(static_tyre) } else { hi };
    let mut y = padded((lo, top.max(lo + 1e-6)), 0.08);
    y.1 += 0.3 * (y.1 - y.0);
    let mut fig = over_run(
        t!("quarter-car-2dof-plot-tyre"),
        t_end,
        Axis::linear(t!("quarter-car-2dof-axis-tyre-deflection"), "m", y),
    )
    .with_line("z_u − u", defl, TRACE);
    if shows_limit {
        fig = fig.with_line(
            t!("quarter-car-2dof-series-lift-off"),
            vec![(0.0, static_tyre), (t_end, static_tyre)],
            LineStyle::dashed(Ink::Vermillion, 1.5),
        );
    }
    for (i, (from, to)) in airborne(run).into_iter().enumerate() {
        let label = if i == 0 {
            t!("quarter-car-2dof-series-off-road")
        } else {
            String::new()
        };
        fig = fig.with_line(
            label,
            vec![(from, static_tyre), (to, static_tyre)],
            LineStyle::solid(Ink::Orange, 5.0),
        );
    }
    fig.with_origin_lines()
        .described(text::describe_tyre(lo, hi, static_tyre, m))
}

/// Magnitudes clamped into a drawable positive band for the log axis.
fn clamp_magnitude(v: f64) -> f64 {
    if v.is_finite() {
        v.clamp(1e-4, 1e4)
    } else {
        1e4
    }
}

/// The largest point of `s` within a factor 1.6 of `f` (`(f, 0)` when none).
fn peak_near(s: &[(f64, f64)], f: f64) -> (f64, f64) {
    s.iter()
        .filter(|p| p.0 > f / 1.6 && p.0 < f * 1.6)
        .fold(
            (f, 0.0),
            |acc: (f64, f64), p| if p.1 > acc.1 { *p } else { acc },
        )
}

/// Body and tyre-deflection responses per unit road height on log axes, with the two
/// natural frequencies and, for a sine road, its frequency marked.
pub(super) fn frf(run: &Run, f_body: f64, f_wheel: f64, sine: Option<f64>) -> Figure {
    let hz = |w: f64| w / TAU;
    let body: Vec<(f64, f64)> = run
        .frf
        .iter()
        .map(|r| (hz(r.omega), clamp_magnitude(r.body.abs())))
        .collect();
    let tyre: Vec<(f64, f64)> = run
        .frf
        .iter()
        .map(|r| (hz(r.omega), clamp_magnitude(r.tyre_deflection.abs())))
        .collect();
    let (lo, hi) = finite_extent(body.iter().chain(&tyre).map(|p| p.1)).unwrap_or((1e-3, 10.0));
    // Log axis: strictly positive, from just below the smallest value (the clamp keeps it
    // ≥ 1e-4) to well above the largest, leaving room for the legend.
    let y = ((lo / 1.5).max(1e-4), hi.max(1.5) * 20.0);
    let nearest = |f: f64| {
        run.frf
            .iter()
            .min_by(|a, b| (hz(a.omega) - f).abs().total_cmp(&(hz(b.omega) - f).abs()))
    };
    let description = text::describe_frf(
        peak_near(&body, f_body),
        nearest(20.0).map_or(f64::NAN, |r| r.body.abs()),
        peak_near(&tyre, f_wheel),
    );
    let mut fig = Figure::plot(
        t!("quarter-car-2dof-plot-frf"),
        Axis::log(t!("quarter-car-2dof-axis-frequency"), "Hz", FRF_RANGE),
        Axis::log(t!("quarter-car-2dof-axis-magnitude"), "", y),
    )
    .with_line(t!("quarter-car-2dof-series-body-gain"), body, BODY)
    .with_line(t!("quarter-car-2dof-series-tyre-gain"), tyre, TYRE);
    for (f, name, ink) in [
        (f_body, "f_body", Ink::Green),
        (f_wheel, "f_wheel", Ink::Purple),
    ] {
        fig = fig.with_line(
            text::frequency_label(name, f),
            vec![(f, y.0), (f, y.1)],
            LineStyle::dotted(ink, 1.8),
        );
    }
    if let Some(f) = sine {
        let g = nearest(f).map_or(1.0, |r| clamp_magnitude(r.body.abs()));
        fig = fig.with_marker(Marker::dot(
            t!("quarter-car-2dof-marker-road"),
            (f, g),
            Ink::Black,
        ));
    }
    fig.described(description)
}
