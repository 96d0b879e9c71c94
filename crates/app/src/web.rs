//! The wasm boundary: a few thin exports over the demos. Errors become JS errors here and
//! nowhere else; a panic (there should be none) is logged by the hook and reported to the
//! page, which then starts a fresh session.

use crate::canvas::{Canvas, Measured};
use crate::demos::{self, Demo, Frame};
use crate::export;
use crate::i18n::{tr, Lang};
use crate::params::{resolve_query, Notice, Params};
use crate::render::{ease_axes, hold_axes, render, render_with, AxisRanges, PlotGeometry, Raster};
use crate::spec::DemoSpec;
use crate::theme::Theme;
use plotters::prelude::{IntoDrawingArea, SVGBackend};
use serde::Serialize;
use wasm_bindgen::prelude::*;
use web_sys::HtmlCanvasElement;

/// Installs the panic hook. Runs once when the module is instantiated.
#[wasm_bindgen(start)]
pub fn start() {
    std::panic::set_hook(Box::new(|info| {
        let msg = format!("Zeta Lab internal error: {info}");
        web_sys::console::error_1(&JsValue::from_str(&msg));
        LAST_PANIC.with(|p| *p.borrow_mut() = Some(msg));
    }));
}

thread_local! {
    static LAST_PANIC: std::cell::RefCell<Option<String>> = const { std::cell::RefCell::new(None) };
}

/// Set by [`arm_panic_for_tests`]: the next [`Session::update`] panics, so the end-to-end
/// tests can check that the page reports a panic and recovers. Never set otherwise.
static PANIC_ARMED: std::sync::atomic::AtomicBool = std::sync::atomic::AtomicBool::new(false);

/// Test hook: makes the next `update` panic (see the recovery end-to-end test).
#[wasm_bindgen(js_name = armPanicForTests)]
pub fn arm_panic_for_tests() {
    PANIC_ARMED.store(true, std::sync::atomic::Ordering::SeqCst);
}

/// The interface language, set once by the page ([`set_language`]).
static LANG: std::sync::atomic::AtomicU8 = std::sync::atomic::AtomicU8::new(0);

fn lang() -> Lang {
    match LANG.load(std::sync::atomic::Ordering::Relaxed) {
        1 => Lang::Es,
        _ => Lang::En,
    }
}

/// Sets the language of every string the module returns (a BCP 47 tag: `en`, `es`, …);
/// returns the tag in use.
#[wasm_bindgen(js_name = setLanguage)]
pub fn set_language(tag: &str) -> String {
    let l = Lang::from_tag(tag);
    LANG.store(
        if l == Lang::Es { 1 } else { 0 },
        std::sync::atomic::Ordering::Relaxed,
    );
    l.tag().to_string()
}

/// Translates, in place, every string of a figure that the page shows.
fn translate_figure(fig: &mut crate::figure::Figure, l: Lang) {
    if l == Lang::En {
        return;
    }
    let t = |s: &mut String| *s = tr(l, s).into_owned();
    t(&mut fig.title);
    t(&mut fig.description);
    t(&mut fig.x.label);
    t(&mut fig.y.label);
    for s in &mut fig.series {
        t(&mut s.label);
    }
    for m in &mut fig.markers {
        t(&mut m.label);
    }
    if let Some(h) = &mut fig.heatmap {
        t(&mut h.label);
    }
}

/// The spec with its human strings in language `l` (keys, symbols and units unchanged).
fn translate_spec(spec: &DemoSpec, l: Lang) -> TranslatedSpec {
    let t = |s: &str| tr(l, s).into_owned();
    TranslatedSpec {
        id: spec.id,
        title: t(spec.title),
        summary: t(spec.summary),
        equation_mathml: spec.equation_mathml,
        params: spec
            .params
            .iter()
            .map(|p| TranslatedParam {
                key: p.key,
                label: t(p.label),
                symbol: p.symbol,
                unit: p.unit,
                min: p.min,
                max: p.max,
                step: p.step,
                default: p.default,
                scale: p.scale,
                kind: p.kind,
                options: p.options.iter().map(|o| (o.key, t(o.label))).collect(),
                visible_when: p.visible_when,
            })
            .collect(),
        readouts: spec
            .readouts
            .iter()
            .map(|r| (r.key, t(r.label), r.unit))
            .collect(),
        plots: spec
            .plots
            .iter()
            .map(|p| (p.key, t(p.title), p.aspect))
            .collect(),
        presets: spec
            .presets
            .iter()
            .map(|p| (t(p.label), p.values.clone()))
            .collect(),
        table: spec.table.as_ref().map(|tb| TranslatedTable {
            caption: t(tb.caption),
            columns: tb.columns.iter().map(|c| t(c)).collect(),
            rows: tb
                .rows
                .iter()
                .map(|(k, cells)| (*k, cells.iter().map(|c| t(c)).collect()))
                .collect(),
            highlight_readout: tb.highlight_readout,
        }),
        primary_plot: spec.primary(),
        schematic: spec.schematic,
    }
}

#[derive(Serialize)]
struct TranslatedParam {
    key: &'static str,
    label: String,
    symbol: &'static str,
    unit: &'static str,
    min: f64,
    max: f64,
    step: f64,
    default: f64,
    scale: crate::spec::Scale,
    kind: crate::spec::Kind,
    #[serde(serialize_with = "options_as_objects")]
    options: Vec<(&'static str, String)>,
    /// `[key, index]`: shown only while that parameter has that value (absent: always).
    #[serde(skip_serializing_if = "Option::is_none")]
    visible_when: Option<(&'static str, usize)>,
}

fn options_as_objects<S: serde::Serializer>(
    v: &[(&'static str, String)],
    s: S,
) -> Result<S::Ok, S::Error> {
    use serde::ser::SerializeSeq;
    #[derive(Serialize)]
    struct Opt<'a> {
        key: &'a str,
        label: &'a str,
    }
    let mut seq = s.serialize_seq(Some(v.len()))?;
    for (key, label) in v {
        seq.serialize_element(&Opt { key, label })?;
    }
    seq.end()
}

#[derive(Serialize)]
struct TranslatedTable {
    caption: String,
    columns: Vec<String>,
    rows: Vec<(&'static str, Vec<String>)>,
    highlight_readout: &'static str,
}

/// [`DemoSpec`] as the page receives it, in the page's language. Same field names.
#[derive(Serialize)]
struct TranslatedSpec {
    id: &'static str,
    title: String,
    summary: String,
    equation_mathml: &'static str,
    params: Vec<TranslatedParam>,
    #[serde(serialize_with = "readouts_as_objects")]
    readouts: Vec<(&'static str, String, &'static str)>,
    #[serde(serialize_with = "plots_as_objects")]
    plots: Vec<(&'static str, String, f64)>,
    #[serde(serialize_with = "presets_as_objects")]
    presets: Vec<(String, Vec<(&'static str, f64)>)>,
    table: Option<TranslatedTable>,
    primary_plot: &'static str,
    schematic: bool,
}

fn readouts_as_objects<S: serde::Serializer>(
    v: &[(&'static str, String, &'static str)],
    s: S,
) -> Result<S::Ok, S::Error> {
    #[derive(Serialize)]
    struct R<'a> {
        key: &'a str,
        label: &'a str,
        unit: &'a str,
    }
    s.collect_seq(v.iter().map(|(key, label, unit)| R { key, label, unit }))
}

fn plots_as_objects<S: serde::Serializer>(
    v: &[(&'static str, String, f64)],
    s: S,
) -> Result<S::Ok, S::Error> {
    #[derive(Serialize)]
    struct P<'a> {
        key: &'a str,
        title: &'a str,
        aspect: f64,
    }
    s.collect_seq(v.iter().map(|(key, title, aspect)| P {
        key,
        title,
        aspect: *aspect,
    }))
}

fn presets_as_objects<S: serde::Serializer>(
    v: &[(String, Vec<(&'static str, f64)>)],
    s: S,
) -> Result<S::Ok, S::Error> {
    #[derive(Serialize)]
    struct P<'a> {
        label: &'a str,
        values: &'a [(&'static str, f64)],
    }
    s.collect_seq(v.iter().map(|(label, values)| P { label, values }))
}

/// The message of the last panic, if any (read by the page after a failed call).
#[wasm_bindgen(js_name = takePanicMessage)]
pub fn take_panic_message() -> Option<String> {
    LAST_PANIC.with(|p| p.borrow_mut().take())
}

fn to_js<T: Serialize>(v: &T) -> Result<JsValue, JsError> {
    v.serialize(&serde_wasm_bindgen::Serializer::json_compatible())
        .map_err(|e| JsError::new(&e.to_string()))
}

#[derive(Serialize)]
struct DemoEntry {
    id: &'static str,
    title: String,
}

/// `[{id, title}]` of every demo, in menu order.
#[wasm_bindgen(js_name = demoList)]
pub fn demo_list() -> Result<JsValue, JsError> {
    let list: Vec<DemoEntry> = demos::ids()
        .filter_map(|id| demos::create(id).map(|d| d.spec()))
        .map(|s| DemoEntry {
            id: s.id,
            title: tr(lang(), s.title).into_owned(),
        })
        .collect();
    to_js(&list)
}

#[derive(Serialize)]
struct SetResult {
    value: f64,
    notice: Option<Notice>,
}

/// What [`Session::update`] returns to the page.
#[derive(Serialize)]
struct UpdateResult<'a> {
    readouts: &'a [crate::demos::Readout],
    /// `[{key, text}]`: each plot's text alternative.
    descriptions: Vec<Description<'a>>,
    /// `[start, end]` of the animation in s, if the demo animates.
    time_span: Option<(f64, f64)>,
    /// `[[key, value]]` of parameters the demo derived from others this update.
    derived: Vec<(&'static str, f64)>,
    /// Keys of readouts and plots showing a coarse study while the full one runs.
    provisional: Vec<&'static str>,
    /// The guided tour with its checked claims, for the demo that has one (`paper`).
    #[serde(skip_serializing_if = "Option::is_none")]
    tour: Option<crate::demos::paper::Tour>,
}

#[derive(Serialize)]
struct Description<'a> {
    key: &'static str,
    text: &'a str,
}

/// One open demo: its parameters, canvases, last figures and where they were drawn.
#[wasm_bindgen]
pub struct Session {
    demo: Box<dyn Demo>,
    spec: DemoSpec,
    params: Params,
    canvases: Vec<Option<HtmlCanvasElement>>,
    schematic_canvas: Option<HtmlCanvasElement>,
    frame: Option<Frame>,
    geometry: Vec<Option<PlotGeometry>>,
    /// Whether a control is being dragged: axes then hold (see [`hold_axes`]).
    dragging: bool,
    /// Each plot's axis ranges as last drawn, `(x, y)`.
    shown: Vec<Option<AxisRanges>>,
    /// The ranges held when the last drag ended, and how far (0…1) the axes have moved
    /// from them to the figures' own (see [`ease_axes`]).
    released: Option<(Vec<Option<AxisRanges>>, f64)>,
}

fn theme(dark: bool) -> Theme {
    let base = if dark { Theme::DARK } else { Theme::LIGHT };
    let note = match tr(lang(), crate::theme::CLIPPED_NOTE) {
        std::borrow::Cow::Borrowed(s) => s,
        // The note is a whole-string catalogue entry; an owned result means no entry.
        std::borrow::Cow::Owned(_) => crate::theme::CLIPPED_NOTE,
    };
    Theme {
        decimal_comma: lang() == Lang::Es,
        clipped_note: note,
        ..base
    }
}

/// A notice in the page's language: its message, with the parameter's label too.
fn translate_notice(spec: &DemoSpec, n: &mut Notice) {
    let l = lang();
    if l == Lang::En {
        return;
    }
    let mut msg = n.message.clone();
    if let Some(p) = spec.param(&n.key) {
        msg = msg.replace(p.label, &tr(l, p.label));
    }
    n.message = tr(l, &msg).into_owned();
}

fn js_err(e: impl std::fmt::Display) -> JsError {
    JsError::new(&e.to_string())
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
            schematic_canvas: None,
            frame: None,
            geometry: vec![None; n],
            dragging: false,
            shown: vec![None; n],
            released: None,
        })
    }

    /// The demo's declaration (see [`DemoSpec`]).
    pub fn spec(&self) -> Result<JsValue, JsError> {
        to_js(&translate_spec(&self.spec, lang()))
    }

    /// Applies a URL query string (`?demo=…&zeta=0.2`); returns the notices `[{key, message}]`.
    #[wasm_bindgen(js_name = applyQuery)]
    pub fn apply_query(&mut self, query: &str) -> Result<JsValue, JsError> {
        // Lecturer overrides (`range.<key>=lo,hi`, `step.<key>=…`) narrow the spec first.
        let mut notices = crate::lecturer::narrow(&mut self.spec, query);
        let (params, more) = resolve_query(&self.spec, query);
        notices.extend(more);
        self.params = params;
        for n in &mut notices {
            translate_notice(&self.spec, n);
        }
        to_js(&notices)
    }

    /// Sets one parameter from text (a slider, number box, checkbox or list); returns
    /// `{value, notice}`, or `undefined` for an unknown key.
    pub fn set(&mut self, key: &str, raw: &str) -> Result<JsValue, JsError> {
        match self.params.set_raw(&self.spec, key, raw) {
            Some((value, mut notice)) => {
                if let Some(n) = &mut notice {
                    translate_notice(&self.spec, n);
                }
                to_js(&SetResult { value, notice })
            }
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

    /// Recomputes, draws every attached plot canvas (sized by the page at `scale` =
    /// devicePixelRatio) and returns `{readouts, descriptions, time_span}`.
    pub fn update(&mut self, scale: f64, dark: bool) -> Result<JsValue, JsError> {
        if PANIC_ARMED.swap(false, std::sync::atomic::Ordering::SeqCst) {
            #[allow(clippy::panic)]
            {
                panic!("deliberate panic armed by armPanicForTests");
            }
        }
        let mut frame = self.demo.update(&self.params);
        let l = lang();
        if l != Lang::En {
            for r in &mut frame.readouts {
                r.text = tr(l, &r.text).into_owned();
            }
            for f in &mut frame.figures {
                translate_figure(f, l);
            }
        }
        let mut derived = Vec::new();
        for (key, value) in self.demo.derived_params() {
            if let Some((v, _)) = self.params.set_raw(&self.spec, key, &format!("{value}")) {
                derived.push((key, v));
            }
        }
        let scale = if scale.is_finite() {
            scale.clamp(0.5, 4.0)
        } else {
            1.0
        };
        for (i, fig) in frame.figures.iter_mut().enumerate() {
            if self.dragging {
                hold_axes(fig, self.shown.get(i).copied().flatten());
            } else if let Some((from, f)) = &self.released {
                ease_axes(fig, from.get(i).copied().flatten(), *f);
            }
            if let Some(slot) = self.shown.get_mut(i) {
                *slot = Some((fig.x.range, fig.y.range));
            }
        }
        for (i, (canvas, fig)) in self.canvases.iter().zip(&frame.figures).enumerate() {
            let Some(canvas) = canvas else { continue };
            let Some(backend) = Canvas::new(canvas) else {
                continue;
            };
            let geo = render_with(
                &backend.into_drawing_area(),
                fig,
                &theme(dark),
                scale,
                Raster::Bitmap,
            )
            .map_err(js_err)?;
            if let Some(slot) = self.geometry.get_mut(i) {
                *slot = Some(geo);
            }
        }
        let descriptions = self
            .spec
            .plots
            .iter()
            .zip(&frame.figures)
            .map(|(p, f)| Description {
                key: p.key,
                text: &f.description,
            })
            .collect();
        let out = to_js(&UpdateResult {
            readouts: &frame.readouts,
            descriptions,
            time_span: frame.time_span,
            derived,
            provisional: self.demo.provisional(),
            tour: self
                .demo
                .tour()
                .map(|t| t.translated(|s| tr(l, s).into_owned())),
        });
        self.frame = Some(frame);
        out
    }

    /// Continues a pending heavy study (sweep, Monte Carlo) for about `budget_ms`:
    /// `undefined` when none is pending, else the fraction done (1: finished, call `update`).
    pub fn refine(&mut self, budget_ms: f64) -> Option<f64> {
        self.demo.refine(budget_ms)
    }

    /// Draws the schematic at time `t` \[s\]; returns its text alternative.
    #[wasm_bindgen(js_name = drawSchematic)]
    pub fn draw_schematic(&self, t: f64, scale: f64, dark: bool) -> Result<String, JsError> {
        let (Some(canvas), Some(mut fig)) = (
            &self.schematic_canvas,
            self.demo
                .schematic(&self.params, if t.is_finite() { t } else { 0.0 }),
        ) else {
            return Ok(String::new());
        };
        translate_figure(&mut fig, lang());
        if let Some(backend) = Canvas::new(canvas) {
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
    /// While dragging, every plot keeps its axis ranges unless the data would leave them;
    /// the next update after release draws each figure with its own ranges again.
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

    fn figure(&self, key: &str) -> Option<(usize, &crate::figure::Figure)> {
        let i = self.spec.plots.iter().position(|p| p.key == key)?;
        Some((i, self.frame.as_ref()?.figures.get(i)?))
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
    pub fn csv(&self, key: &str) -> Result<String, JsError> {
        let (_, fig) = self.figure(key).ok_or_else(|| js_err("no such plot"))?;
        let params: Vec<(&str, f64, &str)> = self
            .params
            .pairs()
            .map(|(k, v)| (k, v, self.spec.param(k).map(|p| p.unit).unwrap_or("")))
            .collect();
        Ok(export::csv(self.spec.id, &params, fig))
    }

    /// SVG document of plot `key` at `w × h` px. Text is measured with `measure`'s 2D
    /// context (any canvas), so export works under a strict Content-Security-Policy.
    pub fn svg(
        &self,
        key: &str,
        w: u32,
        h: u32,
        dark: bool,
        measure: HtmlCanvasElement,
    ) -> Result<String, JsError> {
        let (_, fig) = self.figure(key).ok_or_else(|| js_err("no such plot"))?;
        let mut buf = String::new();
        {
            let size = (w.clamp(16, 8000), h.clamp(16, 8000));
            let backend = Measured::with_measure(SVGBackend::with_string(&mut buf, size), &measure)
                .ok_or_else(|| js_err("no 2D context to measure text"))?;
            render(&backend.into_drawing_area(), fig, &theme(dark), 1.0).map_err(js_err)?;
        }
        Ok(buf)
    }

    /// Draws plot `key` onto another canvas (e.g. a 2× canvas for PNG export).
    #[wasm_bindgen(js_name = renderTo)]
    pub fn render_to(
        &self,
        key: &str,
        canvas: HtmlCanvasElement,
        scale: f64,
        dark: bool,
    ) -> Result<(), JsError> {
        let (_, fig) = self.figure(key).ok_or_else(|| js_err("no such plot"))?;
        let backend = Canvas::new(&canvas).ok_or_else(|| js_err("no 2D context"))?;
        let scale = if scale.is_finite() {
            scale.clamp(0.5, 8.0)
        } else {
            1.0
        };
        render_with(
            &backend.into_drawing_area(),
            fig,
            &theme(dark),
            scale,
            Raster::Bitmap,
        )
        .map_err(js_err)?;
        Ok(())
    }
}
