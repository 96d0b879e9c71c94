//! The demo registry. Each demo lives in its own file and implements [`Demo`]; adding one
//! is one new file and one line in [`IDS`] and [`create`].

use crate::figure::Figure;
use crate::params::Params;
use crate::spec::DemoSpec;
use serde::Serialize;

pub mod analogy;
pub mod design;
pub mod flutter;
pub mod integrators;
pub mod nonlinear;
pub mod quarter_car;
pub mod quarter_car_2dof;
pub mod regimes;
pub mod resonance;
pub mod rlc;
pub mod uncertainty;

/// One computed readout, ready for the page.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Readout {
    /// Key from the demo's [`crate::spec::ReadoutSpec`].
    pub key: &'static str,
    /// Formatted text with unit, e.g. `"8.944 rad/s"`; `"—"` when undefined.
    pub text: String,
    /// The `data-value` attribute: the number in SI units (percent where the name says so)
    /// in Rust's shortest round-trip form, the text for text readouts, or empty when undefined.
    pub data_value: String,
}

impl Readout {
    /// A numeric readout (`None` when the quantity is undefined for this system).
    pub fn number(key: &'static str, value: Option<f64>, unit: &str, sig: usize) -> Self {
        match value.filter(|v| v.is_finite()) {
            Some(v) => Self {
                key,
                text: crate::format::si(v, unit, sig),
                data_value: format!("{v}"),
            },
            None => Self {
                key,
                text: "—".to_string(),
                data_value: String::new(),
            },
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
}

/// What one update produces: readouts and one figure per declared plot, in order.
#[derive(Debug, Clone, PartialEq)]
pub struct Frame {
    /// Readouts in the order of the spec.
    pub readouts: Vec<Readout>,
    /// Figures in the order of the spec's plots.
    pub figures: Vec<Figure>,
    /// Time span \[s\] of the animation and its scrub control, for demos with a schematic.
    pub time_span: Option<(f64, f64)>,
}

/// A live demo.
pub trait Demo {
    /// Parameters, readouts and plots, for the UI to build controls from.
    fn spec(&self) -> DemoSpec;
    /// Recomputes for these (validated) parameter values.
    fn update(&mut self, params: &Params) -> Frame;
    /// The schematic at time `t` \[s\] (for demos whose spec sets `schematic`).
    fn schematic(&self, _params: &Params, _t: f64) -> Option<Figure> {
        None
    }
    /// Parameters the last [`Demo::update`] derived from others (e.g. `c` from a moved
    /// `zeta`); the page moves those controls and the URL follows.
    fn derived_params(&self) -> Vec<(&'static str, f64)> {
        Vec::new()
    }
    /// A click or tap at data point `(x, y)` of plot `plot` (e.g. choosing a design on a
    /// map); returns the parameters to set.
    fn pick(&mut self, _plot: &str, _x: f64, _y: f64) -> Vec<(&'static str, f64)> {
        Vec::new()
    }
    /// The main response at time `t` \[s\], normalised to about −1…1, for sonification
    /// (pitch follows displacement). `None` for demos without a time response.
    fn sonify(&self, _params: &Params, _t: f64) -> Option<f64> {
        None
    }
}

/// Ids of every demo, in menu order.
pub const IDS: &[&str] = &[
    "regimes",
    "quarter-car",
    "rlc",
    "analogy",
    "resonance",
    "integrators",
    "flutter",
    "nonlinear",
    "quarter-car-2dof",
    "design",
    "uncertainty",
];

/// A new instance of the demo `id`, or `None` if there is no such demo.
pub fn create(id: &str) -> Option<Box<dyn Demo>> {
    match id {
        "regimes" => Some(Box::new(regimes::Regimes)),
        "quarter-car" => Some(Box::new(quarter_car::QuarterCar::new())),
        "rlc" => Some(Box::new(rlc::Rlc)),
        "resonance" => Some(Box::new(resonance::Resonance::default())),
        "analogy" => Some(Box::new(analogy::Analogy)),
        "flutter" => Some(Box::new(flutter::Flutter::default())),
        "nonlinear" => Some(Box::new(nonlinear::Nonlinear::default())),
        "quarter-car-2dof" => Some(Box::new(quarter_car_2dof::QuarterCar2Dof::default())),
        "integrators" => Some(Box::new(integrators::Integrators::new())),
        "design" => Some(Box::new(design::DesignSpace::default())),
        "uncertainty" => Some(Box::new(uncertainty::Uncertainty::default())),
        _ => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::collections::HashSet;

    #[test]
    fn every_demo_is_consistent_and_draws_finite_figures_from_its_defaults() {
        let mut ids = HashSet::new();
        for id in IDS {
            let mut demo = create(id).unwrap();
            let spec = demo.spec();
            assert_eq!(spec.id, *id);
            assert!(ids.insert(spec.id), "duplicate id {id}");
            let mut keys = HashSet::new();
            for p in &spec.params {
                assert!(keys.insert(p.key), "{id}: duplicate key {}", p.key);
                assert!(p.min < p.max && p.step > 0.0, "{id}.{}", p.key);
                assert!(
                    (p.min..=p.max).contains(&p.default),
                    "{id}.{} default out of range",
                    p.key
                );
                if p.scale == crate::spec::Scale::Log {
                    assert!(p.min > 0.0);
                }
            }
            let frame = demo.update(&Params::defaults(&spec));
            let rkeys: Vec<_> = frame.readouts.iter().map(|r| r.key).collect();
            let skeys: Vec<_> = spec.readouts.iter().map(|r| r.key).collect();
            assert_eq!(rkeys, skeys, "{id}: readouts follow the spec");
            assert_eq!(frame.figures.len(), spec.plots.len());
            for f in &frame.figures {
                assert!(f.has_visible_data(), "{id}: {} is empty", f.title);
                assert!(
                    !f.description.is_empty(),
                    "{id}: {} has no text alternative",
                    f.title
                );
            }
            if spec.schematic {
                let (t0, t1) = frame.time_span.expect("animated demos give a time span");
                assert!(t0 < t1);
                for t in [t0, (t0 + t1) / 2.0, t1] {
                    let fig = demo
                        .schematic(&Params::defaults(&spec), t)
                        .expect("schematic");
                    assert!(fig.has_visible_data());
                }
            }
            for preset in &spec.presets {
                for (k, v) in &preset.values {
                    let p = spec
                        .param(k)
                        .unwrap_or_else(|| panic!("{id}: preset names {k}"));
                    assert!(
                        (p.min..=p.max).contains(v),
                        "{id}: preset {} sets {k} out of range",
                        preset.label
                    );
                }
            }
            for r in &frame.readouts {
                assert!(!r.data_value.contains("NaN") && !r.data_value.contains("inf"));
            }
        }
        assert!(create("nope").is_none());
    }

    #[test]
    fn every_demo_survives_its_parameter_extremes() {
        for id in IDS {
            let mut demo = create(id).unwrap();
            let spec = demo.spec();
            for p in &spec.params {
                for v in [p.min, p.max] {
                    let mut params = Params::defaults(&spec);
                    params.set_raw(&spec, p.key, &format!("{v}"));
                    let frame = demo.update(&params);
                    for r in &frame.readouts {
                        assert!(
                            !r.data_value.contains("NaN"),
                            "{id}.{}={v}: {}",
                            p.key,
                            r.key
                        );
                    }
                }
            }
        }
    }
}
