//! The flutter demo's plots: `A₂*` against reduced velocity, `ζ_eff(U)`, the root locus and
//! the twist over minutes.

use super::{text, Aero, Results, Section, U_MAX};
use crate::figure::{finite_extent, padded, Axis, Figure, LineStyle, Marker};
use crate::format::si;
use crate::plot::{fit_range, thin, zip, Ink};
use crate::t;
use zeta_solver::flutter::{degrees, DeckSection};

/// Most points drawn of the twist history.
const TWIST_POINTS: usize = 4000;

/// The look of each kind of line, the same in every plot: the chosen model's curve (the
/// lower pole is its mirror image, dashed), the curve compared with it, and the
/// thresholds (the A₂* threshold, the limit cycle).
const CURVE: LineStyle = LineStyle::solid(Ink::Blue, 2.5);
const MIRROR: LineStyle = LineStyle::dashed(Ink::Blue, 2.5);
const COMPARED: LineStyle = LineStyle::dashed(Ink::Green, 1.5);
const THRESHOLD: LineStyle = LineStyle::dotted(Ink::Purple, 1.5);

/// `A₂*` above which the wind's moment beats the structural damping, to first order:
/// `4Iζ_s/(ρB⁴) = 2ζ_s/q`.
pub(super) fn threshold(r: &Results) -> f64 {
    2.0 * r.p.zeta_s / r.model.aero_factor()
}

/// `A₂*` along the plotted wind range (for the simplest picture, the `A₂*` it amounts
/// to), the other section for comparison, the threshold and the current point.
pub(super) fn derivative(r: &Results) -> Figure {
    let along: Vec<(f64, f64)> = r.locus.iter().map(|s| (s.reduced_velocity, s.a2)).collect();
    let h_section = || t!("flutter-series-h-section");
    let streamlined = || t!("flutter-series-box");
    let (label, other) = match (r.p.aero, r.p.section) {
        (Aero::Simplest, _) => (
            t!("flutter-series-simplest"),
            (DeckSection::HSection, h_section()),
        ),
        (Aero::Derivatives, Section::H) => {
            (h_section(), (DeckSection::StreamlinedBox, streamlined()))
        }
        (Aero::Derivatives, Section::Box) => (streamlined(), (DeckSection::HSection, h_section())),
    };
    let table = other.0.table();
    let x_hi = along.iter().map(|p| p.0).fold(16.0, f64::max) * 1.05;
    let others: Vec<(f64, f64)> = zip(table.reduced_velocity, table.a2)
        .into_iter()
        .filter(|p| p.0 <= x_hi)
        .collect();
    let a2_crit = threshold(r);
    let y = fit_range(
        along
            .iter()
            .chain(&others)
            .map(|p| p.1)
            .chain([a2_crit, 0.0]),
        0.08,
        0.05,
    );
    let y = (y.0, y.1 + 0.25 * (y.1 - y.0)); // room for the legend
    let mut fig = Figure::plot(
        t!("flutter-plot-derivative"),
        Axis::linear(t!("flutter-axis-reduced-velocity"), "", (0.0, x_hi)),
        Axis::linear("A₂*", "", y),
    )
    .with_line(other.1, others, COMPARED)
    .with_line(
        t!("flutter-threshold", value = si(a2_crit, "", 3)),
        vec![(0.0, a2_crit), (x_hi, a2_crit)],
        THRESHOLD,
    )
    .with_line(label, along, CURVE);
    if let Some(s) = r.state {
        fig = fig.with_marker(Marker::dot(
            format!(
                "U = {}: K = {}",
                si(r.p.u, "m/s", 3),
                text::reduced_frequency(&s)
            ),
            (s.reduced_velocity, s.a2),
            Ink::Vermillion,
        ));
    }
    fig.with_origin_lines()
        .described(text::describe_derivative(r, a2_crit))
}

/// ζ_eff(U) in percent from calm air to [`U_MAX`], the current wind marked, the critical
/// speed drawn; with flutter derivatives, the simplest picture's straight line for
/// comparison.
pub(super) fn damping(r: &Results) -> Figure {
    let line: Vec<(f64, f64)> = r
        .locus
        .iter()
        .map(|s| (s.wind_speed, 100.0 * s.damping_ratio()))
        .collect();
    let simplest = (r.p.aero == Aero::Derivatives).then(|| {
        vec![
            (0.0, 100.0 * r.p.zeta_s),
            (U_MAX, 100.0 * (r.p.zeta_s - r.p.slope * U_MAX)),
        ]
    });
    let values = line
        .iter()
        .chain(simplest.iter().flatten())
        .map(|p| p.1)
        .chain([0.0]);
    let (lo, hi) = finite_extent(values).unwrap_or((-1.0, 1.0));
    let mut y = padded((lo, hi.max(lo + 1e-2)), 0.1);
    y.1 += 0.3 * (y.1 - y.0); // room for the legend
    let mut fig = Figure::plot(
        t!("flutter-plot-damping"),
        Axis::linear(t!("flutter-axis-wind-speed"), "m/s", (0.0, U_MAX)),
        Axis::linear(t!("flutter-axis-effective-damping"), "%", y),
    );
    if let Some(s) = simplest {
        fig = fig.with_line(t!("flutter-series-simplest-line"), s, COMPARED);
    }
    fig = fig.with_line("ζ_eff(U)", line, CURVE);
    if let Some(s) = r.state {
        fig = fig.with_marker(Marker::dot(
            format!("U = {}", si(r.p.u, "m/s", 3)),
            (r.p.u, 100.0 * s.damping_ratio()),
            Ink::Vermillion,
        ));
    }
    if let Some(uc) = r.u_crit.filter(|&uc| uc <= U_MAX) {
        fig = fig
            .with_line(
                format!("U_crit = {}", si(uc, "m/s", 3)),
                vec![(uc, y.0), (uc, y.1)],
                LineStyle::dashed(Ink::Purple, 1.5),
            )
            .with_marker(Marker::cross("", (uc, 0.0), Ink::Purple));
    }
    fig.with_origin_lines().described(text::describe_damping(r))
}

/// The pole pair from calm air to [`U_MAX`], the poles at the current wind and the
/// crossing at the critical speed.
pub(super) fn locus(r: &Results) -> Figure {
    let upper: Vec<(f64, f64)> = r.locus.iter().map(|s| (s.growth_rate(), s.omega)).collect();
    let lower: Vec<(f64, f64)> = upper.iter().map(|&(re, im)| (re, -im)).collect();
    let w = r.model.still_air_omega();
    let (re_lo, re_hi) =
        finite_extent(upper.iter().map(|p| p.0).chain([0.0])).unwrap_or((-0.01 * w, 0.01 * w));
    let x = padded((re_lo, re_hi.max(re_lo + 1e-6 * w)), 0.15);
    // Taller above than below, so the legend in the upper right clears the upper branch.
    let y = (-1.5 * w, 2.2 * w);
    let mut fig = Figure::plot(
        t!("flutter-plot-locus"),
        Axis::linear(t!("axis-real-part"), "1/s", x),
        Axis::linear(t!("axis-imaginary-part"), "rad/s", y),
    );
    if let Some(&start) = upper.first() {
        fig = fig.with_marker(Marker::dot("U = 0", start, Ink::Green));
    }
    fig = fig
        .with_line(t!("flutter-upper-pole"), upper, CURVE)
        .with_line(t!("flutter-lower-pole"), lower, MIRROR);
    if let Some(s) = r.state {
        let [p1, p2] = s.poles();
        fig = fig
            .with_marker(Marker::cross(
                format!("U = {}", si(r.p.u, "m/s", 3)),
                (p1.re, p1.im),
                Ink::Vermillion,
            ))
            .with_marker(Marker::cross("", (p2.re, p2.im), Ink::Vermillion));
    }
    if let Some(wd) = text::crossing_frequency(r) {
        fig = fig.with_marker(Marker::dot("U_crit", (0.0, -wd), Ink::Purple));
    }
    fig.with_origin_lines().described(text::describe_locus(r))
}

/// θ(t) in degrees over the window (in minutes), inside its amplitude ±a(t), with the
/// limit cycle where there is one.
pub(super) fn response(r: &Results) -> Figure {
    let h = &r.history;
    let minutes: Vec<f64> = h.t.iter().map(|t| t / 60.0).collect();
    let deg =
        |xs: &[f64], sign: f64| -> Vec<f64> { xs.iter().map(|&x| sign * degrees(x)).collect() };
    let theta = thin(&zip(&minutes, &deg(&h.theta, 1.0)), TWIST_POINTS);
    let upper = thin(&zip(&minutes, &deg(&h.amplitude, 1.0)), TWIST_POINTS / 4);
    let lower = thin(&zip(&minutes, &deg(&h.amplitude, -1.0)), TWIST_POINTS / 4);
    let t_end = r.window / 60.0;
    let limit = r.limit.map(degrees);
    let reach = upper
        .iter()
        .map(|p| p.1)
        .chain(limit)
        .fold(r.p.theta0_deg, f64::max)
        .max(1e-6);
    // Head room for the legend above the curve.
    let y = (-1.15 * reach, 1.9 * reach);
    let envelope = LineStyle::dashed(Ink::Vermillion, 1.5);
    let mut fig = Figure::plot(
        t!("flutter-plot-response"),
        Axis::linear(t!("axis-time"), "min", (0.0, t_end)),
        Axis::linear(t!("flutter-axis-twist"), "°", y),
    )
    .with_line(
        format!("θ(t), U = {}", si(r.p.u, "m/s", 3)),
        theta,
        LineStyle::solid(Ink::Blue, 1.0),
    )
    .with_line(t!("flutter-amplitude"), upper, envelope)
    .with_line("", lower, envelope);
    if let Some(lc) = limit {
        fig = fig.with_line(
            t!("flutter-limit-cycle", amplitude = si(lc, "°", 3)),
            vec![(0.0, lc), (t_end, lc)],
            THRESHOLD,
        );
    }
    fig.with_origin_lines()
        .described(text::describe_response(r))
}
