//! The spec, figures and notices in the page's language (keys, symbols and units unchanged).

use crate::i18n::declared::{self, slug};
use crate::spec::DemoSpec;
use serde::Serialize;

/// The spec with its declared strings in the active language (keys, symbols and units
/// unchanged), each looked up by its structural id ([`crate::i18n::declared`]).
pub(super) fn translate_spec(spec: &DemoSpec) -> TranslatedSpec {
    let d = spec.id;
    let t = |id: String, english: &'static str| declared::tr(&id, english);
    TranslatedSpec {
        id: spec.id,
        title: t(format!("{d}-title"), spec.title),
        summary: t(format!("{d}-summary"), spec.summary),
        equation_mathml: spec.equation_mathml,
        params: spec
            .params
            .iter()
            .map(|p| {
                let k = slug(p.key);
                TranslatedParam {
                    key: p.key,
                    label: t(format!("{d}-param-{k}"), p.label),
                    symbol: p.symbol,
                    unit: p.unit,
                    min: p.min,
                    max: p.max,
                    step: p.step,
                    default: p.default,
                    scale: p.scale,
                    kind: p.kind,
                    options: p
                        .options
                        .iter()
                        .map(|o| (o.key, t(format!("{d}-param-{k}-{}", slug(o.key)), o.label)))
                        .collect(),
                    visible_when: p.visible_when,
                }
            })
            .collect(),
        readouts: spec
            .readouts
            .iter()
            .map(|r| {
                (
                    r.key,
                    t(format!("{d}-readout-{}", slug(r.key)), r.label),
                    r.unit,
                )
            })
            .collect(),
        plots: spec
            .plots
            .iter()
            .map(|p| {
                (
                    p.key,
                    t(format!("{d}-plot-{}", slug(p.key)), p.title),
                    p.aspect,
                )
            })
            .collect(),
        presets: spec
            .presets
            .iter()
            .enumerate()
            .map(|(i, p)| {
                (
                    t(format!("{d}-preset-{}", i + 1), p.label),
                    p.values.clone(),
                )
            })
            .collect(),
        table: spec.table.as_ref().map(|tb| TranslatedTable {
            caption: t(format!("{d}-table-caption"), tb.caption),
            columns: tb
                .columns
                .iter()
                .enumerate()
                .map(|(i, c)| t(format!("{d}-table-column-{}", i + 1), c))
                .collect(),
            rows: tb
                .rows
                .iter()
                .map(|(k, cells)| {
                    let row = slug(k);
                    let cells = cells
                        .iter()
                        .enumerate()
                        .map(|(i, c)| t(format!("{d}-table-{row}-{}", i + 1), c))
                        .collect();
                    (*k, cells)
                })
                .collect(),
            highlight_readout: tb.highlight_readout,
        }),
        primary_plot: spec.primary(),
        schematic: spec.schematic,
    }
}

#[derive(Serialize)]
struct TranslatedParam {
    key: &'static str,
    label: String,
    symbol: &'static str,
    unit: &'static str,
    min: f64,
    max: f64,
    step: f64,
    default: f64,
    scale: crate::spec::Scale,
    kind: crate::spec::Kind,
    #[serde(serialize_with = "options_as_objects")]
    options: Vec<(&'static str, String)>,
    /// `[key, index]`: shown only while that parameter has that value (absent: always).
    #[serde(skip_serializing_if = "Option::is_none")]
    visible_when: Option<(&'static str, usize)>,
}

fn options_as_objects<S: serde::Serializer>(
    v: &[(&'static str, String)],
    s: S,
) -> Result<S::Ok, S::Error> {
    use serde::ser::SerializeSeq;
    #[derive(Serialize)]
    struct Opt<'a> {
        key: &'a str,
        label: &'a str,
    }
    let mut seq = s.serialize_seq(Some(v.len()))?;
    for (key, label) in v {
        seq.serialize_element(&Opt { key, label })?;
    }
    seq.end()
}

#[derive(Serialize)]
struct TranslatedTable {
    caption: String,
    columns: Vec<String>,
    rows: Vec<(&'static str, Vec<String>)>,
    highlight_readout: &'static str,
}

/// [`DemoSpec`] as the page receives it, in the page's language. Same field names.
#[derive(Serialize)]
pub(super) struct TranslatedSpec {
    id: &'static str,
    title: String,
    summary: String,
    equation_mathml: &'static str,
    params: Vec<TranslatedParam>,
    #[serde(serialize_with = "readouts_as_objects")]
    readouts: Vec<(&'static str, String, &'static str)>,
    #[serde(serialize_with = "plots_as_objects")]
    plots: Vec<(&'static str, String, f64)>,
    #[serde(serialize_with = "presets_as_objects")]
    presets: Vec<(String, Vec<(&'static str, f64)>)>,
    table: Option<TranslatedTable>,
    primary_plot: &'static str,
    schematic: bool,
}

fn readouts_as_objects<S: serde::Serializer>(
    v: &[(&'static str, String, &'static str)],
    s: S,
) -> Result<S::Ok, S::Error> {
    #[derive(Serialize)]
    struct R<'a> {
        key: &'a str,
        label: &'a str,
        unit: &'a str,
    }
    s.collect_seq(v.iter().map(|(key, label, unit)| R { key, label, unit }))
}

fn plots_as_objects<S: serde::Serializer>(
    v: &[(&'static str, String, f64)],
    s: S,
) -> Result<S::Ok, S::Error> {
    #[derive(Serialize)]
    struct P<'a> {
        key: &'a str,
        title: &'a str,
        aspect: f64,
    }
    s.collect_seq(v.iter().map(|(key, title, aspect)| P {
        key,
        title,
        aspect: *aspect,
    }))
}

fn presets_as_objects<S: serde::Serializer>(
    v: &[(String, Vec<(&'static str, f64)>)],
    s: S,
) -> Result<S::Ok, S::Error> {
    #[derive(Serialize)]
    struct P<'a> {
        label: &'a str,
        values: &'a [(&'static str, f64)],
    }
    s.collect_seq(v.iter().map(|(label, values)| P { label, values }))
}
