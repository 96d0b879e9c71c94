//! Schematic drawings as plain figures: a mass on a spring and damper over a moving base,
//! and a series RLC loop. Coordinates are abstract drawing units; the renderer keeps the
//! two axes at equal scale.

// Drawing: the shapes of springs, coils and road profiles.
#![allow(clippy::disallowed_methods)]

use crate::figure::{Axis, Dash, Figure, FigureKind, LineStyle, Marker, MarkerShape, Series};
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

fn label(text: &str, at: (f64, f64)) -> Marker {
    Marker {
        label: text.to_string(),
        at,
        shape: MarkerShape::Label,
        ink: INK,
    }
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

/// A mass on a spring and damper. `x` is the mass displacement and `u` the base
/// displacement, both already normalised to about −1…1 (1 = the largest excursion).
pub fn mass_spring_damper(x: f64, u: f64, labels: &MassLabels<'_>, description: String) -> Figure {
    let clamp = |v: f64| {
        if v.is_finite() {
            v.clamp(-1.2, 1.2)
        } else {
            0.0
        }
    };
    let (x, u) = (clamp(x), clamp(u));
    let amp = 0.55;
    let base_y = u * amp * 0.6;
    let mass_c = 2.4 + x * amp;
    let mass_h = 0.8;
    let bottom = mass_c - mass_h / 2.0;
    let mut fig = frame("Schematic", description, (-1.6, 1.6), (-0.6, 3.6));
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
    let clamp = |v: f64| {
        if v.is_finite() {
            v.clamp(-1.0, 1.0)
        } else {
            0.0
        }
    };
    let (i, q) = (clamp(current), clamp(charge));
    let mut fig = frame("Circuit", description, (-2.0, 2.0), (-1.6, 1.8));
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
    let len = 1.6 * i;
    if len.abs() > 0.02 {
        let head = if len > 0.0 { -0.15 } else { 0.15 };
        let tip = (-len / 2.0, -1.3);
        fig.series
            .push(line(vec![(len / 2.0, -1.3), tip], Ink::Purple, 3.0));
        fig.series.push(line(
            vec![(tip.0 + head, -1.2), tip, (tip.0 + head, -1.4)],
            Ink::Purple,
            3.0,
        ));
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
        let labels = MassLabels {
            mass: "m",
            spring: "k",
            damper: "c",
            base: "road",
        };
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
        assert!(nan
            .series
            .iter()
            .all(|s| s.points.iter().all(|p| p.0.is_finite() && p.1.is_finite())));
    }
}
