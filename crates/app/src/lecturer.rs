//! The lecturer toolkit's Rust side: the versioned schema a host page asks for
//! (`zeta:describe`), the authoring overrides that narrow a slider (`range.<key>=lo,hi`,
//! `step.<key>=s`), and the few wasm exports the page's own modules call (the schema, the
//! app version, the number parser for predictions, and export stamping).
//!
//! Every value from outside still passes through [`crate::params`]: overrides are parsed
//! with [`parse_number`] and may only narrow the declared range, never widen it.

use crate::params::{parse_number, parse_query, Notice};
use crate::spec::{DemoSpec, Kind, ParamSpec, ReadoutSpec, Scale};
use serde::Serialize;

/// Version of the [`Schema`] layout; `docs/zeta-schema.json` pins the same number.
pub const SCHEMA_VERSION: u32 = 1;
/// The app's version, written into exports and schemas.
pub const APP_VERSION: &str = env!("CARGO_PKG_VERSION");

/// What a host page learns from `zeta:describe`: the demo's controls and outputs.
#[derive(Debug, Clone, Serialize)]
pub struct Schema {
    /// [`SCHEMA_VERSION`].
    pub schema_version: u32,
    /// [`APP_VERSION`].
    pub app_version: &'static str,
    /// Demo id (`demo=`).
    pub demo: &'static str,
    /// Demo title (English).
    pub title: &'static str,
    /// Parameters in declaration order.
    pub parameters: Vec<ParamSchema>,
    /// Readouts in declaration order.
    pub readouts: Vec<ReadoutSchema>,
    /// Plots in declaration order.
    pub plots: Vec<PlotSchema>,
}

/// One parameter as a host sees it; `min`/`max`/`step` include any overrides.
#[derive(Debug, Clone, Serialize)]
pub struct ParamSchema {
    /// URL key.
    pub key: &'static str,
    /// Human label (English).
    pub label: &'static str,
    /// Mathematical symbol.
    pub symbol: &'static str,
    /// SI unit, empty when dimensionless.
    pub unit: &'static str,
    /// `slider`, `toggle` or `choice`.
    pub kind: Kind,
    /// `linear` or `log`.
    pub scale: Scale,
    /// Smallest value.
    pub min: f64,
    /// Largest value.
    pub max: f64,
    /// Slider step.
    pub step: f64,
    /// Default value.
    pub default: f64,
    /// Option keys of a choice (the value is the index), empty otherwise.
    pub options: Vec<&'static str>,
}

/// One readout, as the page declares it: key (`data-readout`, `predict=`, `readouts=`),
/// English label, and the unit of `data-value` (a number in `unit`, or text for text
/// readouts).
pub type ReadoutSchema = ReadoutSpec;

/// One plot (`plots=`, `zeta:export`).
#[derive(Debug, Clone, Serialize)]
pub struct PlotSchema {
    /// Key.
    pub key: &'static str,
    /// Title (English).
    pub title: &'static str,
}

/// The schema of `spec` (already narrowed by [`narrow`] if the page was given overrides).
pub fn schema(spec: &DemoSpec) -> Schema {
    Schema {
        schema_version: SCHEMA_VERSION,
        app_version: APP_VERSION,
        demo: spec.id,
        title: spec.title,
        parameters: spec
            .params
            .iter()
            .map(|p| ParamSchema {
                key: p.key,
                label: p.label,
                symbol: p.symbol,
                unit: p.unit,
                kind: p.kind,
                scale: p.scale,
                min: p.min,
                max: p.max,
                step: p.step,
                default: p.default,
                options: p.options.iter().map(|o| o.key).collect(),
            })
            .collect(),
        readouts: spec.readouts.clone(),
        plots: spec
            .plots
            .iter()
            .map(|p| PlotSchema {
                key: p.key,
                title: p.title,
            })
            .collect(),
    }
}

/// Applies the authoring overrides of `query` to `spec`: `range.<key>=lo,hi` narrows a
/// slider to `[lo, hi]` (clamped into the declared range; `lo < hi`), `step.<key>=s` sets
/// its step (`0 < s ≤ hi − lo`). The default is clamped into the new range. Anything
/// malformed is ignored with a notice; toggles and choices have no range to narrow.
pub fn narrow(spec: &mut DemoSpec, query: &str) -> Vec<Notice> {
    let mut notices = Vec::new();
    let pairs = parse_query(query);
    // Ranges first, so a step is checked against the narrowed span.
    for (key, v) in overrides(&pairs, "range.") {
        let Some(p) = slider_mut(spec, key) else {
            continue;
        };
        let bounds = v
            .split_once(',')
            .and_then(|(a, b)| Some((parse_number(a)?, parse_number(b)?)))
            .map(|(lo, hi)| (lo.clamp(p.min, p.max), hi.clamp(p.min, p.max)));
        match bounds {
            Some((lo, hi)) if lo < hi => {
                p.min = lo;
                p.max = hi;
                p.default = p.default.clamp(lo, hi);
                p.step = p.step.min(hi - lo);
            }
            Some(_) => notices.push(Notice::about(p, v, "range-empty", None)),
            None => notices.push(Notice::about(p, v, "range-not-two-numbers", None)),
        }
    }
    for (key, v) in overrides(&pairs, "step.") {
        let Some(p) = slider_mut(spec, key) else {
            continue;
        };
        match parse_number(v) {
            Some(s) if s > 0.0 && s <= p.max - p.min => p.step = s,
            _ => notices.push(Notice::about(p, v, "step", None)),
        }
    }
    notices
}

/// The `(key, value)` of each `<prefix><key>=<value>` pair.
fn overrides<'a>(
    pairs: &'a [(String, String)],
    prefix: &'a str,
) -> impl Iterator<Item = (&'a str, &'a str)> {
    pairs
        .iter()
        .filter(move |(k, _)| k.starts_with(prefix))
        .map(move |(k, v)| (k.trim_start_matches(prefix), v.as_str()))
}

/// The slider `key` of `spec` (toggles and choices have no range to narrow).
fn slider_mut<'a>(spec: &'a mut DemoSpec, key: &str) -> Option<&'a mut ParamSpec> {
    spec.params
        .iter_mut()
        .find(|p| p.key == key && p.kind == Kind::Slider)
}

/// Not in a first module (feature `first`): the page calls these through `fullGlue`
/// (web/glue.js), after the full module has taken over.
#[cfg(all(target_arch = "wasm32", not(feature = "first")))]
mod wasm {
    use super::*;
    use wasm_bindgen::prelude::*;

    fn to_js<T: Serialize>(v: &T) -> Result<JsValue, JsError> {
        v.serialize(&serde_wasm_bindgen::Serializer::json_compatible())
            .map_err(|e| JsError::new(&e.to_string()))
    }

    /// The schema of demo `id` with the overrides of `query` applied (`zeta:describe`).
    #[wasm_bindgen(js_name = describeDemo)]
    pub fn describe_demo(id: &str, query: &str) -> Result<JsValue, JsError> {
        let mut spec = crate::demos::create(id)
            .map(|d| d.spec())
            .ok_or_else(|| JsError::new(&format!("unknown demo {id:?}")))?;
        let _ = narrow(&mut spec, query);
        to_js(&schema(&spec))
    }

    /// The app's version (written into exports).
    #[wasm_bindgen(js_name = appVersion)]
    pub fn app_version() -> String {
        APP_VERSION.to_string()
    }

    /// A student's typed number through the one parser: finite decimal or `undefined`.
    #[wasm_bindgen(js_name = parseNumber)]
    pub fn parse_number_js(raw: &str) -> Option<f64> {
        parse_number(raw)
    }

    /// `data` (the bytes of an exported PNG, SVG or CSV, by `format`) with the state token
    /// and app version written in; unchanged if the format is unknown or the PNG malformed.
    #[wasm_bindgen(js_name = stampExport)]
    pub fn stamp_export(format: &str, data: &[u8], token: &str) -> Vec<u8> {
        crate::export::stamp(format, data, token, APP_VERSION)
    }

    /// The state token stamped into an exported file's bytes, if any.
    #[wasm_bindgen(js_name = readStamp)]
    pub fn read_stamp(data: &[u8]) -> Option<String> {
        crate::export::read_stamp(data)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::demos;

    fn spec(id: &str) -> DemoSpec {
        demos::create(id).map(|d| d.spec()).unwrap()
    }

    #[test]
    fn overrides_narrow_a_slider_and_never_widen_it() {
        let mut s = spec("regimes");
        let n = narrow(&mut s, "?range.zeta=0,0.2&step.zeta=0.001&range.wn=-5,100");
        assert!(n.is_empty(), "{n:?}");
        let z = s.param("zeta").unwrap();
        assert_eq!((z.min, z.max, z.step), (0.0, 0.2, 0.001));
        assert_eq!(z.default, 0.2, "default clamped into the new range");
        let wn = s.param("wn").unwrap();
        let full = spec("regimes");
        let declared = full.param("wn").unwrap();
        assert_eq!((wn.min, wn.max), (declared.min, declared.max));
    }

    #[test]
    fn malformed_overrides_are_notices_and_change_nothing() {
        let full = spec("regimes");
        for q in [
            "range.zeta=0.5,0.1",
            "range.zeta=abc",
            "range.zeta=NaN,1",
            "step.zeta=0",
            "step.zeta=-1",
            "step.zeta=1e9",
        ] {
            let mut s = spec("regimes");
            let n = narrow(&mut s, q);
            assert_eq!(n.len(), 1, "{q}");
            assert_eq!(s.param("zeta"), full.param("zeta"), "{q}");
        }
        let mut s = spec("regimes");
        assert!(narrow(&mut s, "range.nope=0,1&step.nope=1").is_empty());
    }

    #[test]
    fn every_demo_has_a_schema_with_its_keys() {
        for id in demos::ids() {
            let s = spec(id);
            let sc = schema(&s);
            assert_eq!(sc.parameters.len(), s.params.len());
            assert_eq!(sc.readouts.len(), s.readouts.len());
            assert_eq!(sc.plots.len(), s.plots.len());
        }
    }
}
