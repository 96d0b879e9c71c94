//! The one test harness for demos: run a demo from a URL query, read its readouts.
// Not every demo uses every reader.
#![allow(dead_code)]

use super::{create, Frame, Readout};
use crate::params::resolve_query;

/// Demo `id` updated once for `query` (as the page does on load with that link).
pub fn run(id: &str, query: &str) -> Frame {
    let mut demo = create(id).unwrap_or_else(|| panic!("no demo {id}"));
    let (params, notices) = resolve_query(&demo.spec(), query);
    assert!(notices.is_empty(), "{id}?{query}: {notices:?}");
    demo.update(&params)
}

/// Demo `id` at its preset `label`: the query that preset writes (its values on top of
/// the defaults), run as [`run`] does.
pub fn preset(id: &str, label: &str) -> Frame {
    let spec = create(id).unwrap_or_else(|| panic!("no demo {id}")).spec();
    let preset = spec
        .presets
        .iter()
        .find(|p| p.label == label)
        .unwrap_or_else(|| panic!("{id} has no preset {label:?}"));
    let query = preset
        .values
        .iter()
        .map(|(k, v)| format!("{k}={v}"))
        .collect::<Vec<_>>()
        .join("&");
    run(id, &query)
}

/// Whether `a` equals `b` to `tol` relative to `1 + |b|` (so also absolutely near 0).
pub fn close(a: f64, b: f64, tol: f64) -> bool {
    (a - b).abs() <= tol * (1.0 + b.abs())
}

/// Readout `key`.
pub fn readout<'a>(frame: &'a Frame, key: &str) -> &'a Readout {
    frame
        .readouts
        .iter()
        .find(|r| r.key == key)
        .unwrap_or_else(|| panic!("no readout {key}"))
}

/// The `data-value` of readout `key`.
pub fn value(frame: &Frame, key: &str) -> String {
    readout(frame, key).data_value.clone()
}

/// The `data-value` of readout `key` as a number.
pub fn number(frame: &Frame, key: &str) -> f64 {
    value(frame, key)
        .parse()
        .unwrap_or_else(|_| panic!("readout {key} is not a number"))
}

/// The text of readout `key`.
pub fn text(frame: &Frame, key: &str) -> String {
    readout(frame, key).text.clone()
}
