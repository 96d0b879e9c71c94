//! Snapshot tests of every demo: its declaration, and its readouts, figures (titles, axes,
//! text alternatives, a numeric digest of every series) and schematic at its defaults and at
//! every preset. The snapshots live in `tests/snapshots/` (insta); after a deliberate change,
//! `INSTA_UPDATE=always cargo test -p zeta-app --test snapshots` rewrites them and the diff
//! shows what moved. The end-to-end tests read the same files, so the browser is checked
//! against numbers computed here rather than physics re-implemented in JavaScript.
#![cfg(not(target_arch = "wasm32"))]

use serde_json::{json, Value};
use zeta_app::demos::{self, Frame};
use zeta_app::figure::{Figure, Series};
use zeta_app::params::{resolve_query, Params};

/// `v` with `sig` significant digits, so that a change in the last bits of a
/// floating-point sum is not reported while any visible change is.
fn num(v: f64, sig: usize) -> Value {
    if !v.is_finite() {
        return Value::String(format!("{v}"));
    }
    Value::String(format!("{:.*e}", sig - 1, v))
}

fn series_digest(s: &Series) -> Value {
    let finite: Vec<(f64, f64)> = s
        .points
        .iter()
        .copied()
        .filter(|(x, y)| x.is_finite() && y.is_finite())
        .collect();
    let (mut ylo, mut yhi, mut sum, mut sum_abs) = (f64::INFINITY, f64::NEG_INFINITY, 0.0, 0.0);
    for &(_, y) in &finite {
        ylo = ylo.min(y);
        yhi = yhi.max(y);
        sum += y;
        sum_abs += y.abs();
    }
    let first = finite.first().copied().unwrap_or((f64::NAN, f64::NAN));
    let last = finite.last().copied().unwrap_or((f64::NAN, f64::NAN));
    json!({
        "label": s.label,
        "style": format!(
            "LineStyle {{ color: {}, dash: {:?}, width: {:?} }}",
            s.style.ink.index(), s.style.dash, s.style.width
        ),
        "points": s.points.len(),
        "finite": finite.len(),
        "first": [num(first.0, 9), num(first.1, 9)],
        "last": [num(last.0, 9), num(last.1, 9)],
        "y_min": num(ylo, 9),
        "y_max": num(yhi, 9),
        "y_sum": num(sum, 8),
        "y_abs_sum": num(sum_abs, 8),
    })
}

fn figure_digest(f: &Figure) -> Value {
    let axis = |a: &zeta_app::figure::Axis| {
        json!({
            "title": a.title(),
            "scale": format!("{:?}", a.scale),
            "range": [num(a.range.0, 9), num(a.range.1, 9)],
        })
    };
    json!({
        "title": f.title,
        "kind": format!("{:?}", f.kind),
        "description": f.description,
        "x": axis(&f.x),
        "y": axis(&f.y),
        "origin_lines": f.origin_lines,
        "series": f.series.iter().map(series_digest).collect::<Vec<_>>(),
        "markers": f.markers.iter().map(|m| json!({
            "label": m.label,
            "at": [num(m.at.0, 9), num(m.at.1, 9)],
            "shape": format!("{:?}", m.shape),
            "color": m.ink.index(),
        })).collect::<Vec<_>>(),
        "heatmap": f.heatmap.as_ref().map(|h| {
            let finite: Vec<f64> = h.values.iter().copied().filter(|v| v.is_finite()).collect();
            json!({
                "cells": [h.nx, h.ny],
                "finite": finite.len(),
                "sum": num(finite.iter().sum(), 8),
                "x_edges": [num(h.x_edges.0, 9), num(h.x_edges.1, 9)],
                "y_edges": [num(h.y_edges.0, 9), num(h.y_edges.1, 9)],
                "scale": [num(h.scale.0, 9), num(h.scale.1, 9)],
                "label": h.label,
            })
        }),
    })
}

/// Readouts that report how long a computation took on this machine.
const MEASURED: &[&str] = &["compute_time"];

fn readout_value(data_value: &str) -> Value {
    // Numbers to 12 significant digits; text readouts as they are.
    match data_value.parse::<f64>() {
        Ok(v) if !data_value.is_empty() => num(v, 12),
        _ => Value::String(data_value.to_string()),
    }
}

fn state(demo: &mut dyn demos::Demo, name: &str, query: &str, params: &Params) -> Value {
    let frame: Frame = demo.update(params);
    let derived = demo.derived_params();
    let schematic = frame.time_span.and_then(|(t0, t1)| {
        demo.schematic(params, 0.5 * (t0 + t1))
            .map(|f| f.description)
    });
    json!({
        "name": name,
        "query": query,
        "readouts": frame.readouts.iter().map(|r| if MEASURED.contains(&r.key) {
            // A wall-clock measurement: only whether it is there.
            json!({ "key": r.key, "measured": !r.data_value.is_empty() })
        } else {
            json!({
                "key": r.key,
                "text": r.text,
                "value": readout_value(&r.data_value),
            })
        }).collect::<Vec<_>>(),
        "figures": frame.figures.iter().map(figure_digest).collect::<Vec<_>>(),
        "time_span": frame.time_span.map(|(a, b)| [num(a, 9), num(b, 9)]),
        "derived": derived.iter().map(|(k, v)| json!([k, num(*v, 12)])).collect::<Vec<_>>(),
        "schematic": schematic,
    })
}

/// The query string that a preset writes: its values on top of the defaults.
fn preset_query(values: &[(&'static str, f64)]) -> String {
    values
        .iter()
        .map(|(k, v)| format!("{k}={v}"))
        .collect::<Vec<_>>()
        .join("&")
}

#[test]
fn every_demo_at_its_defaults_and_presets() {
    let mut settings = insta::Settings::clone_current();
    settings.set_prepend_module_to_snapshot(false);
    settings.set_omit_expression(true);
    settings.bind(|| {
        for id in demos::ids() {
            let mut demo = demos::create(id).expect("registered demo");
            let spec = demo.spec();
            let mut states = vec![state(
                demo.as_mut(),
                "defaults",
                "",
                &Params::defaults(&spec),
            )];
            for preset in &spec.presets {
                let query = preset_query(&preset.values);
                let (params, notices) = resolve_query(&spec, &query);
                assert!(
                    notices.is_empty(),
                    "{id}: preset {} {notices:?}",
                    preset.label
                );
                // A fresh instance, as the page has after a reload with this link.
                let mut fresh = demos::create(id).expect("registered demo");
                states.push(state(fresh.as_mut(), preset.label, &query, &params));
            }
            let mut spec_json = serde_json::to_value(&spec).expect("spec serialises");
            spec_json["primary_plot"] = json!(spec.primary());
            let doc = json!({
                "id": id,
                "spec": spec_json,
                "states": states,
            });
            insta::assert_snapshot!(id, serde_json::to_string_pretty(&doc).expect("json"));
        }
    });
}
