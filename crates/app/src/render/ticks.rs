//! Tick choice on log axes and tick labels.

// Drawing: tick placement on log axes (decades), not model maths.
#![allow(clippy::disallowed_methods)]

use crate::figure::{Axis, AxisScale};

/// The grid of a log axis over `lo..hi` (both > 0): its labelled ticks from [`log_ticks`],
/// and a minor grid line at every 1…9 × 10ᵏ when the range spans fewer than six decades.
pub(super) fn log_axis_ticks(lo: f64, hi: f64) -> (Vec<f64>, Vec<f64>) {
    let minor = if (hi / lo).log10() < 6.0 {
        decade_multiples(lo, hi, &[1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0, 9.0])
    } else {
        Vec::new()
    };
    (log_ticks(lo, hi), minor)
}

/// Labelled ticks of a log axis over `lo..hi`: every decade, and between them enough
/// values to read a number off the axis when it spans few decades — 1, 2, 5 × 10ᵏ under
/// three decades, 1, 1.5, 2, 3, 5, 7 × 10ᵏ under one and a half; every other decade
/// above eight. At least two ticks whenever the range allows.
pub fn log_ticks(lo: f64, hi: f64) -> Vec<f64> {
    if !(lo > 0.0 && hi > lo && lo.is_finite() && hi.is_finite()) {
        return Vec::new();
    }
    let decades = (hi / lo).log10();
    let ticks = if decades < 1.5 {
        decade_multiples(lo, hi, &[1.0, 1.5, 2.0, 3.0, 5.0, 7.0])
    } else if decades < 3.0 {
        decade_multiples(lo, hi, &[1.0, 2.0, 5.0])
    } else if decades <= 8.0 {
        decade_multiples(lo, hi, &[1.0])
    } else {
        decade_multiples(lo, hi, &[1.0])
            .into_iter()
            .filter(|v| (v.log10().round() as i64).rem_euclid(2) == 0)
            .collect()
    };
    if ticks.len() >= 2 || decades < 0.05 {
        ticks
    } else {
        decade_multiples(
            lo,
            hi,
            &[1.0, 1.2, 1.5, 2.0, 2.5, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0, 9.0],
        )
    }
}

/// At most `max` (at least one) of a log axis's labelled ticks `ticks`: all when they fit;
/// else its decades (1 × 10ᵏ) when there are two or more, first all of them if they fit,
/// then as many as fit of those whose exponent is a multiple of a stride k (2, 3, 4, 5,
/// 6, 8, 10, …; the smallest of equals: 10⁻¹², 10⁻⁶, 1, 10⁶ for k = 6) or, if more, of
/// every k-th; without two decades, every k-th tick. The first one alone if nothing fits.
#[cfg_attr(feature = "first", allow(dead_code))]
pub(super) fn thinned(ticks: &[f64], max: usize) -> Vec<f64> {
    if ticks.len() <= max {
        return ticks.to_vec();
    }
    let exponent = |v: f64| (v.log10() + 0.5).floor() as i32; // nearest (no libm round)
    let decades: Vec<f64> = ticks
        .iter()
        .copied()
        .filter(|&v| (v / 10f64.powi(exponent(v)) - 1.0).abs() < 1e-9)
        .collect();
    let decades_only = decades.len() >= 2;
    let pool = match decades_only {
        true => decades,
        false => ticks.to_vec(),
    };
    if pool.len() <= max {
        return pool;
    }
    let mut best = pool[..1].to_vec();
    for k in [2, 3, 4, 5, 6, 8, 10, 12, 15, 20, 50] {
        // By exponent only among decades: ticks between them share exponents (2 and 3
        // round to 10⁰, 5 … 30 to 10¹), and a stride there kept one cluster of them.
        let by_exponent = match decades_only {
            true => pool
                .iter()
                .copied()
                .filter(|&v| exponent(v) % k == 0)
                .collect(),
            false => Vec::new(),
        };
        let by_index = pool.iter().copied().step_by(k as usize).collect();
        for kept in [by_exponent, by_index] {
            if kept.len() <= max && kept.len() > best.len() {
                best = kept;
            }
        }
    }
    best
}

/// Every `m × 10ᵏ` (m from `mantissas`) inside `lo..=hi`, ascending.
pub(super) fn decade_multiples(lo: f64, hi: f64, mantissas: &[f64]) -> Vec<f64> {
    let mut out = Vec::new();
    let first = lo.log10().floor() as i32;
    let last = hi.log10().ceil() as i32;
    for k in first..=last.min(first + 400) {
        let base = 10f64.powi(k);
        for m in mantissas {
            // Round to 12 significant digits so labels read 0.2, not 0.20000000000000004.
            let v = crate::format::significant_plain(m * base, 12)
                .parse::<f64>()
                .unwrap_or(m * base);
            if v >= lo * (1.0 - 1e-12) && v <= hi * (1.0 + 1e-12) {
                out.push(v);
            }
        }
    }
    out
}

/// The label of a tick at `v` on `axis`: [`tick_label`], except that on a linear axis a
/// value within a billionth of the axis span of zero reads 0. Ticks are reached by adding
/// up steps, which leaves rounding such as `2.7255e-17` where zero is meant; plotters puts
/// at most a handful of labelled ticks across the span, so a step is at least a tenth of
/// it and a real tick is never that close to zero. Log axes have no zero and keep every
/// value (their ticks can be many decades below the span).
pub(super) fn axis_tick_label(v: f64, axis: &Axis) -> String {
    let (lo, hi) = axis.range;
    let span = (hi - lo).abs();
    if axis.scale == AxisScale::Linear && span.is_finite() && v.abs() < 1e-9 * span {
        return "0".to_string();
    }
    if axis.scale == AxisScale::Log && lo > 0.0 && hi / lo >= WIDE_LOG_SPAN && v > 0.0 {
        return exponent_label(v);
    }
    tick_label(v)
}

/// A log axis at least this wide (a ratio: six decades) labels every tick with an exponent
/// but 1 (`1e4 … 1e-2 … 1e-6`): plain below that reach, an error axis read `10000 … 0.0001
/// … 1e-6`, its decades in two notations.
const WIDE_LOG_SPAN: f64 = 1e6;

/// A tick label: at most 6 significant digits, no rounding tails (`0.30000000000000004` →
/// `0.3`), trailing zeros dropped, in the language's digits and separators; from a million
/// up with an exponent (`1e8`, not `100000000`), as below 10⁻⁴ (`1e-6`).
pub fn tick_label(v: f64) -> String {
    if v == 0.0 || !v.is_finite() {
        return "0".to_string();
    }
    match v.abs() >= 1e6 {
        true => written(&format!("{v:.5e}")),
        false => written(&crate::format::significant_plain(v, 6)),
    }
}

/// `v` as a tick label with an exponent (`1e-6`, `2.5e4`), 1 as `1`.
fn exponent_label(v: f64) -> String {
    match v == 1.0 {
        true => "1".to_string(),
        false => written(&format!("{v:.5e}")),
    }
}

/// A locale-free number (`1.20000`, `3.5e-7`) as a label: trailing zeros dropped, in the
/// language's digits and separators.
fn written(s: &str) -> String {
    let localized = |digits: &str| {
        let digits = trim_zeros(digits);
        let decimals = digits.split_once('.').map_or(0, |(_, f)| f.len());
        crate::i18n::number::fixed(digits.parse().unwrap_or(0.0), decimals)
    };
    match s.split_once('e') {
        Some((mantissa, exp)) => format!("{}e{exp}", localized(mantissa)),
        None => localized(s),
    }
}

/// A colour-bar label: three significant digits, as [`tick_label`] otherwise.
pub(super) fn short_label(v: f64) -> String {
    if v == 0.0 || !v.is_finite() {
        return "0".to_string();
    }
    tick_label(
        crate::format::significant_plain(v, 3)
            .parse::<f64>()
            .unwrap_or(v),
    )
}

pub(super) fn trim_zeros(s: &str) -> &str {
    if s.contains('.') {
        s.trim_end_matches('0').trim_end_matches('.')
    } else {
        s
    }
}
