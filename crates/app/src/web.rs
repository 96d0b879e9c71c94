//! The wasm boundary: a few thin exports over the demos. Errors become JS errors here and
//! nowhere else; a panic (there should be none) is logged by the hook and reported to the
//! page, which then starts a fresh session.

use crate::canvas::Canvas;
use crate::demos::{self, Demo};
use crate::params::{resolve_query, Notice, Params};
use crate::render::render;
use crate::spec::DemoSpec;
use crate::theme::Theme;
use plotters::prelude::IntoDrawingArea;
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
    title: &'static str,
}

/// `[{id, title}]` of every demo, in menu order.
#[wasm_bindgen(js_name = demoList)]
pub fn demo_list() -> Result<JsValue, JsError> {
    let list: Vec<DemoEntry> = demos::IDS
        .iter()
        .filter_map(|id| demos::create(id).map(|d| d.spec()))
        .map(|s| DemoEntry {
            id: s.id,
            title: s.title,
        })
        .collect();
    to_js(&list)
}

#[derive(Serialize)]
struct SetResult {
    value: f64,
    notice: Option<Notice>,
}

/// One open demo: its parameters, canvases and last readouts.
#[wasm_bindgen]
pub struct Session {
    demo: Box<dyn Demo>,
    spec: DemoSpec,
    params: Params,
    canvases: Vec<Option<HtmlCanvasElement>>,
}

#[wasm_bindgen]
impl Session {
    /// Opens demo `id`; errors for an unknown id.
    #[wasm_bindgen(constructor)]
    pub fn new(id: &str) -> Result<Session, JsError> {
        let demo =
            demos::create(id).ok_or_else(|| JsError::new(&format!("unknown demo {id:?}")))?;
        let spec = demo.spec();
        let params = Params::defaults(&spec);
        let canvases = vec![None; spec.plots.len()];
        Ok(Session {
            demo,
            spec,
            params,
            canvases,
        })
    }

    /// The demo's declaration: `{id, title, summary, equation_mathml, params, readouts, plots}`.
    pub fn spec(&self) -> Result<JsValue, JsError> {
        to_js(&self.spec)
    }

    /// Applies a URL query string (`?demo=…&zeta=0.2`); returns the notices `[{key, message}]`.
    #[wasm_bindgen(js_name = applyQuery)]
    pub fn apply_query(&mut self, query: &str) -> Result<JsValue, JsError> {
        let (params, notices) = resolve_query(&self.spec, query);
        self.params = params;
        to_js(&notices)
    }

    /// Sets one parameter from text (a slider or number box); returns `{value, notice}`,
    /// or `undefined` for an unknown key.
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

    /// Gives the canvas for plot `key`; returns whether the key exists.
    pub fn attach(&mut self, key: &str, canvas: HtmlCanvasElement) -> bool {
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

    /// Recomputes, draws every attached canvas (sized by the page at `scale` =
    /// devicePixelRatio) and returns the readouts `[{key, text, data_value}]`.
    pub fn update(&mut self, scale: f64, dark: bool) -> Result<JsValue, JsError> {
        let frame = self.demo.update(&self.params);
        let theme = if dark { Theme::DARK } else { Theme::LIGHT };
        let scale = if scale.is_finite() {
            scale.clamp(0.5, 4.0)
        } else {
            1.0
        };
        for (canvas, fig) in self.canvases.iter().zip(&frame.figures) {
            let Some(canvas) = canvas else { continue };
            let Some(backend) = Canvas::new(canvas) else {
                continue;
            };
            let root = backend.into_drawing_area();
            render(&root, fig, &theme, scale).map_err(|e| JsError::new(&e.to_string()))?;
        }
        to_js(&frame.readouts)
    }
}
