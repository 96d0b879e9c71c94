//! The quarter-car demo's other figures: settling time against ζ, the damping ratio as
//! the sprung mass varies, and the animated car.

use super::{text, Car, Results};
use crate::figure::{finite_extent, padded, Axis, Figure, LineStyle, Marker};
use crate::format::si;
use crate::plot::{curve, Ink};
use crate::schematic::{mass_spring_damper, MassLabels};
use crate::t;

pub(super) const SETTLING_TITLE: &str = "Free-response settling time against ζ";
pub(super) const SENSITIVITY_TITLE: &str = "ζ when the sprung mass varies";

/// Samples of the mass-sensitivity curve.
const STRIP_POINTS: usize = 60;

/// Settling time against ζ, broken at its jumps, with the fastest ζ and this design.
pub(super) fn settling(r: &Results) -> Figure {
    let zeta = r.car.zeta();
    let ts_now = r.metrics.and_then(|m| m.settling_time);
    // Show the interesting part: up to the slower of ζ = 2, this design and 4× the best.
    let best = r.optimum.map_or(f64::NAN, |o| o.settling_time);
    let y_top = finite_extent([r.sweep.at_two, 4.0 * best, ts_now.unwrap_or(f64::NAN)])
        .map_or(1.0, |(_, hi)| 1.12 * hi);
    let points: Vec<(f64, f64)> = r
        .sweep
        .points
        .iter()
        .map(|&(z, t)| {
            if t <= y_top {
                (z, t)
            } else {
                (f64::NAN, f64::NAN)
            }
        })
        .collect();
    let band = text::pct(r.car.band_pct);
    // One curve, named by the axes and the title: no legend box to hide it.
    let mut fig = Figure::plot(
        t!("quarter-car-settling-title", band = band),
        Axis::linear(t!("quarter-car-axis-zeta"), "", (0.0, r.sweep.z_hi)),
        Axis::linear(t!("quarter-car-axis-settling-time"), "s", (0.0, y_top)),
    )
    .with_line("", points, LineStyle::solid(Ink::Blue, 2.5));
    if let Some(o) = r.optimum {
        fig = fig.with_marker(Marker::cross(
            t!("quarter-car-fastest", zeta = si(o.zeta, "", 3)),
            (o.zeta, o.settling_time),
            Ink::Vermillion,
        ));
    }
    if let Some(ts) = ts_now {
        fig = fig.with_marker(Marker::dot(
            t!("quarter-car-this-design"),
            (zeta, ts),
            Ink::Black,
        ));
    }
    fig.described(text::describe_settling(r))
}

/// ζ of this spring and damper as the sprung mass varies by ±dm, against the fastest ζ.
pub(super) fn sensitivity(r: &Results) -> Figure {
    let car = &r.car;
    let x = car.dm_pct / 100.0;
    let (m_lo, m_hi) = (car.m * (1.0 - x), car.m * (1.0 + x));
    let points: Vec<(f64, f64)> = curve((m_lo, m_hi), STRIP_POINTS, |m| car.zeta_at_mass(m))
        .into_iter()
        .map(|(m, z)| (z, m))
        .collect();
    let zeta = car.zeta();
    let z_opt = r.optimum.map(|o| o.zeta);
    let (z_min, z_max) = r.mass_spread.map_or((zeta, zeta), |s| (s.min, s.max));
    let (xl, xh) = finite_extent([z_min, z_max, zeta, z_opt.unwrap_or(zeta)]).map_or(
        (0.0, 1.0),
        |(lo, hi)| {
            let span = (hi - lo).max(0.02 * hi.abs()).max(1e-6);
            // Room on the right for the marker labels, which are drawn right of their point.
            (lo - 0.1 * span, hi + 0.3 * span)
        },
    );
    let y = padded((m_lo.min(car.m), m_hi.max(car.m)), 0.25);
    let x_label = match z_opt {
        Some(z) => t!("quarter-car-axis-zeta-fastest", zeta = si(z, "", 3)),
        None => t!("quarter-car-axis-zeta"),
    };
    // No legend box (it would cover the curve): the axes name the curve, labels the rest.
    let mut fig = Figure::plot(
        t!("quarter-car-plot-sensitivity"),
        Axis::linear(x_label, "", (xl, xh)),
        Axis::linear(t!("quarter-car-axis-sprung-mass"), "kg", y),
    )
    .with_line("", points, LineStyle::solid(Ink::Blue, 3.0));
    if let Some(z) = z_opt {
        fig = fig.with_line(
            "",
            vec![(z, y.0), (z, y.1)],
            LineStyle::dashed(Ink::Vermillion, 1.5),
        );
    }
    let dm = text::pct(car.dm_pct);
    fig.with_marker(Marker::dot(
        t!("quarter-car-nominal"),
        (zeta, car.m),
        Ink::Black,
    ))
    .with_marker(Marker::cross(
        format!("m − {dm}"),
        (car.zeta_at_mass(m_lo), m_lo),
        Ink::Blue,
    ))
    .with_marker(Marker::cross(
        format!("m + {dm}"),
        (car.zeta_at_mass(m_hi), m_hi),
        Ink::Blue,
    ))
    .described(text::describe_sensitivity(r, (m_lo, m_hi)))
}

/// The car with its body displaced `x` \[m\] at time `t` \[s\], drawn at `x/x₀` of full travel.
pub(super) fn schematic(car: &Car, x: f64, t: f64) -> Figure {
    let road = t!("quarter-car-road");
    let labels = MassLabels::mkc(&road);
    mass_spring_damper(
        x / car.x0.abs().max(1e-12),
        0.0,
        &labels,
        text::describe_schematic(x, t),
    )
}
