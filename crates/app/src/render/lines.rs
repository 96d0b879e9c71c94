//! Series (split where they cannot be drawn, clamped to the axes) and markers.

use super::chart::Chart;
use super::{err, px, RenderError};
use crate::figure::{AxisScale, Dash, Figure, FigureKind, MarkerShape, Series};
use crate::theme::Theme;
use plotters::prelude::*;

/// Splits a series at points that cannot be drawn (non-finite, or ≤ 0 on a log axis) and
/// clips the rest to the (slightly widened) plot area: a segment that leaves it is drawn to
/// its edge and resumes where it comes back (clipped in the axes' own scale, so a log axis
/// clips straight lines of its plot). Nothing is flattened along an edge, where it could be
/// read as data. The flag says whether anything was clipped.
pub(super) fn segments(s: &Series, fig: &Figure) -> (Vec<Vec<(f64, f64)>>, bool) {
    let x_log = fig.x.scale == AxisScale::Log;
    let y_log = fig.y.scale == AxisScale::Log;
    // A coordinate in the axis's own scale (log axes: ln), and back.
    let to = |v: f64, log: bool| if log { v.ln() } else { v };
    let from = |v: f64, log: bool| if log { v.exp() } else { v };
    let widen = |(lo, hi): (f64, f64), log: bool| {
        let (lo, hi) = (to(lo, log), to(hi, log));
        let pad = 0.02 * (hi - lo);
        (lo - pad, hi + pad)
    };
    let bx = widen(fig.x.range, x_log);
    let by = widen(fig.y.range, y_log);
    // The same box in data units: a point tested there needs no logarithm, and a segment
    // between two points inside it is drawn as given (the box is convex in the axes' scale).
    let (dx, dy) = (
        (from(bx.0, x_log), from(bx.1, x_log)),
        (from(by.0, y_log), from(by.1, y_log)),
    );
    let inside = |(x, y): (f64, f64)| (dx.0..=dx.1).contains(&x) && (dy.0..=dy.1).contains(&y);
    // A point in the axes' scale, kept far from overflow (no pixel tells 1e300 from 1e200).
    let scaled = |(x, y): (f64, f64)| {
        (
            to(x, x_log).clamp(-1e200, 1e200),
            to(y, y_log).clamp(-1e200, 1e200),
        )
    };
    let back = |(u, v): (f64, f64)| (from(u, x_log), from(v, y_log));
    let mut out: Vec<Vec<(f64, f64)>> = Vec::new();
    let mut cur: Vec<(f64, f64)> = Vec::new();
    let mut clipped = false;
    // The last drawable point and whether it is inside the box.
    let mut prev: Option<((f64, f64), bool)> = None;
    // Ends the piece being drawn, if any.
    let end_piece = |cur: &mut Vec<(f64, f64)>, out: &mut Vec<Vec<(f64, f64)>>| {
        if !cur.is_empty() {
            out.push(std::mem::take(cur));
        }
    };
    for &q in &s.points {
        let (x, y) = q;
        let drawable = x.is_finite() && y.is_finite() && (!x_log || x > 0.0) && (!y_log || y > 0.0);
        if !drawable {
            prev = None;
            end_piece(&mut cur, &mut out);
            continue;
        }
        let q_in = inside(q);
        clipped |= !q_in;
        match prev.replace((q, q_in)) {
            None if q_in => cur.push(q),
            None => {}
            // Both ends inside: the piece goes on to `q` (`a` ends it).
            Some((_, true)) if q_in => cur.push(q),
            Some((a, _)) => {
                let (sa, sq) = (scaled(a), scaled(q));
                match clip(sa, sq, bx, by) {
                    Some((start, end)) => {
                        // Entering the box, or starting a piece (the one drawn so far, if
                        // any, left the box before `a`).
                        if start != sa || cur.is_empty() {
                            end_piece(&mut cur, &mut out);
                            cur.push(if start == sa { a } else { back(start) });
                        }
                        cur.push(if end == sq { q } else { back(end) });
                        if end != sq {
                            end_piece(&mut cur, &mut out); // left the box
                        }
                    }
                    None => end_piece(&mut cur, &mut out),
                }
            }
        }
    }
    if !cur.is_empty() {
        out.push(cur);
    }
    (out, clipped)
}

/// The part of the segment from `a` to `b` inside the box `x.0..=x.1` × `y.0..=y.1`, as its
/// end points (each `a` or `b` itself when inside); `None` if it misses the box
/// (Liang–Barsky: the segment's parameter range narrowed by each edge).
fn clip(
    a: (f64, f64),
    b: (f64, f64),
    x: (f64, f64),
    y: (f64, f64),
) -> Option<((f64, f64), (f64, f64))> {
    let (dx, dy) = (b.0 - a.0, b.1 - a.1);
    let (mut t0, mut t1) = (0.0_f64, 1.0_f64);
    // Each edge as (−direction, distance to it): the segment enters or leaves there.
    for (p, q) in [
        (-dx, a.0 - x.0),
        (dx, x.1 - a.0),
        (-dy, a.1 - y.0),
        (dy, y.1 - a.1),
    ] {
        if p == 0.0 {
            if q < 0.0 {
                return None; // parallel to this edge and outside it
            }
        } else {
            let t = q / p;
            if p < 0.0 {
                t0 = t0.max(t);
            } else {
                t1 = t1.min(t);
            }
        }
    }
    if t0 > t1 {
        return None;
    }
    // The ends themselves where the segment does not leave the box (no rounding).
    let at = |t: f64| {
        if t == 0.0 {
            a
        } else if t == 1.0 {
            b
        } else {
            (a.0 + t * dx, a.1 + t * dy)
        }
    };
    Some((at(t0), at(t1)))
}

/// A text's width (backend px) estimated from its length, `per_char` px a character at
/// scale 1, instead of measured: where measuring costs more than a slightly wide guess.
pub(super) fn estimated_width(text: &str, per_char: f64, scale: f64) -> i32 {
    (text.chars().count() as f64 * per_char * scale) as i32
}

/// Where a marker's label of `width` px goes, relative to its point at backend pixel `x`:
/// right of the point and above it, or left of it when it would run past `right`, the
/// plotting area's right edge (px).
pub(super) fn label_offset(x: i32, width: i32, right: i32, scale: f64) -> (i32, i32) {
    let gap = px(8.0, scale) as i32;
    let dx = match x + gap + width > right {
        true => -gap - width,
        false => gap,
    };
    (dx, -(px(16.0, scale) as i32))
}

/// Where a text marker of `width` px anchored at backend pixel `x` starts, relative to `x`:
/// at it, or ending a little left of it when it would run past `right`, the canvas's right
/// edge (px). A label placed just right of a line near the edge (the current step on a
/// convergence plot) then reads in full on the line's left instead of being cut.
pub(super) fn text_offset(x: i32, width: i32, right: i32, scale: f64) -> i32 {
    match x + width > right {
        true => -width - px(12.0, scale) as i32,
        false => 0,
    }
}

/// Draws `series` (of `fig`, whose axes clip them); returns whether any was clipped. With
/// `direct`, the backend dashes each series as one path (see [`super::Direct::dash`]).
pub(super) fn draw_series<DB: DrawingBackend>(
    chart: &mut Chart<'_, DB>,
    series: &[Series],
    fig: &Figure,
    theme: &Theme,
    scale: f64,
    direct: Option<&dyn super::Direct>,
) -> Result<bool, RenderError> {
    let mut clipped = false;
    for s in series {
        let color = theme.color(s.style.ink.index());
        let style = color.stroke_width(px(s.style.width, scale));
        let (segs, cut) = segments(s, fig);
        clipped |= cut;
        // On and off lengths (px) of a dash.
        let pattern = match s.style.dash {
            Dash::Solid => None,
            Dash::Dashed => Some((px(8.0, scale), px(5.0, scale))),
            Dash::Dotted => Some((px(2.0, scale), px(4.0, scale))),
        };
        match (pattern, direct) {
            (Some((on, off)), Some(direct)) => {
                direct.dash(&[f64::from(on), f64::from(off)]);
                let drawn = segs
                    .into_iter()
                    .try_for_each(|seg| chart.draw_series(LineSeries::new(seg, style)).map(|_| ()));
                direct.dash(&[]);
                drawn.map_err(err)?;
            }
            (Some((on, off)), None) => {
                for seg in segs {
                    chart
                        .draw_series(DashedLineSeries::new(seg, on, off, style))
                        .map_err(err)?;
                }
            }
            (None, _) => {
                for seg in segs {
                    chart
                        .draw_series(LineSeries::new(seg, style))
                        .map_err(err)?;
                }
            }
        }
    }
    Ok(clipped)
}

/// Draws the series of `fig` from `from` on (those before it are its backdrop, drawn with
/// its static layer, `clipped` saying whether that clipped any), then its markers, and
/// says so on the plot if any series was clipped. `right` is the canvas's right edge
/// (backend px), which text markers keep within.
pub(super) fn draw_lines_and_markers<DB: DrawingBackend>(
    chart: &mut Chart<'_, DB>,
    fig: &Figure,
    theme: &Theme,
    scale: f64,
    (direct, right): (Option<&dyn super::Direct>, i32),
    (from, clipped): (usize, bool),
) -> Result<(), RenderError> {
    let fg = theme.foreground;
    let font = |size: f64| (super::SANS, size * scale).into_font().color(&fg);
    let rest = fig.series.get(from..).unwrap_or_default();
    let clipped = draw_series(chart, rest, fig, theme, scale, direct)? | clipped;

    for m in &fig.markers {
        let color = theme.color(m.ink.index());
        let (x, y) = m.at;
        if !(x.is_finite() && y.is_finite()) {
            continue;
        }
        let size = px(7.0, scale) as i32;
        let stroke = color.stroke_width(px(2.5, scale));
        match m.shape {
            MarkerShape::Cross => {
                chart
                    .draw_series(std::iter::once(Cross::new((x, y), size, stroke)))
                    .map_err(err)?;
            }
            MarkerShape::Dot => {
                chart
                    .draw_series(std::iter::once(Circle::new(
                        (x, y),
                        size / 2 + 1,
                        color.filled(),
                    )))
                    .map_err(err)?;
            }
            MarkerShape::Label => {
                // Its width estimated, not measured (a little wide: 8 px a character at
                // 14 px; a sans serif's average is nearer 7.5): an overflow decides the side.
                let width = estimated_width(&m.label, 8.0, scale);
                let dx = text_offset(chart.backend_coord(&(x, y)).0, width, right, scale);
                chart
                    .draw_series(std::iter::once(
                        EmptyElement::at((x, y)) + Text::new(m.label.clone(), (dx, 0), font(14.0)),
                    ))
                    .map_err(err)?;
                continue;
            }
        }
        if !m.label.is_empty() {
            let style = font(12.0);
            let area = chart.plotting_area();
            let right = area.get_pixel_range().0.end;
            let width = area
                .estimate_text_size(&m.label, &style)
                .map_or(0, |(w, _)| w as i32);
            let off = label_offset(chart.backend_coord(&(x, y)).0, width, right, scale);
            chart
                .draw_series(std::iter::once(
                    EmptyElement::at((x, y)) + Text::new(m.label.clone(), off, style),
                ))
                .map_err(err)?;
        }
    }

    if clipped && fig.kind == FigureKind::Plot {
        // Say so when a curve leaves the axes, so a clamped line is not read as data.
        let area = chart.plotting_area().strip_coord_spec();
        let at = (px(6.0, scale) as i32, px(4.0, scale) as i32);
        let note = crate::t!("plot-clipped");
        area.draw(&Text::new(note, at, font(11.0))).map_err(err)?;
    }
    Ok(())
}
