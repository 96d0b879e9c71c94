//! The one parser for values from outside: URL query strings and typed-in numbers.
//!
//! Every value passes through [`resolve_value`], which accepts only finite decimal numbers
//! and clamps them into the declared range. Anything else is replaced by the default, and a
//! [`Notice`] says what happened, so the page can tell the user without blocking.

use crate::format::shortest;
use crate::spec::{DemoSpec, Kind, ParamSpec};
use crate::t;
use serde::Serialize;

/// A non-blocking message about an input that was corrected.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Notice {
    /// The parameter key concerned.
    pub key: String,
    /// Plain-text message (never HTML).
    pub message: String,
}

impl Notice {
    /// The notice about value `raw` given for `p`. `problem` is the variant of message
    /// `notice-value` that says what was wrong: `toggle`, `option`, `number` or `range` for
    /// a parameter's value, `range-empty`, `range-not-two-numbers` or `step` for a
    /// lecturer's override (`crate::lecturer::narrow`); `used` is the value taken instead,
    /// where there is one.
    pub(crate) fn about(p: &ParamSpec, raw: &str, problem: &str, used: Option<f64>) -> Self {
        let options: Vec<&str> = p.options.iter().map(|o| o.key).collect();
        let message = t!(
            "notice-value",
            problem = problem,
            label = p.display_label(),
            key = p.key,
            value = shown(raw),
            options = options.join(", "),
            default = shortest(p.default),
            min = shortest(p.min),
            max = shortest(p.max),
            unit = unit_suffix(p.unit),
            span = shortest(p.max - p.min),
            step = shortest(p.step),
            used = used.map(shortest).unwrap_or_default()
        );
        Self {
            key: p.key.to_string(),
            message,
        }
    }
}

/// Validated parameter values of one demo, in the order of its spec.
#[derive(Debug, Clone, PartialEq)]
pub struct Params {
    keys: Vec<&'static str>,
    values: Vec<f64>,
}

impl Params {
    /// Every parameter at its default.
    pub fn defaults(spec: &DemoSpec) -> Self {
        Self {
            keys: spec.params.iter().map(|p| p.key).collect(),
            values: spec.params.iter().map(|p| p.default).collect(),
        }
    }

    /// The value of `key`; `NaN` only for a key the demo did not declare (a programming
    /// error caught by the registry tests).
    pub fn get(&self, key: &str) -> f64 {
        self.keys
            .iter()
            .position(|k| *k == key)
            .and_then(|i| self.values.get(i).copied())
            .unwrap_or(f64::NAN)
    }

    /// Sets `key` from an outside value after validation; returns the value used and a
    /// notice if it was corrected. Unknown keys are ignored (`None`).
    pub fn set_raw(
        &mut self,
        spec: &DemoSpec,
        key: &str,
        raw: &str,
    ) -> Option<(f64, Option<Notice>)> {
        let p = spec.param(key)?;
        let i = self.keys.iter().position(|k| *k == key)?;
        let (v, notice) = resolve_value(p, raw);
        if let Some(slot) = self.values.get_mut(i) {
            *slot = v;
        }
        Some((v, notice))
    }

    /// `(key, value)` pairs in spec order.
    pub fn pairs(&self) -> impl Iterator<Item = (&'static str, f64)> + '_ {
        self.keys.iter().copied().zip(self.values.iter().copied())
    }
}

/// A value as a notice quotes it: at most 40 characters, no control characters.
fn shown(raw: &str) -> String {
    raw.chars().take(40).filter(|c| !c.is_control()).collect()
}

/// Parses `raw` for parameter `p`: a finite decimal clamped into range for sliders,
/// `1`/`0`/`true`/`false`/`on`/`off` for toggles, an option key or index for choices.
pub fn resolve_value(p: &ParamSpec, raw: &str) -> (f64, Option<Notice>) {
    match p.kind {
        Kind::Toggle => match raw.trim().to_ascii_lowercase().as_str() {
            "1" | "true" | "on" | "yes" => (1.0, None),
            "0" | "false" | "off" | "no" => (0.0, None),
            _ => corrected(p, raw, p.default, "toggle"),
        },
        Kind::Choice => {
            let t = raw.trim();
            let index = p
                .options
                .iter()
                .position(|o| o.key == t)
                .or_else(|| t.parse::<usize>().ok().filter(|&i| i < p.options.len()));
            match index {
                Some(i) => (i as f64, None),
                None => corrected(p, raw, p.default, "option"),
            }
        }
        Kind::Slider => match parse_number(raw) {
            None => corrected(p, raw, p.default, "number"),
            Some(v) if v < p.min || v > p.max => corrected(p, raw, v.clamp(p.min, p.max), "range"),
            Some(v) => (v, None),
        },
    }
}

/// `used` in place of `raw` for `p`, with the notice that says why (see [`Notice::about`]).
fn corrected(p: &ParamSpec, raw: &str, used: f64, problem: &str) -> (f64, Option<Notice>) {
    (used, Some(Notice::about(p, raw, problem, Some(used))))
}

fn unit_suffix(unit: &str) -> String {
    if unit.is_empty() {
        String::new()
    } else {
        format!(" {unit}")
    }
}

/// A finite decimal number (`-1.5`, `2e-3`), or `None` for anything else, including
/// `NaN`, `inf`, hex and empty strings.
pub fn parse_number(raw: &str) -> Option<f64> {
    let s = raw.trim();
    if s.is_empty() || s.len() > 64 {
        return None;
    }
    let ok = s
        .bytes()
        .all(|b| b.is_ascii_digit() || matches!(b, b'+' | b'-' | b'.' | b'e' | b'E'));
    if !ok {
        return None;
    }
    s.parse::<f64>().ok().filter(|v| v.is_finite())
}

/// Splits a URL query (`?a=1&b=2`, leading `?` optional) into decoded `(key, value)` pairs.
/// `+` is a space; malformed percent escapes are kept literally.
pub fn parse_query(query: &str) -> Vec<(String, String)> {
    let q = query.strip_prefix('?').unwrap_or(query);
    q.split('&')
        .filter(|s| !s.is_empty())
        .take(256)
        .map(|pair| {
            let (k, v) = pair.split_once('=').unwrap_or((pair, ""));
            (percent_decode(k), percent_decode(v))
        })
        .collect()
}

fn percent_decode(s: &str) -> String {
    let bytes = s.as_bytes();
    let mut out = Vec::with_capacity(bytes.len());
    let mut i = 0;
    while i < bytes.len() {
        match bytes[i] {
            b'+' => out.push(b' '),
            b'%' if i + 2 < bytes.len() => {
                let hex = |b: u8| (b as char).to_digit(16);
                match (hex(bytes[i + 1]), hex(bytes[i + 2])) {
                    (Some(h), Some(l)) => {
                        out.push((h * 16 + l) as u8);
                        i += 2;
                    }
                    _ => out.push(b'%'),
                }
            }
            b => out.push(b),
        }
        i += 1;
    }
    String::from_utf8_lossy(&out).into_owned()
}

/// Resolves a whole query string against a demo: every declared parameter gets either its
/// URL value (validated) or its default. Unknown keys are ignored.
pub fn resolve_query(spec: &DemoSpec, query: &str) -> (Params, Vec<Notice>) {
    let mut params = Params::defaults(spec);
    let mut notices = Vec::new();
    for (k, v) in parse_query(query) {
        if let Some((_, Some(n))) = params.set_raw(spec, &k, &v) {
            notices.push(n);
        }
    }
    (params, notices)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::demos;

    fn regimes_spec() -> DemoSpec {
        demos::create("regimes").map(|d| d.spec()).unwrap()
    }

    #[test]
    fn numbers_parse_and_everything_else_is_rejected() {
        assert_eq!(parse_number(" 0.25 "), Some(0.25));
        assert_eq!(parse_number("-2e-3"), Some(-0.002));
        for bad in [
            "",
            "NaN",
            "nan",
            "inf",
            "-Infinity",
            "0x10",
            "1,5",
            "<script>",
            "1e999",
            "١",
        ] {
            assert_eq!(parse_number(bad), None, "{bad}");
        }
    }

    #[test]
    fn query_is_decoded_and_hostile_values_become_notices() {
        let spec = regimes_spec();
        let (p, n) = resolve_query(
            &spec,
            "?demo=regimes&zeta=%3Cscript%3Ealert(1)%3C/script%3E&wn=1e308&x0=NaN&bogus=3&v0=0.5",
        );
        assert_eq!(p.get("zeta"), spec.param("zeta").unwrap().default);
        assert_eq!(p.get("wn"), spec.param("wn").unwrap().max);
        assert_eq!(p.get("x0"), spec.param("x0").unwrap().default);
        assert_eq!(p.get("v0"), 0.5);
        let keys: Vec<&str> = n.iter().map(|n| n.key.as_str()).collect();
        assert_eq!(keys, vec!["zeta", "wn", "x0"]);
        assert!(
            n[0].message.contains("<script>alert(1)</script>"),
            "shown as text, escaped by the DOM"
        );
    }

    #[test]
    fn toggles_and_choices_parse_keys_and_reject_the_rest() {
        let t = ParamSpec::toggle("rk4", "RK4", true);
        assert_eq!(resolve_value(&t, "off"), (0.0, None));
        assert_eq!(resolve_value(&t, "1"), (1.0, None));
        assert!(resolve_value(&t, "maybe").1.is_some());
        let c = ParamSpec::choice(
            "metric",
            "metric",
            &[("settling", "settling time"), ("rms", "RMS")],
            0,
        );
        assert_eq!(resolve_value(&c, "rms"), (1.0, None));
        assert_eq!(resolve_value(&c, "0"), (0.0, None));
        let (v, n) = resolve_value(&c, "7");
        assert_eq!(v, 0.0);
        assert!(n.unwrap().message.contains("settling, rms"));
    }

    #[test]
    fn malformed_percent_escapes_do_not_panic() {
        for q in ["%", "%4", "a=%", "a=%zz", "=%%%", "&&&=", "a=%F0%9F%98"] {
            let _ = parse_query(q);
        }
        assert_eq!(parse_query("a=%41+b"), vec![("a".into(), "A b".into())]);
    }
}
