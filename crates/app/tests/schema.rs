//! `docs/zeta-schema.json` documents, as a JSON Schema, what a host page receives from
//! `zeta:describe`. This test keeps it in step with the code: every demo's schema (from
//! `zeta_app::lecturer::schema`) must validate against the file (required fields, no
//! others, types, enums, the pinned `schema_version`), and every field the file describes
//! must be produced. Change the layout in both places and raise `SCHEMA_VERSION`.
#![cfg(not(target_arch = "wasm32"))]
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use serde_json::Value;
use zeta_app::demos;
use zeta_app::lecturer::{narrow, schema, SCHEMA_VERSION};

fn doc() -> Value {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/../../docs/zeta-schema.json");
    serde_json::from_str(&std::fs::read_to_string(path).expect("docs/zeta-schema.json exists"))
        .expect("docs/zeta-schema.json is JSON")
}

/// A small validator for the keywords the file uses: type, const, enum, required,
/// properties, additionalProperties (false), items.
fn check(schema: &Value, v: &Value, at: &str, seen: &mut Vec<String>) {
    seen.push(at.to_string());
    if let Some(c) = schema.get("const") {
        assert_eq!(v, c, "{at}: const");
    }
    if let Some(e) = schema.get("enum").and_then(Value::as_array) {
        assert!(e.contains(v), "{at}: {v} not in {e:?}");
    }
    match schema.get("type").and_then(Value::as_str) {
        Some("object") => {
            let obj = v
                .as_object()
                .unwrap_or_else(|| panic!("{at}: not an object"));
            let props = schema["properties"].as_object().unwrap();
            for r in schema["required"].as_array().unwrap() {
                assert!(obj.contains_key(r.as_str().unwrap()), "{at}: missing {r}");
            }
            for (k, val) in obj {
                let sub = props
                    .get(k)
                    .unwrap_or_else(|| panic!("{at}.{k}: not in docs/zeta-schema.json"));
                check(sub, val, &format!("{at}.{k}"), seen);
            }
        }
        Some("array") => {
            let items = v.as_array().unwrap_or_else(|| panic!("{at}: not an array"));
            for item in items {
                check(&schema["items"], item, &format!("{at}[]"), seen);
            }
            seen.push(format!("{at}[]"));
        }
        Some("string") => assert!(v.is_string(), "{at}: not a string"),
        Some("number") => assert!(v.is_number(), "{at}: not a number"),
        Some(other) => panic!("{at}: type {other} not handled"),
        None => {}
    }
}

/// Every path the file describes, e.g. `$.parameters[].unit`.
fn described(schema: &Value, at: &str, out: &mut Vec<String>) {
    out.push(at.to_string());
    if let Some(props) = schema.get("properties").and_then(Value::as_object) {
        for (k, sub) in props {
            described(sub, &format!("{at}.{k}"), out);
        }
    }
    if let Some(items) = schema.get("items") {
        if items.get("properties").is_some() {
            described(items, &format!("{at}[]"), out);
        }
    }
}

#[test]
fn every_demo_schema_matches_docs_zeta_schema_json() {
    let doc = doc();
    assert_eq!(
        doc["properties"]["schema_version"]["const"],
        Value::from(SCHEMA_VERSION),
        "docs/zeta-schema.json pins another schema_version"
    );
    let mut seen = Vec::new();
    for id in demos::ids() {
        let mut spec = demos::create(id).unwrap().spec();
        let _ = narrow(&mut spec, "");
        let v = serde_json::to_value(schema(&spec)).unwrap();
        check(&doc, &v, "$", &mut seen);
    }
    let mut want = Vec::new();
    described(&doc, "$", &mut want);
    for path in want {
        assert!(
            seen.contains(&path),
            "docs/zeta-schema.json describes {path}, which no demo's schema has"
        );
    }
}
