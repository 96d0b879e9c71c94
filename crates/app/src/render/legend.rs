//! The legend: measured through the backend, placed over no data or in rows below.

use super::chart::Chart;
use super::lines::{estimated_width, label_offset, segments};
use super::{err, px, RenderError};
use crate::figure::{Dash, Figure, LineStyle};
use crate::theme::Theme;
use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

/// The labelled series of a figure, in order: its legend entries.
pub(super) fn legend_entries(fig: &Figure) -> Vec<(&str, LineStyle)> {
    fig.series
        .iter()
        .filter(|s| !s.label.is_empty())
        .map(|s| (s.label.as_str(), s.style))
        .collect()
}

/// Picks a corner (or the middle of the top or bottom edge) of the plotting area where a
/// legend box of `size` backend pixels covers no line, marker or heatmap cell; `None` when
/// every place would cover data. Returns the box's top-left in plotting-area pixels.
pub(super) fn free_corner<DB: DrawingBackend>(
    chart: &Chart<'_, DB>,
    fig: &Figure,
    size: (i32, i32),
    scale: f64,
) -> Option<(i32, i32)> {
    let (xs, ys) = chart.plotting_area().get_pixel_range();
    let (aw, ah) = (xs.end - xs.start, ys.end - ys.start);
    let (bw, bh) = size;
    let pad = px(6.0, scale) as i32;
    if bw + 2 * pad > aw || bh + 2 * pad > ah {
        return None;
    }
    let (right, bottom, middle) = (aw - bw - pad, ah - bh - pad, (aw - bw) / 2);
    let spots = [
        (right, pad),
        (pad, pad),
        (right, bottom),
        (pad, bottom),
        (middle, pad),
        (middle, bottom),
    ];
    // A margin around the box keeps it clear of lines that pass just outside it.
    let m = px(3.0, scale) as i32;
    let mut free = [true; 6];
    let to_area = |p: (f64, f64)| {
        let (x, y) = chart.backend_coord(&p);
        (x - xs.start, y - ys.start)
    };
    if let Some(h) = &fig.heatmap {
        let (x0, y0) = to_area((h.x_edges.0, h.y_edges.1));
        let (x1, y1) = to_area((h.x_edges.1, h.y_edges.0));
        for (k, &(sx, sy)) in spots.iter().enumerate() {
            if sx < x1.max(x0) && sx + bw > x0.min(x1) && sy < y1.max(y0) && sy + bh > y0.min(y1) {
                free[k] = false;
            }
        }
    }
    // Marks the spots (x, y) falls in; says whether any spot is still free.
    let mut mark = |x: i32, y: i32| {
        for (k, &(sx, sy)) in spots.iter().enumerate() {
            if x >= sx - m && x <= sx + bw + m && y >= sy - m && y <= sy + bh + m {
                free[k] = false;
            }
        }
        free.contains(&true)
    };
    let step = px(3.0, scale).max(1) as i32;
    for s in &fig.series {
        for seg in segments(s, fig).0 {
            let mut prev: Option<(i32, i32)> = None;
            for &p in &seg {
                let (x, y) = to_area(p);
                if let Some((px0, py0)) = prev {
                    // Sample the segment so a long straight stretch is seen too.
                    let n = ((x - px0).abs().max((y - py0).abs()) / step).clamp(1, 400);
                    for i in 1..=n {
                        if !mark(px0 + (x - px0) * i / n, py0 + (y - py0) * i / n) {
                            return None; // every spot taken: the rest cannot free one
                        }
                    }
                } else if !mark(x, y) {
                    return None;
                }
                prev = Some((x, y));
            }
        }
    }
    for mk in &fig.markers {
        if !(mk.at.0.is_finite() && mk.at.1.is_finite()) {
            continue;
        }
        let (x, y) = to_area(mk.at);
        let _ = mark(x, y);
        if !mk.label.is_empty() {
            // Where draw_lines_and_markers puts the label (its width estimated here).
            let w = estimated_width(&mk.label, 7.0, scale);
            let (dx, dy) = label_offset(x + xs.start, w, xs.end, scale);
            for i in 0..=4 {
                let _ = mark(x + dx + w * i / 4, y + dy);
                let _ = mark(x + dx + w * i / 4, y + dy / 2);
            }
        }
    }
    spots
        .iter()
        .zip(free)
        .find(|(_, f)| *f)
        .map(|(&spot, _)| spot)
}

/// A legend's measured entries.
///
/// Drawn here rather than with plotters' series labels because those measure text through
/// a styled DOM element on the web, which a strict Content-Security-Policy blocks; this
/// measures through the backend (the canvas's own `measureText`).
pub(super) struct Legend {
    /// Text width of each entry, backend pixels.
    widths: Vec<i32>,
    /// The box's size when drawn inside the plot, backend pixels.
    pub(super) size: (i32, i32),
}

impl Legend {
    fn font(theme: &Theme, scale: f64) -> TextStyle<'static> {
        (super::SANS, 12.0 * scale)
            .into_font()
            .color(&theme.foreground)
            .pos(Pos::new(HPos::Left, VPos::Center))
    }

    pub(super) fn measure<DB: DrawingBackend>(
        area: &DrawingArea<DB, Shift>,
        entries: &[(&str, LineStyle)],
        scale: f64,
    ) -> Result<Self, RenderError> {
        let font = (super::SANS, 12.0 * scale).into_text_style(area);
        let mut widths = Vec::with_capacity(entries.len());
        for (label, _) in entries {
            let (w, _) = area.estimate_text_size(label, &font).map_err(err)?;
            widths.push(w as i32);
        }
        let (pad, swatch, gap, line_h) = Self::metrics(scale);
        let text_w = widths.iter().copied().max().unwrap_or(0);
        let size = (
            pad + swatch + gap + text_w + pad,
            pad * 2 + line_h * entries.len() as i32,
        );
        Ok(Self { widths, size })
    }

    /// Padding, swatch length, gap after the swatch and line height, backend pixels.
    fn metrics(scale: f64) -> (i32, i32, i32, i32) {
        (
            px(6.0, scale) as i32,
            px(24.0, scale) as i32,
            px(6.0, scale) as i32,
            px(17.0, scale) as i32,
        )
    }

    /// Entries laid out in rows across `width`: the start x of each entry and its row.
    /// The rows start under the plotting area (64 px in, past the y axis's labels) unless
    /// starting at the edge takes fewer rows (a phone's narrow plot: every row under the
    /// chart is a row less of data).
    fn rows(&self, width: u32, scale: f64) -> Vec<(i32, i32)> {
        let (pad, ..) = Self::metrics(scale);
        let under = self.rows_from(px(64.0, scale) as i32, width, scale);
        let edge = self.rows_from(pad, width, scale);
        let count = |r: &[(i32, i32)]| r.last().map_or(0, |&(_, row)| row);
        match count(&edge) < count(&under) {
            true => edge,
            false => under,
        }
    }

    /// Entries laid out in rows across `width`, each row starting at `left` (px).
    fn rows_from(&self, left: i32, width: u32, scale: f64) -> Vec<(i32, i32)> {
        let (pad, swatch, gap, _) = Self::metrics(scale);
        let spacing = px(16.0, scale) as i32;
        let limit = (width as i32 - pad).max(left + 1);
        let (mut x, mut row) = (left, 0);
        let mut out = Vec::with_capacity(self.widths.len());
        for &w in &self.widths {
            let need = swatch + gap + w;
            if x > left && x + need > limit {
                x = left;
                row += 1;
            }
            out.push((x, row));
            x += need + spacing;
        }
        out
    }

    /// Height of the rows under the chart, backend pixels.
    pub(super) fn band_height(&self, width: u32, scale: f64) -> u32 {
        let (pad, _, _, line_h) = Self::metrics(scale);
        let rows = self.rows(width, scale).last().map_or(0, |&(_, r)| r + 1);
        (rows * line_h + pad).max(0) as u32
    }

    fn swatch<DB: DrawingBackend>(
        area: &DrawingArea<DB, Shift>,
        (x, y): (i32, i32),
        style: &LineStyle,
        theme: &Theme,
        scale: f64,
    ) -> Result<(), RenderError> {
        let stroke = theme
            .color(style.ink.index())
            .stroke_width(px(style.width, scale));
        let pieces: &[(i32, i32)] = match style.dash {
            Dash::Solid => &[(0, 24)],
            Dash::Dashed => &[(0, 8), (13, 21)],
            Dash::Dotted => &[(0, 2), (6, 8), (12, 14), (18, 20)],
        };
        for &(a, b) in pieces {
            let (a, b) = (x + (a as f64 * scale) as i32, x + (b as f64 * scale) as i32);
            area.draw(&PathElement::new(vec![(a, y), (b.max(a + 1), y)], stroke))
                .map_err(err)?;
        }
        Ok(())
    }

    /// One entry with its swatch centred on height `y` from `x`, its label after it.
    fn entry<DB: DrawingBackend>(
        area: &DrawingArea<DB, Shift>,
        (x, y): (i32, i32),
        label: &str,
        style: &LineStyle,
        font: &TextStyle<'static>,
        theme: &Theme,
        scale: f64,
    ) -> Result<(), RenderError> {
        let (_, swatch, gap, _) = Self::metrics(scale);
        Self::swatch(area, (x, y), style, theme, scale)?;
        area.draw(&Text::new(
            label.to_string(),
            (x + swatch + gap, y),
            font.clone(),
        ))
        .map_err(err)
    }

    /// A box with its top-left at `at` (plotting-area pixels), over a place free of data.
    pub(super) fn draw_box<DB: DrawingBackend>(
        &self,
        area: &DrawingArea<DB, Shift>,
        entries: &[(&str, LineStyle)],
        (x0, y0): (i32, i32),
        theme: &Theme,
        scale: f64,
    ) -> Result<(), RenderError> {
        let (pad, _, _, line_h) = Self::metrics(scale);
        let (box_w, box_h) = self.size;
        area.draw(&Rectangle::new(
            [(x0, y0), (x0 + box_w, y0 + box_h)],
            theme.background.mix(0.88).filled(),
        ))
        .map_err(err)?;
        area.draw(&Rectangle::new(
            [(x0, y0), (x0 + box_w, y0 + box_h)],
            theme.grid.stroke_width(1),
        ))
        .map_err(err)?;
        let font = Self::font(theme, scale);
        for (i, (label, style)) in entries.iter().enumerate() {
            let y = y0 + pad + line_h * i as i32 + line_h / 2;
            let x = x0 + pad;
            Self::entry(area, (x, y), label, style, &font, theme, scale)?;
        }
        Ok(())
    }

    /// Rows of entries in `band`, the strip under the chart.
    pub(super) fn draw_rows<DB: DrawingBackend>(
        &self,
        band: &DrawingArea<DB, Shift>,
        entries: &[(&str, LineStyle)],
        theme: &Theme,
        scale: f64,
    ) -> Result<(), RenderError> {
        let (_, _, _, line_h) = Self::metrics(scale);
        let (w, _) = band.dim_in_pixel();
        let font = Self::font(theme, scale);
        for ((label, style), (x, row)) in entries.iter().zip(self.rows(w, scale)) {
            let y = row * line_h + line_h / 2;
            Self::entry(band, (x, y), label, style, &font, theme, scale)?;
        }
        Ok(())
    }
}
