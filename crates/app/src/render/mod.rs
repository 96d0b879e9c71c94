//! Draws a [`Figure`] on any plotters backend: the canvas in the browser, SVG natively.
//!
//! Sizes are given in CSS pixels and multiplied by `scale` (the screen's
//! `devicePixelRatio`) so text and lines look the same on every screen, and crisp.

// Drawing: pixel geometry of log axes (data ↔ pixels), not model maths.
#![allow(clippy::disallowed_methods)]

mod chart;
mod colour_bar;
mod corners;
mod fit;
mod heatmap;
mod hold;
mod legend;
mod lines;
mod scale;
#[cfg(test)]
mod tests;
mod ticks;

pub use chart::Placement;
pub use corners::corners;
pub use hold::{ease_axes, hold_axes, AxisRanges};
pub use ticks::{log_ticks, tick_label};

use crate::figure::{AxisScale, Figure, FigureKind};
use crate::theme::Theme;
use chart::draw;
use lines::draw_lines_and_markers;
use plotters::coord::Shift;
use plotters::prelude::*;
use scale::Scale;

/// The font of every plot text. The variant, not the name `"sans-serif"`: plotters maps a
/// name to its family by lowercasing it, which links the Unicode case tables into the wasm
/// (about 5 KB brotli) for the same pixels.
const SANS: FontFamily<'static> = FontFamily::SansSerif;

/// Why a figure could not be drawn (a backend failure; figures themselves are always drawable).
#[derive(Debug, Clone, PartialEq)]
pub struct RenderError(pub String);

impl std::fmt::Display for RenderError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "could not draw the plot: {}", self.0)
    }
}

impl std::error::Error for RenderError {}

fn err<E: std::fmt::Display>(e: E) -> RenderError {
    RenderError(e.to_string())
}

/// Where the data went on the backend: the plotting area in backend pixels and the
/// ranges mapped onto it, so the page can turn a pointer position back into data values.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PlotGeometry {
    /// Left, top, right, bottom edges of the plotting area, in backend pixels.
    pub area: (f64, f64, f64, f64),
    /// x range shown.
    pub x: (f64, f64),
    /// y range shown.
    pub y: (f64, f64),
    /// Whether x is logarithmic.
    pub x_log: bool,
    /// Whether y is logarithmic.
    pub y_log: bool,
    /// Where the legend went (kept during a held drag, see [`Output::legend`]).
    pub legend: Placement,
}

impl PlotGeometry {
    fn frac(v: f64, (lo, hi): (f64, f64), log: bool) -> f64 {
        if log {
            (v.ln() - lo.ln()) / (hi.ln() - lo.ln())
        } else {
            (v - lo) / (hi - lo)
        }
    }

    fn unfrac(f: f64, (lo, hi): (f64, f64), log: bool) -> f64 {
        if log {
            (lo.ln() + f * (hi.ln() - lo.ln())).exp()
        } else {
            lo + f * (hi - lo)
        }
    }

    /// Backend pixel of data point `(x, y)`.
    pub fn to_pixel(&self, x: f64, y: f64) -> (f64, f64) {
        let (l, t, r, b) = self.area;
        (
            l + Self::frac(x, self.x, self.x_log) * (r - l),
            b - Self::frac(y, self.y, self.y_log) * (b - t),
        )
    }

    /// Data point at backend pixel `(px, py)`, or `None` outside the plotting area.
    pub fn to_data(&self, px: f64, py: f64) -> Option<(f64, f64)> {
        let (l, t, r, b) = self.area;
        if !(l..=r).contains(&px) || !(t..=b).contains(&py) || r <= l || b <= t {
            return None;
        }
        Some((
            Self::unfrac((px - l) / (r - l), self.x, self.x_log),
            Self::unfrac((b - py) / (b - t), self.y, self.y_log),
        ))
    }
}

/// Draws `fig` onto `root`, filling it with the theme's background first; returns where
/// the plotting area went. Heatmaps are drawn as one rectangle per cell (exact in SVG).
pub fn render<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    fig: &Figure,
    theme: &Theme,
    scale: f64,
) -> Result<PlotGeometry, RenderError> {
    render_with(root, fig, theme, scale, Output::VECTOR)
}

/// What a backend draws itself, beside plotters' calls, because it does in one call what
/// plotters would do in hundreds (the canvas). Without one (SVG, tests), dashes are
/// plotters' separate segments and heatmap cells one rectangle each: exact vector output.
pub trait Direct {
    /// Sets the dash pattern (on, off, … lengths in px; empty: solid) of the strokes that
    /// follow. One path per series instead of one per dash made dashed curves the
    /// costliest part of a frame.
    fn dash(&self, pattern: &[f64]);
    /// Draws `image` stretched over its rectangle, each source pixel a sharp block. A
    /// heatmap is then one image of a pixel per cell, instead of 10 000 rectangle fills
    /// (~10 ms a frame) or a bitmap the size of the plot (~5 ms at 4× CPU slowdown).
    fn stretch(&self, image: &Stretched<'_>);
    /// Stops (`true`) or resumes (`false`) drawing; text is still measured. For a trial
    /// layout that only gives pixels (a plot with a legend is laid out twice).
    fn mute(&self, on: bool);
    /// At the start of a plot's static layer (background, the title's band, grid, ticks,
    /// axis names, origin lines, then the figure's backdrop series and the legend's rows
    /// under the chart; the title is drawn after [`Direct::end_layer`]), which `keys`
    /// name. A backend that holds the whole layer draws it at once and returns
    /// [`Kept::Whole`] with what was noted with it (the caller then skips drawing the
    /// layer); one that holds only what lies under the backdrop draws that and returns
    /// [`Kept::Axes`] (the caller draws the backdrop and the rows over it). Either way it
    /// draws nothing more until [`Direct::axes_done`] or [`Direct::end_layer`]. While a
    /// control is held the axes hold still, so most frames need only the data drawn, and
    /// when the control moves the backdrop too (an exact solution under the numerical
    /// ones), the backdrop and the data.
    fn begin_layer(&self, keys: LayerKeys) -> Option<Kept>;
    /// Between what lies under the backdrop and the backdrop itself (not called over a
    /// [`Kept::Whole`] layer; called, and a no-op, for a figure without a backdrop): resumes
    /// drawing, and may keep what is drawn so far as the layer's part `keys.axes`.
    fn axes_done(&self, keys: LayerKeys);
    /// At the end of the static layer: resumes drawing, and may keep what is drawn so far
    /// as the layer `keys.whole`, with `note`.
    fn end_layer(&self, keys: LayerKeys, note: LayerNote);
}

/// What names a plot's static layer (see [`Direct::begin_layer`]), hashed: `axes` what
/// lies under the backdrop (the axes, the theme, the sizes), `whole` that and the
/// backdrop series; the two are equal for a figure without a backdrop.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct LayerKeys {
    /// What lies under the backdrop.
    pub axes: u64,
    /// All of the static layer.
    pub whole: u64,
}

impl LayerKeys {
    /// Whether the layer has a backdrop over its axes.
    pub fn has_backdrop(self) -> bool {
        self.axes != self.whole
    }
}

/// What a backend drew of a plot's static layer from the copies it keeps.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Kept {
    /// All of it, with what its drawing noted.
    Whole(LayerNote),
    /// What lies under the backdrop; the backdrop and the rows are drawn over it.
    Axes,
}

/// What a static layer's drawing found that the frames drawn over it still show: whether
/// its backdrop leaves the axes (the plot then says it is clipped), and which legend rows
/// under the chart it holds. Kept with the layer, so a frame over it need not go through
/// the backdrop's points again, nor draw rows that have not changed.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct LayerNote {
    /// Whether a backdrop series was clipped.
    pub clipped: bool,
    /// The hash of the legend rows drawn in the layer (`chart::rows_key`); 0: none.
    pub rows: u64,
}

/// An RGB image of `size` = (columns, rows) pixels, rows top to bottom, to be drawn over
/// the backend rectangle `to` and shown only inside `clip` (both `[left, top, right,
/// bottom]` in px).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Stretched<'a> {
    /// Columns and rows.
    pub size: (u32, u32),
    /// Three bytes a pixel.
    pub rgb: &'a [u8],
    /// Where the image goes.
    pub to: [i32; 4],
    /// What of it is shown.
    pub clip: [i32; 4],
}

/// What a backend can do beyond plotters' drawing calls.
#[derive(Clone, Copy)]
pub struct Output<'a> {
    /// What the backend draws itself; `None`: everything through plotters.
    pub direct: Option<&'a dyn Direct>,
    /// Where the legend stays (a held drag: where it was last drawn); `None`: where it
    /// covers no data, found afresh.
    pub legend: Option<Placement>,
}

impl Output<'_> {
    /// Vector output: heatmap cells as rectangles, dashes as segments.
    pub const VECTOR: Output<'static> = Output {
        direct: None,
        legend: None,
    };
}

impl<'a> Output<'a> {
    /// Output through `direct`, the legend placed afresh.
    pub fn with_direct(direct: &'a dyn Direct) -> Self {
        Output {
            direct: Some(direct),
            legend: None,
        }
    }
}

/// [`render`] for a backend that can do more (see [`Output`]).
pub fn render_with<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    fig: &Figure,
    theme: &Theme,
    scale: f64,
    out: Output<'_>,
) -> Result<PlotGeometry, RenderError> {
    // A backend that draws itself fills the background with the plot's static layer, which
    // a kept copy covers whole (see `chart::draw`).
    if fig.kind == FigureKind::Schematic || out.direct.is_none() {
        root.fill(&theme.background).map_err(err)?;
    }
    if fig.kind == FigureKind::Schematic {
        let g = draw_schematic(root, fig, theme, scale)?;
        root.present().map_err(err)?;
        return Ok(g);
    }
    let (area, legend) = draw(root, fig, theme, scale, out)?;
    root.present().map_err(err)?;
    Ok(PlotGeometry {
        area,
        legend,
        x: fig.x.range,
        y: fig.y.range,
        x_log: fig.x.scale == AxisScale::Log,
        y_log: fig.y.scale == AxisScale::Log,
    })
}

/// A schematic: no axes, equal scales, the ranges widened to the canvas's shape.
fn draw_schematic<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    fig: &Figure,
    theme: &Theme,
    scale: f64,
) -> Result<PlotGeometry, RenderError> {
    let (w, h) = root.dim_in_pixel();
    let (w, h) = (f64::from(w.max(1)), f64::from(h.max(1)));
    let (mut x, mut y) = (fig.x.range, fig.y.range);
    let (sx, sy) = ((x.1 - x.0) / w, (y.1 - y.0) / h);
    if sx > sy {
        let pad = (sx * h - (y.1 - y.0)) / 2.0;
        y = (y.0 - pad, y.1 + pad);
    } else {
        let pad = (sy * w - (x.1 - x.0)) / 2.0;
        x = (x.0 - pad, x.1 + pad);
    }
    let mut chart = ChartBuilder::on(root)
        .build_cartesian_2d(Scale::linear(x.0, x.1), Scale::linear(y.0, y.1))
        .map_err(err)?;
    let fitted = Figure {
        x: crate::figure::Axis {
            range: x,
            ..fig.x.clone()
        },
        y: crate::figure::Axis {
            range: y,
            ..fig.y.clone()
        },
        ..fig.clone()
    };
    // Dashes as segments: a schematic has few, short ones.
    let right = root.get_pixel_range().0.end;
    draw_lines_and_markers(&mut chart, &fitted, theme, scale, (None, right), (0, false))?;
    Ok(PlotGeometry {
        area: (0.0, 0.0, w, h),
        x,
        y,
        legend: Placement::None,
        x_log: false,
        y_log: false,
    })
}

fn px(v: f64, scale: f64) -> u32 {
    (v * scale).round().max(1.0) as u32
}
