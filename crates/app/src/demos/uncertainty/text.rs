//! The tolerance demo's prose: summary, equation, labels and the figures' text
//! alternatives.

use super::ranges::Ranges;
use super::{HistOf, System, P};
use crate::format::{si, significant};
use crate::spec::Preset;

pub(super) const SUMMARY: &str =
    "Real parts are not their nominal values. Choose the system: the quarter \
                      car (sprung mass m, spring k and the damper set for ζ at nominal mass; \
                      the mass varies by ±dm as the car is loaded) or the series RLC loop \
                      (R, L and C each within ±dR, ±dL, ±dC). Only the chosen system's sliders \
                      are used; the other group is ignored. The exact ranges of ζ, ωₙ and Q come \
                      from the corners of the tolerance box. The Monte Carlo run draws N designs \
                      (seeded, so the same seed gives the same result): uniform within the \
                      tolerance, or normal with the tolerance as 3σ. The yield is the share of \
                      draws with ζ inside the spec window and a 5 % settling time (release \
                      from rest) no longer than the limit.";

pub(super) const EQUATION: &str = "<math display=\"block\"><mrow>\
<mi>ζ</mi><mo>=</mo><mfrac><mi>c</mi><mrow><mn>2</mn><msqrt><mi>k</mi><mi>m</mi></msqrt></mrow></mfrac>\
<mo>∝</mo><msup><mi>m</mi><mrow><mo>−</mo><mn>1/2</mn></mrow></msup><mo>,</mo><mspace width=\"1em\"/>\
<mi>ζ</mi><mo>=</mo><mfrac><mi>R</mi><mn>2</mn></mfrac><msqrt><mfrac><mi>C</mi><mi>L</mi></mfrac></msqrt>\
</mrow></math>";

/// `v` to `sig` significant digits without trailing zeros ("10", "0.6").
pub(super) fn short(v: f64, sig: usize) -> String {
    let t = significant(v, sig);
    if t.contains('.') && !t.contains('e') {
        t.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        t
    }
}

/// A count with thin-space thousands separators ("100 000").
fn count_text(n: usize) -> String {
    let digits = n.to_string();
    let mut out = String::with_capacity(digits.len() + 4);
    for (i, ch) in digits.chars().enumerate() {
        if i > 0 && (digits.len() - i).is_multiple_of(3) {
            out.push('\u{2009}');
        }
        out.push(ch);
    }
    out
}

/// A band member's legend label: its name and, where defined, its ζ.
pub(super) fn band_label(name: &str, zeta: Option<f64>) -> String {
    match zeta {
        Some(z) => format!("{name} (ζ = {})", significant(z, 3)),
        None => name.to_string(),
    }
}

/// The band of free responses in words.
pub(super) fn describe_band(p: &P, r: &Ranges) -> String {
    let fmt_t = |t: Option<f64>| t.map_or("never".to_string(), |t| si(t, "s", 3));
    let (what, ignored) = match p.system {
        System::Suspension => {
            let pct = short(p.dm, 3);
            (
                format!(
                    "Free response from {} with the sprung mass at +{pct} %, nominal and −{pct} %",
                    si(r.x0, "m", 2),
                ),
                "The RLC sliders are ignored.",
            )
        }
        System::Rlc => (
            "Capacitor voltage from 1 V at the lowest-ζ corner, nominal and highest-ζ corner of \
             the tolerance box"
                .to_string(),
            "The suspension sliders are ignored.",
        ),
    };
    let zeta_text = r.zeta.map_or_else(
        || "ζ is undefined at an end of the range".to_string(),
        |(lo, hi)| format!("ζ spans {}–{}", significant(lo, 3), significant(hi, 3)),
    );
    let [a, b, c] = &r.band;
    format!(
        "{what}: {zeta_text}; 5 % settling times (crosses) {}, {} and {}. {ignored}",
        fmt_t(a.settling_time),
        fmt_t(b.settling_time),
        fmt_t(c.settling_time),
    )
}

/// A histogram in words: its range, percentiles and the spec where it is marked.
pub(super) fn describe_histogram(
    p: &P,
    h: HistOf,
    draws: usize,
    range: Option<(f64, f64)>,
    [p5, p95]: [f64; 2],
    yield_pct: f64,
) -> String {
    let (name, unit) = h.label();
    let dist = match p.dist {
        super::Dist::Normal => "normal (tolerance = 3σ)",
        super::Dist::Uniform => "uniform",
    };
    let (zlo, zhi) = p.zeta_window();
    let spec_text = match h {
        HistOf::Zeta => format!(
            " The spec window ζ {}–{} is marked; {} of draws meet the whole spec.",
            short(zlo, 3),
            short(zhi, 3),
            si(yield_pct, "%", 3)
        ),
        HistOf::SettlingTime => {
            format!(" The spec limit {} is marked.", si(p.ts_max, "s", 3))
        }
        _ => String::new(),
    };
    match range {
        Some((lo, hi)) => format!(
            "Histogram of {name} over {} {dist} draws: from {} to {}, 5th percentile {}, \
             95th percentile {}.{spec_text}",
            count_text(draws),
            si(lo, unit, 4),
            si(hi, unit, 4),
            si(p5, unit, 4),
            si(p95, unit, 4),
        ),
        None => format!("No draw has a finite {name}."),
    }
}

/// Marks a histogram drawn from the first `shown` draws while the full run of `full` draws
/// continues as provisional, in its title and its description.
pub(super) fn mark_provisional(fig: &mut crate::figure::Figure, shown: usize, full: usize) {
    fig.title = format!("{} (provisional)", fig.title);
    fig.description = format!(
        "Provisional: from the first {shown} draws while the run of {full} continues. {}",
        fig.description
    );
}

/// The preset buttons.
pub(super) fn presets() -> Vec<Preset> {
    let car = |label, zeta| Preset {
        label,
        values: vec![
            ("system", 0.0),
            ("m", 300.0),
            ("k", 24_000.0),
            ("zeta", zeta),
            ("dm", 10.0),
        ],
    };
    let rlc = |label, pct| Preset {
        label,
        values: vec![("system", 1.0), ("dR", pct), ("dL", pct), ("dC", pct)],
    };
    vec![
        car("ζ = 1 design under ±10 % mass", 1.0),
        car("ζ = 0.7 design under ±10 % mass", 0.7),
        rlc("RLC 5 % parts", 5.0),
        rlc("RLC 20 % parts", 20.0),
    ]
}
