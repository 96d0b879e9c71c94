//! Property tests at scale ("fuzzing" with proptest, bounded in time by the case count) of
//! everything that takes outside input: the URL/state parser and every demo's update.
//! Any input yields values in range or a notice — never a panic, a NaN readout or a hang.
#![cfg(not(target_arch = "wasm32"))]
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use proptest::prelude::*;
use zeta_app::demos;
use zeta_app::params::{parse_number, parse_query, resolve_query, Params};
use zeta_app::spec::Kind;

/// One of `pieces`, each as likely.
fn fixed(pieces: &'static [&'static str]) -> impl Strategy<Value = String> {
    prop::sample::select(pieces).prop_map(String::from)
}

/// Query strings built from URL-ish pieces, hostile values and raw bytes.
fn query() -> impl Strategy<Value = String> {
    // Each fixed piece as likely as each generated one.
    let key = prop_oneof![
        8 => fixed(&["zeta", "wn", "m", "k", "c", "N", "metric", "euler"]),
        1 => "[a-zA-Z_%0-9]{0,8}",
    ];
    let value = prop_oneof![
        1 => any::<f64>().prop_map(|v| format!("{v}")),
        6 => fixed(&["NaN", "-inf", "1e308", "%3Cscript%3E", "%", "%zz"]),
        1 => ".{0,24}",
    ];
    prop::collection::vec((key, value), 0..12).prop_map(|pairs| {
        let body: Vec<String> = pairs.into_iter().map(|(k, v)| format!("{k}={v}")).collect();
        format!("?{}", body.join("&"))
    })
}

/// The demos with parameters to fuzz (the paper's tour has none; its update runs the other
/// demos at fixed states, which the registry and paper tests cover).
fn tunable() -> Vec<&'static str> {
    demos::ids()
        .filter(|id| demos::create(id).is_some_and(|d| !d.spec().params.is_empty()))
        .collect()
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(300))]

    #[test]
    fn any_text_parses_without_panicking(s in ".{0,200}") {
        let _ = parse_query(&s);
        if let Some(v) = parse_number(&s) {
            prop_assert!(v.is_finite());
        }
    }

    /// Every demo, any query: every value lands in its declared range, and the update
    /// gives readouts without NaN or infinity.
    #[test]
    fn every_demo_accepts_any_query(q in query(), which in 0usize..64) {
        let id = tunable()[which % tunable().len()];
        let mut demo = demos::create(id).unwrap();
        let spec = demo.spec();
        let (params, notices): (Params, _) = resolve_query(&spec, &q);
        for (key, value) in params.pairs() {
            let p = spec.param(key).unwrap();
            prop_assert!(value.is_finite() && value >= p.min && value <= p.max, "{id}.{key} = {value}");
            if p.kind != Kind::Slider {
                prop_assert_eq!(value.fract(), 0.0);
            }
        }
        for n in &notices {
            prop_assert!(!n.message.is_empty());
        }
        let frame = demo.update(&params);
        for r in &frame.readouts {
            prop_assert!(!r.data_value.contains("NaN") && !r.data_value.contains("inf"), "{id}: {} = {}", r.key, r.data_value);
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(120))]

    /// Random values inside every parameter's range, for every demo: the update never
    /// panics and never shows NaN (the registry test covers the ends of each range).
    #[test]
    fn every_demo_survives_random_parameters(which in 0usize..64, fractions in prop::collection::vec(0.0f64..=1.0, 32)) {
        let id = tunable()[which % tunable().len()];
        let mut demo = demos::create(id).unwrap();
        let spec = demo.spec();
        let mut params = Params::defaults(&spec);
        for (p, f) in spec.params.iter().zip(fractions) {
            let v = p.min + f * (p.max - p.min);
            let v = if p.kind == Kind::Slider { v } else { v.round() };
            params.set_raw(&spec, p.key, &format!("{v}"));
        }
        let frame = demo.update(&params);
        for r in &frame.readouts {
            prop_assert!(!r.data_value.contains("NaN") && !r.data_value.contains("inf"), "{id}: {} = {}", r.key, r.data_value);
        }
        for f in &frame.figures {
            prop_assert!(!f.description.is_empty());
        }
    }
}
