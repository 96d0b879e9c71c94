//! [`Session`]: one open demo, its parameters, canvases and last figures.

use super::result::{Description, SetResult, StaleResult, UpdateResult};
use super::translate::translate_spec;
use super::{js_err, theme, to_js};
use crate::canvas::Canvas;
use crate::demos::{self, Demo, Frame};
use crate::export;
use crate::figure::Figure;
use crate::params::{resolve_query, Params};
use crate::render::{
    ease_axes, hold_axes, render, render_with, AxisRanges, Direct, Output, Placement, PlotGeometry,
};
use crate::spec::DemoSpec;
use plotters::prelude::IntoDrawingArea;
use wasm_bindgen::prelude::*;
use web_sys::HtmlCanvasElement;

/// One open demo: its parameters, canvases, last figures and where they were drawn.
#[wasm_bindgen]
pub struct Session {
    demo: Box<dyn Demo>,
    spec: DemoSpec,
    params: Params,
    canvases: Vec<Option<HtmlCanvasElement>>,
    /// Whether each plot's canvas is on screen, as the page observes it. An update draws
    /// only those; the others wait, [`stale`](Self::stale), for [`Session::draw_stale`].
    visible: Vec<bool>,
    /// Plots whose canvas shows an older frame than the last update's.
    stale: Vec<bool>,
    schematic_canvas: Option<HtmlCanvasElement>,
    /// The last update's readouts and time span (its figures are in `figures`).
    frame: Option<Frame>,
    /// The last update's figures, each built when it is first drawn or asked for (see
    /// [`Demo::figure`]): while a control moves, plots out of view cost nothing.
    figures: Vec<Option<Figure>>,
    geometry: Vec<Option<PlotGeometry>>,
    /// Whether a control is being dragged: axes then hold (see [`hold_axes`]).
    dragging: bool,
    /// Each plot's axis ranges as last drawn, `(x, y)`.
    shown: Vec<Option<AxisRanges>>,
    /// The ranges held when the last drag ended, and how far (0…1) the axes have moved
    /// from them to the figures' own (see [`ease_axes`]).
    released: Option<(Vec<Option<AxisRanges>>, f64)>,
}

#[wasm_bindgen]
impl Session {
    /// Opens demo `id`; errors for an unknown id.
    #[wasm_bindgen(constructor)]
    pub fn new(id: &str) -> Result<Session, JsError> {
        let mut demo =
            demos::create(id).ok_or_else(|| JsError::new(&format!("unknown demo {id:?}")))?;
        demo.set_progressive(true);
        let spec = demo.spec();
        let params = Params::defaults(&spec);
        let n = spec.plots.len();
        Ok(Session {
            demo,
            spec,
            params,
            canvases: vec![None; n],
            visible: vec![true; n],
            stale: vec![false; n],
            schematic_canvas: None,
            frame: None,
            figures: vec![None; n],
            geometry: vec![None; n],
            dragging: false,
            shown: vec![None; n],
            released: None,
        })
    }

    /// The demo's declaration (see [`DemoSpec`]).
    pub fn spec(&self) -> Result<JsValue, JsError> {
        to_js(&translate_spec(&self.spec))
    }

    /// Applies a URL query string (`?demo=…&zeta=0.2`); returns the notices `[{key, message}]`.
    #[wasm_bindgen(js_name = applyQuery)]
    pub fn apply_query(&mut self, query: &str) -> Result<JsValue, JsError> {
        // Lecturer overrides (`range.<key>=lo,hi`, `step.<key>=…`) narrow the spec first.
        let mut notices = crate::lecturer::narrow(&mut self.spec, query);
        let (params, more) = resolve_query(&self.spec, query);
        notices.extend(more);
        self.params = params;
        to_js(&notices)
    }

    /// Sets one parameter from text (a slider, number box, checkbox or list); returns
    /// `{value, notice}`, or `undefined` for an unknown key.
    pub fn set(&mut self, key: &str, raw: &str) -> Result<JsValue, JsError> {
        match self.params.set_raw(&self.spec, key, raw) {
            Some((value, notice)) => to_js(&SetResult { value, notice }),
            None => Ok(JsValue::UNDEFINED),
        }
    }

    /// Current values as `[[key, value], …]` in spec order.
    pub fn values(&self) -> Result<JsValue, JsError> {
        let pairs: Vec<(&str, f64)> = self.params.pairs().collect();
        to_js(&pairs)
    }

    /// Gives the canvas for plot `key` (or `"schematic"`); returns whether the key exists.
    pub fn attach(&mut self, key: &str, canvas: HtmlCanvasElement) -> bool {
        if key == "schematic" && self.spec.schematic {
            self.schematic_canvas = Some(canvas);
            return true;
        }
        match self.spec.plots.iter().position(|p| p.key == key) {
            Some(i) => {
                if let Some(slot) = self.canvases.get_mut(i) {
                    *slot = Some(canvas);
                }
                true
            }
            None => false,
        }
    }

    /// Recomputes, draws every attached plot canvas that is on screen (sized by the page
    /// at `scale` = devicePixelRatio; see [`Session::set_visible`]) and returns
    /// `{readouts, descriptions, time_span, derived, provisional, tour}`. Only the figures
    /// drawn, and the first plot's (its text is announced), are built.
    pub fn update(&mut self, scale: f64, dark: bool) -> Result<JsValue, JsError> {
        let frame = self.demo.recompute(&self.params);
        let mut derived = Vec::new();
        for (key, value) in self.demo.derived_params() {
            if let Some((v, _)) = self.params.set_raw(&self.spec, key, &format!("{value}")) {
                derived.push((key, v));
            }
        }
        self.frame = Some(frame);
        self.figures.fill(None);
        self.stale.fill(true);
        let built: Vec<bool> = (0..self.figures.len())
            .map(|i| (i == 0 || self.visible[i] && self.attached(i)) && self.build(i).is_some())
            .collect();
        self.draw_plots(&self.visible.clone(), Drawn { scale, dark })?;
        let descriptions = self.descriptions(&built);
        let frame = self.frame.as_ref().ok_or_else(|| js_err("no frame"))?;
        to_js(&UpdateResult {
            readouts: &frame.readouts,
            descriptions,
            time_span: frame.time_span,
            derived,
            provisional: self.demo.provisional(),
            tour: self.demo.tour(),
        })
    }

    /// Tells the session whether plot `key`'s canvas is on screen (the page observes it;
    /// every plot counts as on screen until told otherwise). Returns whether the plot has
    /// just come into view showing an older frame: the page then calls
    /// [`Session::draw_stale`].
    #[wasm_bindgen(js_name = setVisible)]
    pub fn set_visible(&mut self, key: &str, on: bool) -> bool {
        let Some(i) = self.spec.plots.iter().position(|p| p.key == key) else {
            return false;
        };
        if let Some(v) = self.visible.get_mut(i) {
            *v = on;
        }
        on && self.stale.get(i).copied().unwrap_or(false)
    }

    /// Draws the plots that show an older frame than the last update's, from that update's
    /// results (nothing is recomputed): those on screen, or with `all` the first one of any
    /// (the page calls that once per task while the controls rest, so no task grows long).
    /// Returns `{left, descriptions}`: whether any plot is still stale, and the text
    /// alternatives of those drawn.
    #[wasm_bindgen(js_name = drawStale)]
    pub fn draw_stale(&mut self, scale: f64, dark: bool, all: bool) -> Result<JsValue, JsError> {
        if self.frame.is_none() {
            return to_js(&StaleResult {
                left: false,
                descriptions: Vec::new(),
            });
        }
        let next = self.stale.iter().position(|s| *s);
        let wanted: Vec<bool> = (self.stale.iter().zip(&self.visible).enumerate())
            .map(|(i, (stale, on))| *stale && if all { Some(i) == next } else { *on })
            .collect();
        // A plot the page shows no canvas for (an embed's `plots=`) is not built; drawing
        // clears its mark.
        for (i, _) in wanted.iter().enumerate().filter(|(_, w)| **w) {
            if self.attached(i) {
                self.build(i);
            }
        }
        self.draw_plots(&wanted, Drawn { scale, dark })?;
        to_js(&StaleResult {
            left: self.stale.iter().any(|s| *s),
            descriptions: self.descriptions(&wanted),
        })
    }

    /// Sets up, while the controls rest, what a first drag would otherwise pay for: the
    /// canvas that keeps each attached plot's static layer (see `canvas::prepare`).
    #[wasm_bindgen(js_name = prepareLayers)]
    pub fn prepare_layers(&self) {
        for canvas in self.canvases.iter().flatten() {
            crate::canvas::prepare(canvas);
        }
    }

    /// Continues a pending heavy study (sweep, Monte Carlo) for about `budget_ms`:
    /// `undefined` when none is pending, else the fraction done (1: finished, call `update`).
    pub fn refine(&mut self, budget_ms: f64) -> Option<f64> {
        self.demo.refine(budget_ms)
    }

    /// Draws the schematic at time `t` \[s\]; returns its text alternative.
    #[wasm_bindgen(js_name = drawSchematic)]
    pub fn draw_schematic(&self, t: f64, scale: f64, dark: bool) -> Result<String, JsError> {
        let (Some(canvas), Some(fig)) = (
            &self.schematic_canvas,
            self.demo
                .schematic(&self.params, if t.is_finite() { t } else { 0.0 }),
        ) else {
            return Ok(String::new());
        };
        if let Some(backend) = crate::canvas::on(canvas) {
            let scale = if scale.is_finite() {
                scale.clamp(0.5, 4.0)
            } else {
                1.0
            };
            render(&backend.into_drawing_area(), &fig, &theme(dark), scale).map_err(js_err)?;
        }
        Ok(fig.description)
    }

    /// The main response at time `t` \[s\], normalised to about −1…1 (for sonification).
    pub fn sonify(&self, t: f64) -> Option<f64> {
        self.demo.sonify(&self.params, t).filter(|v| v.is_finite())
    }

    /// A click at backend pixel `(px, py)` of plot `key`: the demo may choose parameters
    /// from the point (e.g. a design on a map). Returns `[[key, value]]` applied.
    pub fn pick(&mut self, key: &str, px: f64, py: f64) -> Result<JsValue, JsError> {
        let Some(i) = self.spec.plots.iter().position(|p| p.key == key) else {
            return to_js(&Vec::<(&str, f64)>::new());
        };
        let Some((x, y)) = self
            .geometry
            .get(i)
            .copied()
            .flatten()
            .and_then(|g| g.to_data(px, py))
        else {
            return to_js(&Vec::<(&str, f64)>::new());
        };
        let plot = self.spec.plots.get(i).map(|p| p.key).unwrap_or("");
        let mut applied = Vec::new();
        for (k, v) in self.demo.pick(plot, x, y) {
            if let Some((v, _)) = self.params.set_raw(&self.spec, k, &format!("{v}")) {
                applied.push((k, v));
            }
        }
        to_js(&applied)
    }

    /// Tells the session a control is being dragged (`true`) or was released (`false`).
    /// While dragging, every plot keeps its axis ranges unless the data would leave them,
    /// and its legend where it was; the next update after release draws each figure with
    /// its own ranges and legend place again.
    #[wasm_bindgen(js_name = setDragging)]
    pub fn set_dragging(&mut self, on: bool) {
        if self.dragging && !on {
            self.released = Some((self.shown.clone(), 0.0));
        }
        if on {
            self.released = None;
        }
        self.dragging = on;
    }

    /// Sets how far (0…1) the axes have moved, since the last drag ended, from the ranges
    /// they were held at to each figure's own; the page steps this over a few frames so
    /// the rescale is smooth. 1 (or anything not below 1) ends the easing.
    #[wasm_bindgen(js_name = easeAxes)]
    pub fn ease_axes(&mut self, f: f64) {
        match &mut self.released {
            Some((_, at)) if f.is_finite() && f < 1.0 => *at = f.max(0.0),
            _ => self.released = None,
        }
    }

    /// Restores every parameter's default.
    pub fn reset(&mut self) {
        self.params = Params::defaults(&self.spec);
    }

    /// Plot `key`'s figure of the last update, if it has been built.
    fn figure(&self, key: &str) -> Option<(usize, &Figure)> {
        let i = self.spec.plots.iter().position(|p| p.key == key)?;
        Some((i, self.figures.get(i)?.as_ref()?))
    }

    /// Whether the page gave plot `i` a canvas.
    fn attached(&self, i: usize) -> bool {
        self.canvases.get(i).is_some_and(Option::is_some)
    }

    /// Builds plot `key`'s figure of the last update unless it has been (see
    /// [`Session::figure`]).
    fn build_plot(&mut self, key: &str) {
        if let Some(i) = self.spec.plots.iter().position(|p| p.key == key) {
            self.build(i);
        }
    }

    /// Builds plot `i`'s figure of the last update unless it has been, its axes held
    /// during a drag or eased after one, and notes its ranges as shown.
    fn build(&mut self, i: usize) -> Option<&Figure> {
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
        self.figures.get(i)?.as_ref()
    }

    /// The text alternatives of the plots flagged in `which` that have a figure.
    fn descriptions(&self, which: &[bool]) -> Vec<Description<'_>> {
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

    /// Draws the built figures whose `wanted` flag is set on their attached canvases,
    /// clearing their `stale` mark and keeping where each was drawn.
    fn draw_plots(&mut self, wanted: &[bool], how: Drawn) -> Result<(), JsError> {
        let scale = if how.scale.is_finite() {
            how.scale.clamp(0.5, 4.0)
        } else {
            1.0
        };
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
                .zip(canvas.as_ref().and_then(crate::canvas::on))
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

    /// Backend-pixel x of time `t` on plot `key`, if its x axis is time and `t` is in range.
    #[wasm_bindgen(js_name = timeToPixel)]
    pub fn time_to_pixel(&self, key: &str, t: f64) -> Option<f64> {
        let (i, fig) = self.figure(key)?;
        let geo = self.geometry.get(i).copied().flatten()?;
        (fig.x.unit == "s" && t >= fig.x.range.0 && t <= fig.x.range.1)
            .then(|| geo.to_pixel(t, fig.y.range.0).0)
    }

    /// The values under the pointer at backend pixel `(px, py)` of plot `key`:
    /// `{x_text, y_text, points: [{px, py, color, text}]}`, or `undefined` outside the plot.
    pub fn probe(&self, key: &str, px: f64, py: f64) -> Result<JsValue, JsError> {
        let Some((i, fig)) = self.figure(key) else {
            return Ok(JsValue::UNDEFINED);
        };
        let Some(geo) = self.geometry.get(i).copied().flatten() else {
            return Ok(JsValue::UNDEFINED);
        };
        match export::probe(fig, &geo, px, py) {
            Some(p) => to_js(&p),
            None => Ok(JsValue::UNDEFINED),
        }
    }

    /// CSV of plot `key`'s data, with the parameters and units in a header.
    pub fn csv(&mut self, key: &str) -> Result<String, JsError> {
        self.build_plot(key);
        let (_, fig) = self.figure(key).ok_or_else(|| js_err("no such plot"))?;
        let params: Vec<(&str, f64, &str)> = self
            .params
            .pairs()
            .map(|(k, v)| (k, v, self.spec.param(k).map(|p| p.unit).unwrap_or("")))
            .collect();
        Ok(export::csv(self.spec.id, &params, fig))
    }

    /// SVG document of plot `key` at `w × h` px. Text is measured with `measure`'s 2D
    /// context (any canvas), so export works under a strict Content-Security-Policy. Not in
    /// the first module (feature `first`): the page waits for the full one to export SVG.
    #[cfg(not(feature = "first"))]
    pub fn svg(
        &mut self,
        key: &str,
        w: u32,
        h: u32,
        dark: bool,
        measure: HtmlCanvasElement,
    ) -> Result<String, JsError> {
        self.build_plot(key);
        let (_, fig) = self.figure(key).ok_or_else(|| js_err("no such plot"))?;
        let mut buf = String::new();
        {
            let size = (w.clamp(16, 8000), h.clamp(16, 8000));
            let svg = plotters::prelude::SVGBackend::with_string(&mut buf, size);
            let backend = crate::canvas::Web::svg(svg, &measure)
                .ok_or_else(|| js_err("no 2D context to measure text"))?;
            render(&backend.into_drawing_area(), fig, &theme(dark), 1.0).map_err(js_err)?;
        }
        Ok(buf)
    }

    /// Draws plot `key` onto another canvas (e.g. a 2× canvas for PNG export).
    #[wasm_bindgen(js_name = renderTo)]
    pub fn render_to(
        &mut self,
        key: &str,
        canvas: HtmlCanvasElement,
        scale: f64,
        dark: bool,
    ) -> Result<(), JsError> {
        self.build_plot(key);
        let (_, fig) = self.figure(key).ok_or_else(|| js_err("no such plot"))?;
        let backend = crate::canvas::on(&canvas).ok_or_else(|| js_err("no 2D context"))?;
        let scale = if scale.is_finite() {
            scale.clamp(0.5, 8.0)
        } else {
            1.0
        };
        draw_on(backend, fig, dark, scale, None).map(|_| ())
    }
}

/// How plots are drawn: `scale` = devicePixelRatio (clamped to 0.5…4), dark or light theme.
#[derive(Debug, Clone, Copy)]
struct Drawn {
    scale: f64,
    dark: bool,
}

/// Draws `fig` on a canvas in the light or dark theme (heatmaps as one bitmap), the legend
/// at `legend` if given (see [`Output::legend`]).
fn draw_on(
    backend: Canvas,
    fig: &crate::figure::Figure,
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
