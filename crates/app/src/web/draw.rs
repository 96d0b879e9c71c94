//! How a [`Session`] builds and draws its figures: only those of plots on screen (and the
//! first plot's, whose text is announced) are built after an update; the others when they
//! come into view, are caught up at rest or exported. During a drag the axes and the legend
//! hold where they were drawn.

use super::result::Description;
use super::session::Session;
use super::{js_err, theme};
use crate::canvas::Canvas;
use crate::figure::Figure;
use crate::render::{ease_axes, hold_axes, render_with, Direct, Output, Placement, PlotGeometry};
use plotters::prelude::IntoDrawingArea;
use wasm_bindgen::JsError;

impl Session {
    /// The index of plot `key` in the declaration.
    pub(super) fn plot_index(&self, key: &str) -> Option<usize> {
        self.spec.plots.iter().position(|p| p.key == key)
    }

    /// Plot `key`'s figure of the last update, if it has been built.
    pub(super) fn figure(&self, key: &str) -> Option<(usize, &Figure)> {
        let i = self.plot_index(key)?;
        Some((i, self.built(i)?))
    }

    /// Plot `i`'s figure of the last update, if it has been built.
    pub(super) fn built(&self, i: usize) -> Option<&Figure> {
        self.figures.get(i)?.as_ref()
    }

    /// Whether the page gave plot `i` a canvas.
    pub(super) fn attached(&self, i: usize) -> bool {
        self.canvases.get(i).is_some_and(Option::is_some)
    }

    /// Builds plot `key`'s figure of the last update unless it has been (see
    /// [`Session::build`]); returns the plot's index if it has a figure.
    pub(super) fn build_plot(&mut self, key: &str) -> Option<usize> {
        let i = self.plot_index(key)?;
        self.build(i).map(|_| i)
    }

    /// Builds plot `i`'s figure of the last update unless it has been, its axes held
    /// during a drag or eased after one, and notes its ranges as shown.
    pub(super) fn build(&mut self, i: usize) -> Option<&Figure> {
        if self.figures.get(i)?.is_none() {
            let mut fig = self.demo.figure(i)?;
            if self.dragging {
                hold_axes(&mut fig, self.shown.get(i).copied().flatten());
            } else if let Some((from, f)) = &self.released {
                ease_axes(&mut fig, from.get(i).copied().flatten(), *f);
            }
            if let Some(slot) = self.shown.get_mut(i) {
                *slot = Some((fig.x.range, fig.y.range));
            }
            *self.figures.get_mut(i)? = Some(fig);
        }
        self.built(i)
    }

    /// The text alternatives of the plots flagged in `which` that have a figure.
    pub(super) fn descriptions(&self, which: &[bool]) -> Vec<Description<'_>> {
        let plots = self.spec.plots.iter().zip(&self.figures).zip(which);
        plots
            .filter(|(_, w)| **w)
            .filter_map(|((p, f), _)| {
                Some(Description {
                    key: p.key,
                    text: &f.as_ref()?.description,
                })
            })
            .collect()
    }

    /// Draws plot `i` alone (see [`Session::draw_plots`]): a plot a task while the controls
    /// rest, or one the page needs drawn now.
    #[cfg(not(feature = "first"))]
    pub(super) fn draw_one(&mut self, i: usize, how: Drawn) -> Result<(), JsError> {
        let mut wanted = vec![false; self.canvases.len()];
        if let Some(w) = wanted.get_mut(i) {
            *w = true;
        }
        self.draw_plots(&wanted, how)
    }

    /// Draws the built figures whose `wanted` flag is set on their attached canvases,
    /// clearing their `stale` mark and keeping where each was drawn.
    pub(super) fn draw_plots(&mut self, wanted: &[bool], how: Drawn) -> Result<(), JsError> {
        let scale = device_scale(how.scale, 4.0);
        let plots = self.canvases.iter().zip(&self.figures).enumerate();
        for (i, (canvas, fig)) in plots {
            if wanted.get(i) != Some(&true) {
                continue;
            }
            // A plot with no figure (parameters that describe no valid system) has nothing
            // newer to show either.
            if let Some(slot) = self.stale.get_mut(i) {
                *slot = false;
            }
            let Some((fig, backend)) = fig
                .as_ref()
                .zip(canvas.as_ref().and_then(crate::canvas::on_surface))
            else {
                continue;
            };
            // During a drag the legend stays where it was last drawn.
            let held = self.geometry.get(i).copied().flatten();
            let legend = held.filter(|_| self.dragging).map(|g| g.legend);
            let geo = draw_on(backend, fig, how.dark, scale, legend)?;
            if let Some(slot) = self.geometry.get_mut(i) {
                *slot = Some(geo);
            }
        }
        Ok(())
    }
}

/// How plots are drawn: `scale` = devicePixelRatio (clamped to 0.5…4), dark or light theme.
#[derive(Debug, Clone, Copy)]
pub(super) struct Drawn {
    pub(super) scale: f64,
    pub(super) dark: bool,
}

/// Draws `fig` on a canvas in the light or dark theme (heatmaps as one bitmap), the legend
/// at `legend` if given (see [`Output::legend`]).
pub(super) fn draw_on(
    backend: Canvas,
    fig: &Figure,
    dark: bool,
    scale: f64,
    legend: Option<Placement>,
) -> Result<PlotGeometry, JsError> {
    let direct = crate::canvas::direct(&backend);
    let out = Output {
        direct: direct.as_ref().map(|d| d as &dyn Direct),
        legend,
    };
    render_with(&backend.into_drawing_area(), fig, &theme(dark), scale, out).map_err(js_err)
}

/// A page's device pixel ratio as a drawing scale: clamped to `0.5…max`, 1 if not finite.
pub(super) fn device_scale(scale: f64, max: f64) -> f64 {
    match scale.is_finite() {
        true => scale.clamp(0.5, max),
        false => 1.0,
    }
}
