//! The message catalogues (`crates/app/locales/*.ftl`) against the code and each other:
//! - `en.ftl`'s "Declared strings" block equals what the demo declarations carry
//!   (regenerate with `ZETA_UPDATE_DOCS=1 cargo test -p zeta-app --test catalogues`);
//! - every `t!("id")` in the Rust code and every `t('key')` in the page's scripts has an
//!   English message, and every hand-written English message is used;
//! - a demo's hand-written messages are named after it (`<id>-…`), sit in its `### <id>`
//!   section and are used by its own code alone (a first module keeps only its demo's
//!   section: build.rs);
//! - every other catalogue parses, has every English id and no other, and uses no
//!   variable its English source does not have.
#![cfg(not(target_arch = "wasm32"))]
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use fluent_syntax::ast;
use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};
use zeta_app::demos;
use zeta_app::i18n::declared::{ftl_escape, strings};
use zeta_app::i18n::LOCALES;

const DECLARED: &str = "## Declared strings (generated from the demo declarations)";

fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).to_path_buf()
}

fn catalogue_path(tag: &str) -> PathBuf {
    root().join("locales").join(format!("{tag}.ftl"))
}

fn declared_block() -> String {
    let mut out = format!("{DECLARED}\n");
    for id in demos::ids() {
        let spec = demos::create(id).unwrap().spec();
        out.push_str(&format!("\n### {}\n\n", spec.id));
        for (id, english) in strings(&spec) {
            out.push_str(&format!("{id} = {}\n", ftl_escape(english)));
        }
    }
    out
}

/// Message id → the variables its pattern (value, selectors, variants) uses.
fn messages(ftl: &str, tag: &str) -> BTreeMap<String, BTreeSet<String>> {
    let res = match fluent_syntax::parser::parse(ftl) {
        Ok(r) => r,
        Err((_, errors)) => panic!("{tag}.ftl does not parse: {errors:?}"),
    };
    let mut out = BTreeMap::new();
    for entry in res.body {
        if let ast::Entry::Message(m) = entry {
            let mut vars = BTreeSet::new();
            if let Some(p) = &m.value {
                pattern_vars(p, &mut vars);
            }
            assert!(
                out.insert(m.id.name.to_string(), vars).is_none(),
                "{tag}.ftl: {} twice",
                m.id.name
            );
        }
    }
    out
}

fn pattern_vars(p: &ast::Pattern<&str>, vars: &mut BTreeSet<String>) {
    for el in &p.elements {
        if let ast::PatternElement::Placeable { expression } = el {
            expression_vars(expression, vars);
        }
    }
}

fn expression_vars(e: &ast::Expression<&str>, vars: &mut BTreeSet<String>) {
    match e {
        ast::Expression::Select { selector, variants } => {
            inline_vars(selector, vars);
            for v in variants {
                pattern_vars(&v.value, vars);
            }
        }
        ast::Expression::Inline(i) => inline_vars(i, vars),
    }
}

fn inline_vars(i: &ast::InlineExpression<&str>, vars: &mut BTreeSet<String>) {
    match i {
        ast::InlineExpression::VariableReference { id } => {
            vars.insert(id.name.to_string());
        }
        ast::InlineExpression::FunctionReference { arguments, .. } => {
            for a in &arguments.positional {
                inline_vars(a, vars);
            }
        }
        ast::InlineExpression::Placeable { expression } => expression_vars(expression, vars),
        _ => {}
    }
}

fn english() -> BTreeMap<String, BTreeSet<String>> {
    messages(
        &std::fs::read_to_string(catalogue_path("en")).unwrap(),
        "en",
    )
}

#[test]
fn english_declared_block_matches_the_declarations() {
    let path = catalogue_path("en");
    let text = std::fs::read_to_string(&path).unwrap();
    let head = text.split(DECLARED).next().unwrap().to_string();
    let want = format!("{head}{}", declared_block());
    if std::env::var_os("ZETA_UPDATE_DOCS").is_some() {
        std::fs::write(&path, &want).unwrap();
        return;
    }
    assert!(
        text == want,
        "locales/en.ftl's declared block is out of date: run \
         ZETA_UPDATE_DOCS=1 cargo test -p zeta-app --test catalogues"
    );
}

fn files(dir: &Path, ext: &str, out: &mut Vec<PathBuf>) {
    for e in std::fs::read_dir(dir).unwrap() {
        let p = e.unwrap().path();
        if p.is_dir() {
            files(&p, ext, out);
        } else if p.extension().is_some_and(|x| x == ext) {
            out.push(p);
        }
    }
}

/// The string literals (quoted by `quote`) that open the calls `opener` in `text`,
/// across line breaks: `t!(\n    "id",` gives `id`.
fn literals_after(text: &str, opener: &str, quote: char) -> Vec<String> {
    text.match_indices(opener)
        .filter(|(i, _)| {
            // `t!(` but not `format!(`; `t(` but not `set(`.
            text[..*i]
                .chars()
                .next_back()
                .is_none_or(|c| !(c.is_alphanumeric() || c == '_' || c == '.'))
        })
        .filter_map(|(i, _)| {
            let rest = text[i + opener.len()..].trim_start();
            let rest = rest.strip_prefix(quote)?;
            rest.find(quote).map(|end| rest[..end].to_string())
        })
        .collect()
}

/// `text` without its comment lines (`//`, `///`, `//!`, and JSDoc's ` * `).
fn code_only(text: &str) -> String {
    text.lines()
        .filter(|l| {
            let l = l.trim_start();
            !(l.starts_with("//") || l.starts_with("* ") || l.starts_with("/**"))
        })
        .collect::<Vec<_>>()
        .join("\n")
}

/// The page's key `exportGroup` is the message `page-export-group`.
fn page_id(key: &str) -> String {
    let mut id = String::from("page-");
    for c in key.chars() {
        if c.is_ascii_uppercase() {
            id.push('-');
            id.push(c.to_ascii_lowercase());
        } else {
            id.push(c);
        }
    }
    id
}

fn used_ids() -> BTreeSet<String> {
    let mut used = BTreeSet::new();
    let mut rs = Vec::new();
    files(&root().join("src"), "rs", &mut rs);
    files(&root().join("tests"), "rs", &mut rs);
    rs.retain(|f| !f.ends_with("catalogues.rs"));
    for f in rs {
        let text = code_only(&std::fs::read_to_string(&f).unwrap());
        used.extend(literals_after(&text, "t!(", '"'));
        used.extend(literals_after(&text, "message(", '"'));
    }
    let web = root().join("../../web");
    let mut js = Vec::new();
    files(&web, "js", &mut js);
    js.push(root().join("../../index.html"));
    for f in js {
        let text = code_only(&std::fs::read_to_string(&f).unwrap());
        for key in literals_after(&text, "t(", '\'')
            .into_iter()
            .chain(literals_after(&text, "data-i18n=", '"'))
        {
            used.insert(page_id(&key));
        }
        used.extend(literals_after(&text, "message(", '\''));
    }
    used
}

/// The demo whose message `id` is (`<demo>-…`; the longest such demo id), if any.
fn owner(id: &str) -> Option<&'static str> {
    demos::menu()
        .map(|(demo, _)| demo)
        .filter(|demo| {
            id.strip_prefix(demo)
                .is_some_and(|rest| rest.starts_with('-'))
        })
        .max_by_key(|demo| demo.len())
}

#[test]
fn a_demos_messages_are_in_its_section_and_used_by_its_code_alone() {
    let text = std::fs::read_to_string(catalogue_path("en")).unwrap();
    let mut section: Option<&str> = None;
    for line in text.split(DECLARED).next().unwrap().lines() {
        if let Some(id) = line.strip_prefix("### ") {
            section = Some(id.trim());
            assert_eq!(owner(&format!("{id}-x")), section, "### {id} is no demo");
        } else if line.starts_with("## ") {
            section = None;
        } else if let Some((id, _)) = line
            .split_once(" =")
            .filter(|_| line.starts_with(|c: char| c.is_ascii_lowercase()))
        {
            assert_eq!(owner(id), section, "message {id} is in the wrong section");
        }
    }
    // Every `t!("<demo>-…")` is in src/demos/<demo>.rs or src/demos/<demo>/ (`_` for `-`).
    let src = root().join("src");
    let mut rs = Vec::new();
    files(&src, "rs", &mut rs);
    let mut seen = 0;
    for f in rs {
        let rel = f
            .strip_prefix(&src)
            .unwrap()
            .to_string_lossy()
            .replace('\\', "/");
        let home = rel
            .strip_prefix("demos/")
            .and_then(|r| r.split(['/', '.']).next())
            .map(|d| d.replace('_', "-"));
        for id in literals_after(
            &code_only(&std::fs::read_to_string(&f).unwrap()),
            "t!(",
            '"',
        ) {
            seen += 1;
            if let Some(demo) = owner(&id) {
                assert_eq!(
                    home.as_deref(),
                    Some(demo),
                    "{rel} uses {id}, a message of {demo}"
                );
            }
        }
    }
    assert!(seen > 100, "found only {seen} t! calls");
}

#[test]
fn every_message_in_code_has_english_and_every_english_message_is_used() {
    let en = english();
    let declared: BTreeSet<String> = demos::ids()
        .flat_map(|id| strings(&demos::create(id).unwrap().spec()))
        .map(|(id, _)| id)
        .collect();
    let used = used_ids();
    let missing: Vec<_> = used.iter().filter(|id| !en.contains_key(*id)).collect();
    assert!(missing.is_empty(), "used but not in en.ftl: {missing:?}");
    let unused: Vec<_> = en
        .keys()
        .filter(|id| !used.contains(*id) && !declared.contains(*id))
        .collect();
    assert!(unused.is_empty(), "in en.ftl but never used: {unused:?}");
}

#[test]
fn every_catalogue_has_every_english_message_and_no_foreign_variables() {
    let en = english();
    for l in LOCALES.iter().filter(|l| l.file().is_some()) {
        let text = std::fs::read_to_string(catalogue_path(l.tag)).unwrap();
        let other = messages(&text, l.tag);
        let missing: Vec<_> = en.keys().filter(|id| !other.contains_key(*id)).collect();
        assert!(
            missing.is_empty(),
            "{}.ftl lacks {} messages, e.g. {:?}",
            l.tag,
            missing.len(),
            &missing[..missing.len().min(10)]
        );
        for (id, vars) in &other {
            let Some(source) = en.get(id) else {
                panic!("{}.ftl: {id} is not an English message", l.tag);
            };
            let foreign: Vec<_> = vars.difference(source).collect();
            assert!(
                foreign.is_empty(),
                "{}.ftl: {id} uses {foreign:?}, which the English source does not have",
                l.tag
            );
        }
    }
}
