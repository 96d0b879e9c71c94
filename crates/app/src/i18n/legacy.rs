//! The old Spanish catalogue matched by English text, kept only while the demos move to
//! message ids ([`super::t!`]); strings that have moved never reach it.

use std::borrow::Cow;
use std::collections::HashMap;
use std::sync::OnceLock;

#[path = "es.rs"]
mod es;

/// A language of the interface.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Lang {
    /// English (the language of the source).
    #[default]
    En,
    /// Spanish.
    Es,
}

impl Lang {
    /// The language for a BCP 47 tag such as `es`, `es-MX` or `en-GB`; English otherwise.
    pub fn from_tag(tag: &str) -> Lang {
        let primary = tag
            .split(['-', '_'])
            .next()
            .unwrap_or("")
            .to_ascii_lowercase();
        match primary.as_str() {
            "es" => Lang::Es,
            _ => Lang::En,
        }
    }

    /// The BCP 47 tag.
    pub fn tag(self) -> &'static str {
        match self {
            Lang::En => "en",
            Lang::Es => "es",
        }
    }

    fn decimal_comma(self) -> bool {
        matches!(self, Lang::Es)
    }
}

struct Catalogue {
    whole: HashMap<&'static str, &'static str>,
    phrases: Vec<(&'static str, &'static str)>,
}

fn catalogue(lang: Lang) -> Option<&'static Catalogue> {
    static ES: OnceLock<Catalogue> = OnceLock::new();
    match lang {
        Lang::En => None,
        Lang::Es => Some(ES.get_or_init(|| {
            let mut phrases: Vec<_> = es::PHRASES.to_vec();
            phrases.sort_by_key(|(en, _)| std::cmp::Reverse(en.len()));
            Catalogue {
                whole: es::WHOLE.iter().copied().collect(),
                phrases,
            }
        })),
    }
}

/// Whether `lang` has a whole-string translation of `s` (for the completeness test).
pub fn has_whole(lang: Lang, s: &str) -> bool {
    catalogue(lang).is_some_and(|c| c.whole.contains_key(s))
}

/// `s` in `lang`: the whole-string translation if there is one, else `s` with every known
/// phrase replaced; numbers take the language's decimal separator.
pub fn tr(lang: Lang, s: &str) -> Cow<'_, str> {
    let Some(cat) = catalogue(lang) else {
        return Cow::Borrowed(s);
    };
    if let Some(t) = cat.whole.get(s) {
        return Cow::Borrowed(t);
    }
    let mut out = s.to_string();
    for (en, other) in &cat.phrases {
        if out.contains(en) {
            out = out.replace(en, other);
        }
    }
    if lang.decimal_comma() {
        out = decimal_comma(&out);
    }
    Cow::Owned(out)
}

/// Replaces the decimal point between two digits with a comma (`1.69 s` → `1,69 s`).
fn decimal_comma(s: &str) -> String {
    let chars: Vec<char> = s.chars().collect();
    chars
        .iter()
        .enumerate()
        .map(|(i, &c)| {
            let digit = |j: Option<usize>| {
                j.and_then(|j| chars.get(j))
                    .is_some_and(|d| d.is_ascii_digit())
            };
            if c == '.' && digit(i.checked_sub(1)) && digit(Some(i + 1)) {
                ','
            } else {
                c
            }
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn english_is_unchanged_and_spanish_translates() {
        assert_eq!(tr(Lang::En, "damping ratio"), "damping ratio");
        assert_eq!(
            tr(Lang::Es, "damping ratio"),
            "coeficiente de amortiguamiento"
        );
        assert_eq!(tr(Lang::Es, "6.000 rad/s"), "6,000 rad/s");
        assert_eq!(Lang::from_tag("es-MX"), Lang::Es);
        assert_eq!(Lang::from_tag("de"), Lang::En);
    }

    #[test]
    fn phrases_translate_generated_sentences() {
        let s = tr(Lang::Es, "underdamped: swings past equilibrium 3 times before settling, stays within 5 % of rest after 1.69 s, peak rebound 37.2 %.");
        assert!(!s.contains("swings") && !s.contains("after"), "{s}");
        assert!(s.contains("1,69 s") && s.contains("37,2 %"), "{s}");
    }

    #[test]
    fn every_catalogue_entry_is_distinct_and_non_empty() {
        let mut seen = std::collections::HashSet::new();
        for (en, es) in es::WHOLE.iter().chain(es::PHRASES) {
            assert!(!en.is_empty() && !es.is_empty());
            assert!(
                seen.insert(*en) || es::PHRASES.iter().any(|(p, _)| p == en),
                "duplicate {en}"
            );
        }
    }
}
