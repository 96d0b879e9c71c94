//! The loaded catalogues and the active language. The module is single-threaded in the
//! browser; natively each test thread has its own state, English unless it chooses.

use super::locale::{self, Locale, Source};
use fluent_bundle::{FluentArgs, FluentBundle, FluentResource, FluentValue};
use std::cell::RefCell;

/// The hand-written English messages, the fallback of every language (`locales/en.ftl`
/// without its generated block of declared strings, which the module reads
/// from the declarations themselves; see `build.rs`).
pub const ENGLISH_FTL: &str = include_str!(concat!(env!("OUT_DIR"), "/en-messages.ftl"));

/// The English text of a declared string's id (`regimes-plot-response`), from the
/// declaration of the demo it names (`<demo>-…`, see `declared::strings`), read on first
/// use of that demo's strings. One demo's, not every demo's: the full module's first plot
/// title built all thirteen declarations (~14 ms at 4× CPU slowdown, in the task that
/// computes the demo behind the page).
fn declared_english(id: &str) -> Option<&'static str> {
    use std::collections::HashMap;
    thread_local! {
        /// The demos read so far, and their strings by id.
        static READ: RefCell<(Vec<&'static str>, HashMap<String, &'static str>)> =
            RefCell::new((Vec::new(), HashMap::new()));
    }
    READ.with_borrow_mut(|(demos, strings)| {
        // `quarter-car-2dof-…` may be the 2-DOF car's or `quarter-car`'s: read both.
        for demo in crate::demos::ids() {
            let names = id
                .strip_prefix(demo)
                .is_some_and(|rest| rest.starts_with('-'));
            if names && !demos.contains(&demo) {
                demos.push(demo);
                if let Some(d) = crate::demos::create(demo) {
                    strings.extend(super::declared::strings(&d.spec()));
                }
            }
        }
        strings.get(id).copied()
    })
}

type Bundle = FluentBundle<FluentResource>;

struct State {
    /// `(tag, bundle)` of every language loaded so far; English is built on first use.
    bundles: Vec<(&'static str, Bundle)>,
    /// Ids the active catalogue lacked since the last [`take_missing`] (shown in English).
    missing: std::collections::BTreeSet<String>,
}

thread_local! {
    /// The active language, apart from [`STATE`] so that the number formatter, which
    /// Fluent calls while a bundle is borrowed, can read it.
    static ACTIVE: std::cell::Cell<&'static Locale> = std::cell::Cell::new(locale::english());
    static STATE: RefCell<State> = const {
        RefCell::new(State {
            bundles: Vec::new(),
            missing: std::collections::BTreeSet::new(),
        })
    };
}

/// Formats Fluent number arguments (counts) with the active language's digits.
fn format_value(v: &FluentValue, _: &intl_memoizer::IntlLangMemoizer) -> Option<String> {
    match v {
        FluentValue::Number(n) => {
            let decimals = n
                .options
                .minimum_fraction_digits
                .or(n.options.maximum_fraction_digits)
                .unwrap_or(if n.value.fract() == 0.0 { 0 } else { 2 });
            Some(super::number::fixed(n.value, decimals))
        }
        _ => None,
    }
}

/// The bundle of `l` from `ftl`, with every message that parsed, and the problems found
/// (syntax errors, a message defined twice: the first one is kept).
fn new_bundle(l: &'static Locale, ftl: &str) -> (Bundle, Vec<String>) {
    let mut bundle = Bundle::new(vec![l.rules_id()]);
    bundle.set_use_isolating(l.dir == locale::Dir::Rtl);
    bundle.set_formatter(Some(format_value));
    if let Source::Pseudo(transform) = l.source {
        bundle.set_transform(Some(transform));
    }
    let mut errors = Vec::new();
    let resource = match FluentResource::try_new(ftl.to_string()) {
        Ok(r) => r,
        Err((r, errs)) => {
            errors.extend(
                errs.iter()
                    .map(|e| format!("{}: {e} (bytes {}–{})", l.tag, e.pos.start, e.pos.end)),
            );
            r
        }
    };
    if let Err(errs) = bundle.add_resource(resource) {
        errors.extend(errs.iter().map(|e| format!("{}: {e}", l.tag)));
    }
    (bundle, errors)
}

/// Loads the catalogue of language `tag` from its `.ftl` text (fetched by the page).
/// A catalogue with syntax errors keeps its good messages; the errors are returned so
/// the page can log them.
pub fn load(tag: &str, ftl: &str) -> Result<(), Vec<String>> {
    let Some(l) = locale::by_tag(tag).filter(|l| matches!(l.source, Source::File)) else {
        return Err(vec![format!("{tag}: not a language with a catalogue file")]);
    };
    let (bundle, errors) = new_bundle(l, ftl);
    STATE.with(|s| {
        let mut s = s.borrow_mut();
        s.bundles.retain(|(t, _)| *t != l.tag);
        s.bundles.push((l.tag, bundle));
    });
    if errors.is_empty() {
        Ok(())
    } else {
        Err(errors)
    }
}

/// Whether the messages of `l` are available (built in, pseudo, or loaded).
pub fn is_loaded(l: &Locale) -> bool {
    !matches!(l.source, Source::File)
        || STATE.with(|s| s.borrow().bundles.iter().any(|(t, _)| *t == l.tag))
}

/// Makes `l` the active language. A file language whose catalogue is not loaded yet
/// shows English until [`load`] brings it.
pub fn set_active(l: &'static Locale) {
    ACTIVE.with(|a| a.set(l));
}

/// The active language.
pub fn active() -> &'static Locale {
    ACTIVE.with(|a| a.get())
}

fn ensure_builtin(s: &mut State, l: &'static Locale) {
    if matches!(l.source, Source::File) || s.bundles.iter().any(|(t, _)| *t == l.tag) {
        return;
    }
    // The English catalogue is compiled in and tested, so it always parses.
    let (b, _) = new_bundle(l, ENGLISH_FTL);
    s.bundles.push((l.tag, b));
}

/// Formats message `id` in `l`'s bundle; `None` if that bundle lacks it.
fn format_in(s: &State, tag: &str, id: &str, args: Option<&FluentArgs>) -> Option<String> {
    let (_, bundle) = s.bundles.iter().find(|(t, _)| *t == tag)?;
    let pattern = bundle.get_message(id)?.value()?;
    let mut errors = Vec::new();
    Some(
        bundle
            .format_pattern(pattern, args, &mut errors)
            .into_owned(),
    )
}

/// Message `id` in the active language, falling back to English; the id itself (which
/// the catalogue tests catch) if no catalogue has it.
pub fn format(id: &str, args: Option<&FluentArgs>) -> String {
    STATE.with(|cell| {
        let mut s = cell.borrow_mut();
        let active = active();
        ensure_builtin(&mut s, active);
        ensure_builtin(&mut s, locale::english());
        if let Some(text) = format_in(&s, active.tag, id, args) {
            return text;
        }
        if matches!(active.source, Source::File) {
            s.missing.insert(id.to_string());
        }
        if let Some(text) = format_in(&s, "en", id, args) {
            return text;
        }
        match (declared_english(id), active.source) {
            (Some(english), Source::Pseudo(transform)) => transform(english).into_owned(),
            (Some(english), _) => english.to_string(),
            (None, _) => id.to_string(),
        }
    })
}

/// Message `id` of the active language if its catalogue has one; else `english`
/// (transformed, for a pseudo-locale). For the strings the demo declarations carry.
pub fn declared(id: &str, english: &str) -> String {
    STATE.with(|cell| {
        let mut s = cell.borrow_mut();
        let active = active();
        match active.source {
            Source::Builtin => english.to_string(),
            Source::Pseudo(transform) => transform(english).into_owned(),
            Source::File => format_in(&s, active.tag, id, None).unwrap_or_else(|| {
                s.missing.insert(id.to_string());
                english.to_string()
            }),
        }
    })
}

/// The ids shown in English because the active catalogue lacked them, since the last
/// call (the end-to-end tests read this to find untranslated messages by id).
pub fn take_missing() -> Vec<String> {
    STATE.with(|s| {
        std::mem::take(&mut s.borrow_mut().missing)
            .into_iter()
            .collect()
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn declared_ids_fall_back_to_the_declarations_and_pseudo_transforms_them() {
        assert!(!ENGLISH_FTL.contains("regimes-plot-response ="));
        assert_eq!(format("regimes-plot-response", None), "Free response x(t)");
        set_active(locale::by_tag("en-XA").unwrap_or(locale::english()));
        let pseudo = format("regimes-plot-response", None);
        set_active(locale::english());
        assert!(
            pseudo.starts_with('[') && pseudo.contains("ŕéšþöñšé"),
            "{pseudo}"
        );
        assert_eq!(format("no-such-message", None), "no-such-message");
    }

    #[test]
    fn every_declared_string_falls_back_to_its_own_demo_declaration() {
        // Ids of one demo can start with another's (`quarter-car-2dof-…`, `quarter-car-…`).
        for demo in crate::demos::ids().filter_map(crate::demos::create) {
            for (id, english) in super::super::declared::strings(&demo.spec()) {
                assert_eq!(declared_english(&id), Some(english), "{id}");
            }
        }
        assert_eq!(declared_english("quarter-car-no-such-key"), None);
        assert_eq!(declared_english("regimes"), None);
    }

    #[test]
    fn a_loaded_catalogue_wins_and_missing_ids_are_recorded() {
        let fr = locale::by_tag("fr").unwrap_or(locale::english());
        assert!(load("fr", "plot-clipped = rogné\nbroken = {").is_err());
        set_active(fr);
        assert_eq!(format("plot-clipped", None), "rogné");
        assert_eq!(format("axis-time", None), "time t");
        assert_eq!(take_missing(), vec!["axis-time".to_string()]);
        set_active(locale::english());
        assert!(load("xx", "a = b").is_err());
    }

    /// A first module's English catalogue: every message of the page, the shared sections
    /// and its demos' `### <id>` sections; none of another demo's (whose messages are
    /// its own: `tests/catalogues.rs`).
    #[cfg(feature = "first")]
    #[test]
    fn a_first_module_keeps_its_demos_and_the_shared_messages_only() {
        let first = crate::demos::FIRST_DEMO;
        let linked: Vec<&str> = env!("ZETA_FIRST_LINKED").split(' ').collect();
        let all = include_str!("../../locales/en.ftl");
        let kept = |id: &str| {
            ENGLISH_FTL
                .lines()
                .any(|l| l.strip_prefix(id).is_some_and(|r| r.starts_with(" =")))
        };
        let (mut section, mut checked) = (None, 0);
        for line in all.split("## Declared strings").next().unwrap().lines() {
            if let Some(id) = line.strip_prefix("### ") {
                section = Some(id.trim());
            } else if line.starts_with("## ") {
                section = None;
            } else if let Some((id, _)) = line
                .split_once(" =")
                .filter(|_| line.starts_with(|c: char| c.is_ascii_lowercase()))
            {
                let wanted = section.is_none_or(|demo| linked.contains(&demo));
                assert_eq!(kept(id), wanted, "{id} in the first module of {first}");
                checked += 1;
            }
        }
        assert!(checked > 400, "{checked} messages");
    }
}
