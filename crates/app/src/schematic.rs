//! Schematic drawings as plain figures: a mass on a spring and damper over a moving base,
//! and a series RLC loop. Coordinates are abstract drawing units; the renderer keeps the
//! two axes at equal scale.
//!
//! Shared pieces: [`arrow`] (a shaft with a head, e.g. a current or a force), [`caption`]
//! (a name on a drawing) and [`beside`], which composes two schematics into one figure
//! (e.g. a mechanism and its electrical twin).
//!
//! ```
//! use zeta_app::schematic::{beside, caption, mass_spring_damper, rlc_loop, MassLabels};
//! let labels = MassLabels { mass: "m", spring: "k", damper: "c", base: "" };
//! let mech = mass_spring_damper(0.5, 0.0, &labels, String::new());
//! let elec = rlc_loop(0.2, 0.5, String::new());
//! let both = beside(mech, elec, (4.7, 1.4)).with_marker(caption("electrical", (3.7, 4.2)));
//! assert!(both.x.range.1 >= 4.7 + 2.0);
//! ```

// Drawing: the shapes of springs, coils and road profiles.
#![allow(clippy::disallowed_methods)]

use crate::figure::{Axis, Dash, Figure, FigureKind, LineStyle, Marker, Series};
use crate::plot::Ink;

const INK: Ink = Ink::Black;

fn line(points: Vec<(f64, f64)>, color: Ink, width: f64) -> Series {
    Series {
        label: String::new(),
        points,
        style: LineStyle {
            ink: color,
            dash: Dash::Solid,
            width,
        },
    }
}

/// A name written on a drawing at `at`, in the text colour.
pub fn caption(text: &str, at: (f64, f64)) -> Marker {
    Marker::text(text, at, INK)
}

fn label(text: &str, at: (f64, f64)) -> Marker {
    caption(text, at)
}

/// An arrow from `from` to `to` as two polylines, the shaft and the open head: the head's
/// sides reach back `head.0` along the shaft and `head.1` to each side of it (drawing
/// units). Empty when the two ends coincide.
pub fn arrow(from: (f64, f64), to: (f64, f64), head: (f64, f64)) -> Vec<Vec<(f64, f64)>> {
    let (dx, dy) = (to.0 - from.0, to.1 - from.1);
    let len = dx.hypot(dy);
    if !(len > 0.0 && len.is_finite()) {
        return Vec::new();
    }
    let (ux, uy) = (dx / len, dy / len);
    let back = (to.0 - head.0 * ux, to.1 - head.0 * uy);
    let side = (-uy * head.1, ux * head.1);
    vec![
        vec![from, to],
        vec![
            (back.0 - side.0, back.1 - side.1),
            to,
            (back.0 + side.0, back.1 + side.1),
        ],
    ]
}

/// `right` drawn beside `left` in one figure: every point and marker of `right` shifted by
/// `offset = (dx, dy)` drawing units, and the ranges widened to hold both. Title and text
/// alternative are `left`'s; set them for the pair.
pub fn beside(mut left: Figure, right: Figure, offset: (f64, f64)) -> Figure {
    let (dx, dy) = offset;
    let shift = |p: (f64, f64)| (p.0 + dx, p.1 + dy);
    for mut s in right.series {
        for p in &mut s.points {
            *p = shift(*p);
        }
        left.series.push(s);
    }
    for mut m in right.markers {
        m.at = shift(m.at);
        left.markers.push(m);
    }
    left.x.range = (
        left.x.range.0.min(right.x.range.0 + dx),
        left.x.range.1.max(right.x.range.1 + dx),
    );
    left.y.range = (
        left.y.range.0.min(right.y.range.0 + dy),
        left.y.range.1.max(right.y.range.1 + dy),
    );
    left
}

/// A zigzag spring from `(x, y0)` up to `(x, y1)` with `coils` turns of half-width `w`.
pub fn spring(x: f64, y0: f64, y1: f64, coils: usize, w: f64) -> Vec<(f64, f64)> {
    let lead = 0.15 * (y1 - y0);
    let (a, b) = (y0 + lead, y1 - lead);
    let n = coils.max(1) * 2;
    let mut pts = vec![(x, y0), (x, a)];
    for i in 0..n {
        let y = a + (b - a) * (i as f64 + 0.5) / n as f64;
        pts.push((if i % 2 == 0 { x - w } else { x + w }, y));
    }
    pts.extend([(x, b), (x, y1)]);
    pts
}

/// A dashpot from `(x, y0)` up to `(x, y1)`: a cylinder fixed below, a piston rod above.
pub fn damper(x: f64, y0: f64, y1: f64, w: f64) -> Vec<Vec<(f64, f64)>> {
    let mid = y0 + 0.45 * (y1 - y0);
    let cyl_top = y0 + 0.7 * (y1 - y0).max(0.3);
    vec![
        vec![(x, y0), (x, y0 + 0.15 * (y1 - y0))],
        vec![
            (x - w, cyl_top),
            (x - w, y0 + 0.15 * (y1 - y0)),
            (x + w, y0 + 0.15 * (y1 - y0)),
            (x + w, cyl_top),
        ],
        vec![(x - 0.75 * w, mid), (x + 0.75 * w, mid)],
        vec![(x, mid), (x, y1)],
    ]
}

/// A closed rectangle centred at `c`.
pub fn rect(c: (f64, f64), w: f64, h: f64) -> Vec<(f64, f64)> {
    let (x0, x1, y0, y1) = (c.0 - w / 2.0, c.0 + w / 2.0, c.1 - h / 2.0, c.1 + h / 2.0);
    vec![(x0, y0), (x1, y0), (x1, y1), (x0, y1), (x0, y0)]
}

fn frame(title: &str, description: String, x: (f64, f64), y: (f64, f64)) -> Figure {
    Figure {
        kind: FigureKind::Schematic,
        description,
        ..Figure::plot(title, Axis::linear("", "", x), Axis::linear("", "", y))
    }
}

/// `v` clamped into `[−limit, limit]`; 0 when not finite (a drawing at rest).
fn within(v: f64, limit: f64) -> f64 {
    if v.is_finite() {
        v.clamp(-limit, limit)
    } else {
        0.0
    }
}

/// Labels for [`mass_spring_damper`].
pub struct MassLabels<'a> {
    /// Text on the mass, e.g. `"m"`.
    pub mass: &'a str,
    /// Text beside the spring.
    pub spring: &'a str,
    /// Text beside the damper.
    pub damper: &'a str,
    /// Text under the base, e.g. `"road"`.
    pub base: &'a str,
}

impl<'a> MassLabels<'a> {
    /// The usual labels m, k and c, with `base` under the base (empty for none).
    pub fn mkc(base: &'a str) -> Self {
        Self {
            mass: "m",
            spring: "k",
            damper: "c",
            base,
        }
    }
}

/// A mass on a spring and damper. `x` is the mass displacement and `u` the base
/// displacement, both already normalised to about −1…1 (1 = the largest excursion).
pub fn mass_spring_damper(x: f64, u: f64, labels: &MassLabels<'_>, description: String) -> Figure {
    let (x, u) = (within(x, 1.2), within(u, 1.2));
    let amp = 0.55;
    let base_y = u * amp * 0.6;
    let mass_c = 2.4 + x * amp;
    let mass_h = 0.8;
    let bottom = mass_c - mass_h / 2.0;
    let mut fig = frame(
        &crate::t!("schematic-title"),
        description,
        (-1.6, 1.6),
        (-0.6, 3.6),
    );
    // Ground and base: a hatched line that moves with the road input.
    fig.series
        .push(line(vec![(-1.3, base_y), (1.3, base_y)], INK, 2.5));
    for i in 0..9 {
        let x0 = -1.2 + 0.3 * i as f64;
        fig.series.push(line(
            vec![(x0, base_y), (x0 - 0.18, base_y - 0.22)],
            INK,
            1.0,
        ));
    }
    fig.series
        .push(line(spring(-0.5, base_y, bottom, 5, 0.18), Ink::Blue, 2.5));
    for part in damper(0.5, base_y, bottom, 0.16) {
        fig.series.push(line(part, Ink::Vermillion, 2.5));
    }
    fig.series
        .push(line(rect((0.0, mass_c), 1.7, mass_h), Ink::Green, 3.0));
    // Rest position of the mass, for reference.
    fig.series.push(Series {
        label: String::new(),
        points: vec![(1.0, 2.4), (1.5, 2.4)],
        style: LineStyle {
            ink: INK,
            dash: Dash::Dashed,
            width: 1.0,
        },
    });
    fig.markers.push(label(labels.mass, (-0.12, mass_c + 0.1)));
    fig.markers
        .push(label(labels.spring, (-1.25, (base_y + bottom) / 2.0)));
    fig.markers
        .push(label(labels.damper, (0.75, (base_y + bottom) / 2.0)));
    fig.markers.push(label(labels.base, (-0.3, base_y - 0.35)));
    fig
}

/// A series RLC loop drawn as a rectangle: inductor on top, resistor on the right,
/// capacitor on the left. `current` (−1…1, normalised) is shown as an arrow whose length
/// follows the current, and `charge` (−1…1) as the capacitor's plate labels.
pub fn rlc_loop(current: f64, charge: f64, description: String) -> Figure {
    let (i, q) = (within(current, 1.0), within(charge, 1.0));
    let mut fig = frame(
        &crate::t!("schematic-circuit"),
        description,
        (-2.0, 2.0),
        (-1.6, 1.8),
    );
    // Top: inductor coils between (−1, 1) and (1, 1).
    let mut top = vec![(-1.4, 1.0), (-0.8, 1.0)];
    for k in 0..=48 {
        let th = std::f64::consts::PI * k as f64 / 12.0;
        top.push((-0.8 + 1.6 * k as f64 / 48.0, 1.0 + 0.18 * th.sin().abs()));
    }
    top.extend([(0.8, 1.0), (1.4, 1.0)]);
    fig.series.push(line(top, Ink::Blue, 2.5));
    // Right: resistor zigzag from (1.4, 1) down to (1.4, −1).
    let mut right = vec![(1.4, 1.0), (1.4, 0.6)];
    for k in 0..8 {
        let y = 0.6 - 1.2 * (k as f64 + 0.5) / 8.0;
        right.push((if k % 2 == 0 { 1.55 } else { 1.25 }, y));
    }
    right.extend([(1.4, -0.6), (1.4, -1.0)]);
    fig.series.push(line(right, Ink::Vermillion, 2.5));
    // Bottom wire and left side with the capacitor plates.
    fig.series.push(line(
        vec![(1.4, -1.0), (-1.4, -1.0), (-1.4, -0.12)],
        Ink::Black,
        2.5,
    ));
    fig.series
        .push(line(vec![(-1.4, 1.0), (-1.4, 0.12)], Ink::Black, 2.5));
    fig.series
        .push(line(vec![(-1.75, 0.12), (-1.05, 0.12)], Ink::Green, 3.5));
    fig.series
        .push(line(vec![(-1.75, -0.12), (-1.05, -0.12)], Ink::Green, 3.5));
    // Current arrow along the bottom wire; its length and direction follow i.
    // Positive i = dq/dt charges the upper plate: it flows left to right along the bottom
    // wire, so the arrow points right; a discharging capacitor (i < 0) points it left.
    let len = 1.6 * i;
    if len.abs() > 0.02 {
        for part in arrow((-len / 2.0, -1.3), (len / 2.0, -1.3), (0.15, 0.1)) {
            fig.series.push(line(part, Ink::Purple, 3.0));
        }
    }
    fig.markers.push(label("L", (-0.1, 1.55)));
    fig.markers.push(label("R", (1.6, 0.35)));
    fig.markers.push(label("C", (-1.95, 0.35)));
    let sign = |v: f64| {
        if v > 0.05 {
            "+"
        } else if v < -0.05 {
            "−"
        } else {
            ""
        }
    };
    fig.markers.push(label(sign(q), (-1.0, 0.45)));
    fig.markers.push(label(sign(-q), (-1.0, -0.2)));
    fig.markers.push(label("i", (0.0, -1.25)));
    fig
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn spring_spans_its_ends_and_mass_follows_displacement() {
        let s = spring(0.0, 0.0, 2.0, 5, 0.2);
        assert_eq!(s.first(), Some(&(0.0, 0.0)));
        assert_eq!(s.last(), Some(&(0.0, 2.0)));
        let labels = MassLabels::mkc("road");
        let up = mass_spring_damper(1.0, 0.0, &labels, String::new());
        let down = mass_spring_damper(-1.0, 0.0, &labels, String::new());
        let top = |f: &Figure| {
            f.series[f.series.len() - 2]
                .points
                .iter()
                .map(|p| p.1)
                .fold(f64::MIN, f64::max)
        };
        assert!(top(&up) > top(&down) + 1.0);
        let nan = mass_spring_damper(f64::NAN, f64::INFINITY, &labels, String::new());
        assert!(nan.all_points_finite());
    }

    #[test]
    fn arrows_point_at_their_tip() {
        let a = arrow((1.0, 0.0), (-1.0, 0.0), (0.15, 0.1));
        assert_eq!(a[0], vec![(1.0, 0.0), (-1.0, 0.0)]);
        // The head's ends lie behind the tip, one on each side of the shaft.
        let head = &a[1];
        assert_eq!(head[1], (-1.0, 0.0));
        for end in [head[0], head[2]] {
            assert!((end.0 - -0.85).abs() < 1e-15 && (end.1.abs() - 0.1).abs() < 1e-15);
        }
        assert!(head[0].1 * head[2].1 < 0.0);
        assert!(arrow((0.0, 0.0), (0.0, 0.0), (0.1, 0.1)).is_empty());
    }

    #[test]
    fn two_drawings_compose_side_by_side() {
        let labels = MassLabels::mkc("");
        let left = mass_spring_damper(0.0, 0.0, &labels, String::new());
        let right = rlc_loop(0.5, 0.5, String::new());
        let (n, m) = (
            left.series.len() + right.series.len(),
            left.markers.len() + right.markers.len(),
        );
        let both = beside(left, right, (5.0, 1.0));
        assert_eq!((both.series.len(), both.markers.len()), (n, m));
        let l = both.markers.iter().find(|m| m.label == "L").unwrap();
        assert_eq!(l.at, (-0.1 + 5.0, 1.55 + 1.0));
        assert_eq!(both.x.range, (-1.6, 2.0 + 5.0));
        assert!((both.y.range.0 - -0.6).abs() < 1e-12 && both.y.range.1 == 3.6);
    }
}
