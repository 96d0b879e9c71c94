//! The languages of the interface: one row a language. Adding a language is one
//! catalogue file, `crates/app/locales/<tag>.ftl`, and one row in [`LOCALES`].

use std::borrow::Cow;
use unic_langid::LanguageIdentifier;

/// Writing direction of a language.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Dir {
    /// Left to right.
    Ltr,
    /// Right to left (the page mirrors through CSS logical properties).
    Rtl,
}

/// Where a language's messages come from.
#[derive(Debug, Clone, Copy)]
pub enum Source {
    /// Compiled into the module: the English source catalogue.
    Builtin,
    /// Fetched by the page from `locales/<tag>.ftl` when the language is chosen.
    File,
    /// Made from the English catalogue by a text transform (for testing layouts).
    Pseudo(fn(&str) -> Cow<'_, str>),
}

/// One language of the interface.
#[derive(Debug)]
pub struct Locale {
    /// BCP 47 tag, as in `lang=` and the catalogue's file name.
    pub tag: &'static str,
    /// The language's name in itself, for the language menu.
    pub name: &'static str,
    /// Writing direction.
    pub dir: Dir,
    /// The locale whose CLDR rules format numbers and select plurals (the browser's
    /// `Intl` and Fluent's plural rules); a pseudo-locale uses its base language's.
    pub rules: &'static str,
    /// Where the messages come from.
    pub source: Source,
}

impl Locale {
    /// Whether this is a pseudo-locale (never offered by negotiation, only by `lang=`).
    pub fn is_pseudo(&self) -> bool {
        matches!(self.source, Source::Pseudo(_))
    }

    /// The catalogue file the page fetches, relative to the site root.
    pub fn file(&self) -> Option<String> {
        matches!(self.source, Source::File).then(|| format!("locales/{}.ftl", self.tag))
    }

    /// The language identifier of [`Locale::rules`].
    pub fn rules_id(&self) -> LanguageIdentifier {
        self.rules.parse().unwrap_or_default()
    }
}

/// Every language, English (the source and the fallback) first.
pub const LOCALES: &[Locale] = &[
    Locale {
        tag: "en",
        name: "English",
        dir: Dir::Ltr,
        rules: "en",
        source: Source::Builtin,
    },
    Locale {
        tag: "es",
        name: "Español",
        dir: Dir::Ltr,
        rules: "es",
        source: Source::File,
    },
    Locale {
        tag: "fr",
        name: "Français",
        dir: Dir::Ltr,
        rules: "fr",
        source: Source::File,
    },
    Locale {
        tag: "pt-BR",
        name: "Português (Brasil)",
        dir: Dir::Ltr,
        rules: "pt-BR",
        source: Source::File,
    },
    Locale {
        tag: "zh-CN",
        name: "中文（简体）",
        dir: Dir::Ltr,
        rules: "zh-CN",
        source: Source::File,
    },
    Locale {
        tag: "en-XA",
        name: "[Ëñğļîšĥ (pseudo)]",
        dir: Dir::Ltr,
        rules: "en",
        source: Source::Pseudo(super::pseudo::accented),
    },
    Locale {
        tag: "ar-XB",
        name: "English (pseudo RTL)",
        dir: Dir::Rtl,
        rules: "en",
        source: Source::Pseudo(super::pseudo::mirrored),
    },
];

/// English, the source language.
pub fn english() -> &'static Locale {
    &LOCALES[0]
}

/// The locale with exactly this tag (case-insensitive).
pub fn by_tag(tag: &str) -> Option<&'static Locale> {
    LOCALES
        .iter()
        .find(|l| l.tag.eq_ignore_ascii_case(tag.trim()))
}

/// The best language for a list of requested BCP 47 tags, most wanted first (`lang=`,
/// then the browser's languages): a pseudo-locale only when asked for by its exact tag,
/// otherwise CLDR-style negotiation (`fr-CA` → `fr`, `pt` → `pt-BR`, `zh` → `zh-CN`);
/// English when nothing matches.
pub fn negotiate<S: AsRef<str>>(requested: &[S]) -> &'static Locale {
    if let Some(pseudo) = requested
        .first()
        .and_then(|t| by_tag(t.as_ref()))
        .filter(|l| l.is_pseudo())
    {
        return pseudo;
    }
    let wanted: Vec<LanguageIdentifier> = requested
        .iter()
        .filter_map(|t| t.as_ref().trim().parse().ok())
        .collect();
    let real: Vec<&Locale> = LOCALES.iter().filter(|l| !l.is_pseudo()).collect();
    let available: Vec<LanguageIdentifier> = real
        .iter()
        .map(|l| l.tag.parse().unwrap_or_default())
        .collect();
    let chosen = fluent_langneg::negotiate_languages(
        &wanted,
        &available,
        None,
        fluent_langneg::NegotiationStrategy::Lookup,
    );
    chosen
        .first()
        .and_then(|id| available.iter().position(|a| a == *id))
        .map(|i| real[i])
        .unwrap_or_else(english)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn negotiation_follows_the_request_order_and_regions() {
        assert_eq!(negotiate(&["fr-CA", "en"]).tag, "fr");
        assert_eq!(negotiate(&["pt"]).tag, "pt-BR");
        assert_eq!(negotiate(&["pt-PT"]).tag, "pt-BR");
        assert_eq!(negotiate(&["zh"]).tag, "zh-CN");
        assert_eq!(negotiate(&["de-DE", "es-MX"]).tag, "es");
        assert_eq!(negotiate(&["de"]).tag, "en");
        assert_eq!(negotiate::<&str>(&[]).tag, "en");
        assert_eq!(negotiate(&["en-XA"]).tag, "en-XA");
        assert_eq!(negotiate(&["AR-xb"]).tag, "ar-XB");
        assert_eq!(negotiate(&["<script>", "es"]).tag, "es");
    }

    #[test]
    fn every_tag_parses_and_every_file_locale_has_a_catalogue() {
        for l in LOCALES {
            assert!(l.tag.parse::<LanguageIdentifier>().is_ok(), "{}", l.tag);
            assert!(l.rules.parse::<LanguageIdentifier>().is_ok(), "{}", l.rules);
            if let Some(file) = l.file() {
                let path = format!("{}/{file}", env!("CARGO_MANIFEST_DIR"));
                assert!(std::path::Path::new(&path).exists(), "missing {path}");
            }
        }
    }
}
