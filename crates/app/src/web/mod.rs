//! The wasm boundary: a few thin exports over the demos. Errors become JS errors here and
//! nowhere else; a panic (there should be none) is logged by the hook and reported to the
//! page, which then instantiates the module afresh and opens a new session there.
//!
//! - this file: start-up (panic hook), the interface language, the demo list;
//! - [`session`]: [`Session`], one open demo with its canvases;
//! - [`translate`]: the spec, figures and notices in the page's language;
//! - [`result`]: what `Session::set` and `Session::update` return.

mod result;
mod session;
mod translate;

pub use session::Session;

use crate::demos;
use crate::i18n::{tr, Lang};
use crate::theme::Theme;
use serde::Serialize;
use wasm_bindgen::prelude::*;

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

fn js_err(e: impl std::fmt::Display) -> JsError {
    JsError::new(&e.to_string())
}
