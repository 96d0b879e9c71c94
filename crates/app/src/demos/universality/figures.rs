//! The universality demo's figures: both machines' normalised free responses against
//! ωₙt and in real time, and both machines drawn side by side.

use super::params::Kind;
use super::{drawings, machine, text, One, Results};
use crate::figure::{Axis, Figure, LineStyle};
use crate::plot::{fit_range, Ink};
use crate::schematic::{mass_spring_damper, rlc_loop, MassLabels};
use crate::t;
use zeta_solver::grid::linspace;
use zeta_solver::{FreeResponse, SecondOrder};

/// Samples per curve on the normalised axis, and at least on the time axis.
const SAMPLES: usize = 600;
/// At most this many samples of a fast machine on A's time axis.
const MAX_SAMPLES: usize = 4000;

/// The free response of `one` released from rest at `y₀ = 1`.
fn released(one: &One) -> FreeResponse {
    FreeResponse::new(one.sys, 1.0, 0.0)
}

/// `y(t)/y₀` of `one` released from rest, at time `t` \[s\].
pub(super) fn normalised_at(one: &One, t: f64) -> f64 {
    released(one).displacement(t)
}

/// `"A: x/x₀"`.
fn legend(slot: &str, one: &One) -> String {
    format!("{slot}: {}", machine::normalised_coordinate(one.kind))
}

const STYLES: [LineStyle; 2] = [
    LineStyle::solid(Ink::Blue, 3.5),
    LineStyle::dashed(Ink::Vermillion, 2.0),
];

/// A y axis that holds −1…1 and the curves, with headroom for the legend.
fn response_axis(values: impl IntoIterator<Item = f64>) -> Axis {
    let (lo, hi) = fit_range(values.into_iter().chain([-0.2, 1.0]), 0.06, 0.5);
    Axis::linear(
        t!("universality-axis-response"),
        "",
        (lo, hi + 0.4 * (hi - lo)),
    )
}

/// y/y₀ of A and B against their own ωₙt, with the critically damped response for
/// reference: machines with equal ζ draw one curve.
pub(super) fn normalised(r: &Results) -> Figure {
    let curves: Vec<Vec<(f64, f64)>> =
        r.m.iter()
            .map(|one| {
                let (resp, wn) = (released(one), one.wn());
                // On its own clock: τ = ωₙt.
                let taus = linspace(0.0, r.tau_end, SAMPLES);
                let traced = resp.trace((0.0, r.tau_end / wn), SAMPLES);
                taus.into_iter()
                    .zip(traced)
                    .map(|(tau, (_, y))| (tau, y))
                    .collect()
            })
            .collect();
    let gap = curves[0]
        .iter()
        .zip(&curves[1])
        .map(|(a, b)| (a.1 - b.1).abs())
        .fold(0.0, f64::max);
    let critical = SecondOrder::from_natural(1.0, 1.0)
        .ok()
        .map(|sys| {
            let resp = FreeResponse::new(sys, 1.0, 0.0);
            resp.trace((0.0, r.tau_end), SAMPLES)
        })
        .unwrap_or_default();
    let y = response_axis(curves.iter().flatten().map(|p| p.1));
    let mut fig = Figure::plot(
        t!("universality-plot-normalised"),
        Axis::linear(t!("universality-axis-time"), "rad", (0.0, r.tau_end)),
        y,
    )
    .with_line(
        t!("universality-series-critical"),
        critical,
        LineStyle::dotted(Ink::Black, 1.5),
    );
    for (i, points) in curves.into_iter().enumerate() {
        fig = fig.with_line(legend(["A", "B"][i], &r.m[i]), points, STYLES[i]);
    }
    fig.with_origin_lines()
        .described(text::describe_normalised(&r.m, gap))
}

/// y/y₀ of A and B against time on A's clock: with equal ωₙ as well as ζ they coincide.
pub(super) fn realtime(r: &Results) -> Figure {
    let mut fig = Figure::plot(
        t!("universality-plot-realtime"),
        Axis::linear(t!("axis-time"), "s", (0.0, r.t_end)),
        Axis::linear("", "", (0.0, 1.0)),
    );
    let mut values = Vec::new();
    for (i, one) in r.m.iter().enumerate() {
        // Enough samples to follow a faster machine's swings, up to a cap.
        let periods = one.wn() * r.t_end / std::f64::consts::TAU;
        let n = ((20.0 * periods).ceil() as usize).clamp(SAMPLES, MAX_SAMPLES);
        let resp = released(one);
        let points = resp.trace((0.0, r.t_end), n);
        values.extend(points.iter().map(|p| p.1));
        fig = fig.with_line(legend(["A", "B"][i], one), points, STYLES[i]);
    }
    fig.y = response_axis(values);
    fig.with_origin_lines()
        .described(text::describe_realtime(&r.m, r.t_end))
}

/// One machine drawn at its normalised state `[y/y₀, y′/(y₀ωₙ)]`.
fn drawing(one: &One, state: [f64; 2]) -> Figure {
    let [y, rate] = state;
    match one.kind {
        Kind::MassSpring => {
            let labels = MassLabels::mkc("");
            mass_spring_damper(y, 0.0, &labels, String::new())
        }
        Kind::Rlc => rlc_loop(rate, y, String::new()),
        Kind::UTube => drawings::u_tube(y),
        Kind::Servo => drawings::servo(y),
        Kind::Storey => drawings::storey(y),
        // T₁ = T₂ + R₂C₂·T₂′ (the second body warms or cools only through the first).
        Kind::Thermal => drawings::thermal(y + one.v.r2 * one.v.c2 * rate * one.wn(), y),
    }
}

/// A and B side by side at time `t` \[s\], each released from rest at `t = 0`.
pub(super) fn schematic(m: &[One; 2], t: f64) -> Figure {
    let states = m.each_ref().map(|one| {
        let [y, v] = released(one).state(t);
        [y, v / one.wn()]
    });
    let mut fig = drawings::side_by_side(
        drawing(&m[0], states[0]),
        drawing(&m[1], states[1]),
        0.6,
        ["A", "B"],
    );
    fig.title = t!("universality-schematic-title");
    fig.described(text::describe_schematic(m, t, [states[0][0], states[1][0]]))
}
