//! Languages. Every human-readable string is a message id with named arguments in a
//! [Project Fluent](https://projectfluent.org) catalogue, one file a language under
//! `crates/app/locales/`: plurals, selectors and argument order are the catalogue's;
//! numbers take the language's digits and separators from the browser's `Intl`
//! ([`number`]). English (`en.ftl`) is compiled in and is the fallback for any message a
//! catalogue lacks; the page fetches only the active language's file.
//!
//! Two kinds of id:
//! - **Messages** written in code with [`t!`](crate::t): `t!("regimes-settles", time =
//!   si(t, "s", 3))`. The id is a literal, so the catalogue tests find every one.
//! - **Declared strings** (labels, titles, options, table cells of a demo's declaration)
//!   keep their English text in the declaration and get structural ids
//!   (`regimes-param-zeta`): see [`declared`].
//!
//! Machine-readable values (`data-value`, URL keys, CSV numbers) never pass through here.

mod catalogue;
pub mod declared;
pub mod locale;
pub mod number;
pub mod pseudo;

pub use catalogue::{active, is_loaded, load, take_missing, ENGLISH_FTL};
pub use locale::{Dir, Locale, LOCALES};

use fluent_bundle::{FluentArgs, FluentValue};

/// A typed message argument.
#[derive(Debug, Clone, PartialEq)]
pub enum Arg {
    /// Text already in the interface language: a formatted quantity with its unit
    /// (`crate::format::si`), a name, or another message.
    Text(String),
    /// A count: selects the plural form and is written with the language's digits.
    Count(i64),
}

impl From<String> for Arg {
    fn from(s: String) -> Self {
        Arg::Text(s)
    }
}

impl From<&str> for Arg {
    fn from(s: &str) -> Self {
        Arg::Text(s.to_string())
    }
}

impl From<&String> for Arg {
    fn from(s: &String) -> Self {
        Arg::Text(s.clone())
    }
}

macro_rules! count_from {
    ($($t:ty),*) => {$(
        impl From<$t> for Arg {
            fn from(n: $t) -> Self {
                Arg::Count(i64::try_from(n).unwrap_or(i64::MAX))
            }
        }
    )*};
}
count_from!(usize, u32, u64, i32, i64);

/// Message `id` with `args` in the active language (English if the catalogue lacks it).
/// Prefer the [`t!`](crate::t) macro.
pub fn message(id: &str, args: &[(&str, Arg)]) -> String {
    if args.is_empty() {
        return catalogue::format(id, None);
    }
    let mut fa = FluentArgs::with_capacity(args.len());
    for (name, arg) in args {
        match arg {
            Arg::Text(s) => fa.set(*name, FluentValue::from(s.clone())),
            Arg::Count(n) => fa.set(*name, FluentValue::from(*n)),
        }
    }
    catalogue::format(id, Some(&fa))
}

/// Runs `f` with English active (for locale-free values such as a text readout's
/// `data-value`), then restores the language.
pub fn in_english<T>(f: impl FnOnce() -> T) -> T {
    let previous = catalogue::active();
    if previous.tag == "en" {
        return f();
    }
    catalogue::set_active(locale::english());
    let out = f();
    catalogue::set_active(previous);
    out
}

/// Makes the language best matching `requested` (most wanted first) active and returns
/// it; see [`locale::negotiate`].
pub fn set_language<S: AsRef<str>>(requested: &[S]) -> &'static Locale {
    let l = locale::negotiate(requested);
    catalogue::set_active(l);
    l
}

/// A message in the interface language: `t!("id")` or `t!("id", name = value, …)`, where
/// each value converts [`Into`] an [`Arg`](crate::i18n::Arg) (text or a count).
#[macro_export]
macro_rules! t {
    ($id:literal) => {
        $crate::i18n::message($id, &[])
    };
    ($id:literal, $($name:ident = $value:expr),+ $(,)?) => {
        $crate::i18n::message(
            $id,
            &[$((stringify!($name), $crate::i18n::Arg::from($value))),+],
        )
    };
}
