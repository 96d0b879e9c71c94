//! Short numbers for prose, shared by the demos' text alternatives and legends.

use crate::format::{si, significant_plain};
use crate::i18n::number;

/// `v` to `sig` significant digits with no trailing zeros (`0.05`, `1.5`, `20`), in the
/// interface language's digits and decimal separator; scientific notation for extreme
/// magnitudes and `—` when `v` is not finite, as [`si`] without a unit writes them.
pub(crate) fn trimmed(v: f64, sig: usize) -> String {
    let plain = significant_plain(v, sig);
    match plain.split_once('.') {
        Some((_, fraction)) if !plain.contains('e') => {
            let kept = fraction.trim_end_matches('0').len();
            number::fixed(plain.parse().unwrap_or(v), kept)
        }
        _ => si(v, "", sig),
    }
}

#[cfg(test)]
mod tests {
    use super::trimmed;

    #[test]
    fn only_trailing_zeros_are_dropped() {
        for (v, want) in [
            (0.05, "0.05"),
            (0.0, "0"),
            (20.0, "20"),
            (1.5, "1.5"),
            (1.05, "1.05"),
            (0.7072, "0.707"),
            (1234.0, "1234"),
            (2.5e-7, "2.50e-7"),
            (f64::NAN, "—"),
        ] {
            assert_eq!(trimmed(v, 3), want, "{v}");
        }
    }
}
