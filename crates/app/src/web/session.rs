//! [`Session`]: one open demo, its parameters, canvases and last figures. How it builds and
//! draws them is in `draw.rs`; what the page asks of one drawn plot (pointer, exports) in
//! `plots.rs`.

use super::draw::{device_scale, Drawn};
use super::result::{SetResult, StaleResult, UpdateResult};
use super::translate::translate_spec;
use super::{js_err, theme, to_js};
use crate::canvas::Surface;
use crate::demos::{self, Demo, Frame};
use crate::figure::Figure;
use crate::params::{resolve_query, Params};
use crate::render::{render, AxisRanges, PlotGeometry};
use crate::spec::DemoSpec;
use plotters::prelude::IntoDrawingArea;
use wasm_bindgen::prelude::*;
use web_sys::HtmlCanvasElement;

/// One open demo: its parameters, canvases, last figures and where they were drawn.
#[wasm_bindgen]
pub struct Session {
    pub(super) demo: Box<dyn Demo>,
    pub(super) spec: DemoSpec,
    pub(super) params: Params,
    pub(super) canvases: Vec<Option<Surface>>,
    /// Whether each plot's canvas is on screen, as the page observes it. An update draws
    /// only those; the others wait, [`stale`](Self::stale), for [`Session::draw_stale`].
    pub(super) visible: Vec<bool>,
    /// Plots whose canvas shows an older frame than the last update's.
    pub(super) stale: Vec<bool>,
    pub(super) schematic_canvas: Option<Surface>,
    /// The last update's readouts and time span (its figures are in `figures`).
    pub(super) frame: Option<Frame>,
    /// The last update's figures, each built when it is first drawn or asked for (see
    /// [`Demo::figure`]): while a control moves, plots out of view cost nothing.
    pub(super) figures: Vec<Option<Figure>>,
    pub(super) geometry: Vec<Option<PlotGeometry>>,
    /// Whether a control is being dragged: axes then hold (see [`hold_axes`](crate::render::hold_axes)).
    pub(super) dragging: bool,
    /// Each plot's axis ranges as last drawn, `(x, y)`.
    pub(super) shown: Vec<Option<AxisRanges>>,
    /// The ranges held when the last drag ended, and how far (0…1) the axes have moved
    /// from them to the figures' own (see [`ease_axes`](crate::render::ease_axes)).
    pub(super) released: Option<(Vec<Option<AxisRanges>>, f64)>,
    /// The demo's [`Demo::study_round`] at the last update.
    pub(super) study_round: u32,
    /// How the last update drew: a plot drawn later for a click or the pointer on it
    /// (`plots.rs`, `drawn_plot`) is drawn the same way.
    pub(super) last_drawn: Option<Drawn>,
}

#[wasm_bindgen]
impl Session {
    /// Opens demo `id`; errors for an unknown id.
    #[wasm_bindgen(constructor)]
    pub fn new(id: &str) -> Result<Session, JsError> {
        let mut demo =
            demos::create(id).ok_or_else(|| JsError::new(&format!("unknown demo “{id}”")))?;
        demo.set_progressive(true);
        let spec = demo.spec();
        let params = Params::defaults(&spec);
        let n = spec.plots.len();
        Ok(Session {
            demo,
            spec,
            params,
            canvases: std::iter::repeat_with(|| None).take(n).collect(),
            visible: vec![true; n],
            stale: vec![false; n],
            schematic_canvas: None,
            frame: None,
            figures: vec![None; n],
            geometry: vec![None; n],
            dragging: false,
            shown: vec![None; n],
            released: None,
            study_round: 0,
            last_drawn: None,
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
            self.schematic_canvas = Some(Surface::of(canvas));
            return true;
        }
        match self.plot_index(key) {
            Some(i) => {
                if let Some(slot) = self.canvases.get_mut(i) {
                    *slot = Some(Surface::of(canvas));
                }
                true
            }
            None => false,
        }
    }

    /// Recomputes, draws every attached plot canvas that is on screen (sized by the page
    /// at `scale` = devicePixelRatio; see [`Session::set_visible`]) and returns
    /// `{readouts, descriptions, time_span, derived, provisional, restarted, tour}`. Only the figures
    /// drawn, and the first plot's (its text is announced), are built.
    pub fn update(&mut self, scale: f64, dark: bool) -> Result<JsValue, JsError> {
        let frame = self.demo.recompute(&self.params);
        let round = self.demo.study_round();
        let restarted = std::mem::replace(&mut self.study_round, round) != round;
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
        self.last_drawn = Some(Drawn { scale, dark });
        self.draw_plots(&self.visible.clone(), Drawn { scale, dark })?;
        let descriptions = self.descriptions(&built);
        let frame = self.frame.as_ref().ok_or_else(|| js_err("no frame"))?;
        to_js(&UpdateResult {
            readouts: &frame.readouts,
            descriptions,
            time_span: frame.time_span,
            derived,
            provisional: self.demo.provisional(),
            restarted,
            tour: self.demo.tour(),
        })
    }

    /// Tells the session whether plot `key`'s canvas is on screen (the page observes it;
    /// every plot counts as on screen until told otherwise). Returns whether the plot has
    /// just come into view showing an older frame: the page then calls
    /// [`Session::draw_stale`].
    #[wasm_bindgen(js_name = setVisible)]
    pub fn set_visible(&mut self, key: &str, on: bool) -> bool {
        let Some(i) = self.plot_index(key) else {
            return false;
        };
        if let Some(v) = self.visible.get_mut(i) {
            *v = on;
        }
        on && self.stale.get(i).copied().unwrap_or(false)
    }

    /// Draws the plots that show an older frame than the last update's, from that update's
    /// results (nothing is recomputed): those on screen, or with `all` one of any, the first
    /// on screen if one is (the page calls that once per task while the controls rest, so
    /// no task grows long).
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
        let next = (0..self.stale.len())
            .filter(|&i| self.stale[i])
            .min_by_key(|&i| !self.visible.get(i).copied().unwrap_or(true));
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
        for surface in self.canvases.iter().flatten() {
            crate::canvas::prepare(&surface.canvas);
        }
    }

    /// Draws again the first plot on screen, drawn and current, whose canvas does not keep
    /// its static layer yet: a layer is kept once it has been drawn twice in a row, so
    /// without this a drag's first frame drew its plots whole (the slowest frame of every
    /// drag, about twice the others at 4× CPU slowdown). The pixels do not change. Called
    /// while the controls rest, a plot a task; `true` if it drew one.
    #[cfg(not(feature = "first"))]
    #[wasm_bindgen(js_name = keepLayer)]
    pub fn keep_layer(&mut self, scale: f64, dark: bool) -> Result<bool, JsError> {
        let redraw = (0..self.canvases.len()).find(|&i| {
            let ready = self.visible.get(i) == Some(&true)
                && self.stale.get(i) == Some(&false)
                && self
                    .built(i)
                    .is_some_and(|f| f.kind == crate::figure::FigureKind::Plot)
                && self.geometry.get(i).is_some_and(Option::is_some);
            ready
                && self.canvases[i]
                    .as_ref()
                    .is_some_and(|s| !crate::canvas::keeps_layer(&s.canvas))
        });
        let Some(i) = redraw else {
            return Ok(false);
        };
        self.draw_one(i, Drawn { scale, dark })?;
        Ok(true)
    }

    /// Continues a pending heavy study (sweep, Monte Carlo) for about `budget_ms`:
    /// `undefined` when none is pending, else the fraction done (1: finished, call `update`).
    pub fn refine(&mut self, budget_ms: f64) -> Option<f64> {
        self.demo.refine(budget_ms)
    }

    /// Whether the page computes the full study in its worker (`on`): [`Session::refine`]
    /// then leaves it alone and the worker's result comes in through
    /// [`Session::adopt_study`]. Not in the first module (feature `first`), which has no worker.
    #[cfg(not(feature = "first"))]
    #[wasm_bindgen(js_name = setWorker)]
    pub fn set_worker(&mut self, on: bool) {
        self.demo.set_worker(on);
    }

    /// Takes in the worker's finished study ([`Study::result`](super::Study::result)):
    /// `1` when it was for the pending study's inputs (then call `update`), `undefined`
    /// when those inputs have moved on (nothing changes).
    #[cfg(not(feature = "first"))]
    #[wasm_bindgen(js_name = adoptStudy)]
    pub fn adopt_study(&mut self, bytes: &[u8]) -> Option<f64> {
        self.demo.adopt_study(bytes)
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
        if let Some(backend) = crate::canvas::on_surface(canvas) {
            let scale = device_scale(scale, 4.0);
            render(&backend.into_drawing_area(), &fig, &theme(dark), scale).map_err(js_err)?;
        }
        Ok(fig.description)
    }

    /// The main response at time `t` \[s\], normalised to about −1…1 (for sonification).
    pub fn sonify(&self, t: f64) -> Option<f64> {
        self.demo.sonify(&self.params, t).filter(|v| v.is_finite())
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
        self.demo.set_held(on);
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
}
