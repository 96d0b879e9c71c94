//! The stability plot: the regions `|R(z)| ≤ 1` of Euler, Heun and RK4 and the system's
//! `z = hλ`, with the path `z = h'λ` as the step grows.

use super::figures::LOOKS;
use super::text::limit_text;
use super::{h_lambda, text, Results, P};
use crate::figure::{Axis, Figure, LineStyle, Marker, Series};
use crate::format::si;
use crate::plot::Ink;
use crate::t;
use zeta_solver::Complex;

pub(super) const TITLE: &str = "Stability regions and z = hλ";

/// Fixed-step methods with a region (in readout order): forward Euler, Heun, RK4.
const WITH_REGION: [usize; 3] = [0, 2, 3];
/// The plot grows to show hλ up to this far from the origin.
const LIMIT: f64 = 12.0;

/// The regions, the poles' `hλ` and the path along which they move as h grows.
pub(super) fn figure(p: &P, r: &Results, regions: &[Vec<(f64, f64)>]) -> Figure {
    let mut series = Vec::new();
    for (outline, &k) in regions.iter().zip(&WITH_REGION) {
        if !p.show[k] {
            continue;
        }
        series.push(Series::new(
            LOOKS[k].legend(),
            outline.clone(),
            LineStyle {
                width: 2.0,
                ..LOOKS[k].style
            },
        ));
    }
    // The regions do not depend on the system: a backdrop.
    let backdrop = series.len();
    let z = h_lambda(r);
    let (x, y) = window(&z);
    let mut markers = Vec::new();
    let same = z.len() == 2 && z[0] == z[1];
    for (i, q) in z.iter().enumerate() {
        if same && i == 1 {
            continue;
        }
        let off = q.re < x.0 || q.re > x.1 || q.im < y.0 || q.im > y.1;
        let at = (q.re.clamp(x.0, x.1), q.im.clamp(y.0, y.1));
        let name = if same {
            "hλ₁,₂"
        } else if i == 0 {
            "hλ₁"
        } else {
            "hλ₂"
        };
        let label = if off {
            t!(
                "integrators-off-scale",
                name = name,
                value = si(q.re, "", 3)
            )
        } else {
            name.into()
        };
        markers.push(Marker::cross(label, at, Ink::Black));
        // The path z = h'λ for 0 < h' ≤ h, along which z moves as h grows.
        series.push(Series::new(
            if i == 0 {
                t!("integrators-path")
            } else {
                String::new()
            },
            (0..=50)
                .map(|j| {
                    let s = *q * (j as f64 / 50.0);
                    (s.re, s.im)
                })
                .collect(),
            LineStyle::dotted(Ink::Sky, 1.5),
        ));
    }
    Figure {
        series,
        backdrop,
        markers,
        ..Figure::plot(
            t!("integrators-plot-stability"),
            Axis::linear(t!("integrators-axis-re"), "", x),
            Axis::linear(t!("integrators-axis-im"), "", y),
        )
    }
    .with_origin_lines()
    .described(describe(r, &z, same))
}

/// A window that holds every region and grows to show `z`, up to [`LIMIT`], with roughly
/// equal scales on both axes (the canvas is 1.3 : 1).
fn window(z: &[Complex]) -> ((f64, f64), (f64, f64)) {
    let mut x = (-3.2f64, 1.0f64);
    let mut y = (-3.2f64, 3.2f64);
    for q in z {
        x = (
            x.0.min(q.re * 1.15).max(-LIMIT),
            x.1.max(q.re * 1.15).min(LIMIT),
        );
        y = (
            y.0.min(q.im * 1.15).max(-LIMIT),
            y.1.max(q.im * 1.15).min(LIMIT),
        );
    }
    let (w, hgt) = (x.1 - x.0, y.1 - y.0);
    if w < 1.3 * hgt {
        let pad = 0.5 * (1.3 * hgt - w);
        // Most of the widening goes right, where the legend sits.
        x = (x.0 - pad * 0.2, x.1 + pad * 1.8);
    } else {
        let pad = 0.5 * (w / 1.3 - hgt);
        y = (y.0 - pad, y.1 + pad);
    }
    (x, y)
}

fn describe(r: &Results, z: &[Complex], same: bool) -> String {
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
        t!(
            "integrators-z-real-pair",
            z1 = si(z[0].re, "", 3),
            z2 = si(z[1].re, "", 3)
        )
    };
    let words: Vec<String> = WITH_REGION
        .iter()
        .map(|&k| {
            let (method, growth, limit) = (
                LOOKS[k].name(),
                si(r.growth[k], "", 4),
                limit_text(r.limit[k]),
            );
            if r.growth[k] <= 1.0 {
                t!(
                    "integrators-region-inside",
                    method = method,
                    growth = growth,
                    limit = limit
                )
            } else {
                t!(
                    "integrators-region-outside",
                    method = method,
                    growth = growth,
                    limit = limit
                )
            }
        })
        .collect();
    t!(
        "integrators-describe-stability",
        step = si(r.h, "s", 3),
        z = zs,
        methods = text::join(&words),
        radius = si(r.growth[1], "", 4),
        limit = limit_text(r.limit[1])
    )
}
