//! Structural message ids for the strings a demo declares (its title, summary, parameter
//! and option labels, readout labels, plot titles, preset labels and table cells). The
//! declaration keeps the English text; the id follows from where the string stands, so
//! renaming the English never orphans a translation:
//!
//! | string | id |
//! |---|---|
//! | title, summary | `<demo>-title`, `<demo>-summary` |
//! | parameter label / option | `<demo>-param-<key>`, `<demo>-param-<key>-<option>` |
//! | readout label, plot title | `<demo>-readout-<key>`, `<demo>-plot-<key>` |
//! | preset | `<demo>-preset-<n>` (1-based) |
//! | table | `<demo>-table-caption`, `<demo>-table-column-<n>`, `<demo>-table-<row>-<n>` |
//!
//! Keys keep their ASCII letters and digits (case matters: `c` and `C` differ); every
//! other character becomes `-`.
//! `en.ftl` carries these strings too (generated, so translators see the source); the
//! catalogue test keeps that block equal to the declarations.

use crate::spec::DemoSpec;

/// A Fluent identifier made from a key: ASCII letters and digits, others `-`.
pub fn slug(key: &str) -> String {
    key.chars()
        .map(|c| if c.is_ascii_alphanumeric() { c } else { '-' })
        .collect()
}

/// Whether a table cell is a live readout placeholder (never translated).
pub fn is_live_cell(cell: &str) -> bool {
    cell.starts_with("{readout:")
}

/// Every declared string of `spec` with its id, in declaration order.
pub fn strings(spec: &DemoSpec) -> Vec<(String, &'static str)> {
    let d = spec.id;
    let mut out = vec![
        (format!("{d}-title"), spec.title),
        (format!("{d}-summary"), spec.summary),
    ];
    for p in &spec.params {
        out.push((format!("{d}-param-{}", slug(p.key)), p.label));
        for o in &p.options {
            out.push((
                format!("{d}-param-{}-{}", slug(p.key), slug(o.key)),
                o.label,
            ));
        }
    }
    for r in &spec.readouts {
        out.push((format!("{d}-readout-{}", slug(r.key)), r.label));
    }
    for p in &spec.plots {
        out.push((format!("{d}-plot-{}", slug(p.key)), p.title));
    }
    for (i, p) in spec.presets.iter().enumerate() {
        out.push((format!("{d}-preset-{}", i + 1), p.label));
    }
    if let Some(t) = &spec.table {
        out.push((format!("{d}-table-caption"), t.caption));
        for (i, c) in t.columns.iter().enumerate() {
            out.push((format!("{d}-table-column-{}", i + 1), *c));
        }
        for (key, cells) in &t.rows {
            for (i, c) in cells.iter().enumerate() {
                if !is_live_cell(c) && !c.trim().is_empty() {
                    out.push((format!("{d}-table-{}-{}", slug(key), i + 1), *c));
                }
            }
        }
    }
    out
}

/// The declared string `english` with id `id`, in the active language.
pub fn tr(id: &str, english: &'static str) -> String {
    if is_live_cell(english) || english.trim().is_empty() {
        return english.to_string();
    }
    super::catalogue::declared(id, english)
}

/// `text` as a Fluent pattern on one line: braces become string literals, and leading
/// or trailing spaces (which Fluent would trim) are kept as literal placeables.
pub fn ftl_escape(text: &str) -> String {
    let trimmed = text.trim_matches(' ');
    if trimmed.is_empty() {
        return format!("{{\"{text}\"}}");
    }
    let lead = text.len() - text.trim_start_matches(' ').len();
    let trail = text.len() - text.trim_end_matches(' ').len();
    let mut out = String::new();
    if lead > 0 {
        out.push_str(&format!("{{\"{}\"}}", " ".repeat(lead)));
    }
    for c in trimmed.chars() {
        match c {
            '{' => out.push_str("{\"{\"}"),
            '}' => out.push_str("{\"}\"}"),
            c => out.push(c),
        }
    }
    if trail > 0 {
        out.push_str(&format!("{{\"{}\"}}", " ".repeat(trail)));
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn slugs_are_fluent_identifiers() {
        assert_eq!(slug("critically damped"), "critically-damped");
        assert_eq!(slug("k_t"), "k-t");
        assert_eq!(slug("Q"), "Q");
    }

    #[test]
    fn escaping_round_trips_through_fluent() {
        for text in [
            "a {b} c",
            " lead and trail ",
            "}{",
            "plain",
            "x = {readout:y}",
        ] {
            let ftl = format!("m = {}\n", ftl_escape(text));
            let res = fluent_bundle::FluentResource::try_new(ftl.clone()).expect(&ftl);
            let mut b = fluent_bundle::FluentBundle::new(vec!["en".parse().unwrap()]);
            b.set_use_isolating(false);
            b.add_resource(res).unwrap();
            let p = b.get_message("m").unwrap().value().unwrap();
            let mut errs = vec![];
            assert_eq!(b.format_pattern(p, None, &mut errs), text, "{ftl}");
        }
    }
}
