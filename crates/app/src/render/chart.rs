//! A plot with axes: the chart, its mesh and tick labels, and where each layer goes.

use super::colour_bar::{draw_colour_bar, COLOUR_BAR_WIDTH};
use super::fit::fit;
use super::heatmap::{draw_heatmap, stretch_heatmap};
use super::legend::{free_corner, legend_entries, Legend};
use super::lines::{draw_lines_and_markers, draw_series};
use super::scale::Scale;
use super::ticks::axis_tick_label;
use super::{err, px, Kept, LayerKeys, Output, RenderError};
use crate::figure::{AxisScale, Figure, LineStyle};
use crate::theme::Theme;
use plotters::coord::Shift;
use plotters::prelude::*;
use std::hash::{Hash, Hasher};

/// Where a figure's legend goes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Placement {
    /// No legend entries.
    None,
    /// A box with its top-left corner here, in plotting-area pixels, over no data.
    Inside(i32, i32),
    /// Rows under the chart, outside the plotting area (no corner was free of data), in a
    /// band this high (backend pixels; 0 until measured). Held, the band keeps at least
    /// its height, so entries that wrap to fewer rows do not move the chart.
    Below(u32),
}

/// Left, top, right, bottom edges of a plotting area, backend pixels.
pub(super) type Edges = (f64, f64, f64, f64);

/// A chart over data values, on linear or log axes (one type for every pairing).
pub(super) type Chart<'a, DB> = ChartContext<'a, DB, Cartesian2d<Scale, Scale>>;

/// Whether a canvas `height` backend pixels high is short (under 300 px at scale 1: a
/// phone's staged plot, about 200 px, and its other plots): the tick labels and the axis
/// name under the chart sit closer, so more of the height is data.
fn is_short(height: u32, scale: f64) -> bool {
    f64::from(height) < 300.0 * scale
}

/// The chart of `fig` on `area`, leaving room for the title, tick labels and axis names;
/// `short` (see [`is_short`]): less room under the chart.
pub(super) fn build<'a, DB: DrawingBackend>(
    area: &'a DrawingArea<DB, Shift>,
    fig: &Figure,
    theme: &Theme,
    scale: f64,
    short: bool,
) -> Result<Chart<'a, DB>, RenderError> {
    // The title's band, left blank for [`draw_title`]: as high as the title at its full
    // size and [`TITLE_GAP`] more, whatever size it is drawn at, so a title that grows or
    // shrinks with the data (a map's names its range) neither moves the plot nor changes
    // its static layer.
    let font = (super::SANS, (TITLE_SIZE + TITLE_GAP) * scale)
        .into_font()
        .color(&theme.foreground);
    ChartBuilder::on(area)
        .caption("", font)
        .margin(px(MARGIN, scale))
        .margin_right(px(right_margin(fig), scale))
        .margin_bottom(px(if short { 4.0 } else { MARGIN }, scale))
        .x_label_area_size(px(if short { 34.0 } else { 42.0 }, scale))
        .y_label_area_size(px(64.0, scale))
        .build_cartesian_2d(Scale::of(&fig.x), Scale::of(&fig.y))
        .map_err(err)
}

/// A title's full size (px at scale 1); a long one is drawn smaller (see [`fit`]).
const TITLE_SIZE: f64 = 15.0;

/// Room (px at scale 1) the title's band keeps below the title: a tick label at the top
/// of the y axis is centred on the plot's top edge, and reached into the title.
const TITLE_GAP: f64 = 6.0;

/// The chart's margin (px at scale 1): [`build`] leaves it, and [`fit_title`] and
/// [`draw_title`] place the title inside it as [`build`]'s caption would be.
const MARGIN: f64 = 10.0;

/// The right margin (px at scale 1): wider beside a colour bar, and on a log x axis that
/// ends on a labelled tick, wide enough for the half of its label past the end (the
/// work–precision plot's `100000` was cut in two).
fn right_margin(fig: &Figure) -> f64 {
    if fig.heatmap.is_some() {
        return COLOUR_BAR_WIDTH;
    }
    MARGIN.max(end_label_overhang(&fig.x))
}

/// Width of a digit of the tick labels (px at scale 1, 12 px sans-serif: 0.56 em), a
/// generous estimate, so that the margin needs no text measured.
const DIGIT_WIDTH: f64 = 6.8;

/// How far (px at scale 1) the label of a tick at the right end of log axis `axis` reaches
/// past the end, with 2 px to spare; 0 if no labelled tick is within 2 % of its decades
/// from the end, or on a linear axis (whose labels are short numbers).
fn end_label_overhang(axis: &crate::figure::Axis) -> f64 {
    let (lo, hi) = axis.range;
    if axis.scale != AxisScale::Log || !(lo > 0.0 && hi > lo) {
        return 0.0;
    }
    let Some(&last) = super::ticks::log_ticks(lo, hi).last() else {
        return 0.0;
    };
    if (hi / last).log10() > 0.02 * (hi / lo).log10() {
        return 0.0;
    }
    let chars = axis_tick_label(last, axis).chars().count() as f64;
    DIGIT_WIDTH * chars / 2.0 + 2.0
}

/// The title as drawn and its size (px): centred between the margins, fitted to the room.
fn fit_title<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    fig: &Figure,
    scale: f64,
) -> (String, f64) {
    let (w, _) = area.dim_in_pixel();
    let room =
        f64::from(w) - f64::from(px(MARGIN, scale)) - f64::from(px(right_margin(fig), scale));
    fit(area, &fig.title, TITLE_SIZE * scale, room)
}

/// Draws the title on the band [`build`] left, centred between the margins (plotters'
/// own title placement); drawn after a kept static layer, which holds only the band.
fn draw_title<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    fig: &Figure,
    theme: &Theme,
    scale: f64,
) -> Result<(), RenderError> {
    let (text, size) = fit_title(area, fig, scale);
    let font = (super::SANS, size).into_font().color(&theme.foreground);
    let m = px(MARGIN, scale);
    area.margin(m, m, m, px(right_margin(fig), scale))
        .titled(&text, font)
        .map(|_| ())
        .map_err(err)
}

/// What a plot's static layer (background, the title's band, grid, ticks, axis names and
/// the first `backdrop` series) depends on, hashed (the title itself is drawn over it, see
/// [`draw_title`]): under the backdrop, the axes, whether a colour bar takes room on the
/// right, whether the origin lines are drawn, the theme, the scale, the backend's size and the legend band's height, and the
/// language's way of writing numbers; the whole layer, those and the backdrop's points and
/// strokes. Hashed with `FxHasher`: a key for the layer last drawn on one canvas, not a
/// guard against chosen collisions, and several times cheaper per point than the standard
/// hasher (resonance's family is ~6 500 points, hashed every frame of a drag);
/// fluent-bundle links it already.
pub(super) fn static_keys(
    fig: &Figure,
    backdrop: usize,
    theme: &Theme,
    scale: f64,
    size: (u32, u32, u32),
) -> LayerKeys {
    let mut h = rustc_hash::FxHasher::default();
    for axis in [&fig.x, &fig.y] {
        (&axis.label, axis.unit, axis.scale == AxisScale::Log).hash(&mut h);
        (axis.range.0.to_bits(), axis.range.1.to_bits()).hash(&mut h);
    }
    (fig.heatmap.is_some(), fig.origin_lines).hash(&mut h);
    for c in [
        theme.background,
        theme.foreground,
        theme.grid,
        theme.grid_minor,
    ] {
        (c.0, c.1, c.2).hash(&mut h);
    }
    (scale.to_bits(), size).hash(&mut h);
    super::tick_label(1.5).hash(&mut h);
    let axes = h.finish();
    if backdrop == 0 {
        return LayerKeys { axes, whole: axes };
    }
    for s in fig.series.iter().take(backdrop) {
        let style = s.style;
        (style.ink.index(), style.width.to_bits(), style.dash as u8).hash(&mut h);
        s.points.len().hash(&mut h);
        for &(x, y) in &s.points {
            (x.to_bits(), y.to_bits()).hash(&mut h);
        }
    }
    // Never equal to `axes`: equal keys say there is no backdrop.
    let whole = match h.finish() {
        w if w == axes => w ^ 1,
        w => w,
    };
    LayerKeys { axes, whole }
}

/// The legend rows `entries` (labels and swatches) as a hash, never 0 (0 stands for no
/// rows in [`super::LayerNote`]).
fn rows_key(entries: &[(&str, LineStyle)]) -> u64 {
    let mut h = rustc_hash::FxHasher::default();
    for (label, style) in entries {
        (
            label,
            style.ink.index(),
            style.width.to_bits(),
            style.dash as u8,
        )
            .hash(&mut h);
    }
    h.finish().max(1)
}

/// What names `axis` in `room` px from `size` px down, and the size it fits at (see
/// [`fit`]): its whole title if that fits, shrunk or not; else its short form
/// ([`crate::figure::Axis::short_title`]: symbol and unit) if that fits; else the title,
/// to be cut. A phone's short plot then reads `x [mm]` rather than `displacement x [m…`,
/// which loses the unit.
fn axis_name<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    axis: &crate::figure::Axis,
    size: f64,
    room: f64,
) -> (String, f64) {
    let title = axis.title();
    let (text, fits_at) = fit(area, &title, size, room);
    if text == title {
        return (title, fits_at);
    }
    if let Some(short) = axis.short_title() {
        let (text, short_at) = fit(area, &short, size, room);
        if text == short {
            return (short, short_at);
        }
    }
    (title, fits_at)
}

/// The grid, ticks, tick labels and axis names of `chart`: axis names as long as the
/// axes, one size for both, each cut only if it must be.
fn draw_mesh<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    chart: &mut Chart<'_, DB>,
    fig: &Figure,
    theme: &Theme,
    scale: f64,
) -> Result<(), RenderError> {
    let fg = theme.foreground;
    let font = |size: f64| (super::SANS, size * scale).into_font().color(&fg);
    let (px_w, px_h) = chart.plotting_area().dim_in_pixel();
    let (x_title, x_size) = axis_name(area, &fig.x, 13.0 * scale, f64::from(px_w));
    let (y_title, y_size) = axis_name(area, &fig.y, 13.0 * scale, f64::from(px_h));
    let desc = x_size.min(y_size);
    let (x_title, _) = fit(area, &x_title, desc, f64::from(px_w));
    let (y_title, _) = fit(area, &y_title, desc, f64::from(px_h));
    chart
        .configure_mesh()
        .x_desc(x_title)
        .y_desc(y_title)
        .axis_desc_style((super::SANS, desc).into_font().color(&fg))
        .label_style(font(12.0))
        .bold_line_style(theme.grid.stroke_width(px(1.0, scale)))
        .light_line_style(theme.grid_minor.stroke_width(px(1.0, scale)))
        .max_light_lines(4)
        .axis_style(fg.stroke_width(px(1.0, scale)))
        .x_labels(LABELS)
        .y_labels(y_label_count(px_h, scale))
        .x_label_formatter(&|v| axis_tick_label(*v, &fig.x))
        .y_label_formatter(&|v| axis_tick_label(*v, &fig.y))
        .draw()
        .map_err(err)
}

/// Tick labels an axis asks for (plotters' hint; a log axis gives all of its labelled
/// ticks for this many or more, see `scale::Scale`).
pub(super) const LABELS: usize = 6;

/// Tick labels one on a y axis `height` backend pixels long may carry: six, or fewer on a
/// short plot, at least 2.5 label heights (12 px at scale 1) apart, and never under two
/// (a phone's 70-px convergence plot stacked eleven decades into one another).
pub(super) fn y_label_count(height: u32, scale: f64) -> usize {
    let fits = f64::from(height) / (2.5 * 12.0 * scale);
    (fits.floor() as usize).clamp(2, LABELS)
}

/// The reference lines through the origin, if `fig` has them and they fall in its range.
fn draw_origin_lines<DB: DrawingBackend>(
    chart: &mut Chart<'_, DB>,
    fig: &Figure,
    theme: &Theme,
    scale: f64,
) -> Result<(), RenderError> {
    if !fig.origin_lines {
        return Ok(());
    }
    let fg = theme.foreground;
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
    Ok(())
}

pub(super) fn draw<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    fig: &Figure,
    theme: &Theme,
    scale: f64,
    out: Output<'_>,
) -> Result<(Edges, Placement), RenderError> {
    let entries = legend_entries(fig);
    let legend = Legend::measure(root, &entries, scale)?;
    let short = is_short(root.dim_in_pixel().1, scale);

    // Where the legend can go without covering data: a trial layout gives the pixels.
    // During a held drag it stays where it was (`out.legend`; a box whose entries grew is
    // moved in just enough to fit): a legend that jumps between corners, or between a
    // corner and rows below, moves the plot under the pointer and makes it draw whole.
    let mut placement = Placement::None;
    let held = out
        .legend
        .filter(|p| *p != Placement::None && !entries.is_empty());
    if let Some(held) = held {
        placement = held;
    } else if !entries.is_empty() {
        if let Some(direct) = out.direct {
            direct.mute(true);
        }
        let trial = build(root, fig, theme, scale, short);
        if let Some(direct) = out.direct {
            direct.mute(false);
        }
        placement = match free_corner(&trial?, fig, legend.size, scale) {
            Some((x, y)) => Placement::Inside(x, y),
            None => Placement::Below(0),
        };
        if out.direct.is_none() {
            root.fill(&theme.background).map_err(err)?;
        }
    }
    let (w, h) = root.dim_in_pixel();
    let band_h = match placement {
        Placement::Below(held) => legend.band_height(w, scale).max(held).min(h / 3),
        _ => 0,
    };
    if let Placement::Below(_) = placement {
        placement = Placement::Below(band_h);
    }
    let (area, band) = root.split_vertically(h.saturating_sub(band_h));
    // The origin lines and the backdrop series go into the static layer, under the other
    // series; over a heatmap, which is drawn over the layer, there is no backdrop and the
    // origin lines come after it.
    let backdrop = match fig.heatmap {
        Some(_) => 0,
        None => fig.backdrop.min(fig.series.len()),
    };
    let layer = out
        .direct
        .map(|d| (d, static_keys(fig, backdrop, theme, scale, (w, h, band_h))));
    // A legend in rows under the chart covers no data: it goes into the static layer, so a
    // drag need not draw its swatches and labels every frame; over a kept layer whose rows
    // differ (a label that names a value), the band is cleared and the rows drawn again.
    let rows = match placement {
        Placement::Below(_) if layer.is_some() && !cfg!(feature = "first") => rows_key(&entries),
        _ => 0,
    };
    // A layer the backend keeps is drawn already: its mesh (and backdrop) are skipped.
    let kept = layer.and_then(|(direct, keys)| direct.begin_layer(keys));
    if layer.is_some() && kept.is_none() {
        root.fill(&theme.background).map_err(err)?;
    }
    let mut chart = build(&area, fig, theme, scale, short)?;
    let (backdrop_clipped, rows_drawn) = match kept {
        Some(Kept::Whole(note)) => (note.clipped, note.rows),
        _ => {
            if kept.is_none() {
                draw_mesh(&area, &mut chart, fig, theme, scale)?;
                if fig.heatmap.is_none() {
                    draw_origin_lines(&mut chart, fig, theme, scale)?;
                }
            }
            if let Some((direct, keys)) = layer {
                direct.axes_done(keys);
            }
            let clipped = draw_series(
                &mut chart,
                &fig.series[..backdrop],
                fig,
                theme,
                scale,
                out.direct,
            )?;
            if rows != 0 {
                legend.draw_rows(&band, &entries, theme, scale)?;
            }
            (clipped, rows)
        }
    };
    if let Some((direct, keys)) = layer {
        let note = super::LayerNote {
            clipped: backdrop_clipped,
            rows: rows_drawn,
        };
        direct.end_layer(keys, note);
    }
    draw_title(&area, fig, theme, scale)?;

    if let Some(h) = &fig.heatmap {
        if h.has_every_cell() {
            // One image needs linear axes; on log axes the cells are drawn.
            let linear = (fig.x.scale, fig.y.scale) == (AxisScale::Linear, AxisScale::Linear);
            match out.direct {
                Some(direct) if linear => stretch_heatmap(&chart, h, theme, direct),
                _ => draw_heatmap(&mut chart, h)?,
            }
        }
        let (xs, ys) = chart.plotting_area().get_pixel_range();
        let bar = (xs.end, ys.start, ys.end);
        draw_colour_bar(&area, h, bar, theme, scale, out.direct)?;
    }

    if fig.heatmap.is_some() {
        draw_origin_lines(&mut chart, fig, theme, scale)?;
    }

    let right = area.get_pixel_range().0.end;
    draw_lines_and_markers(
        &mut chart,
        fig,
        theme,
        scale,
        (out.direct, right),
        (backdrop, backdrop_clipped),
    )?;
    match placement {
        Placement::Inside(x, y) => {
            let plot = chart.plotting_area().strip_coord_spec();
            let (aw, ah) = plot.dim_in_pixel();
            let pad = px(6.0, scale) as i32;
            let (bw, bh) = legend.size;
            let x = x.min(aw as i32 - bw - pad).max(pad);
            let y = y.min(ah as i32 - bh - pad).max(pad);
            legend.draw_box(&plot, &entries, (x, y), theme, scale)?
        }
        // Rows the static layer holds already (see `rows`) are not drawn again.
        Placement::Below(_) if rows_drawn == rows && rows != 0 => {}
        Placement::Below(_) => {
            if rows_drawn != 0 && !cfg!(feature = "first") {
                band.fill(&theme.background).map_err(err)?;
            }
            legend.draw_rows(&band, &entries, theme, scale)?
        }
        Placement::None => {}
    }
    let (xs, ys) = chart.plotting_area().get_pixel_range();
    let area = (
        f64::from(xs.start),
        f64::from(ys.start),
        f64::from(xs.end),
        f64::from(ys.end),
    );
    Ok((area, placement))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::figure::Axis;

    #[test]
    fn a_log_axis_ending_on_a_tick_leaves_room_for_half_its_label() {
        // `100000` at 12 px: six digits, half of them past the end.
        let wide = end_label_overhang(&Axis::log("N", "", (10.0, 1e5)));
        assert!(wide >= 3.0 * 6.5, "{wide}");
        // Ending between ticks (the last, 10⁴, is a fifth of the decades from the end), or
        // linear: the usual margin.
        assert_eq!(end_label_overhang(&Axis::log("N", "", (10.0, 5e4))), 0.0);
        assert_eq!(end_label_overhang(&Axis::linear("t", "s", (0.0, 1e5))), 0.0);
    }
}
