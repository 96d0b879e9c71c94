//! The one test harness for demos: run a demo from a URL query (by id, or by its model
//! type through [`Tested`]), read its readouts, draw its schematic.
// Not every demo uses every reader.
#![allow(dead_code)]

use super::{create, Demo, Frame, Model, Readout};
use crate::figure::Figure;
use crate::params::{resolve_query, Params};

/// A demo run through the page path, named by its model type: in a demo's tests,
/// `Flutter::run("U=19")`, `Flutter::preset("…")` and `Flutter::live("")` are [`run`],
/// [`preset`] and [`live`] with that demo's declared id, so no test file wraps them.
pub trait Tested: Model {
    /// [`run`] for this demo.
    fn run(query: &str) -> Frame {
        run(Self::declare().id, query)
    }

    /// [`preset`] for this demo.
    fn preset(label: &str) -> Frame {
        preset(Self::declare().id, label)
    }

    /// [`live`] for this demo.
    fn live(query: &str) -> Live {
        live(Self::declare().id, query)
    }

    /// Plot `key`'s figure in `frame` (a frame holds them in declaration order).
    fn plot<'a>(frame: &'a Frame, key: &str) -> &'a Figure {
        let plots = Self::declare().plots;
        let i = plots.iter().position(|p| p.key == key);
        &frame.figures[i.unwrap_or_else(|| panic!("no plot {key}"))]
    }
}

impl<M: Model> Tested for M {}

/// Demo `id` updated once for `query` (as the page does on load with that link).
pub fn run(id: &str, query: &str) -> Frame {
    live(id, query).frame
}

/// A demo updated once for a query, kept to draw its schematic at chosen times (or to
/// update again).
pub struct Live {
    /// What the update showed.
    pub frame: Frame,
    /// The demo, after that update.
    pub demo: Box<dyn Demo>,
    /// The query's parameter values.
    pub params: Params,
}

impl Live {
    /// The schematic at time `t` \[s\].
    pub fn at(&self, t: f64) -> Figure {
        self.demo
            .schematic(&self.params, t)
            .unwrap_or_else(|| panic!("no schematic at t = {t}"))
    }
}

/// Demo `id` updated once for `query`, as [`run`] does, with its schematic to draw.
pub fn live(id: &str, query: &str) -> Live {
    let mut demo = create(id).unwrap_or_else(|| panic!("no demo {id}"));
    let params = params(id, query);
    let frame = demo.update(&params);
    Live {
        frame,
        demo,
        params,
    }
}

/// Moves `(key, value)` made in turn on one live demo `id` (from `query`): after each, the
/// frame is the one a fresh demo shows for the same values, so what a demo keeps between
/// updates is never stale.
pub fn assert_kept_is_fresh(id: &str, query: &str, moves: &[(&str, &str)]) {
    let mut live = live(id, query);
    let spec = live.demo.spec();
    for (key, v) in moves {
        live.params.set_raw(&spec, key, v);
        let kept = live.demo.update(&live.params);
        let mut demo = create(id).unwrap_or_else(|| panic!("no demo {id}"));
        let fresh = demo.update(&live.params);
        assert_eq!(
            format!("{kept:?}"),
            format!("{fresh:?}"),
            "{id} after {key}={v}"
        );
    }
}

/// The parameter values of `query` for demo `id` (every value in range and well formed).
pub fn params(id: &str, query: &str) -> Params {
    let demo = create(id).unwrap_or_else(|| panic!("no demo {id}"));
    let (params, notices) = resolve_query(&demo.spec(), query);
    assert!(notices.is_empty(), "{id}?{query}: {notices:?}");
    params
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
