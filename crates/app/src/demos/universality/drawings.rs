//! Schematics of the machines the shared `crate::schematic` does not draw: a U-tube
//! manometer, a DC-motor servo, a building storey and a two-capacity thermal system, and
//! two drawings placed side by side. Each takes the machine's normalised coordinate
//! (`y/y₀`, about −1…1) and draws in the frame of `crate::schematic::mass_spring_damper`
//! (x −1.6…1.6, y −0.6…3.6, drawing units).

// Drawing geometry (arcs, rotated pointers, bent columns), not model maths.
#![allow(clippy::disallowed_methods)]

use crate::figure::{Axis, Figure, LineStyle, Marker};
use crate::plot::{circle, Ink};
use crate::schematic::{rect, spring};

const X: (f64, f64) = (-1.6, 1.6);
const Y: (f64, f64) = (-0.6, 3.6);

fn frame() -> Figure {
    Figure::schematic(
        "Schematic",
        Axis::linear("", "", X),
        Axis::linear("", "", Y),
    )
}

/// Finite and within `±limit`; 0 otherwise.
fn bounded(v: f64, limit: f64) -> f64 {
    if v.is_finite() {
        v.clamp(-limit, limit)
    } else {
        0.0
    }
}

fn ink(fig: Figure, points: Vec<(f64, f64)>, ink: Ink, width: f64) -> Figure {
    fig.with_line("", points, LineStyle::solid(ink, width))
}

fn dashed(fig: Figure, points: Vec<(f64, f64)>) -> Figure {
    fig.with_line("", points, LineStyle::dashed(Ink::Black, 1.0))
}

fn label(fig: Figure, text: &str, at: (f64, f64)) -> Figure {
    fig.with_marker(Marker::text(text, at, Ink::Black))
}

/// A hatched ground line from `x0` to `x1` at height `y`.
fn ground(mut fig: Figure, x0: f64, x1: f64, y: f64) -> Figure {
    fig = ink(fig, vec![(x0, y), (x1, y)], Ink::Black, 2.5);
    let n = ((x1 - x0) / 0.3).floor() as usize;
    for i in 0..n {
        let x = x0 + 0.1 + 0.3 * i as f64;
        fig = ink(fig, vec![(x, y), (x - 0.18, y - 0.22)], Ink::Black, 1.0);
    }
    fig
}

/// The lower half of a circle of radius `r` about `(0, cy)`, from left to right.
fn lower_arc(r: f64, cy: f64) -> Vec<(f64, f64)> {
    (0..=48)
        .map(|i| {
            let th = std::f64::consts::PI * (1.0 + i as f64 / 48.0);
            (r * th.cos(), cy + r * th.sin())
        })
        .collect()
}

/// A U-tube whose left level stands `h` (normalised) above rest and the right one as far
/// below.
pub(super) fn u_tube(h: f64) -> Figure {
    let h = bounded(h, 1.2);
    let (rest, swing, bend) = (2.0, 0.8, 0.6);
    let (left, right) = (rest + swing * h, rest - swing * h);
    let wall = |r: f64| {
        let mut p = vec![(-r, 3.2), (-r, bend)];
        p.extend(lower_arc(r, bend));
        p.extend([(r, bend), (r, 3.2)]);
        p
    };
    let mut liquid = vec![(-0.8, left), (-0.8, bend)];
    liquid.extend(lower_arc(0.8, bend));
    liquid.extend([(0.8, bend), (0.8, right)]);
    let mut fig = frame();
    fig = ink(fig, liquid, Ink::Sky, 9.0);
    fig = ink(fig, wall(1.0), Ink::Black, 2.0);
    fig = ink(fig, wall(0.6), Ink::Black, 2.0);
    fig = ink(fig, vec![(-1.0, left), (-0.6, left)], Ink::Blue, 3.0);
    fig = ink(fig, vec![(0.6, right), (1.0, right)], Ink::Blue, 3.0);
    fig = dashed(fig, vec![(-1.4, rest), (1.4, rest)]);
    fig = label(fig, "h", (-1.45, left + 0.1));
    fig = label(fig, "ρ, μ", (-0.25, 1.1));
    label(fig, "d", (1.1, 3.0))
}

/// A motor driven by a PD controller, turning a disc whose pointer is `theta`
/// (normalised; 1 is drawn as 1 rad) from the set point.
pub(super) fn servo(theta: f64) -> Figure {
    let th = bounded(theta, 1.5);
    let centre = (0.75, 1.5);
    let disc: Vec<(f64, f64)> = circle(0.65, 72)
        .into_iter()
        .map(|(x, y)| (x + centre.0, y + centre.1))
        .collect();
    let at = |angle: f64, r: f64| (centre.0 + r * angle.cos(), centre.1 + r * angle.sin());
    let up = std::f64::consts::FRAC_PI_2;
    let mut fig = frame();
    fig = ink(fig, rect((-0.85, 1.5), 0.9, 0.8), Ink::Green, 3.0);
    fig = ink(fig, vec![(-0.4, 1.5), (0.1, 1.5)], Ink::Black, 3.0);
    fig = ink(fig, disc, Ink::Blue, 2.5);
    fig = dashed(fig, vec![centre, at(up, 0.85)]);
    fig = ink(fig, vec![centre, at(up - th, 0.6)], Ink::Vermillion, 4.0);
    fig = ink(fig, rect((-0.85, 3.0), 1.1, 0.6), Ink::Purple, 2.0);
    fig = ink(fig, vec![(-0.85, 2.7), (-0.85, 1.9)], Ink::Black, 1.5);
    fig = label(fig, "M", (-0.95, 1.45));
    fig = label(fig, "PD", (-1.0, 2.95));
    fig = label(fig, "V", (-0.75, 2.3));
    fig = label(fig, "J", (1.45, 0.85));
    label(fig, "θ", (at(up, 0.95).0 - 0.05, at(up, 0.95).1))
}

/// A floor on two (of its four) clamped columns over moving ground, drifted `u`
/// (normalised) to the side; the columns bend in the clamped–clamped shape 3s² − 2s³.
pub(super) fn storey(u: f64) -> Figure {
    let d = 0.5 * bounded(u, 1.2);
    let top = 2.6;
    let column = |x: f64| -> Vec<(f64, f64)> {
        (0..=24)
            .map(|i| {
                let s = i as f64 / 24.0;
                (x + d * (3.0 * s * s - 2.0 * s * s * s), top * s)
            })
            .collect()
    };
    let mut fig = frame();
    fig = ground(fig, -1.5, 1.5, 0.0);
    fig = dashed(fig, vec![(-1.0, 0.0), (-1.0, top)]);
    fig = dashed(fig, vec![(1.0, 0.0), (1.0, top)]);
    fig = ink(fig, column(-1.0), Ink::Blue, 3.0);
    fig = ink(fig, column(1.0), Ink::Blue, 3.0);
    fig = ink(fig, rect((d, top + 0.18), 2.5, 0.36), Ink::Green, 3.0);
    fig = label(fig, "m", (d - 0.1, top + 0.2));
    fig = label(fig, "EI", (-0.9 + d, 1.2));
    fig = label(fig, "h", (-1.5, 1.3));
    fig = label(fig, "c", (0.25 + d, 1.7));
    label(fig, "x_g(t)", (-1.6, 0.35))
}

/// A horizontal resistor zigzag from `x0` to `x1` at height `y`.
fn resistor(x0: f64, x1: f64, y: f64) -> Vec<(f64, f64)> {
    spring(y, x0, x1, 3, 0.12)
        .into_iter()
        .map(|(a, b)| (b, a))
        .collect()
}

/// Two bodies in a chain from the surroundings, each with a bar showing its temperature
/// above the surroundings, `t1` and `t2` normalised to the initial excess.
pub(super) fn thermal(t1: f64, t2: f64) -> Figure {
    let (y, h) = (1.6, 1.4);
    let bar = |x: f64, t: f64| {
        let base = y - h / 2.0 + 0.1;
        vec![(x, base), (x, base + bounded(t, 1.1).max(0.0) * (h - 0.2))]
    };
    let mut fig = frame();
    // The surroundings: a hatched wall on the left.
    fig = ink(fig, vec![(-1.5, 0.6), (-1.5, 2.6)], Ink::Black, 2.5);
    for i in 0..7 {
        let yy = 0.7 + 0.3 * i as f64;
        fig = ink(fig, vec![(-1.5, yy), (-1.7, yy - 0.15)], Ink::Black, 1.0);
    }
    fig = ink(fig, resistor(-1.5, -1.0, y), Ink::Black, 2.0);
    fig = ink(fig, rect((-0.55, y), 0.9, h), Ink::Orange, 3.0);
    fig = ink(fig, resistor(-0.1, 0.5, y), Ink::Black, 2.0);
    fig = ink(fig, rect((0.95, y), 0.9, h), Ink::Orange, 3.0);
    fig = ink(fig, bar(-0.55, t1), Ink::Vermillion, 8.0);
    fig = ink(fig, bar(0.95, t2), Ink::Vermillion, 8.0);
    fig = label(fig, "R₁", (-1.4, y + 0.35));
    fig = label(fig, "C₁", (-0.7, y + h / 2.0 + 0.25));
    fig = label(fig, "R₂", (0.05, y + 0.35));
    fig = label(fig, "C₂", (0.8, y + h / 2.0 + 0.25));
    fig = label(fig, "T₁", (-0.7, y - h / 2.0 - 0.3));
    label(fig, "T₂", (0.8, y - h / 2.0 - 0.3))
}

/// `right` drawn to the right of `left`, `gap` apart, centred on the same height, with
/// the names `names` over each; ranges widened to hold both.
pub(super) fn side_by_side(mut left: Figure, right: Figure, gap: f64, names: [&str; 2]) -> Figure {
    let mid = |r: (f64, f64)| 0.5 * (r.0 + r.1);
    let dx = left.x.range.1 + gap - right.x.range.0;
    let dy = mid(left.y.range) - mid(right.y.range);
    let top = left.y.range.1.max(right.y.range.1 + dy);
    left.markers.push(Marker::text(
        names[0],
        (mid(left.x.range) - 0.1, top + 0.2),
        Ink::Black,
    ));
    left.markers.push(Marker::text(
        names[1],
        (mid(right.x.range) + dx - 0.1, top + 0.2),
        Ink::Black,
    ));
    for mut s in right.series {
        for p in &mut s.points {
            *p = (p.0 + dx, p.1 + dy);
        }
        left.series.push(s);
    }
    for mut m in right.markers {
        m.at = (m.at.0 + dx, m.at.1 + dy);
        left.markers.push(m);
    }
    left.x.range = (left.x.range.0, left.x.range.1.max(right.x.range.1 + dx));
    left.y.range = (left.y.range.0.min(right.y.range.0 + dy), top + 0.6);
    left
}

#[cfg(test)]
mod tests {
    use super::*;

    fn finite(f: &Figure) -> bool {
        f.series
            .iter()
            .all(|s| s.points.iter().all(|p| p.0.is_finite() && p.1.is_finite()))
    }

    #[test]
    fn drawings_stay_finite_and_in_frame_for_any_input() {
        for v in [-1.0, 0.0, 0.7, f64::NAN, f64::INFINITY] {
            for fig in [u_tube(v), servo(v), storey(v), thermal(v, v)] {
                assert!(finite(&fig) && fig.has_visible_data());
                for s in &fig.series {
                    for p in &s.points {
                        assert!((X.0 - 0.2..=X.1).contains(&p.0), "{p:?}");
                        assert!((Y.0..=Y.1).contains(&p.1), "{p:?}");
                    }
                }
            }
        }
    }

    #[test]
    fn the_levels_and_the_floor_follow_the_coordinate() {
        let level = |f: &Figure| f.series[3].points[0].1;
        assert!(level(&u_tube(1.0)) > level(&u_tube(-1.0)) + 1.0);
        let floor = |f: &Figure| f.series.last().map(|s| s.points[0].0).unwrap();
        assert!(floor(&storey(1.0)) > floor(&storey(-1.0)) + 0.5);
        let both = side_by_side(u_tube(0.0), storey(0.0), 0.4, ["A", "B"]);
        assert!(both.x.range.1 > 4.0);
        assert!(both.markers.iter().any(|m| m.label == "B"));
    }
}
