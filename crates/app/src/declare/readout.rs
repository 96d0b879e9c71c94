//! Readouts declared once — key, label, unit, precision and a getter — from which the
//! spec, the computed values and the undefined fallback all follow.

use crate::format::{si, significant};
use crate::spec::ReadoutSpec;
use serde::Serialize;

/// One computed readout, ready for the page.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Readout {
    /// Key from the declaration.
    pub key: &'static str,
    /// Formatted text with unit, e.g. `"8.944 rad/s"`; `"—"` when undefined.
    pub text: String,
    /// The `data-value` attribute: the number in SI units (percent where the name says so)
    /// in Rust's shortest round-trip form, the text for text readouts, or empty when undefined.
    pub data_value: String,
}

impl Readout {
    /// A numeric readout with an SI prefix on `unit` (`None` when undefined).
    pub fn number(key: &'static str, value: Option<f64>, unit: &str, sig: usize) -> Self {
        match value.filter(|v| v.is_finite()) {
            Some(v) => Self {
                key,
                text: si(v, unit, sig),
                data_value: format!("{v}"),
            },
            None => Self::undefined(key),
        }
    }

    /// A numeric readout in `unit` exactly as given, never prefixed (e.g. `"36.2 ms"`).
    pub fn plain(key: &'static str, value: Option<f64>, unit: &str, sig: usize) -> Self {
        match value.filter(|v| v.is_finite()) {
            Some(v) => Self {
                key,
                text: if unit.is_empty() {
                    significant(v, sig)
                } else {
                    format!("{} {unit}", significant(v, sig))
                },
                data_value: format!("{v}"),
            },
            None => Self::undefined(key),
        }
    }

    /// A text readout.
    pub fn text(key: &'static str, text: impl Into<String>) -> Self {
        let text = text.into();
        Self {
            key,
            data_value: text.clone(),
            text,
        }
    }

    /// An undefined readout: `"—"` with an empty `data-value`.
    pub fn undefined(key: &'static str) -> Self {
        Self {
            key,
            text: "—".to_string(),
            data_value: String::new(),
        }
    }
}

/// How a readout's value is read from the results `R` and shown.
enum Show<R> {
    /// A number with an SI prefix, `sig` significant digits.
    Number {
        sig: usize,
        get: fn(&R) -> Option<f64>,
    },
    /// A number in its unit as given, `sig` significant digits.
    Plain {
        sig: usize,
        get: fn(&R) -> Option<f64>,
    },
    /// A text.
    Text(fn(&R) -> String),
    /// A number with its own text: `(data-value, text)`.
    Formatted(fn(&R) -> Option<(f64, String)>),
    /// A number with an SI prefix, or a note instead of a number (empty `data-value`).
    NumberOrNote {
        sig: usize,
        get: fn(&R) -> Result<Option<f64>, String>,
    },
}

/// The number constructors of [`ReadoutDef`], one per way of showing a number, all with
/// the same arguments.
macro_rules! numbers {
    ($($(#[$doc:meta])* $name:ident: $show:ident;)+) => {
        $(
            $(#[$doc])*
            pub const fn $name(
                key: &'static str,
                label: &'static str,
                unit: &'static str,
                sig: usize,
                get: fn(&R) -> Option<f64>,
            ) -> Self {
                Self {
                    key,
                    label,
                    unit,
                    show: Show::$show { sig, get },
                }
            }
        )+
    };
}

/// One row of a demo's readout table.
pub struct ReadoutDef<R> {
    /// Key, used in `data-readout="<key>"`.
    pub key: &'static str,
    /// Human label saying exactly what the number is.
    pub label: &'static str,
    /// SI unit of `data-value` (percent for quantities named in percent).
    pub unit: &'static str,
    show: Show<R>,
}

impl<R> ReadoutDef<R> {
    numbers! {
        /// A number shown with `sig` significant digits and an SI prefix on `unit`.
        number: Number;
        /// A number shown in `unit` exactly as given (no prefix), e.g. a time in ms.
        plain: Plain;
    }

    /// A text readout.
    pub const fn text(key: &'static str, label: &'static str, get: fn(&R) -> String) -> Self {
        Self {
            key,
            label,
            unit: "",
            show: Show::Text(get),
        }
    }

    /// A number with a text of the demo's own making.
    pub const fn formatted(
        key: &'static str,
        label: &'static str,
        unit: &'static str,
        get: fn(&R) -> Option<(f64, String)>,
    ) -> Self {
        Self {
            key,
            label,
            unit,
            show: Show::Formatted(get),
        }
    }

    /// A number shown with `sig` significant digits and an SI prefix on `unit`, or — where
    /// no number can be given — a note saying why (e.g. "overflow at t = 3.1 s") with an
    /// empty `data-value`.
    pub const fn number_or_note(
        key: &'static str,
        label: &'static str,
        unit: &'static str,
        sig: usize,
        get: fn(&R) -> Result<Option<f64>, String>,
    ) -> Self {
        Self {
            key,
            label,
            unit,
            show: Show::NumberOrNote { sig, get },
        }
    }

    /// The spec entry.
    pub fn spec(&self) -> ReadoutSpec {
        ReadoutSpec {
            key: self.key,
            label: self.label,
            unit: self.unit,
        }
    }

    /// The readout for results `r`.
    pub fn read(&self, r: &R) -> Readout {
        match &self.show {
            Show::Number { sig, get } => Readout::number(self.key, get(r), self.unit, *sig),
            Show::Plain { sig, get } => Readout::plain(self.key, get(r), self.unit, *sig),
            // The text in the interface language; the data-value in English, locale-free.
            Show::Text(get) => Readout {
                key: self.key,
                text: get(r),
                data_value: crate::i18n::in_english(|| get(r)),
            },
            Show::Formatted(get) => match get(r).filter(|(v, _)| v.is_finite()) {
                Some((v, text)) => Readout {
                    key: self.key,
                    text,
                    data_value: format!("{v}"),
                },
                None => Readout::undefined(self.key),
            },
            Show::NumberOrNote { sig, get } => match get(r) {
                Ok(v) => Readout::number(self.key, v, self.unit, *sig),
                Err(note) => Readout {
                    key: self.key,
                    text: note,
                    data_value: String::new(),
                },
            },
        }
    }

    /// The readout when nothing could be computed.
    pub fn undefined(&self) -> Readout {
        Readout::undefined(self.key)
    }
}
