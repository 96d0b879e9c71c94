//! Pseudo-locales, as large products test their layouts: English text transformed so that
//! untranslated strings, clipping and mirroring show at a glance. Fluent applies a
//! transform to the text of a message only, never to its arguments (numbers, names).
//!
//! - `en-XA` ([`accented`]): every Latin letter accented, about 40 % longer, in brackets,
//!   so a string that escaped the catalogue is the one without brackets.
//! - `ar-XB` ([`mirrored`]): the English text laid out right to left (each run wrapped in
//!   RIGHT-TO-LEFT OVERRIDE … POP DIRECTIONAL FORMATTING), with the page's `dir="rtl"`.

use std::borrow::Cow;

/// The accented look-alike of an ASCII letter.
fn accent(c: char) -> char {
    const FROM: &str = "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ";
    const TO: &str = "àƀçđéƒĝĥîĵķļɱñöþǫŕšţûṽŵẋýžÀßÇĐÉƑĜĤÎĴĶĻṀÑÖÞǪŔŠŢÛṼŴẊÝŽ";
    FROM.chars()
        .position(|f| f == c)
        .and_then(|i| TO.chars().nth(i))
        .unwrap_or(c)
}

/// `en-XA`: accented letters, padded by 40 % of the text's length (at least one
/// character), wrapped in `[` … `]`. Whitespace-only fragments (between arguments) pass
/// through unchanged so spacing stays readable.
pub fn accented(s: &str) -> Cow<'_, str> {
    if s.trim().is_empty() {
        return Cow::Borrowed(s);
    }
    let letters = s.chars().filter(|c| c.is_alphanumeric()).count();
    let pad = (letters * 2).div_ceil(5).max(1);
    let lead = s.len() - s.trim_start().len();
    let trail = s.len() - s.trim_end().len();
    let body = &s[lead..s.len() - trail];
    let mut out = String::with_capacity(s.len() * 2 + pad * 3);
    out.push_str(&s[..lead]);
    out.push('[');
    out.extend(body.chars().map(accent));
    for i in 0..pad {
        out.push(if i % 5 == 4 { ' ' } else { '~' });
    }
    out.push(']');
    out.push_str(&s[s.len() - trail..]);
    Cow::Owned(out)
}

/// `ar-XB`: the text between U+202E RIGHT-TO-LEFT OVERRIDE and U+202C POP DIRECTIONAL
/// FORMATTING, so it reads right to left like a right-to-left script.
pub fn mirrored(s: &str) -> Cow<'_, str> {
    if s.trim().is_empty() {
        return Cow::Borrowed(s);
    }
    Cow::Owned(format!("\u{202E}{s}\u{202C}"))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn accented_is_longer_bracketed_and_keeps_outer_spaces() {
        let s = accented(" damping ratio ");
        assert!(s.starts_with(" [đàɱþîñĝ ŕàţîö"), "{s}");
        assert!(s.ends_with("] "), "{s}");
        let plain = "damping ratio".chars().count();
        assert!(s.chars().count() >= plain * 14 / 10, "{s}");
        assert_eq!(accented("  "), "  ");
    }

    #[test]
    fn mirrored_wraps_in_an_override() {
        assert_eq!(mirrored("poles"), "\u{202E}poles\u{202C}");
        assert_eq!(mirrored(" "), " ");
    }
}
