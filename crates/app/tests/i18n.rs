//! Every string a demo shows is a message of every language, checked by id: each
//! catalogue is loaded from `crates/app/locales/`, every demo is run at its defaults,
//! every preset, every option and toggle and both ends of every slider, and the ids the
//! catalogue lacked ([`zeta_app::i18n::take_missing`]) must be none. In the accented
//! pseudo-locale `en-XA`, which changes every letter of every message, a run of four
//! plain ASCII letters in a generated string is text that bypassed the catalogues.
#![cfg(not(target_arch = "wasm32"))]
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use zeta_app::demos::{self, Demo};
use zeta_app::figure::Figure;
use zeta_app::i18n::{self, LOCALES};
use zeta_app::params::Params;
use zeta_app::spec::{DemoSpec, Kind};

fn cases(spec: &DemoSpec) -> Vec<(String, Params)> {
    let defaults = Params::defaults(spec);
    let mut out = vec![("defaults".to_string(), defaults.clone())];
    for preset in &spec.presets {
        let mut p = defaults.clone();
        for (k, v) in &preset.values {
            p.set_raw(spec, k, &format!("{v}"));
        }
        out.push((format!("preset \u{201c}{}\u{201d}", preset.label), p));
    }
    for param in &spec.params {
        let values: Vec<f64> = match param.kind {
            Kind::Choice => (0..param.options.len()).map(|i| i as f64).collect(),
            Kind::Toggle => vec![0.0, 1.0],
            Kind::Slider => vec![param.min, param.max],
        };
        for v in values {
            let mut p = defaults.clone();
            p.set_raw(spec, param.key, &format!("{v}"));
            out.push((format!("{} = {v}", param.key), p));
        }
    }
    out
}

fn figure_strings(fig: &Figure, out: &mut Vec<(&'static str, String)>) {
    out.push(("figure title", fig.title.clone()));
    out.push(("description", fig.description.clone()));
    out.push(("x axis", fig.x.label.clone()));
    out.push(("y axis", fig.y.label.clone()));
    for s in &fig.series {
        out.push(("legend", s.label.clone()));
    }
    for m in &fig.markers {
        out.push(("marker", m.label.clone()));
    }
    if let Some(h) = &fig.heatmap {
        out.push(("colour map", h.label.clone()));
    }
}

/// Every generated string the demo shows for these parameters.
fn generated_strings(
    demo: &mut dyn Demo,
    spec: &DemoSpec,
    params: &Params,
) -> Vec<(&'static str, String)> {
    let frame = demo.update(params);
    let mut out = Vec::new();
    for r in &frame.readouts {
        let is_text = spec
            .readouts
            .iter()
            .find(|s| s.key == r.key)
            .is_some_and(|s| s.unit.is_empty())
            || r.data_value != r.text;
        if is_text {
            out.push(("readout", r.text.clone()));
        }
    }
    for f in &frame.figures {
        figure_strings(f, &mut out);
    }
    if spec.schematic {
        if let Some((t0, t1)) = frame.time_span {
            for t in [t0, (t0 + t1) / 2.0] {
                if let Some(f) = demo.schematic(params, t) {
                    figure_strings(&f, &mut out);
                }
            }
        }
    }
    out.retain(|(_, s)| !s.trim().is_empty());
    out
}

/// Every generated string of every demo in every case, in the active language.
fn every_generated_string() -> Vec<(String, &'static str, String)> {
    let mut out = Vec::new();
    for id in demos::ids() {
        let mut demo = demos::create(id).unwrap();
        let spec = demo.spec();
        for (case, params) in cases(&spec) {
            for (what, text) in generated_strings(demo.as_mut(), &spec, &params) {
                out.push((format!("{id}, {case}"), what, text));
            }
        }
    }
    out
}

#[test]
fn every_language_has_every_message_the_demos_show() {
    for l in LOCALES.iter().filter(|l| l.file().is_some()) {
        let path = format!("{}/locales/{}.ftl", env!("CARGO_MANIFEST_DIR"), l.tag);
        let ftl = std::fs::read_to_string(&path).unwrap();
        assert_eq!(i18n::load(l.tag, &ftl), Ok(()), "{path} has syntax errors");
        assert_eq!(i18n::set_language(&[l.tag]).tag, l.tag);
        i18n::take_missing();
        let shown = every_generated_string();
        let missing = i18n::take_missing();
        i18n::set_language(&["en"]);
        assert!(!shown.is_empty());
        assert!(
            missing.is_empty(),
            "{}: {} messages shown in English: {missing:?}",
            l.tag,
            missing.len()
        );
    }
}

/// Words of four or more plain ASCII letters. A token with `_` or `/` is a symbol or a
/// unit (`f_wheel`, `U_crit`, `mrad/s`), never a word.
fn ascii_words(s: &str) -> Vec<&str> {
    s.split(|c: char| !(c.is_ascii_alphanumeric() || c == '_' || c == '/'))
        .filter(|t| !t.contains(['_', '/']))
        .flat_map(|t| t.split(|c: char| !c.is_ascii_alphabetic()))
        .filter(|w| w.len() >= 4)
        .collect()
}

#[test]
fn no_generated_string_bypasses_the_catalogues() {
    i18n::set_language(&["en-XA"]);
    let shown = every_generated_string();
    i18n::set_language(&["en"]);
    let mut escaped: Vec<String> = shown
        .iter()
        .filter(|(_, _, text)| !ascii_words(text).is_empty())
        .map(|(case, what, text)| format!("{case}: {what} {text:?}"))
        .collect();
    escaped.sort();
    escaped.dedup();
    if std::env::var_os("ZETA_I18N_DUMP").is_some() {
        println!("{}", escaped.join("\n"));
    }
    assert!(
        escaped.is_empty(),
        "{} strings bypass the catalogues, e.g. {:#?}",
        escaped.len(),
        &escaped[..escaped.len().min(20)]
    );
}
