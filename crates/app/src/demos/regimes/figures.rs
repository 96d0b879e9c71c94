//! The regimes demo's figures: the free response with its decay envelope, the poles on
//! the s-plane, and the animated mass on a spring.

use super::{text, Results};
use crate::figure::{finite_extent, padded, Axis, Figure, LineStyle, Marker};
use crate::format::{self, si};
use crate::plot::{circle, curve, Ink};
use crate::schematic::{mass_spring_damper, MassLabels};
use crate::t;

/// Samples per curve: smooth at any canvas width up to ~1200 CSS px.
const SAMPLES: usize = 600;

pub(super) const RESPONSE_TITLE: &str = "Free response x(t)";
pub(super) const POLES_TITLE: &str = "Poles in the s-plane";

/// x(t) over the window, with the envelope ±A·e^(−ζωₙt) when the response oscillates.
pub(super) fn response(r: &Results) -> Figure {
    let x = r.response.trace((0.0, r.t_end), SAMPLES);
    let envelope = r.response.envelope_amplitude().map(|_| {
        curve((0.0, r.t_end), SAMPLES, |t| {
            r.response.envelope(t).unwrap_or(0.0)
        })
    });
    let floor = r.reach.max(1e-6);
    let envelope_values = envelope.iter().flatten().flat_map(|p| [p.1, -p.1]);
    let (lo, hi) =
        finite_extent(x.iter().map(|p| p.1).chain(envelope_values)).unwrap_or((-floor, floor));
    let y = padded((lo.min(-0.2 * floor), hi.max(0.2 * floor)), 0.08);
    let mut fig = Figure::plot(
        t!("regimes-plot-response"),
        Axis::linear(t!("axis-time"), "s", (0.0, r.t_end)),
        Axis::linear(t!("axis-displacement"), "m", y),
    );
    if let Some(upper) = envelope {
        let lower = upper.iter().map(|&(t, e)| (t, -e)).collect();
        let style = LineStyle::dashed(Ink::Vermillion, 1.5);
        fig = fig
            .with_line(t!("regimes-envelope"), upper, style)
            .with_line("", lower, style);
    }
    fig.with_line(
        t!("regimes-series-response", regime = format::regime(r.regime)),
        x,
        LineStyle::solid(Ink::Blue, 2.5),
    )
    .with_origin_lines()
    .described(text::describe(r))
}

/// The two poles, with the circle |s| = ωₙ on which underdamped poles move as ζ varies.
pub(super) fn poles(r: &Results) -> Figure {
    let wn = r.sys.natural_frequency().unwrap_or(0.0);
    let reach = r.poles.iter().map(|p| p.abs()).fold(wn, f64::max).max(1e-6) * 1.25;
    let [s1, s2] = r.poles;
    Figure::plot(
        t!("regimes-plot-poles"),
        // Wider than tall, like the canvas, so the circle |s| = ωₙ looks round.
        Axis::linear(t!("axis-real-part"), "1/s", (-1.35 * reach, 1.35 * reach)),
        Axis::linear(t!("axis-imaginary-part"), "rad/s", (-reach, reach)),
    )
    .with_line(
        "|s| = ωₙ",
        circle(wn, 180),
        LineStyle::dotted(Ink::Green, 1.5),
    )
    .with_marker(Marker::cross("s₁", (s1.re, s1.im), Ink::Vermillion))
    .with_marker(Marker::cross("s₂", (s2.re, s2.im), Ink::Vermillion))
    .with_origin_lines()
    .described(text::describe_poles(&r.poles))
}

/// The mass displaced `x` \[m\] at time `t` \[s\], drawn at `x / reach` of full travel.
pub(super) fn schematic(x: f64, reach: f64, t: f64) -> Figure {
    let labels = MassLabels::mkc("");
    let description = t!(
        "regimes-schematic",
        time = si(t, "s", 3),
        displacement = si(x, "m", 3)
    );
    mass_spring_damper(x / reach, 0.0, &labels, description)
}
