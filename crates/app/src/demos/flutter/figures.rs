//! The flutter demo's plots: effective damping against wind speed, the root locus as the
//! wind rises, and the deck's twist over time.

use super::{text, Results, LOCUS_SAMPLES, SAMPLES, U_MAX};
use crate::figure::{finite_extent, padded, Axis, Figure, LineStyle, Marker};
use crate::format::si;
use crate::plot::{curve, Ink};
use zeta_solver::flutter::degrees;

pub(super) const DAMPING_TITLE: &str = "Effective damping against wind speed";
pub(super) const LOCUS_TITLE: &str = "Root locus as the wind rises";
pub(super) const RESPONSE_TITLE: &str = "Deck twist θ(t)";

/// ζ_eff(U) from calm air to [`U_MAX`], the current wind marked, the critical speed drawn.
pub(super) fn damping(r: &Results) -> Figure {
    let m = &r.model;
    let line = curve((0.0, U_MAX), LOCUS_SAMPLES, |u| m.effective_damping(u));
    let (lo, hi) = finite_extent(line.iter().map(|p| p.1).chain([0.0])).unwrap_or((-0.01, 0.01));
    let y = padded((lo, hi.max(lo + 1e-4)), 0.1);
    let mut fig = Figure::plot(
        DAMPING_TITLE,
        Axis::linear("wind speed U", "m/s", (0.0, U_MAX)),
        Axis::linear("effective damping ratio ζ_eff", "", y),
    )
    .with_line(
        "ζ_eff(U) = ζ_s − g·U",
        line,
        LineStyle::solid(Ink::Blue, 2.5),
    )
    .with_marker(Marker::dot(
        format!("U = {}", si(r.u, "m/s", 3)),
        (r.u, r.zeta),
        Ink::Vermillion,
    ));
    if let Some(uc) = m.critical_speed().filter(|&uc| uc <= U_MAX) {
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

/// The upper pole of each locus sample `(Re s, Im s)`.
fn upper_branch(r: &Results) -> Vec<(f64, f64)> {
    r.locus
        .iter()
        .map(|p| {
            let s = if p.poles[0].im >= p.poles[1].im {
                p.poles[0]
            } else {
                p.poles[1]
            };
            (s.re, s.im)
        })
        .collect()
}

/// The pole pair from calm air to [`U_MAX`], with the poles at the current wind and the
/// crossing at the critical speed.
pub(super) fn locus(r: &Results) -> Figure {
    let m = &r.model;
    let upper = upper_branch(r);
    let lower: Vec<(f64, f64)> = upper.iter().map(|&(re, im)| (re, -im)).collect();
    let w = m.config().omega;
    let (re_lo, re_hi) =
        finite_extent(upper.iter().map(|p| p.0).chain([0.0])).unwrap_or((-0.01 * w, 0.01 * w));
    let x = padded((re_lo, re_hi.max(re_lo + 1e-6 * w)), 0.15);
    // Taller above than below, so the legend in the upper right clears the upper branch.
    let y = (-1.5 * w, 2.2 * w);
    let start = upper.first().copied();
    let description = text::describe_locus(r, start.map_or(f64::NAN, |p| p.0));
    let mut fig = Figure::plot(
        LOCUS_TITLE,
        Axis::linear("real part Re s", "1/s", x),
        Axis::linear("imaginary part Im s", "rad/s", y),
    )
    .with_line("upper pole", upper, LineStyle::solid(Ink::Blue, 2.5))
    .with_line("lower pole", lower, LineStyle::dashed(Ink::Blue, 2.5));
    if let Some(start) = start {
        fig = fig.with_marker(Marker::dot("U = 0", start, Ink::Green));
    }
    if let Ok(poles) = m.poles(r.u) {
        for (i, s) in poles.iter().enumerate() {
            let label = if i == 0 {
                format!("U = {}", si(r.u, "m/s", 3))
            } else {
                String::new()
            };
            fig = fig.with_marker(Marker::cross(label, (s.re, s.im), Ink::Vermillion));
        }
    }
    if let Some(wd) = text::crossing_frequency(r) {
        fig = fig.with_marker(Marker::dot("U_crit", (0.0, -wd), Ink::Purple));
    }
    fig.with_origin_lines().described(description)
}

/// θ(t) in degrees over the window, inside its envelope ±A·e^(σt).
pub(super) fn response(r: &Results) -> Figure {
    let m = &r.model;
    let x = Axis::linear("time t", "s", (0.0, r.t_end));
    let Ok(resp) = m.response(r.u, r.theta0, 0.0) else {
        return Figure::plot(RESPONSE_TITLE, x, Axis::linear("twist θ", "°", (-1.0, 1.0)))
            .described("No response: invalid parameters.");
    };
    let theta = curve((0.0, r.t_end), SAMPLES, |t| degrees(resp.displacement(t)));
    let envelope = |sign: f64| {
        curve((0.0, r.t_end), 101, |t| {
            degrees(sign * m.envelope(r.u, r.theta0, t))
        })
    };
    let amp = m.envelope_amplitude(r.u, r.theta0);
    let end_factor = m.growth_factor(r.u, r.t_end);
    let (lo, hi) = finite_extent(
        theta
            .iter()
            .map(|p| p.1)
            .chain([degrees(amp) * end_factor.max(1.0)]),
    )
    .unwrap_or((-1.0, 1.0));
    let reach = lo.abs().max(hi.abs()).max(1e-9);
    // Head room for the legend above the curve.
    let y = (-1.15 * reach, 1.5 * reach);
    let style = LineStyle::dashed(Ink::Vermillion, 1.5);
    Figure::plot(RESPONSE_TITLE, x, Axis::linear("twist θ", "°", y))
        .with_line("envelope ±A·e^(σt)", envelope(1.0), style)
        .with_line("", envelope(-1.0), style)
        .with_line(
            format!("θ(t), U = {}", si(r.u, "m/s", 3)),
            theta,
            LineStyle::solid(Ink::Blue, 2.0),
        )
        .with_origin_lines()
        .described(text::describe_response(r, end_factor))
}
