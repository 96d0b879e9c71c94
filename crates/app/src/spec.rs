//! What a demo declares about itself: its parameters, readouts and plots.
//!
//! The web front end builds every control from this declaration (sent to JavaScript with
//! serde-wasm-bindgen), so adding a demo touches Rust only. Keys are part of the URL
//! contract (`?demo=<id>&<key>=<value>`) and must stay stable.

use serde::Serialize;

/// How a slider maps its position to a value.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Scale {
    /// Evenly spaced values.
    Linear,
    /// Evenly spaced logarithms (`min > 0`).
    Log,
}

/// One numeric parameter, shown as a slider with a paired number box.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ParamSpec {
    /// URL key, e.g. `"zeta"`.
    pub key: &'static str,
    /// Human label, e.g. `"damping ratio"`.
    pub label: &'static str,
    /// Mathematical symbol, e.g. `"ζ"`.
    pub symbol: &'static str,
    /// SI unit, empty for dimensionless quantities.
    pub unit: &'static str,
    /// Smallest allowed value.
    pub min: f64,
    /// Largest allowed value.
    pub max: f64,
    /// Slider step (for log sliders, the step of the number box).
    pub step: f64,
    /// Value when none is given.
    pub default: f64,
    /// Slider mapping.
    pub scale: Scale,
}

impl ParamSpec {
    /// A linear slider.
    pub const fn linear(
        key: &'static str,
        label: &'static str,
        symbol: &'static str,
        unit: &'static str,
        range: (f64, f64, f64),
        default: f64,
    ) -> Self {
        Self {
            key,
            label,
            symbol,
            unit,
            min: range.0,
            max: range.1,
            step: range.2,
            default,
            scale: Scale::Linear,
        }
    }

    /// A logarithmic slider.
    pub const fn log(
        key: &'static str,
        label: &'static str,
        symbol: &'static str,
        unit: &'static str,
        range: (f64, f64, f64),
        default: f64,
    ) -> Self {
        Self {
            key,
            label,
            symbol,
            unit,
            min: range.0,
            max: range.1,
            step: range.2,
            default,
            scale: Scale::Log,
        }
    }
}

/// One readout: a number with a unit, or a text.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ReadoutSpec {
    /// Key, used in `data-readout="<key>"`.
    pub key: &'static str,
    /// Human label.
    pub label: &'static str,
    /// SI unit of `data-value` (percent for quantities named in percent).
    pub unit: &'static str,
}

/// One plot: a canvas the demo draws a figure onto.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct PlotSpec {
    /// Key, used as the canvas's `data-plot`.
    pub key: &'static str,
    /// Title, also the canvas's accessible name.
    pub title: &'static str,
    /// Width over height of the canvas.
    pub aspect: f64,
}

/// Everything the front end needs to build a demo's controls.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct DemoSpec {
    /// Stable id, the `demo=` URL value.
    pub id: &'static str,
    /// Title shown in the page.
    pub title: &'static str,
    /// One-paragraph explanation (plain text).
    pub summary: &'static str,
    /// The equation, as MathML markup built by the demo (trusted, not from the URL).
    pub equation_mathml: &'static str,
    /// Parameters in display order.
    pub params: Vec<ParamSpec>,
    /// Readouts in display order.
    pub readouts: Vec<ReadoutSpec>,
    /// Plots in display order.
    pub plots: Vec<PlotSpec>,
}

impl DemoSpec {
    /// The parameter with this key.
    pub fn param(&self, key: &str) -> Option<&ParamSpec> {
        self.params.iter().find(|p| p.key == key)
    }
}
