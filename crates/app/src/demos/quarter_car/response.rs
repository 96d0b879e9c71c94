//! The quarter-car demo's main plot: the body released from x₀, this design against the
//! family of textbook settings on the same car, with the settling band.

use super::{text, Results};
use crate::figure::{finite_extent, Axis, Figure, LineStyle, Marker, MarkerShape, Series};
use crate::format::si;
use crate::plot::Ink;
use crate::t;
use zeta_solver::grid::linspace;
use zeta_solver::{FreeResponse, SecondOrder};

pub(super) const RESPONSE_TITLE: &str = "Body displacement x(t)";

/// Samples per time curve.
const SAMPLES: usize = 500;
/// Displacements are drawn in millimetres.
const MM: f64 = 1000.0;
/// Marks along each marked family curve.
const MARKS: usize = 6;

/// Line style of each family group, and the marks along the curve that tell it apart
/// without colour.
fn family_style(group: &str) -> (LineStyle, Option<MarkerShape>) {
    match group {
        "comfort" => (LineStyle::dashed(Ink::Vermillion, 1.5), None),
        "performance" => (LineStyle::dotted(Ink::Green, 2.0), None),
        "critical" => (LineStyle::solid(Ink::Purple, 1.5), Some(MarkerShape::Cross)),
        _ => (LineStyle::solid(Ink::Orange, 1.5), Some(MarkerShape::Dot)),
    }
}

/// x(t) of this design and of the preset family, with the ±band·x₀ lines.
pub(super) fn response(r: &Results) -> Figure {
    let (car, t_end) = (&r.car, r.t_end);
    let sample = |sys: &SecondOrder| -> Vec<(f64, f64)> {
        let resp = FreeResponse::new(*sys, car.x0, 0.0);
        resp.trace((0.0, t_end), SAMPLES)
            .into_iter()
            .map(|(t, x)| (t, MM * x))
            .collect()
    };
    let mut series = Vec::with_capacity(9);
    let mut markers = Vec::new();
    let mut legend_done: Vec<&str> = Vec::new();
    for member in &r.family {
        let Some(sys) = &member.sys else { continue };
        let (style, marker) = family_style(member.group);
        if let Some(shape) = marker {
            // Marks along the curve, so the group is told apart without colour.
            let shift = if shape == MarkerShape::Cross {
                0.3
            } else {
                0.7
            };
            let resp = car.release(sys);
            for j in 0..MARKS {
                let t = t_end * (j as f64 + shift) / MARKS as f64;
                markers.push(Marker {
                    label: String::new(),
                    at: (t, MM * resp.displacement(t)),
                    shape,
                    ink: style.ink,
                });
            }
        }
        let first = !legend_done.contains(&member.group);
        if first {
            legend_done.push(member.group);
        }
        let label = if first {
            text::family_legend(member.group)
        } else {
            String::new()
        };
        series.push(Series::new(label, sample(sys), style));
    }
    let h = MM * car.band.fraction() * car.x0.abs();
    for sign in [1.0, -1.0] {
        series.push(Series::new(
            "",
            linspace(0.0, t_end, 2)
                .into_iter()
                .map(|t| (t, sign * h))
                .collect(),
            LineStyle::dotted(Ink::Black, 1.0),
        ));
    }
    let current = sample(&car.sys);
    let (lo, hi) = finite_extent(
        series
            .iter()
            .flat_map(|s| s.points.iter().map(|p| p.1))
            .chain(current.iter().map(|p| p.1)),
    )
    .unwrap_or((-MM * car.x0, MM * car.x0));
    // Head-room above x₀ for the legend box in the upper right.
    let span = hi - lo;
    let y = (lo - 0.06 * span, hi + 0.6 * span);
    // Named under the lower band line, right of the middle: text hangs below its point, and
    // there the curves are back near rest.
    markers.push(Marker::text(
        t!("quarter-car-band-label", band = text::pct(car.band_pct)),
        (0.62 * t_end, -h - 0.015 * span),
        Ink::Black,
    ));
    series.push(Series::new(
        t!("quarter-car-series-design", zeta = si(car.zeta(), "", 3)),
        current,
        LineStyle::solid(Ink::Blue, 3.0),
    ));
    Figure {
        series,
        markers,
        ..Figure::plot(
            t!("quarter-car-plot-response"),
            Axis::linear(t!("axis-time"), "s", (0.0, t_end)),
            Axis::linear(t!("axis-displacement"), "mm", y),
        )
    }
    .with_origin_lines()
    .described(text::describe_response(r))
}
