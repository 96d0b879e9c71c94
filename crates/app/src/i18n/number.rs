//! Numbers in the interface language. In the browser the digits, decimal separator and
//! grouping come from `Intl.NumberFormat` (CLDR data the browser keeps up to date);
//! native builds (tests, snapshots, SVG export checks) print the plain English form.
//! Machine-readable numbers (`data-value`, URL values, CSV) never pass through here.

/// `v` with exactly `decimals` digits after the separator, in the active language
/// (`1234.5, 1` → `1234.5` in English, `1234,5` in French; from five integer digits the
/// locale's grouping applies: `12 345,6`).
pub fn fixed(v: f64, decimals: usize) -> String {
    let decimals = decimals.min(20);
    imp::fixed(v, decimals).unwrap_or_else(|| plain(v, decimals))
}

/// The locale-free form of [`fixed`] (what native builds show).
pub fn plain(v: f64, decimals: usize) -> String {
    let s = format!("{v:.decimals$}");
    // `-0.00` reads as 0.
    if s.starts_with('-') && s.trim_start_matches(['-', '0', '.']).is_empty() {
        s[1..].to_string()
    } else {
        s
    }
}

#[cfg(target_arch = "wasm32")]
mod imp {
    use std::cell::RefCell;
    use wasm_bindgen::{JsCast, JsValue};

    thread_local! {
        /// The bound `format` functions of the active rules' `Intl.NumberFormat`s, one a
        /// count of decimals, built on first use (building one is the slow part).
        static FORMATS: RefCell<(String, Vec<Option<js_sys::Function>>)> =
            const { RefCell::new((String::new(), Vec::new())) };
    }

    fn formatter(rules: &str, decimals: usize) -> Option<js_sys::Function> {
        FORMATS.with(|cell| {
            let mut cache = cell.borrow_mut();
            if cache.0 != rules {
                *cache = (rules.to_string(), Vec::new());
            }
            if cache.1.len() <= decimals {
                cache.1.resize(decimals + 1, None);
            }
            if cache.1[decimals].is_none() {
                let options = js_sys::Object::new();
                let d = JsValue::from_f64(decimals as f64);
                let set = |k: &str, v: &JsValue| js_sys::Reflect::set(&options, &k.into(), v).ok();
                set("minimumFractionDigits", &d)?;
                set("maximumFractionDigits", &d)?;
                set("useGrouping", &JsValue::from_str("min2"))?;
                let locales = js_sys::Array::of1(&JsValue::from_str(rules));
                let nf = js_sys::Intl::NumberFormat::new(&locales, &options);
                let bound = js_sys::Reflect::get(&nf, &"format".into()).ok()?;
                cache.1[decimals] = Some(bound.dyn_into().ok()?);
            }
            cache.1[decimals].clone()
        })
    }

    pub(super) fn fixed(v: f64, decimals: usize) -> Option<String> {
        let rules = super::super::catalogue::active().rules;
        if rules == "en" {
            return None; // English keeps the plain form, as the snapshots and SI style do
        }
        let f = formatter(rules, decimals)?;
        let s = f
            .call1(&JsValue::NULL, &JsValue::from_f64(v))
            .ok()?
            .as_string()?;
        // Intl writes "-0" for tiny negatives rounded to zero; the app reads them as 0.
        // Whether it rounds to zero is read from the number, not from the digits Intl
        // wrote (a language may have its own digits).
        let rounds_to_zero = super::plain(v, decimals)
            .chars()
            .all(|c| matches!(c, '0' | '.'));
        if rounds_to_zero {
            return Some(s.trim_start_matches(['-', '\u{2212}']).to_string());
        }
        Some(s)
    }
}

#[cfg(not(target_arch = "wasm32"))]
mod imp {
    pub(super) fn fixed(_v: f64, _decimals: usize) -> Option<String> {
        None
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn plain_rounds_and_reads_negative_zero_as_zero() {
        assert_eq!(fixed(1.23456, 2), "1.23");
        assert_eq!(fixed(-0.0001, 2), "0.00");
        assert_eq!(fixed(-1.5, 0), "-2");
        assert_eq!(plain(12.0, 1), "12.0");
    }
}
