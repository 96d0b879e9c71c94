//! Every string a demo shows has a Spanish translation.
//!
//! * Static strings of a spec (title, summary, labels, choice options, readout labels, plot
//!   titles, presets, table caption, columns and cells) must be whole entries of the
//!   catalogue, so they are translated exactly; strings of symbols and units only (`N·s/m`,
//!   `ζ = 1`) are exempt and must come out unchanged.
//! * Generated strings (figure titles, axes, legends, markers, descriptions, text readouts)
//!   are computed for the defaults, every preset, every choice option and toggle state and
//!   both ends of every slider; after translation they must contain no English word from
//!   [`ENGLISH`].
//!
//! When a test fails, its message lists every missing string: add them to
//! `crates/app/src/i18n/es.rs` (whole entries for fixed strings, phrases for the fixed
//! fragments of `format!`-built ones). `ZETA_I18N_DUMP=1 cargo test -p zeta-app --test i18n
//! -- --nocapture` prints every generated string with its translation.
#![cfg(not(target_arch = "wasm32"))]
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use std::collections::BTreeSet;
use zeta_app::demos::{self, Demo};
use zeta_app::figure::Figure;
use zeta_app::i18n::{has_whole, tr, Lang};
use zeta_app::params::Params;
use zeta_app::spec::{DemoSpec, Kind};

/// English words that must not survive translation: a maximal run of ASCII letters of
/// length ≥ 4 found here (case-insensitive) is a leftover. Symbols (`x(t)`, `ωₙ`), units
/// and numbers are never in this list, so they pass.
const ENGLISH: &[&str] = &[
    // Function words.
    "about",
    "above",
    "after",
    "again",
    "against",
    "along",
    "also",
    "around",
    "away",
    "because",
    "been",
    "before",
    "behind",
    "below",
    "beside",
    "between",
    "beyond",
    "both",
    "each",
    "every",
    "from",
    "have",
    "here",
    "into",
    "less",
    "more",
    "most",
    "much",
    "near",
    "never",
    "none",
    "once",
    "only",
    "over",
    "past",
    "same",
    "than",
    "that",
    "their",
    "them",
    "then",
    "there",
    "these",
    "they",
    "this",
    "those",
    "through",
    "till",
    "times",
    "twice",
    "under",
    "until",
    "upon",
    "very",
    "when",
    "where",
    "which",
    "while",
    "whose",
    "will",
    "with",
    "within",
    "without",
    "would",
    "your",
    // Verbs.
    "does",
    "drops",
    "falls",
    "grows",
    "keeps",
    "leaves",
    "lies",
    "lift",
    "lifts",
    "makes",
    "moves",
    "reaches",
    "rises",
    "settle",
    "settles",
    "settling",
    "shows",
    "stays",
    "starts",
    "swing",
    "swings",
    "takes",
    "using",
    "decays",
    "decaying",
    "growing",
    "oscillates",
    "oscillating",
    "follows",
    "crosses",
    "peaks",
    "driven",
    "drive",
    "drives",
    "holds",
    "loses",
    "gains",
    "shown",
    "means",
    "gives",
    // Nouns and adjectives of the domain.
    "acceleration",
    "amplitude",
    "analogy",
    "axis",
    "axes",
    "band",
    "bandwidth",
    "body",
    "bump",
    "capacitor",
    "charge",
    "circuit",
    "clipped",
    "coefficient",
    "comfort",
    "contact",
    "critical",
    "critically",
    "current",
    "curve",
    "damped",
    "damper",
    "damping",
    "decay",
    "default",
    "deflection",
    "design",
    "displacement",
    "divergent",
    "effect",
    "electrical",
    "energy",
    "envelope",
    "equilibrium",
    "excitation",
    "flutter",
    "force",
    "free",
    "frequency",
    "gain",
    "half",
    "hardening",
    "height",
    "imaginary",
    "inductor",
    "initial",
    "input",
    "left",
    "length",
    "level",
    "limit",
    "line",
    "linear",
    "load",
    "loss",
    "magnitude",
    "mass",
    "mechanical",
    "mode",
    "model",
    "negative",
    "negatively",
    "nonlinear",
    "number",
    "output",
    "overdamped",
    "overshoot",
    "peak",
    "phase",
    "plane",
    "pole",
    "poles",
    "position",
    "power",
    "quality",
    "random",
    "ratio",
    "rebound",
    "regime",
    "resistor",
    "resonance",
    "response",
    "rest",
    "right",
    "ride",
    "road",
    "roots",
    "schematic",
    "settling",
    "sine",
    "slow",
    "softening",
    "speed",
    "spring",
    "stable",
    "static",
    "step",
    "stiffness",
    "suspension",
    "system",
    "time",
    "tire",
    "transmissibility",
    "travel",
    "tyre",
    "undamped",
    "underdamped",
    "unstable",
    "unsprung",
    "sprung",
    "value",
    "velocity",
    "voltage",
    "wheel",
    "wing",
    "zero",
    "forced",
    "steady",
    "state",
    "transient",
    "shift",
    "point",
    "region",
    "first",
    "second",
    "upper",
    "lower",
    "high",
    "highest",
    "largest",
    "smallest",
    "lowest",
    "fast",
    "faster",
    "slower",
    "small",
    "large",
    "both",
    "case",
    "mean",
    "root",
    "square",
    "pitch",
    "plunge",
    "torsion",
    "bending",
    "airspeed",
    "onset",
    "stiff",
    "soft",
    "trace",
    "marker",
    "sweep",
    "frame",
    "drawn",
    "equal",
    "twice",
    "half",
    "exact",
    "numerical",
    "simulation",
    "approximation",
    "backbone",
    "jump",
    "jumps",
    "branch",
    "branches",
    "cubic",
    "duffing",
    "hysteresis",
    "still",
    "grow",
    "above",
    "hits",
    "crossing",
    "crossings",
    "reaching",
    "since",
    "same",
    "yes",
];

/// Every static string of the spec that the page shows.
fn static_strings(spec: &DemoSpec) -> Vec<&'static str> {
    let mut out = vec![spec.title, spec.summary];
    for p in &spec.params {
        out.push(p.label);
        out.extend(p.options.iter().map(|o| o.label));
    }
    out.extend(spec.readouts.iter().map(|r| r.label));
    out.extend(spec.plots.iter().map(|p| p.title));
    out.extend(spec.presets.iter().map(|p| p.label));
    if let Some(t) = &spec.table {
        out.push(t.caption);
        out.extend(t.columns.iter().copied());
        for (_, cells) in &t.rows {
            out.extend(cells.iter().copied());
        }
    }
    out.retain(|s| !s.trim().is_empty());
    out
}

/// The parameter sets a demo is checked with, each with a name for failure messages.
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

/// The English words left in `s`: maximal runs of ASCII letters of length ≥ 4 that are in
/// [`ENGLISH`], not counting subscripts (`f_wheel`, `T_linear`).
fn english_words(s: &str) -> Vec<String> {
    let mut out = Vec::new();
    let mut prev = ' ';
    let mut run = String::new();
    let mut subscript = false;
    for c in s.chars().chain([' ']) {
        if c.is_ascii_alphabetic() {
            if run.is_empty() {
                subscript = prev == '_';
            }
            run.push(c);
        } else {
            let w = run.to_ascii_lowercase();
            if w.len() >= 4 && !subscript && ENGLISH.contains(&w.as_str()) {
                out.push(w);
            }
            run.clear();
        }
        prev = c;
    }
    out
}

/// Letter runs that are symbols or units, not words (`rad/s`, `sgn`, `log₁₀`).
const SYMBOLS: &[&str] = &[
    "rad", "sgn", "log", "max", "min", "mph", "gap", "cos", "sin", "Hz", "Re", "Im", "dB",
];

/// Whether `s` is made of symbols, units and numbers only: no word, i.e. no run of three
/// or more ASCII letters and no capitalised pair (`At`, `No`), except [`SYMBOLS`] and
/// subscripts (`U_crit`, `ζ_eff`). Such strings (`N·s/m`, `ζ = 1`, `F_c·sgn(x′)`) need no
/// translation.
fn is_symbolic(s: &str) -> bool {
    let mut prev = ' ';
    let mut run = String::new();
    let mut subscript = false;
    for c in s.chars().chain([' ']) {
        if c.is_ascii_alphabetic() {
            if run.is_empty() {
                subscript = prev == '_';
            }
            run.push(c);
        } else {
            let capitalised_pair = run.len() == 2
                && run.starts_with(|c: char| c.is_ascii_uppercase())
                && run.ends_with(|c: char| c.is_ascii_lowercase());
            let word = run.len() >= 3 || capitalised_pair;
            if word && !subscript && !SYMBOLS.contains(&run.as_str()) {
                return false;
            }
            run.clear();
        }
        prev = c;
    }
    true
}

#[test]
fn every_static_spec_string_has_a_whole_spanish_entry() {
    let mut missing = BTreeSet::new();
    for id in demos::ids() {
        let spec = demos::create(id).unwrap().spec();
        for s in static_strings(&spec) {
            if has_whole(Lang::Es, s) {
                continue;
            }
            if is_symbolic(s) {
                // Symbols pass through untouched (apart from decimal commas).
                let es = tr(Lang::Es, s);
                assert_eq!(es.replace(',', "."), s.replace(',', "."), "[{id}] {s:?}");
            } else {
                missing.insert(format!("[{id}] {s:?}"));
            }
        }
    }
    assert!(
        missing.is_empty(),
        "{} static strings have no whole Spanish entry in crates/app/src/i18n/es.rs:\n{}",
        missing.len(),
        missing.into_iter().collect::<Vec<_>>().join("\n")
    );
}

#[test]
fn every_generated_string_translates_without_english_left() {
    let dump = std::env::var_os("ZETA_I18N_DUMP").is_some();
    let mut problems = BTreeSet::new();
    let mut seen = BTreeSet::new();
    for id in demos::ids() {
        let mut demo = demos::create(id).unwrap();
        let spec = demo.spec();
        for (case, params) in cases(&spec) {
            for (what, s) in generated_strings(demo.as_mut(), &spec, &params) {
                let es = tr(Lang::Es, &s);
                if dump && seen.insert(s.clone()) {
                    println!("[{id}] {what}: {s}\n    -> {es}");
                }
                let left = english_words(&es);
                if !left.is_empty() {
                    problems.insert(format!(
                        "[{id}, {case}] {what} {s:?}\n    -> {es:?}\n    English left: {}",
                        left.join(", ")
                    ));
                }
            }
        }
    }
    assert!(
        problems.is_empty(),
        "{} generated strings keep English words in Spanish (add whole entries or phrases \
         to crates/app/src/i18n/es.rs):\n{}",
        problems.len(),
        problems.into_iter().collect::<Vec<_>>().join("\n")
    );
}

#[test]
fn spanish_whole_values_survive_a_second_translation() {
    // The page may translate a string twice (e.g. a label reused inside a figure); a
    // Spanish value must come back unchanged, not be corrupted by an English phrase.
    let mut changed = BTreeSet::new();
    for id in demos::ids() {
        let spec = demos::create(id).unwrap().spec();
        for s in static_strings(&spec) {
            let es = tr(Lang::Es, s);
            assert!(!es.trim().is_empty(), "[{id}] {s:?} translates to nothing");
            let again = tr(Lang::Es, &es);
            if again != es {
                changed.insert(format!("[{id}] {es:?}\n    -> {again:?}"));
            }
        }
    }
    assert!(
        changed.is_empty(),
        "{} Spanish strings change when translated again:\n{}",
        changed.len(),
        changed.into_iter().collect::<Vec<_>>().join("\n")
    );
}
