//! A heatmap's colour bar and its labels.

use super::ticks::short_label;
use super::{err, px, Direct, RenderError, Stretched};
use crate::theme::Theme;
use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

/// CSS pixels right of the plotting area taken by a heatmap's colour bar and its labels.
pub(super) const COLOUR_BAR_WIDTH: f64 = 92.0;

/// A heatmap's colour bar right of the plotting area (`right` edge, `top`..`bottom` in
/// backend pixels of `area`): the colour map from low (bottom) to high (top), its ends
/// and middle labelled, and the metric with its unit written along it.
pub(super) fn draw_colour_bar<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    h: &crate::figure::Heatmap,
    (right, top, bottom): (i32, i32, i32),
    theme: &Theme,
    scale: f64,
    direct: Option<&dyn Direct>,
) -> Result<(), RenderError> {
    let (lo, hi) = h.scale;
    if bottom - top < 8 || !(lo.is_finite() && hi.is_finite()) {
        return Ok(());
    }
    let x0 = right + px(12.0, scale) as i32;
    let x1 = x0 + px(12.0, scale) as i32;
    let n = (bottom - top).clamp(2, 128);
    let colour = |j: i32| crate::theme::viridis((f64::from(j) + 0.5) / f64::from(n));
    match direct {
        // The same bands as one image of a pixel per band.
        Some(direct) => {
            let rgb: Vec<u8> = (0..n)
                .rev()
                .flat_map(|j| {
                    let c = colour(j);
                    [c.0, c.1, c.2]
                })
                .collect();
            let rect = [x0, top, x1, bottom];
            direct.stretch(&Stretched {
                size: (1, n as u32),
                rgb: &rgb,
                to: rect,
                clip: rect,
            });
        }
        None => {
            for j in 0..n {
                let ya = bottom - (bottom - top) * j / n;
                let yb = bottom - (bottom - top) * (j + 1) / n;
                area.draw(&Rectangle::new([(x0, yb), (x1, ya)], colour(j).filled()))
                    .map_err(err)?;
            }
        }
    }
    area.draw(&Rectangle::new(
        [(x0, top), (x1, bottom)],
        theme.grid.stroke_width(1),
    ))
    .map_err(err)?;
    let font = (super::SANS, 11.0 * scale)
        .into_font()
        .color(&theme.foreground);
    let label_x = x1 + px(4.0, scale) as i32;
    // On a logarithmic bar the positions are ln(value): label the values themselves.
    let value = |position: f64| if h.log { position.exp() } else { position };
    let ends = [
        (value(hi), top, VPos::Top),
        (value((lo + hi) / 2.0), (top + bottom) / 2, VPos::Center),
        (value(lo), bottom, VPos::Bottom),
    ];
    for (v, y, vpos) in ends {
        area.draw(&Text::new(
            short_label(v),
            (label_x, y),
            font.clone().pos(Pos::new(HPos::Left, vpos)),
        ))
        .map_err(err)?;
    }
    if !h.label.is_empty() {
        let (label, size) = super::fit::fit(area, &h.label, 12.0 * scale, f64::from(bottom - top));
        let along = (super::SANS, size)
            .into_font()
            .color(&theme.foreground)
            .transform(FontTransform::Rotate90)
            .pos(Pos::new(HPos::Center, VPos::Top));
        let x = right + px(COLOUR_BAR_WIDTH - 4.0, scale) as i32;
        area.draw(&Text::new(label, (x, (top + bottom) / 2), along))
            .map_err(err)?;
    }
    Ok(())
}
