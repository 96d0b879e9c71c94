//! The backends the page draws with: an HTML canvas ([`HtmlCanvas`], this crate's own,
//! which skips repeated state changes) and, for SVG export, plotters' SVG backend with text
//! measured by a canvas 2D context; in the full module both as one type, `Web`
//! (`web.rs`), so the render code is compiled once: a generic drawing function is a copy
//! of machine code per backend type, and the SVG export's copy of every render function
//! cost about 10 KB brotli of wasm. The first module has no SVG export.
//!
//! Text is measured with `CanvasRenderingContext2d.measureText`: plotters' default on the
//! web inserts a styled `<span>` into the page and reads its layout, once per label, which
//! is slow (a forced layout per label, every frame) and blocked by a strict
//! Content-Security-Policy (`style-src 'self'`).

mod direct;
mod html;
#[cfg(not(feature = "first"))]
mod web;

pub use direct::{prepare, CanvasDirect};
pub use html::{CanvasError, HtmlCanvas};
use plotters_backend::BackendTextStyle;
use wasm_bindgen::JsCast;
#[cfg(not(feature = "first"))]
pub use web::{Web, WebError};
use web_sys::{CanvasRenderingContext2d, HtmlCanvasElement};

/// What the page draws its plots on: [`Web`] in the full module; in the first module
/// (feature `first`), which has no SVG export, the canvas backend itself, so the render
/// code is still compiled once.
#[cfg(not(feature = "first"))]
pub type Canvas = Web<'static>;
/// What the page draws its plots on (see the full module's alias).
#[cfg(feature = "first")]
pub type Canvas = HtmlCanvas;

/// What `backend` draws itself, beside plotters' calls (the canvas; see `render::Direct`);
/// an SVG is drawn through plotters alone.
pub fn direct(backend: &Canvas) -> Option<CanvasDirect> {
    #[cfg(not(feature = "first"))]
    return backend.direct();
    #[cfg(feature = "first")]
    return Some(backend.direct());
}

/// Draws on `canvas`; `None` if it has no 2D context.
pub fn on(canvas: &HtmlCanvasElement) -> Option<Canvas> {
    let backend = HtmlCanvas::new(canvas)?;
    #[cfg(not(feature = "first"))]
    let backend = Web::Canvas(backend);
    Some(backend)
}

/// The CSS font shorthand of `style`: `"<style> <size>px <family>"`.
pub(crate) fn css_font(style: &impl BackendTextStyle) -> String {
    format!(
        "{} {}px {}",
        style.style().as_str(),
        style.size(),
        style.family().as_str()
    )
}

/// Width and height (px) of `text` in the font already set on `context` (`style`'s).
pub(crate) fn measure(
    context: &CanvasRenderingContext2d,
    text: &str,
    style: &impl BackendTextStyle,
) -> (u32, u32) {
    let width = context.measure_text(text).map(|m| m.width()).unwrap_or(0.0);
    (
        width.ceil().max(0.0) as u32,
        style.size().ceil().max(0.0) as u32,
    )
}

pub(crate) fn context_of(canvas: &HtmlCanvasElement) -> Option<CanvasRenderingContext2d> {
    canvas
        .get_context("2d")
        .ok()??
        .dyn_into::<CanvasRenderingContext2d>()
        .ok()
}
