//! Formatting numbers for readouts: significant digits and engineering prefixes.

// Number formatting needs the decimal exponent of a value.
#![allow(clippy::disallowed_methods)]

/// The name of a damping regime in the interface language.
pub fn regime(r: zeta_solver::Regime) -> String {
    use zeta_solver::Regime;
    match r {
        Regime::Undamped => crate::t!("regime-undamped"),
        Regime::Underdamped => crate::t!("regime-underdamped"),
        Regime::CriticallyDamped => crate::t!("regime-critically-damped"),
        Regime::Overdamped => crate::t!("regime-overdamped"),
        Regime::NegativelyDamped => crate::t!("regime-negatively-damped"),
        Regime::Neutral => crate::t!("regime-neutral"),
        Regime::Divergent => crate::t!("regime-divergent"),
    }
}

/// `v` with the digits of its shortest round-trip form (`0.2`, `1500`, `1e-7`), in the
/// interface language's separators: for values a user typed or a declaration set.
pub fn shortest(v: f64) -> String {
    let s = format!("{v}");
    if s.contains(['N', 'i']) {
        return s;
    }
    let decimals = s.split_once('.').map_or(0, |(_, f)| f.len());
    if decimals <= 12 {
        return crate::i18n::number::fixed(v, decimals);
    }
    // Tiny values: the shortest mantissa with its exponent (`1e-25`, `2.5e-13`).
    let e = format!("{v:e}");
    let (mantissa, exp) = e.split_once('e').unwrap_or((e.as_str(), "0"));
    let decimals = mantissa.split_once('.').map_or(0, |(_, f)| f.len());
    let m = crate::i18n::number::fixed(mantissa.parse().unwrap_or(0.0), decimals);
    format!("{m}e{exp}")
}

/// Formats `v` with `sig` significant digits and an SI prefix for `unit`
/// (`0.0012 s` → `1.20 ms`). Dimensionless values and percentages get no prefix; nor does
/// a frequency from a thousandth of its unit up to 1 (`0.9576 Hz`, not `957.6 mHz`: a
/// vehicle's bounce or a slow oscillator is read in hertz or rad/s, never in milli-).
pub fn si(v: f64, unit: &str, sig: usize) -> String {
    if !v.is_finite() {
        return "—".to_string();
    }
    let prefixable =
        !unit.is_empty() && !unit.starts_with('1') && !matches!(unit, "%" | "rad" | "°");
    let plain_frequency = matches!(unit, "Hz" | "rad/s") && (1e-3..1.0).contains(&v.abs());
    let (scaled, prefix) = match prefixable && !plain_frequency {
        true => engineering(v),
        false => (v, ""),
    };
    let num = significant(scaled, sig);
    match (prefix, unit) {
        (_, "") => num,
        // The degree sign follows the number without a space (SI Brochure, 5.4.3).
        (_, "°") => format!("{num}°"),
        (p, "%") => format!("{num}{p} %"),
        (p, u) => format!("{num} {p}{u}"),
    }
}

fn engineering(v: f64) -> (f64, &'static str) {
    const PREFIXES: [(f64, &str); 9] = [
        (1e9, "G"),
        (1e6, "M"),
        (1e3, "k"),
        (1.0, ""),
        (1e-3, "m"),
        (1e-6, "µ"),
        (1e-9, "n"),
        (1e-12, "p"),
        (1e-15, "f"),
    ];
    let a = v.abs();
    if a == 0.0 || !(1e-15..1e12).contains(&a) {
        return (v, "");
    }
    for (scale, p) in PREFIXES {
        if a >= scale * 0.999_999_5 {
            return (v / scale, p);
        }
    }
    (v, "")
}

/// `v` rounded to `sig` significant digits, in plain or (for extreme magnitudes)
/// scientific notation, in the interface language's digits and decimal separator.
pub fn significant(v: f64, sig: usize) -> String {
    let s = significant_plain(v, sig);
    let (mantissa, exp) = match s.split_once('e') {
        Some((m, e)) => (m, Some(e)),
        None => (s.as_str(), None),
    };
    let decimals = mantissa.split_once('.').map_or(0, |(_, f)| f.len());
    let local = crate::i18n::number::fixed(mantissa.parse().unwrap_or(0.0), decimals);
    match exp {
        Some(e) => format!("{local}e{e}"),
        None => local,
    }
}

/// [`significant`] in the locale-free form (`1.20`, `3.5e-7`).
pub fn significant_plain(v: f64, sig: usize) -> String {
    if v == 0.0 {
        return "0".to_string();
    }
    let sig = sig.clamp(1, 15);
    let mag = v.abs().log10().floor() as i32;
    if !(-4..=9).contains(&mag) {
        return format!("{:.*e}", sig - 1, v);
    }
    let decimals = (sig as i32 - 1 - mag).max(0) as usize;
    let s = format!("{v:.decimals$}");
    if s.starts_with("-0") && s.trim_start_matches(['-', '0', '.']).is_empty() {
        s.trim_start_matches('-').to_string()
    } else {
        s
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn shortest_keeps_every_digit_and_writes_tiny_values_with_an_exponent() {
        assert_eq!(shortest(0.2), "0.2");
        assert_eq!(shortest(1500.0), "1500");
        assert_eq!(shortest(-0.05), "-0.05");
        assert_eq!(shortest(1e-25), "1e-25");
        assert_eq!(shortest(2.5e-13), "2.5e-13");
        assert_eq!(shortest(f64::NAN), "NaN");
    }

    #[test]
    fn prefixes_and_digits() {
        assert_eq!(si(8.944_271_9, "rad/s", 4), "8.944 rad/s");
        assert_eq!(si(0.0012, "s", 3), "1.20 ms");
        assert_eq!(si(24_000.0, "N/m", 3), "24.0 kN/m");
        assert_eq!(si(-4.472, "1/s", 4), "-4.472 1/s");
        assert_eq!(si(4.598, "%", 4), "4.598 %");
        assert_eq!(si(-30.0, "°", 3), "-30.0°");
        assert_eq!(si(0.3, "", 3), "0.300");
        assert_eq!(si(f64::NAN, "s", 3), "—");
        assert_eq!(si(0.0, "s", 3), "0 s");
        assert_eq!(significant(1.0e-7, 3), "1.00e-7");
    }

    #[test]
    fn a_frequency_under_its_unit_is_written_without_milli() {
        assert_eq!(si(0.957_62, "Hz", 4), "0.9576 Hz");
        assert_eq!(si(-0.25, "rad/s", 3), "-0.250 rad/s");
        assert_eq!(si(0.0012, "Hz", 3), "0.00120 Hz");
        assert_eq!(si(0.000_5, "Hz", 3), "500 µHz");
        assert_eq!(si(12_500.0, "rad/s", 3), "12.5 krad/s");
        assert_eq!(si(0.5, "s", 3), "500 ms");
    }
}
