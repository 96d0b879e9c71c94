//! The resonance demo's time response from rest, with the steady amplitude and the slow
//! envelope, and the animated mass with its force arrow.

use super::{text, Results, P};
use crate::figure::{Axis, Figure, LineStyle, Marker, Series};
use crate::plot::{sampled, Ink};
use crate::schematic::{mass_spring_damper, MassLabels};
use crate::t;
use std::f64::consts::TAU;
use zeta_solver::forced::HarmonicResponse;
use zeta_solver::grid::times;

pub(super) const TIME_TITLE: &str = "Response from rest x(t)";

/// Points of the time response.
const TIME_SAMPLES: usize = 1000;
/// Samples searched for the largest excursion that scales the schematic.
const SCHEMATIC_SAMPLES: usize = 201;

/// The largest finite `|v|` among `values` (`floor` if none is larger).
fn largest(values: impl IntoIterator<Item = f64>, floor: f64) -> f64 {
    values
        .into_iter()
        .map(f64::abs)
        .filter(|v| v.is_finite())
        .fold(floor, f64::max)
}

/// x(t) from rest over the window, with ±X and, near resonance, the envelope ±E(t).
pub(super) fn response(res: &Results) -> Figure {
    let (p, resp, t_end) = (&res.p, &res.resp, res.t_end);
    let ts = times(t_end, TIME_SAMPLES);
    let points = sampled(&ts, |t| resp.displacement(t));
    let max_x = largest(points.iter().map(|q| q.1), 0.0);
    let mut reach = max_x;
    let mut series = Vec::with_capacity(5);
    // The envelope is informative only while it varies slowly against the oscillation
    // (near resonance: slow beats or a build-up) and the free motion rings for a while.
    let slowest = TAU / p.wn.min(p.r * p.wn);
    let slow = resp.beat_period().is_none_or(|tb| tb > 3.0 * slowest);
    if p.zeta < 0.5 && slow && resp.envelope(0.0).is_some() {
        let env = sampled(&ts, |t| resp.envelope(t).unwrap_or(f64::NAN));
        reach = largest(env.iter().map(|q| q.1), reach);
        let lower = env.iter().map(|&(t, e)| (t, -e)).collect();
        let style = LineStyle::dotted(Ink::Green, 2.0);
        series.push(Series::new(t!("resonance-envelope"), env, style));
        series.push(Series::new("", lower, style));
    }
    if let Some(s) = resp.steady_state() {
        reach = reach.max(s.amplitude);
        for (sign, label) in [
            (1.0, t!("resonance-steady-amplitude")),
            (-1.0, String::new()),
        ] {
            series.push(Series::new(
                label,
                vec![(0.0, sign * s.amplitude), (t_end, sign * s.amplitude)],
                LineStyle::dashed(Ink::Vermillion, 1.5),
            ));
        }
    }
    series.push(Series::new(
        "x(t)",
        points,
        LineStyle::solid(Ink::Blue, 2.0),
    ));
    let m = reach.max(1e-12);
    Figure {
        series,
        ..Figure::plot(
            t!("resonance-plot-time"),
            Axis::linear(t!("axis-time"), "s", (0.0, t_end)),
            Axis::linear(t!("axis-displacement"), "m", (-1.12 * m, 1.9 * m)),
        )
    }
    .with_origin_lines()
    .described(text::describe_time(p, resp, t_end, max_x))
}

/// The mass at time `t` \[s\] with the force arrow above it, scaled by the largest
/// excursion in the window `t_end` \[s\] so the mass stays in the frame.
pub(super) fn schematic(p: &P, resp: &HarmonicResponse, t_end: f64, t: f64) -> Figure {
    let reach = largest(
        times(t_end, SCHEMATIC_SAMPLES)
            .into_iter()
            .map(|ti| resp.displacement(ti)),
        1e-12,
    );
    let x = resp.displacement(t);
    let force = resp.force().at(t);
    let base = t!("resonance-fixed-base");
    let labels = MassLabels::mkc(&base);
    let mut fig = mass_spring_damper(
        x / reach,
        0.0,
        &labels,
        text::describe_schematic(force, x, t),
    );
    // The force arrow, drawn from the top of the mass in the direction of F(t).
    // Geometry of `mass_spring_damper`: centre 2.4 + 0.55·x, height 0.8.
    let top = 2.4 + 0.55 * (x / reach).clamp(-1.2, 1.2) + 0.4;
    let f = if p.f0 != 0.0 { force / p.f0 } else { 0.0 };
    let f = if f.is_finite() {
        f.clamp(-1.0, 1.0)
    } else {
        0.0
    };
    let base = top + 0.1 + if f < 0.0 { 0.75 } else { 0.0 };
    let tip = base + 0.75 * f;
    let ink = LineStyle::solid(Ink::Orange, 3.0);
    if (tip - base).abs() > 0.03 {
        let head = if f > 0.0 { -0.15 } else { 0.15 };
        fig = fig
            .with_line("", vec![(0.0, base), (0.0, tip)], ink)
            .with_line(
                "",
                vec![(-0.12, tip + head), (0.0, tip), (0.12, tip + head)],
                ink,
            );
    }
    fig.markers
        .push(Marker::text("F(t)", (0.25, top + 0.6), Ink::Black));
    fig.y.range = (fig.y.range.0, fig.y.range.1.max(top + 1.0).max(4.4));
    fig
}
