//! A demo's declaration as data, in the style of ripgrep's flag table: each parameter and
//! each readout is declared once, and everything else is derived from that one table — the
//! [`DemoSpec`] the page builds its controls from, the typed parameter struct a model step
//! reads, the readouts in order, and the all-undefined frame shown when a step fails.
//!
//! ```
//! use zeta_app::declare::{Declaration, Param, ReadoutDef};
//! #[derive(Default)]
//! struct P { wn: f64 }
//! struct R { wn: f64 }
//! let decl: Declaration<P, R> = Declaration {
//!     params: vec![Param::linear("wn", "natural frequency", "ωₙ", "rad/s", (0.5, 20.0, 0.01), 6.0, |p, v| p.wn = v)],
//!     readouts: vec![ReadoutDef::number("wn", "natural frequency ωₙ", "rad/s", 4, |r| Some(r.wn))],
//!     ..Declaration::new("demo", "A demo", "What it shows.")
//! };
//! let spec = decl.spec();
//! let typed = decl.read(&zeta_app::params::Params::defaults(&spec));
//! assert_eq!(typed.wn, 6.0);
//! assert_eq!(decl.readouts(&R { wn: 6.0 })[0].text, "6.000 rad/s");
//! ```

mod param;
mod readout;

pub use crate::spec::Quantity;
pub(crate) use param::choice_enum;
pub use param::{
    Choice, Param, DAMPING_RATIO, INITIAL_DISPLACEMENT, INITIAL_VELOCITY, NATURAL_FREQUENCY,
};
pub use readout::{Readout, ReadoutDef};

use crate::demos::Frame;
use crate::params::Params;
use crate::spec::{DemoSpec, ParamSpec, PlotSpec, Preset, Table};

/// Everything a demo declares: the typed parameters `P` it reads, the readouts it shows
/// from its results `R`, its plots, presets and text.
pub struct Declaration<P, R> {
    /// Stable id, the `demo=` URL value.
    pub id: &'static str,
    /// Title shown in the page and the menu.
    pub title: &'static str,
    /// One-paragraph explanation (plain text).
    pub summary: &'static str,
    /// The equation as MathML (trusted markup, never from the URL).
    pub equation_mathml: &'static str,
    /// Parameters in display order, each with the field of `P` it fills.
    pub params: Vec<Param<P>>,
    /// Readouts in display order, each with its getter from `R`.
    pub readouts: Vec<ReadoutDef<R>>,
    /// Plots in display order, the primary one first (see [`DemoSpec::primary`]).
    pub plots: Vec<PlotSpec>,
    /// One-click configurations.
    pub presets: Vec<Preset>,
    /// An optional reference table.
    pub table: Option<Table>,
    /// Whether the demo draws an animated schematic.
    pub schematic: bool,
}

impl<P, R> Declaration<P, R> {
    /// A declaration with no parameters, readouts or plots yet; fill them with struct
    /// update syntax (`..Declaration::new(id, title, summary)`).
    pub fn new(id: &'static str, title: &'static str, summary: &'static str) -> Self {
        Self {
            id,
            title,
            summary,
            equation_mathml: "",
            params: Vec::new(),
            readouts: Vec::new(),
            plots: Vec::new(),
            presets: Vec::new(),
            table: None,
            schematic: false,
        }
    }

    /// The spec the page builds its controls from.
    pub fn spec(&self) -> DemoSpec {
        DemoSpec {
            id: self.id,
            title: self.title,
            summary: self.summary,
            equation_mathml: self.equation_mathml,
            params: self
                .params
                .iter()
                .map(|p| ParamSpec {
                    demo: self.id,
                    ..p.spec().clone()
                })
                .collect(),
            readouts: self.readouts.iter().map(ReadoutDef::spec).collect(),
            plots: self.plots.clone(),
            presets: self.presets.clone(),
            table: self.table.clone(),
            schematic: self.schematic,
        }
    }

    /// The readouts for results `r`, in declared order.
    pub fn readouts(&self, r: &R) -> Vec<Readout> {
        self.readouts.iter().map(|d| d.read(r)).collect()
    }

    /// A frame with every readout undefined and no figures: what the page shows when a
    /// model step fails (validated parameters make this unreachable; it is never a panic).
    pub fn undefined_frame(&self) -> Frame {
        Frame {
            readouts: self.readouts.iter().map(ReadoutDef::undefined).collect(),
            figures: Vec::new(),
            time_span: None,
        }
    }
}

impl<P: Default, R> Declaration<P, R> {
    /// The typed parameters for validated values: each declared parameter's setter fills
    /// its field, so a wrong key cannot reach a model step.
    pub fn read(&self, values: &Params) -> P {
        let mut p = P::default();
        for (param, (_, v)) in self.params.iter().zip(values.pairs()) {
            param.apply(&mut p, v);
        }
        p
    }
}
