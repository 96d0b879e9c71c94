//! Draws a [`Figure`] on any plotters backend: the canvas in the browser, SVG natively.
//!
//! Sizes are given in CSS pixels and multiplied by `scale` (the screen's
//! `devicePixelRatio`) so text and lines look the same on every screen, and crisp.

// Drawing: pixel geometry, tick placement and text metrics, not model maths.
#![allow(clippy::disallowed_methods)]

use crate::figure::{AxisScale, Dash, Figure, FigureKind, LineStyle, MarkerShape, Series};
use crate::theme::Theme;
use plotters::coord::combinators::{BindKeyPoints, LogCoord, WithKeyPoints};
use plotters::coord::ranged1d::{AsRangedCoord, Ranged, ValueFormatter};
use plotters::coord::Shift;
use plotters::element::{Drawable, PointCollection};
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

/// Why a figure could not be drawn (a backend failure; figures themselves are always drawable).
#[derive(Debug, Clone, PartialEq)]
pub struct RenderError(pub String);

impl std::fmt::Display for RenderError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "could not draw the plot: {}", self.0)
    }
}

impl std::error::Error for RenderError {}

fn err<E: std::fmt::Debug>(e: E) -> RenderError {
    RenderError(format!("{e:?}"))
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

/// A plot's `(x, y)` axis ranges.
pub type AxisRanges = ((f64, f64), (f64, f64));

/// While a control is dragged, a plot keeps the ranges it was last drawn with (`held`),
/// widened only as far as the new figure's own ranges need, so the axes hold still and the
/// change the control makes is seen; the figure's own ranges return when the drag ends.
/// Schematics (equal scales, no axes) are left alone.
pub fn hold_axes(fig: &mut Figure, held: Option<AxisRanges>) {
    let Some((hx, hy)) = held else { return };
    if fig.kind != FigureKind::Plot {
        return;
    }
    let widen = |(lo, hi): (f64, f64), (a, b): (f64, f64)| (lo.min(a), hi.max(b));
    fig.x.range = widen(hx, fig.x.range);
    fig.y.range = widen(hy, fig.y.range);
}

/// After a drag, moves a plot's axes from the ranges it was held at (`from`) towards the
/// figure's own, by `f` in 0…1 (1 = the figure's own ranges); log axes move geometrically.
/// Used over a few frames so the rescale is seen as a motion, not a jump.
pub fn ease_axes(fig: &mut Figure, from: Option<AxisRanges>, f: f64) {
    let Some((fx, fy)) = from else { return };
    if fig.kind != FigureKind::Plot || !(0.0..1.0).contains(&f) {
        return;
    }
    let mix = |a: f64, b: f64, log: bool| {
        if log && a > 0.0 && b > 0.0 {
            (a.ln() + f * (b.ln() - a.ln())).exp()
        } else {
            a + f * (b - a)
        }
    };
    let x_log = fig.x.scale == AxisScale::Log;
    let y_log = fig.y.scale == AxisScale::Log;
    let (x, y) = (fig.x.range, fig.y.range);
    fig.x.range = (mix(fx.0, x.0, x_log), mix(fx.1, x.1, x_log));
    fig.y.range = (mix(fy.0, y.0, y_log), mix(fy.1, y.1, y_log));
}

/// Draws `fig` onto `root`, filling it with the theme's background first; returns where
/// the plotting area went. Heatmaps are drawn as one rectangle per cell (exact in SVG).
pub fn render<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    fig: &Figure,
    theme: &Theme,
    scale: f64,
) -> Result<PlotGeometry, RenderError> {
    render_with(root, fig, theme, scale, Raster::Cells)
}

/// How heatmaps are drawn.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Raster {
    /// One filled rectangle per cell: exact, and right for vector output.
    Cells,
    /// One bitmap blitted into the plotting area (linear axes only; log axes fall back to
    /// cells): for backends with a fast `blit_bitmap`, such as the canvas, where 10 000
    /// rectangle fills would take ~10 ms a frame.
    Bitmap,
}

/// [`render`], choosing how heatmaps are drawn.
pub fn render_with<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    fig: &Figure,
    theme: &Theme,
    scale: f64,
    raster: Raster,
) -> Result<PlotGeometry, RenderError> {
    root.fill(&theme.background).map_err(err)?;
    if fig.kind == FigureKind::Schematic {
        let g = draw_schematic(root, fig, theme, scale)?;
        root.present().map_err(err)?;
        return Ok(g);
    }
    let (x0, x1) = fig.x.range;
    let (y0, y1) = fig.y.range;
    let area = match (fig.x.scale, fig.y.scale) {
        (AxisScale::Linear, AxisScale::Linear) => {
            draw(root, fig, theme, scale, raster, || x0..x1, || y0..y1)
        }
        (AxisScale::Log, AxisScale::Linear) => draw(
            root,
            fig,
            theme,
            scale,
            Raster::Cells,
            || log_axis(x0, x1),
            || y0..y1,
        ),
        (AxisScale::Linear, AxisScale::Log) => draw(
            root,
            fig,
            theme,
            scale,
            Raster::Cells,
            || x0..x1,
            || log_axis(y0, y1),
        ),
        (AxisScale::Log, AxisScale::Log) => draw(
            root,
            fig,
            theme,
            scale,
            Raster::Cells,
            || log_axis(x0, x1),
            || log_axis(y0, y1),
        ),
    }?;
    root.present().map_err(err)?;
    Ok(PlotGeometry {
        area,
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
        .build_cartesian_2d(x.0..x.1, y.0..y.1)
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
    draw_lines_and_markers(&mut chart, &fitted, theme, scale)?;
    Ok(PlotGeometry {
        area: (0.0, 0.0, w, h),
        x,
        y,
        x_log: false,
        y_log: false,
    })
}

/// A log axis over `lo..hi` (both > 0) with its labelled ticks from [`log_ticks`] and a
/// minor grid line at every 1…9 × 10ᵏ when the range spans fewer than six decades.
fn log_axis(lo: f64, hi: f64) -> WithKeyPoints<LogCoord<f64>> {
    let minor = if (hi / lo).log10() < 6.0 {
        decade_multiples(lo, hi, &[1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0, 9.0])
    } else {
        Vec::new()
    };
    (lo..hi)
        .log_scale()
        .with_key_points(log_ticks(lo, hi))
        .with_light_points(minor)
}

/// Labelled ticks of a log axis over `lo..hi`: every decade, and between them enough
/// values to read a number off the axis when it spans few decades — 1, 2, 5 × 10ᵏ under
/// three decades, 1, 1.5, 2, 3, 5, 7 × 10ᵏ under one and a half; every other decade
/// above eight. At least two ticks whenever the range allows.
pub fn log_ticks(lo: f64, hi: f64) -> Vec<f64> {
    if !(lo > 0.0 && hi > lo && lo.is_finite() && hi.is_finite()) {
        return Vec::new();
    }
    let decades = (hi / lo).log10();
    let ticks = if decades < 1.5 {
        decade_multiples(lo, hi, &[1.0, 1.5, 2.0, 3.0, 5.0, 7.0])
    } else if decades < 3.0 {
        decade_multiples(lo, hi, &[1.0, 2.0, 5.0])
    } else if decades <= 8.0 {
        decade_multiples(lo, hi, &[1.0])
    } else {
        decade_multiples(lo, hi, &[1.0])
            .into_iter()
            .filter(|v| (v.log10().round() as i64).rem_euclid(2) == 0)
            .collect()
    };
    if ticks.len() >= 2 || decades < 0.05 {
        ticks
    } else {
        decade_multiples(
            lo,
            hi,
            &[1.0, 1.2, 1.5, 2.0, 2.5, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0, 9.0],
        )
    }
}

/// Every `m × 10ᵏ` (m from `mantissas`) inside `lo..=hi`, ascending.
fn decade_multiples(lo: f64, hi: f64, mantissas: &[f64]) -> Vec<f64> {
    let mut out = Vec::new();
    let first = lo.log10().floor() as i32;
    let last = hi.log10().ceil() as i32;
    for k in first..=last.min(first + 400) {
        let base = 10f64.powi(k);
        for m in mantissas {
            // Round to 12 significant digits so labels read 0.2, not 0.20000000000000004.
            let v = crate::format::significant(m * base, 12)
                .parse::<f64>()
                .unwrap_or(m * base);
            if v >= lo * (1.0 - 1e-12) && v <= hi * (1.0 + 1e-12) {
                out.push(v);
            }
        }
    }
    out
}

fn px(v: f64, scale: f64) -> u32 {
    (v * scale).round().max(1.0) as u32
}

/// A tick label: at most 6 significant digits, no rounding tails (`0.30000000000000004` →
/// `0.3`), trailing zeros dropped, and the language's decimal separator.
pub fn tick_label(v: f64, decimal_comma: bool) -> String {
    if v == 0.0 || !v.is_finite() {
        return "0".to_string();
    }
    let s = crate::format::significant(v, 6);
    let s = match s.split_once('e') {
        Some((mantissa, exp)) => format!("{}e{exp}", trim_zeros(mantissa)),
        None => trim_zeros(&s).to_string(),
    };
    if decimal_comma {
        s.replace('.', ",")
    } else {
        s
    }
}

/// A colour-bar label: three significant digits, as [`tick_label`] otherwise.
fn short_label(v: f64, decimal_comma: bool) -> String {
    if v == 0.0 || !v.is_finite() {
        return "0".to_string();
    }
    tick_label(
        crate::format::significant(v, 3).parse::<f64>().unwrap_or(v),
        decimal_comma,
    )
}

fn trim_zeros(s: &str) -> &str {
    if s.contains('.') {
        s.trim_end_matches('0').trim_end_matches('.')
    } else {
        s
    }
}

/// Splits a series at points that cannot be drawn (non-finite, or ≤ 0 on a log axis) and
/// clamps the rest into the (slightly widened) plot area, so a diverging curve is drawn to
/// the edge instead of off the canvas. The flag says whether anything was clamped.
fn segments(s: &Series, fig: &Figure) -> (Vec<Vec<(f64, f64)>>, bool) {
    let widen = |(lo, hi): (f64, f64), log: bool| {
        if log {
            (lo / 1.05, hi * 1.05)
        } else {
            let pad = 0.02 * (hi - lo);
            (lo - pad, hi + pad)
        }
    };
    let (xl, xh) = widen(fig.x.range, fig.x.scale == AxisScale::Log);
    let (yl, yh) = widen(fig.y.range, fig.y.scale == AxisScale::Log);
    let x_log = fig.x.scale == AxisScale::Log;
    let y_log = fig.y.scale == AxisScale::Log;
    let mut out: Vec<Vec<(f64, f64)>> = Vec::new();
    let mut cur: Vec<(f64, f64)> = Vec::new();
    let mut clipped = false;
    for &(x, y) in &s.points {
        let drawable = x.is_finite() && y.is_finite() && (!x_log || x > 0.0) && (!y_log || y > 0.0);
        if drawable {
            let p = (x.clamp(xl, xh), y.clamp(yl, yh));
            clipped |= p != (x, y);
            cur.push(p);
        } else if !cur.is_empty() {
            out.push(std::mem::take(&mut cur));
        }
    }
    if !cur.is_empty() {
        out.push(cur);
    }
    (out, clipped)
}

/// Where a figure's legend goes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Placement {
    /// No legend entries.
    None,
    /// A box with its top-left corner here, in plotting-area pixels, over no data.
    Inside(i32, i32),
    /// Rows under the chart, outside the plotting area (no corner was free of data).
    Below,
}

/// A chart over the coordinates `X` × `Y` describe.
type Chart<'a, DB, X, Y> = ChartContext<
    'a,
    DB,
    Cartesian2d<<X as AsRangedCoord>::CoordDescType, <Y as AsRangedCoord>::CoordDescType>,
>;

fn build<'a, DB, X, Y>(
    area: &'a DrawingArea<DB, Shift>,
    fig: &Figure,
    theme: &Theme,
    scale: f64,
    xr: X,
    yr: Y,
) -> Result<Chart<'a, DB, X, Y>, RenderError>
where
    DB: DrawingBackend,
    X: AsRangedCoord<Value = f64>,
    Y: AsRangedCoord<Value = f64>,
{
    let font = ("sans-serif", 15.0 * scale)
        .into_font()
        .color(&theme.foreground);
    let right = if fig.heatmap.is_some() {
        COLOUR_BAR_WIDTH
    } else {
        10.0
    };
    ChartBuilder::on(area)
        .caption(&fig.title, font)
        .margin(px(10.0, scale))
        .margin_right(px(right, scale))
        .x_label_area_size(px(42.0, scale))
        .y_label_area_size(px(64.0, scale))
        .build_cartesian_2d(xr, yr)
        .map_err(err)
}

/// CSS pixels right of the plotting area taken by a heatmap's colour bar and its labels.
const COLOUR_BAR_WIDTH: f64 = 92.0;

fn draw<DB, X, Y>(
    root: &DrawingArea<DB, Shift>,
    fig: &Figure,
    theme: &Theme,
    scale: f64,
    raster: Raster,
    xr: impl Fn() -> X,
    yr: impl Fn() -> Y,
) -> Result<(f64, f64, f64, f64), RenderError>
where
    DB: DrawingBackend,
    X: AsRangedCoord<Value = f64>,
    Y: AsRangedCoord<Value = f64>,
    X::CoordDescType: ValueFormatter<f64>,
    Y::CoordDescType: ValueFormatter<f64>,
{
    let fg = theme.foreground;
    let font = |size: f64| ("sans-serif", size * scale).into_font().color(&fg);
    let entries = legend_entries(fig);
    let legend = Legend::measure(root, &entries, scale)?;

    // Where the legend can go without covering data: a trial layout gives the pixels.
    let mut placement = Placement::None;
    if !entries.is_empty() {
        let trial = build(root, fig, theme, scale, xr(), yr())?;
        placement = match free_corner(&trial, fig, legend.size, scale) {
            Some((x, y)) => Placement::Inside(x, y),
            None => Placement::Below,
        };
        root.fill(&theme.background).map_err(err)?;
    }
    let (w, h) = root.dim_in_pixel();
    let band_h = if placement == Placement::Below {
        legend.band_height(w, scale).min(h / 3)
    } else {
        0
    };
    let (area, band) = root.split_vertically(h.saturating_sub(band_h));
    let mut chart = build(&area, fig, theme, scale, xr(), yr())?;

    chart
        .configure_mesh()
        .x_desc(fig.x.title())
        .y_desc(fig.y.title())
        .axis_desc_style(font(13.0))
        .label_style(font(12.0))
        .bold_line_style(theme.grid.stroke_width(px(1.0, scale)))
        .light_line_style(theme.grid_minor.stroke_width(px(1.0, scale)))
        .max_light_lines(4)
        .axis_style(fg.stroke_width(px(1.0, scale)))
        .x_labels(6)
        .y_labels(6)
        .x_label_formatter(&|v| tick_label(*v, theme.decimal_comma))
        .y_label_formatter(&|v| tick_label(*v, theme.decimal_comma))
        .draw()
        .map_err(err)?;

    if let Some(h) = &fig.heatmap {
        match raster {
            Raster::Cells => draw_heatmap(&mut chart, h)?,
            Raster::Bitmap => blit_heatmap(&mut chart, h, theme)?,
        }
        let (xs, ys) = chart.plotting_area().get_pixel_range();
        draw_colour_bar(&area, h, (xs.end, ys.start, ys.end), theme, scale)?;
    }

    if fig.origin_lines {
        let (x0, x1) = fig.x.range;
        let (y0, y1) = fig.y.range;
        let style = fg.mix(0.6).stroke_width(px(1.0, scale));
        if x0 < 0.0 && x1 > 0.0 {
            chart
                .draw_series(std::iter::once(PathElement::new(
                    vec![(0.0, y0), (0.0, y1)],
                    style,
                )))
                .map_err(err)?;
        }
        if y0 < 0.0 && y1 > 0.0 {
            chart
                .draw_series(std::iter::once(PathElement::new(
                    vec![(x0, 0.0), (x1, 0.0)],
                    style,
                )))
                .map_err(err)?;
        }
    }

    draw_lines_and_markers(&mut chart, fig, theme, scale)?;
    match placement {
        Placement::Inside(x, y) => legend.draw_box(
            &chart.plotting_area().strip_coord_spec(),
            &entries,
            (x, y),
            theme,
            scale,
        )?,
        Placement::Below => legend.draw_rows(&band, &entries, theme, scale)?,
        Placement::None => {}
    }
    let (xs, ys) = chart.plotting_area().get_pixel_range();
    Ok((
        f64::from(xs.start),
        f64::from(ys.start),
        f64::from(xs.end),
        f64::from(ys.end),
    ))
}

/// The labelled series of a figure, in order: its legend entries.
fn legend_entries(fig: &Figure) -> Vec<(&str, LineStyle)> {
    fig.series
        .iter()
        .filter(|s| !s.label.is_empty())
        .map(|s| (s.label.as_str(), s.style))
        .collect()
}

/// Picks a corner (or the middle of the top or bottom edge) of the plotting area where a
/// legend box of `size` backend pixels covers no line, marker or heatmap cell; `None` when
/// every place would cover data. Returns the box's top-left in plotting-area pixels.
fn free_corner<DB, X, Y>(
    chart: &ChartContext<'_, DB, Cartesian2d<X, Y>>,
    fig: &Figure,
    size: (i32, i32),
    scale: f64,
) -> Option<(i32, i32)>
where
    DB: DrawingBackend,
    X: Ranged<ValueType = f64>,
    Y: Ranged<ValueType = f64>,
{
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
    let mut mark = |x: i32, y: i32| {
        for (k, &(sx, sy)) in spots.iter().enumerate() {
            if x >= sx - m && x <= sx + bw + m && y >= sy - m && y <= sy + bh + m {
                free[k] = false;
            }
        }
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
                        mark(px0 + (x - px0) * i / n, py0 + (y - py0) * i / n);
                    }
                } else {
                    mark(x, y);
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
        mark(x, y);
        if !mk.label.is_empty() {
            // The label runs right of the point, above it (see draw_lines_and_markers).
            let w = (mk.label.chars().count() as f64 * 7.0 * scale) as i32;
            let (dx, dy) = (px(8.0, scale) as i32, px(16.0, scale) as i32);
            for i in 0..=4 {
                mark(x + dx + w * i / 4, y - dy);
                mark(x + dx + w * i / 4, y - dy / 2);
            }
        }
    }
    spots
        .iter()
        .zip(free)
        .find(|(_, f)| *f)
        .map(|(&spot, _)| spot)
}

/// Fills the heatmap's cells (one rectangle each; blank where the value is not finite).
fn draw_heatmap<DB, X, Y>(
    chart: &mut ChartContext<'_, DB, Cartesian2d<X, Y>>,
    h: &crate::figure::Heatmap,
) -> Result<(), RenderError>
where
    DB: DrawingBackend,
    X: Ranged<ValueType = f64>,
    Y: Ranged<ValueType = f64>,
{
    if h.nx == 0 || h.ny == 0 || h.values.len() < h.nx * h.ny {
        return Ok(());
    }
    let dx = (h.x_edges.1 - h.x_edges.0) / h.nx as f64;
    let dy = (h.y_edges.1 - h.y_edges.0) / h.ny as f64;
    let (lo, hi) = h.scale;
    let span = if hi > lo { hi - lo } else { 1.0 };
    let cells = h
        .values
        .iter()
        .enumerate()
        .filter(|(_, v)| v.is_finite())
        .map(|(i, &v)| {
            let (ix, iy) = ((i % h.nx) as f64, (i / h.nx) as f64);
            let x0 = h.x_edges.0 + ix * dx;
            let y0 = h.y_edges.0 + iy * dy;
            let color = crate::theme::viridis((v - lo) / span);
            Rectangle::new([(x0, y0), (x0 + dx, y0 + dy)], color.filled())
        });
    chart.draw_series(cells).map_err(err)?;
    Ok(())
}

/// An RGB image placed with its top-left corner at a point; drawn by the backend's
/// `blit_bitmap`.
struct Image<C> {
    at: C,
    size: (u32, u32),
    rgb: Vec<u8>,
}

impl<'a, C: 'a> PointCollection<'a, C> for &'a Image<C> {
    type Point = &'a C;
    type IntoIter = std::iter::Once<&'a C>;
    fn point_iter(self) -> Self::IntoIter {
        std::iter::once(&self.at)
    }
}

impl<C, DB: DrawingBackend> Drawable<DB> for Image<C> {
    fn draw<I: Iterator<Item = plotters_backend::BackendCoord>>(
        &self,
        mut pos: I,
        backend: &mut DB,
        _: (u32, u32),
    ) -> Result<(), plotters_backend::DrawingErrorKind<DB::ErrorType>> {
        match pos.next() {
            Some(p) => backend.blit_bitmap(p, self.size, &self.rgb),
            None => Ok(()),
        }
    }
}

/// Draws the heatmap as one bitmap over its pixel rectangle (linear axes), each pixel
/// taking the colour of the cell under its centre; blank cells show the background.
fn blit_heatmap<DB, X, Y>(
    chart: &mut ChartContext<'_, DB, Cartesian2d<X, Y>>,
    h: &crate::figure::Heatmap,
    theme: &Theme,
) -> Result<(), RenderError>
where
    DB: DrawingBackend,
    X: Ranged<ValueType = f64>,
    Y: Ranged<ValueType = f64>,
{
    if h.nx == 0 || h.ny == 0 || h.values.len() < h.nx * h.ny {
        return Ok(());
    }
    let area = chart.plotting_area();
    let (xs, ys) = area.get_pixel_range();
    let (ax, ay) = chart.backend_coord(&(h.x_edges.0, h.y_edges.1));
    let (bx, by) = chart.backend_coord(&(h.x_edges.1, h.y_edges.0));
    // The image covers the heatmap clipped to the plotting area.
    let (x0, x1) = (ax.max(xs.start), bx.min(xs.end));
    let (y0, y1) = (ay.max(ys.start), by.min(ys.end));
    if x1 <= x0 || y1 <= y0 || bx <= ax || by <= ay {
        return Ok(());
    }
    let (w, hgt) = ((x1 - x0) as usize, (y1 - y0) as usize);
    let (lo, hi) = h.scale;
    let span = if hi > lo { hi - lo } else { 1.0 };
    let bg = theme.background;
    // Colour of each cell once, then pixels index into it.
    let colours: Vec<(u8, u8, u8)> = h
        .values
        .iter()
        .map(|&v| {
            if v.is_finite() {
                let c = crate::theme::viridis((v - lo) / span);
                (c.0, c.1, c.2)
            } else {
                (bg.0, bg.1, bg.2)
            }
        })
        .collect();
    let cell_x: Vec<usize> = (0..w)
        .map(|i| {
            let f = ((x0 + i as i32) as f64 + 0.5 - ax as f64) / (bx - ax) as f64;
            ((f * h.nx as f64) as usize).min(h.nx - 1)
        })
        .collect();
    let mut rgb = Vec::with_capacity(w * hgt * 3);
    for j in 0..hgt {
        // Rows go up in data, down in pixels.
        let f = (by as f64 - ((y0 + j as i32) as f64 + 0.5)) / (by - ay) as f64;
        let iy = ((f * h.ny as f64) as usize).min(h.ny - 1);
        for &ix in &cell_x {
            let (r, g, b) = colours
                .get(iy * h.nx + ix)
                .copied()
                .unwrap_or((bg.0, bg.1, bg.2));
            rgb.extend_from_slice(&[r, g, b]);
        }
    }
    let image = Image {
        at: (x0 - xs.start, y0 - ys.start),
        size: (w as u32, hgt as u32),
        rgb,
    };
    area.strip_coord_spec().draw(&image).map_err(err)
}

/// Draws the series and markers of `fig`; returns the legend entries.
fn draw_lines_and_markers<'f, DB, X, Y>(
    chart: &mut ChartContext<'_, DB, Cartesian2d<X, Y>>,
    fig: &'f Figure,
    theme: &Theme,
    scale: f64,
) -> Result<Vec<(&'f str, LineStyle)>, RenderError>
where
    DB: DrawingBackend,
    X: Ranged<ValueType = f64>,
    Y: Ranged<ValueType = f64>,
{
    let fg = theme.foreground;
    let font = |size: f64| ("sans-serif", size * scale).into_font().color(&fg);
    let mut legend: Vec<(&str, LineStyle)> = Vec::new();
    let mut clipped = false;
    for s in &fig.series {
        let color = theme.color(s.style.ink.index());
        let style = color.stroke_width(px(s.style.width, scale));
        let (segs, cut) = segments(s, fig);
        clipped |= cut;
        for seg in segs {
            match s.style.dash {
                Dash::Solid => chart
                    .draw_series(LineSeries::new(seg, style))
                    .map_err(err)?,
                Dash::Dashed => chart
                    .draw_series(DashedLineSeries::new(
                        seg,
                        px(8.0, scale),
                        px(5.0, scale),
                        style,
                    ))
                    .map_err(err)?,
                Dash::Dotted => chart
                    .draw_series(DashedLineSeries::new(
                        seg,
                        px(2.0, scale),
                        px(4.0, scale),
                        style,
                    ))
                    .map_err(err)?,
            };
        }
        if !s.label.is_empty() {
            legend.push((&s.label, s.style));
        }
    }

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
                chart
                    .draw_series(std::iter::once(
                        EmptyElement::at((x, y)) + Text::new(m.label.clone(), (0, 0), font(14.0)),
                    ))
                    .map_err(err)?;
                continue;
            }
        }
        if !m.label.is_empty() {
            let off = (px(8.0, scale) as i32, -(px(16.0, scale) as i32));
            chart
                .draw_series(std::iter::once(
                    EmptyElement::at((x, y)) + Text::new(m.label.clone(), off, font(12.0)),
                ))
                .map_err(err)?;
        }
    }

    if clipped && fig.kind == FigureKind::Plot {
        // Say so when a curve leaves the axes, so a clamped line is not read as data.
        let area = chart.plotting_area().strip_coord_spec();
        let at = (px(6.0, scale) as i32, px(4.0, scale) as i32);
        let note = theme.clipped_note;
        area.draw(&Text::new(note, at, font(11.0))).map_err(err)?;
    }
    Ok(legend)
}

/// A legend's measured entries.
///
/// Drawn here rather than with plotters' series labels because those measure text through
/// a styled DOM element on the web, which a strict Content-Security-Policy blocks; this
/// measures through the backend (the canvas's own `measureText`).
struct Legend {
    /// Text width of each entry, backend pixels.
    widths: Vec<i32>,
    /// The box's size when drawn inside the plot, backend pixels.
    size: (i32, i32),
}

impl Legend {
    fn font(theme: &Theme, scale: f64) -> TextStyle<'static> {
        ("sans-serif", 12.0 * scale)
            .into_font()
            .color(&theme.foreground)
            .pos(Pos::new(HPos::Left, VPos::Center))
    }

    fn measure<DB: DrawingBackend>(
        area: &DrawingArea<DB, Shift>,
        entries: &[(&str, LineStyle)],
        scale: f64,
    ) -> Result<Self, RenderError> {
        let font = ("sans-serif", 12.0 * scale).into_text_style(area);
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
    fn rows(&self, width: u32, scale: f64) -> Vec<(i32, i32)> {
        let (pad, swatch, gap, _) = Self::metrics(scale);
        let spacing = px(16.0, scale) as i32;
        let left = px(64.0, scale) as i32;
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
    fn band_height(&self, width: u32, scale: f64) -> u32 {
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

    /// A box with its top-left at `at` (plotting-area pixels), over a place free of data.
    fn draw_box<DB: DrawingBackend>(
        &self,
        area: &DrawingArea<DB, Shift>,
        entries: &[(&str, LineStyle)],
        (x0, y0): (i32, i32),
        theme: &Theme,
        scale: f64,
    ) -> Result<(), RenderError> {
        let (pad, swatch, gap, line_h) = Self::metrics(scale);
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
            Self::swatch(area, (x, y), style, theme, scale)?;
            area.draw(&Text::new(
                label.to_string(),
                (x + swatch + gap, y),
                font.clone(),
            ))
            .map_err(err)?;
        }
        Ok(())
    }

    /// Rows of entries in `band`, the strip under the chart.
    fn draw_rows<DB: DrawingBackend>(
        &self,
        band: &DrawingArea<DB, Shift>,
        entries: &[(&str, LineStyle)],
        theme: &Theme,
        scale: f64,
    ) -> Result<(), RenderError> {
        let (_, swatch, gap, line_h) = Self::metrics(scale);
        let (w, _) = band.dim_in_pixel();
        let font = Self::font(theme, scale);
        for ((label, style), (x, row)) in entries.iter().zip(self.rows(w, scale)) {
            let y = row * line_h + line_h / 2;
            Self::swatch(band, (x, y), style, theme, scale)?;
            band.draw(&Text::new(
                label.to_string(),
                (x + swatch + gap, y),
                font.clone(),
            ))
            .map_err(err)?;
        }
        Ok(())
    }
}

/// A heatmap's colour bar right of the plotting area (`right` edge, `top`..`bottom` in
/// backend pixels of `area`): the colour map from low (bottom) to high (top), its ends
/// and middle labelled, and the metric with its unit written along it.
fn draw_colour_bar<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    h: &crate::figure::Heatmap,
    (right, top, bottom): (i32, i32, i32),
    theme: &Theme,
    scale: f64,
) -> Result<(), RenderError> {
    let (lo, hi) = h.scale;
    if bottom - top < 8 || !(lo.is_finite() && hi.is_finite()) {
        return Ok(());
    }
    let x0 = right + px(12.0, scale) as i32;
    let x1 = x0 + px(12.0, scale) as i32;
    let n = (bottom - top).clamp(2, 128);
    for j in 0..n {
        let ya = bottom - (bottom - top) * j / n;
        let yb = bottom - (bottom - top) * (j + 1) / n;
        let colour = crate::theme::viridis((f64::from(j) + 0.5) / f64::from(n));
        area.draw(&Rectangle::new([(x0, yb), (x1, ya)], colour.filled()))
            .map_err(err)?;
    }
    area.draw(&Rectangle::new(
        [(x0, top), (x1, bottom)],
        theme.grid.stroke_width(1),
    ))
    .map_err(err)?;
    let font = ("sans-serif", 11.0 * scale)
        .into_font()
        .color(&theme.foreground);
    let label_x = x1 + px(4.0, scale) as i32;
    let ends = [
        (hi, top, VPos::Top),
        ((lo + hi) / 2.0, (top + bottom) / 2, VPos::Center),
        (lo, bottom, VPos::Bottom),
    ];
    for (v, y, vpos) in ends {
        area.draw(&Text::new(
            short_label(v, theme.decimal_comma),
            (label_x, y),
            font.clone().pos(Pos::new(HPos::Left, vpos)),
        ))
        .map_err(err)?;
    }
    if !h.label.is_empty() {
        let along = ("sans-serif", 12.0 * scale)
            .into_font()
            .color(&theme.foreground)
            .transform(FontTransform::Rotate90)
            .pos(Pos::new(HPos::Center, VPos::Top));
        let x = right + px(COLOUR_BAR_WIDTH - 4.0, scale) as i32;
        area.draw(&Text::new(h.label.clone(), (x, (top + bottom) / 2), along))
            .map_err(err)?;
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::figure::{Axis, Marker};
    use crate::plot::Ink;

    fn sample() -> Figure {
        Figure {
            series: vec![Series {
                label: "x(t)".into(),
                points: vec![(0.0, 0.0), (0.5, f64::NAN), (0.6, 1e300), (1.0, -0.5)],
                style: LineStyle::solid(Ink::Blue, 2.0),
            }],
            markers: vec![Marker {
                label: "p".into(),
                at: (0.5, 0.5),
                shape: MarkerShape::Cross,
                ink: Ink::Vermillion,
            }],
            origin_lines: true,
            ..Figure::plot(
                "test",
                Axis::linear("time t", "s", (0.0, 1.0)),
                Axis::linear("x", "m", (-1.0, 1.0)),
            )
        }
    }

    #[test]
    fn draws_to_svg_with_axes_legend_and_markers() {
        let mut svg = String::new();
        {
            let root = SVGBackend::with_string(&mut svg, (640, 360)).into_drawing_area();
            render(&root, &sample(), &Theme::LIGHT, 1.0).unwrap();
        }
        assert!(svg.contains("time t [s]"));
        assert!(svg.contains("x(t)"));
        assert!(
            svg.matches("<polyline").count() >= 2,
            "line split at the NaN"
        );
    }

    #[test]
    fn log_axes_never_receive_zero_or_negative_values() {
        let mut fig = sample();
        fig.x = Axis {
            scale: AxisScale::Log,
            ..Axis::linear("r", "", (0.01, 100.0))
        };
        fig.series[0].points = vec![
            (0.0, 1.0),
            (-1.0, 1.0),
            (0.1, 0.5),
            (1.0, 0.2),
            (-0.5, 0.1),
            (10.0, 0.3),
        ];
        let (segs, _) = segments(&fig.series[0], &fig);
        assert_eq!(segs.len(), 2);
        assert!(segs.iter().flatten().all(|p| p.0 > 0.0));
        let mut svg = String::new();
        let root = SVGBackend::with_string(&mut svg, (640, 360)).into_drawing_area();
        render(&root, &fig, &Theme::LIGHT, 1.0).unwrap();
    }

    #[test]
    fn heatmap_cells_are_filled_and_blank_where_undefined() {
        let mut fig = sample();
        fig.heatmap = Some(crate::figure::Heatmap {
            nx: 4,
            ny: 3,
            values: (0..12)
                .map(|i| if i == 5 { f64::NAN } else { i as f64 })
                .collect(),
            x_edges: (0.0, 1.0),
            y_edges: (-1.0, 1.0),
            scale: (0.0, 11.0),
            label: "metric [s]".into(),
        });
        let mut svg = String::new();
        {
            let root = SVGBackend::with_string(&mut svg, (640, 360)).into_drawing_area();
            render(&root, &fig, &Theme::LIGHT, 1.0).unwrap();
        }
        let lo = crate::theme::viridis(0.0);
        let hi = crate::theme::viridis(1.0);
        let hex = |c: RGBColor| format!("#{:02X}{:02X}{:02X}", c.0, c.1, c.2);
        assert!(
            svg.contains(&hex(lo)) && svg.contains(&hex(hi)),
            "both ends of the colour map"
        );
        // The same map with every cell undefined: the same axes, legend and colour bar.
        let without = {
            let mut blank = fig.clone();
            if let Some(h) = &mut blank.heatmap {
                h.values = vec![f64::NAN; 12];
            }
            let mut s = String::new();
            let root = SVGBackend::with_string(&mut s, (640, 360)).into_drawing_area();
            render(&root, &blank, &Theme::LIGHT, 1.0).unwrap();
            drop(root);
            s
        };
        assert!(
            svg.contains("metric [s]"),
            "the colour bar names the metric and unit"
        );
        assert_eq!(
            svg.matches("<rect").count() - without.matches("<rect").count(),
            11
        );
    }

    #[test]
    fn bitmap_heatmap_paints_the_same_colours_as_cells() {
        let mut fig = sample();
        fig.series.clear();
        fig.markers.clear();
        fig.heatmap = Some(crate::figure::Heatmap {
            nx: 2,
            ny: 1,
            values: vec![0.0, 1.0],
            x_edges: (0.0, 1.0),
            y_edges: (-1.0, 1.0),
            scale: (0.0, 1.0),
            label: String::new(),
        });
        let mut svg = String::new();
        {
            let root = SVGBackend::with_string(&mut svg, (320, 160)).into_drawing_area();
            render_with(&root, &fig, &Theme::LIGHT, 1.0, Raster::Bitmap).unwrap();
        }
        let hex = |c: RGBColor| format!("#{:02X}{:02X}{:02X}", c.0, c.1, c.2);
        let (lo, hi) = (
            hex(crate::theme::viridis(0.0)),
            hex(crate::theme::viridis(1.0)),
        );
        let (a, b) = (svg.matches(&lo).count(), svg.matches(&hi).count());
        assert!(
            a > 100 && b > 100,
            "both halves painted pixel by pixel: {a} {b}"
        );
        assert!(
            (a as f64 / b as f64 - 1.0).abs() < 0.1,
            "left and right halves equal: {a} {b}"
        );
    }

    #[test]
    fn tick_labels_are_short_and_follow_the_language() {
        assert_eq!(tick_label(0.1 + 0.2, false), "0.3");
        assert_eq!(tick_label(2.0, false), "2");
        assert_eq!(tick_label(-0.05, false), "-0.05");
        assert_eq!(tick_label(1.000_000_000_000_000_2e-6, false), "1e-6");
        assert_eq!(tick_label(1e-7, false), "1e-7");
        assert_eq!(tick_label(24_000.0, false), "24000");
        assert_eq!(tick_label(0.25, true), "0,25");
        assert_eq!(tick_label(0.0, true), "0");
    }

    #[test]
    fn held_axes_keep_their_ranges_and_widen_only_for_data_that_leaves_them() {
        let mut fig = sample();
        fig.x.range = (0.0, 1.2);
        fig.y.range = (-0.5, 0.5);
        hold_axes(&mut fig, Some(((0.0, 1.5), (-1.0, 1.0))));
        assert_eq!((fig.x.range, fig.y.range), ((0.0, 1.5), (-1.0, 1.0)));
        fig.y.range = (-2.0, 0.5);
        hold_axes(&mut fig, Some(((0.0, 1.5), (-1.0, 1.0))));
        assert_eq!(fig.y.range, (-2.0, 1.0));
        let mut drawing = Figure::schematic(
            "s",
            Axis::linear("x", "m", (0.0, 1.0)),
            Axis::linear("y", "m", (0.0, 1.0)),
        );
        hold_axes(&mut drawing, Some(((0.0, 5.0), (0.0, 5.0))));
        assert_eq!(drawing.x.range, (0.0, 1.0));
    }

    #[test]
    fn log_axes_label_enough_ticks_to_read_a_value() {
        // Two decades: 1, 2, 5 in each.
        assert_eq!(
            log_ticks(0.1, 10.0),
            vec![0.1, 0.2, 0.5, 1.0, 2.0, 5.0, 10.0]
        );
        // Under one decade: still several labelled values.
        assert_eq!(log_ticks(0.5, 3.0), vec![0.5, 0.7, 1.0, 1.5, 2.0, 3.0]);
        assert!(log_ticks(1.1, 1.9).len() >= 2);
        // Many decades: the decades alone.
        assert_eq!(log_ticks(1e-3, 1e2).len(), 6);
        assert!(log_ticks(0.0, 1.0).is_empty());
    }

    /// The top of the legend box in an SVG rendering, if a box was drawn.
    fn legend_box_y(svg: &str) -> Option<f64> {
        // The legend box is the only rectangle filled with the background at 88 % opacity.
        let at = svg.find("opacity=\"0.88\"")?;
        let start = svg[..at].rfind("<rect")?;
        let y = svg[start..].split("y=\"").nth(1)?.split('"').next()?;
        y.parse().ok()
    }

    #[test]
    fn the_legend_goes_where_the_curves_are_not() {
        // A curve along the top of the plot: the legend moves to the bottom.
        let mut fig = sample();
        fig.markers.clear();
        fig.series[0].points = (0..=50).map(|i| (f64::from(i) / 50.0, 0.9)).collect();
        let mut svg = String::new();
        {
            let root = SVGBackend::with_string(&mut svg, (640, 360)).into_drawing_area();
            render(&root, &fig, &Theme::LIGHT, 1.0).unwrap();
        }
        let y = legend_box_y(&svg).expect("a legend box inside the plot");
        assert!(
            y > 180.0,
            "legend in the lower half, clear of the curve: y = {y}"
        );
        // Curves everywhere: the legend goes under the chart, outside the plotting area.
        fig.series = (0..12)
            .map(|k| {
                let level = -1.0 + f64::from(k) / 6.0;
                Series::new(
                    format!("level {k}"),
                    vec![(0.0, level), (1.0, level)],
                    LineStyle::solid(Ink::Blue, 1.0),
                )
            })
            .collect();
        let mut svg = String::new();
        let g = {
            let root = SVGBackend::with_string(&mut svg, (640, 360)).into_drawing_area();
            render(&root, &fig, &Theme::LIGHT, 1.0).unwrap()
        };
        assert!(legend_box_y(&svg).is_none(), "no box over the data");
        assert!(svg.contains("level 11"), "every entry still drawn");
        assert!(
            g.area.3 < 300.0,
            "room left under the chart for the legend rows"
        );
    }

    #[test]
    fn released_axes_ease_from_the_held_ranges_to_the_figures_own() {
        let mut fig = sample();
        fig.x.range = (0.0, 1.0);
        ease_axes(&mut fig, Some(((0.0, 3.0), (-1.0, 1.0))), 0.5);
        assert_eq!(fig.x.range, (0.0, 2.0));
        let mut fig = sample();
        fig.x = Axis::log("f", "Hz", (1.0, 100.0));
        ease_axes(&mut fig, Some(((1.0, 10_000.0), (-1.0, 1.0))), 0.5);
        assert!((fig.x.range.1 - 1000.0).abs() < 1e-9);
        let mut fig = sample();
        ease_axes(&mut fig, Some(((0.0, 3.0), (-5.0, 5.0))), 1.0);
        assert_eq!(fig.x.range, (0.0, 1.0), "at 1 the figure's own ranges");
    }

    #[test]
    fn geometry_round_trips_pixels_and_data() {
        let mut svg = String::new();
        let g = {
            let root = SVGBackend::with_string(&mut svg, (640, 360)).into_drawing_area();
            render(&root, &sample(), &Theme::LIGHT, 1.0).unwrap()
        };
        let (l, t, r, b) = g.area;
        assert!(l > 20.0 && r < 640.0 && t > 10.0 && b < 360.0 && l < r && t < b);
        let (px, py) = g.to_pixel(0.25, 0.5);
        let (x, y) = g.to_data(px, py).unwrap();
        assert!((x - 0.25).abs() < 1e-12 && (y - 0.5).abs() < 1e-12);
        assert!(g.to_data(0.0, 0.0).is_none());
    }

    #[test]
    fn non_finite_points_split_lines_and_huge_ones_are_clamped() {
        let fig = sample();
        let (segs, clipped) = segments(&fig.series[0], &fig);
        assert_eq!(segs.len(), 2);
        assert!(segs[1][0].1 <= 1.05);
        assert!(clipped);
        let mut svg = String::new();
        {
            let root = SVGBackend::with_string(&mut svg, (640, 360)).into_drawing_area();
            render(&root, &fig, &Theme::LIGHT, 1.0).unwrap();
        }
        assert!(svg.contains("clipped"), "the plot says it is clipped");
    }
}
