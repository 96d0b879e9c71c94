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

#[cfg(not(feature = "first"))]
pub use direct::keeps_layer;
pub use direct::{prepare, CanvasDirect};
use html::Memory;
pub use html::{CanvasError, HtmlCanvas};
use plotters_backend::BackendTextStyle;
use std::cell::RefCell;
use std::rc::Rc;
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
    on_surface(&Surface::of(canvas.clone()))
}

/// A page canvas with its 2D context, taken once: a session draws on the same canvases
/// every frame, and `getContext` is a call into JavaScript (about 0.4 ms a frame at 4×
/// CPU slowdown for one plot, profiled 2026-12-01). Resizing a canvas resets its context's
/// state but keeps the object; the memory of that state (`html::Memory`) is kept
/// here too, so each frame's backend sets only what differs from the frame before.
pub struct Surface {
    /// The canvas.
    pub canvas: HtmlCanvasElement,
    /// Its 2D context; `None` if it has none (another kind was taken): the canvas is still
    /// the page's, its plot built and described, only not drawn.
    context: Option<CanvasRenderingContext2d>,
    /// What the context was last given by this surface's backends.
    memory: Rc<Memory>,
}

impl Surface {
    /// `canvas` and its 2D context, if it has one.
    pub fn of(canvas: HtmlCanvasElement) -> Self {
        let context = context_of(&canvas);
        Self {
            canvas,
            context,
            memory: Memory::new(),
        }
    }
}

/// Draws on `surface`; `None` if its canvas has no 2D context.
pub fn on_surface(surface: &Surface) -> Option<Canvas> {
    let context = surface.context.clone()?;
    let backend = HtmlCanvas::with_context(surface.canvas.clone(), context, surface.memory.clone());
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

/// Slots of the memory of measured widths (see [`measure`]).
const WIDTH_SLOTS: usize = 256;

thread_local! {
    /// Widths of text already measured, px, by [`width_hash`] (slot: the hash modulo
    /// [`WIDTH_SLOTS`]; hash 0 marks an empty slot and is never looked up). The page loads
    /// no web fonts, so a font and a text always measure the same, and a held drag redraws
    /// the same legend entries, titles and marker labels every frame: each `measureText`
    /// (with the font set before it) is a call into JavaScript and a trip through the
    /// browser's text shaper, about a tenth of drawing quarter-car's plot at 4× CPU
    /// slowdown (profiled 2026-12-01). Hashes rather than the strings: no allocation per
    /// label, and less code than a `HashMap`; among the few thousand labels a session
    /// measures, two share a 64-bit hash with odds below 10⁻¹².
    static WIDTHS: RefCell<Vec<(u64, f64)>> = const { RefCell::new(Vec::new()) };
}

/// FNV-1a (64-bit) of `font`, a NUL and `text`.
pub(super) fn width_hash(font: &str, text: &str) -> u64 {
    let bytes = font.bytes().chain(std::iter::once(0)).chain(text.bytes());
    bytes.fold(0xcbf2_9ce4_8422_2325, |h, b| {
        (h ^ u64::from(b)).wrapping_mul(0x0000_0100_0000_01b3)
    })
}

/// Whether measured widths are remembered ([`WIDTHS`]): in the full module. A first
/// module draws the first frames only, until the full one takes over, and is within its
/// download budget by a few hundred bytes, which the memory's code would take.
const REMEMBER_WIDTHS: bool = cfg!(not(feature = "first"));

/// Width and height (px) of `text` in `style`: the width remembered, or measured on
/// `context` after `set_font` has made the style's font (its CSS shorthand, see
/// [`css_font`]) the context's (and then remembered in its slot, in place of what was
/// there). In the full module every digit is measured as `0` ([`with_zeros`]).
pub(crate) fn measure(
    context: &CanvasRenderingContext2d,
    text: &str,
    style: &impl BackendTextStyle,
    set_font: impl FnOnce(String),
) -> (u32, u32) {
    let font = css_font(style);
    let zeros;
    let text = match REMEMBER_WIDTHS {
        true => {
            zeros = with_zeros(text);
            zeros.as_deref().unwrap_or(text)
        }
        false => text,
    };
    let hash = width_hash(&font, text);
    let slot = (hash % WIDTH_SLOTS as u64) as usize;
    let known = match REMEMBER_WIDTHS {
        true => WIDTHS.with_borrow(|w| {
            w.get(slot)
                .filter(|k| k.0 == hash && hash != 0)
                .map(|k| k.1)
        }),
        false => None,
    };
    let width = known.unwrap_or_else(|| {
        set_font(font);
        let width = context.measure_text(text).map(|m| m.width()).unwrap_or(0.0);
        if REMEMBER_WIDTHS {
            WIDTHS.with_borrow_mut(|w| {
                w.resize(WIDTH_SLOTS, (0, 0.0));
                w[slot] = (hash, width);
            });
        }
        width
    });
    (
        width.ceil().max(0.0) as u32,
        style.size().ceil().max(0.0) as u32,
    )
}

/// `text` with every ASCII digit written `0` (`None` if it has none), for measuring: a
/// label whose number changes every frame of a drag (a legend's `DP45: order 5.02`, a
/// marker's value) then measures once, not once a frame. The same width where digits
/// share one width, as in the default sans-serif faces of the common systems (Arial,
/// Helvetica, Liberation Sans, DejaVu Sans); in a face with proportional digits, within a
/// pixel or two (`0` is one of the wider digits), which a legend box's padding absorbs.
fn with_zeros(text: &str) -> Option<String> {
    text.bytes().any(|b| b.is_ascii_digit()).then(|| {
        text.chars()
            .map(|c| if c.is_ascii_digit() { '0' } else { c })
            .collect()
    })
}

/// `canvas`'s 2D context; `None` if it has another kind. A canvas answers `"2d"` with a
/// `CanvasRenderingContext2d` or with null, so the object is not checked again (an
/// `instanceof` call into JavaScript per plot per frame).
pub(crate) fn context_of(canvas: &HtmlCanvasElement) -> Option<CanvasRenderingContext2d> {
    Some(canvas.get_context("2d").ok()??.unchecked_into())
}

#[cfg(test)]
mod tests {
    #[test]
    fn digits_are_measured_as_zeros() {
        assert_eq!(
            super::with_zeros("DP45: 5.02").as_deref(),
            Some("DP00: 0.00")
        );
        assert_eq!(
            super::with_zeros("ζ = −1,5 e-7").as_deref(),
            Some("ζ = −0,0 e-0")
        );
        assert_eq!(super::with_zeros("Euler"), None);
    }
}
