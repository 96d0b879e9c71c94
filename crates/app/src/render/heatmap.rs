//! Heatmap cells: one rectangle each, or one image stretched over them on backends that
//! draw images themselves ([`Direct`]).

use super::chart::Chart;
use super::{err, Direct, RenderError, Stretched};
use crate::theme::Theme;
use plotters::prelude::*;

/// Fills the heatmap's cells (one rectangle each; blank where the value is not finite).
/// The caller checks [`Heatmap::has_every_cell`](crate::figure::Heatmap::has_every_cell).
pub(super) fn draw_heatmap<DB: DrawingBackend>(
    chart: &mut Chart<'_, DB>,
    h: &crate::figure::Heatmap,
) -> Result<(), RenderError> {
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

/// Draws the heatmap as one image of a pixel per cell, stretched over the cells' pixel
/// rectangle and clipped to the plotting area; blank cells show the background. The
/// caller checks [`Heatmap::has_every_cell`](crate::figure::Heatmap::has_every_cell).
pub(super) fn stretch_heatmap<DB: DrawingBackend>(
    chart: &Chart<'_, DB>,
    h: &crate::figure::Heatmap,
    theme: &Theme,
    direct: &dyn Direct,
) {
    let (xs, ys) = chart.plotting_area().get_pixel_range();
    let (left, top) = chart.backend_coord(&(h.x_edges.0, h.y_edges.1));
    let (right, bottom) = chart.backend_coord(&(h.x_edges.1, h.y_edges.0));
    if right <= left || bottom <= top {
        return;
    }
    let (lo, hi) = h.scale;
    let span = if hi > lo { hi - lo } else { 1.0 };
    let bg = theme.background;
    // Rows go up in data, down in the image.
    let mut rgb = Vec::with_capacity(h.nx * h.ny * 3);
    for iy in (0..h.ny).rev() {
        for ix in 0..h.nx {
            let c = match h.values.get(iy * h.nx + ix) {
                Some(&v) if v.is_finite() => crate::theme::viridis((v - lo) / span),
                _ => bg,
            };
            rgb.extend_from_slice(&[c.0, c.1, c.2]);
        }
    }
    direct.stretch(&Stretched {
        size: (h.nx as u32, h.ny as u32),
        rgb: &rgb,
        to: [left, top, right, bottom],
        clip: [xs.start, ys.start, xs.end, ys.end],
    });
}
