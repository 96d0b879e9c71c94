//! The one test harness for demos: run a demo from a URL query, read its readouts.
// Not every demo uses every reader.
#![allow(dead_code)]

use super::{create, Frame};
use crate::params::resolve_query;

/// Demo `id` updated once for `query` (as the page does on load with that link).
pub fn run(id: &str, query: &str) -> Frame {
    let mut demo = create(id).unwrap_or_else(|| panic!("no demo {id}"));
    let (params, notices) = resolve_query(&demo.spec(), query);
    assert!(notices.is_empty(), "{id}?{query}: {notices:?}");
    demo.update(&params)
}

/// The `data-value` of readout `key`.
pub fn value(frame: &Frame, key: &str) -> String {
    frame
        .readouts
        .iter()
        .find(|r| r.key == key)
        .map(|r| r.data_value.clone())
        .unwrap_or_else(|| panic!("no readout {key}"))
}

/// The `data-value` of readout `key` as a number.
pub fn number(frame: &Frame, key: &str) -> f64 {
    value(frame, key)
        .parse()
        .unwrap_or_else(|_| panic!("readout {key} is not a number"))
}

/// The text of readout `key`.
pub fn text(frame: &Frame, key: &str) -> String {
    frame
        .readouts
        .iter()
        .find(|r| r.key == key)
        .map(|r| r.text.clone())
        .unwrap_or_else(|| panic!("no readout {key}"))
}
