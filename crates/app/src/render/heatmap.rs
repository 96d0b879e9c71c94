//! Heatmap cells: one rectangle each, or one bitmap on backends that blit fast.

use super::chart::Chart;
use super::{err, RenderError};
use crate::theme::Theme;
use plotters::element::{Drawable, PointCollection};
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

/// An RGB image placed with its top-left corner at a point; drawn by the backend's
/// `blit_bitmap`.
pub(super) struct Image<C> {
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
/// The caller checks [`Heatmap::has_every_cell`](crate::figure::Heatmap::has_every_cell).
pub(super) fn blit_heatmap<DB: DrawingBackend>(
    chart: &mut Chart<'_, DB>,
    h: &crate::figure::Heatmap,
    theme: &Theme,
) -> Result<(), RenderError> {
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
