//! The wasm boundary: a few thin exports over the demos. Errors become JS errors here and
//! nowhere else; a panic (there should be none) is logged by the hook and reported to the
//! page, which then instantiates the module afresh and opens a new session there.
//!
//! - this file: start-up (panic hook), the interface language, the demo list;
//! - `session`: [`Session`], one open demo with its canvases;
//! - `draw`: how a session builds and draws its figures;
//! - `plots`: what the page asks of one drawn plot (pointer, exports);
//! - `translate`: the spec, figures and notices in the page's language;
//! - `result`: what `Session::set` and `Session::update` return;
//! - `study`: [`Study`], a demo's full study computed in the page's worker.

mod draw;
mod plots;
mod result;
mod session;
#[cfg(not(feature = "first"))]
mod study;
mod translate;

pub use session::Session;
#[cfg(not(feature = "first"))]
pub use study::Study;

use crate::demos;
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

#[derive(Serialize)]
struct LanguageEntry {
    tag: &'static str,
    name: &'static str,
    dir: crate::i18n::Dir,
    /// The locale whose CLDR rules format numbers (`Intl`): a pseudo-locale's base.
    rules: &'static str,
    pseudo: bool,
    /// The catalogue file to fetch (absent: built in).
    #[serde(skip_serializing_if = "Option::is_none")]
    file: Option<String>,
    /// Whether its messages are available now.
    loaded: bool,
}

fn entry(l: &'static crate::i18n::Locale) -> LanguageEntry {
    LanguageEntry {
        tag: l.tag,
        name: l.name,
        dir: l.dir,
        rules: l.rules,
        pseudo: l.is_pseudo(),
        file: l.file(),
        loaded: crate::i18n::is_loaded(l),
    }
}

/// `[{tag, name, dir, rules, pseudo, file?, loaded}]` of every interface language.
#[wasm_bindgen]
pub fn languages() -> Result<JsValue, JsError> {
    to_js(&crate::i18n::LOCALES.iter().map(entry).collect::<Vec<_>>())
}

/// Makes the language that best matches `requested` (BCP 47 tags, most wanted first,
/// separated by commas: `lang=`, then the browser's) active for every string the module
/// returns; returns its entry. A language whose catalogue is not loaded yet shows English
/// until [`load_catalogue`] brings it.
#[wasm_bindgen(js_name = setLanguage)]
pub fn set_language(requested: &str) -> Result<JsValue, JsError> {
    let tags: Vec<&str> = requested.split(',').map(str::trim).collect();
    to_js(&entry(crate::i18n::set_language(&tags)))
}

/// Loads the catalogue of language `tag` from its `.ftl` text; returns the problems
/// found (empty when it parsed cleanly; messages that parsed are kept either way).
#[wasm_bindgen(js_name = loadCatalogue)]
pub fn load_catalogue(tag: &str, ftl: &str) -> Vec<String> {
    crate::i18n::load(tag, ftl).err().unwrap_or_default()
}

/// The message ids shown in English since the last call because the active language's
/// catalogue lacks them (empty when everything on screen is translated).
#[wasm_bindgen(js_name = takeMissingMessages)]
pub fn take_missing_messages() -> Vec<String> {
    crate::i18n::take_missing()
}

/// Message `id` in the active language, with `args` (an object of strings and numbers;
/// integers select plural forms) — for the page's own strings.
#[wasm_bindgen]
pub fn message(id: &str, args: JsValue) -> String {
    use crate::i18n::Arg;
    let mut list: Vec<(String, Arg)> = Vec::new();
    if let Some(obj) = args.dyn_ref::<js_sys::Object>() {
        for pair in js_sys::Object::entries(obj).iter() {
            let pair = js_sys::Array::from(&pair);
            let Some(name) = pair.get(0).as_string() else {
                continue;
            };
            let v = pair.get(1);
            let arg = match v.as_f64() {
                Some(n) if n.fract() == 0.0 && n.abs() < 9e15 => Arg::Count(n as i64),
                Some(n) => Arg::Text(crate::format::significant(n, 6)),
                None => Arg::Text(v.as_string().unwrap_or_default()),
            };
            list.push((name, arg));
        }
    }
    let borrowed: Vec<(&str, Arg)> = list.iter().map(|(k, a)| (k.as_str(), a.clone())).collect();
    crate::i18n::message(id, &borrowed)
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

/// `[{id, title}]` of every demo, in menu order (every demo, even in the `first` build).
#[wasm_bindgen(js_name = demoList)]
pub fn demo_list() -> Result<JsValue, JsError> {
    let list: Vec<DemoEntry> = demos::menu()
        .map(|(id, title)| DemoEntry {
            id,
            title: crate::i18n::declared::tr(&format!("{id}-title"), title),
        })
        .collect();
    to_js(&list)
}

/// Whether this module can open every demo (`false` for the `first` build, which holds
/// only the default demo).
#[wasm_bindgen(js_name = isFull)]
pub fn is_full() -> bool {
    !cfg!(feature = "first")
}

fn theme(dark: bool) -> Theme {
    if dark {
        Theme::DARK
    } else {
        Theme::LIGHT
    }
}

fn js_err(e: impl std::fmt::Display) -> JsError {
    JsError::new(&e.to_string())
}
