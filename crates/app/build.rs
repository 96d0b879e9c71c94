//! 1. Compiles in only the hand-written part of the English catalogue: the block of
//!    declared strings at its end (generated for translators from the demo declarations)
//!    repeats text the declarations already carry, so the module reads those from the
//!    declarations instead (`i18n::catalogue`). A first module (feature `first`) also
//!    leaves out the other demos' sections (`### <id>`): about 8 KB brotli.
//! 2. Names the demo a first module holds (feature `first`): `ZETA_FIRST_DEMO`, the
//!    default demo if unset; ids after the first (space-separated) are demos it links too
//!    (the paper's tour shows another demo's figure first). The registry links only those
//!    (`cfg(first_demo = "<id>")`) and checks at compile time that they are demos; the
//!    first is the one the module opens (`demos::FIRST_DEMO`).

use std::path::Path;

const DECLARED: &str = "## Declared strings (generated from the demo declarations)";

/// The demo a first module holds when `ZETA_FIRST_DEMO` is not set.
const DEFAULT_DEMO: &str = "regimes";

fn main() {
    println!("cargo:rerun-if-env-changed=ZETA_FIRST_DEMO");
    let named = std::env::var("ZETA_FIRST_DEMO").unwrap_or_else(|_| DEFAULT_DEMO.to_string());
    let linked: Vec<&str> = named.split_whitespace().collect();
    let first = linked.first().copied().unwrap_or(DEFAULT_DEMO);

    println!("cargo:rerun-if-changed=locales/en.ftl");
    let text = std::fs::read_to_string("locales/en.ftl").unwrap_or_default();
    let mut messages = text.split(DECLARED).next().unwrap_or_default().to_string();
    if std::env::var_os("CARGO_FEATURE_FIRST").is_some() {
        messages = only_demos(&messages, &linked);
    }
    let out = std::env::var("OUT_DIR").unwrap_or_else(|_| ".".to_string());
    if let Err(e) = std::fs::write(Path::new(&out).join("en-messages.ftl"), messages) {
        println!("cargo:warning=could not write the English messages: {e}");
    }

    println!("cargo:rustc-check-cfg=cfg(first_demo, values(any()))");
    for id in &linked {
        println!("cargo:rustc-cfg=first_demo=\"{id}\"");
    }
    println!("cargo:rustc-env=ZETA_FIRST_DEMO={first}");
    println!("cargo:rustc-env=ZETA_FIRST_LINKED={}", linked.join(" "));
}

/// `messages` without the sections of demos other than `demos`: a `### <id>` heading opens
/// demo `id`'s section, whose messages are named `<id>-…` and used by that demo alone; a
/// `## ` heading closes it (both checked by the catalogue tests).
fn only_demos(messages: &str, demos: &[&str]) -> String {
    let mut keep = true;
    let mut out = String::with_capacity(messages.len());
    for line in messages.lines() {
        if let Some(id) = line.strip_prefix("### ") {
            keep = demos.contains(&id.trim());
        } else if line.starts_with("## ") {
            keep = true;
        }
        if keep {
            out.push_str(line);
            out.push('\n');
        }
    }
    out
}
