//! Compiles in only the hand-written part of the English catalogue: the block of
//! declared strings at its end (generated for translators from the demo declarations)
//! repeats text the declarations already carry, so the module reads those from the
//! declarations instead (`i18n::catalogue`).

use std::path::Path;

const DECLARED: &str = "## Declared strings (generated from the demo declarations)";

fn main() {
    println!("cargo:rerun-if-changed=locales/en.ftl");
    let text = std::fs::read_to_string("locales/en.ftl").unwrap_or_default();
    let messages = text.split(DECLARED).next().unwrap_or_default();
    let out = std::env::var("OUT_DIR").unwrap_or_else(|_| ".".to_string());
    if let Err(e) = std::fs::write(Path::new(&out).join("en-messages.ftl"), messages) {
        println!("cargo:warning=could not write the English messages: {e}");
    }
}
