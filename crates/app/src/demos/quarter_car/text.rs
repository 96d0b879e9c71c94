//! The quarter-car demo's prose: summary, equation and the figures' text alternatives.

use super::{Member, Results, FAMILY};
use crate::format::{self, si};
use crate::i18n::number;
use crate::t;
use zeta_solver::metrics::free::FreeMetrics;
use zeta_solver::Regime;

pub(super) const SUMMARY: &str =
    "One corner of a car: the body (sprung mass m) on a spring k and a damper \
                      c over a fixed road, pushed by x₀ and released from rest (x′(0) = 0). c and ζ are two \
                      views of one damper, c = 2ζ√(km): move either and the other follows; \
                      changing m or k keeps the damper, so ζ moves. The thin curves show the \
                      textbook settings on this car: comfort (ζ ≈ 0.3–0.4) rebounds, \
                      performance (ζ ≈ 0.65–0.7) settles fastest, critical (ζ = 1) and \
                      overdamped settings return without rebound but more slowly. Settling \
                      time jumps as ζ passes the values where a rebound drops inside the band: \
                      the fastest ζ sits just past such a jump, so a heavier load can push a \
                      well-tuned car over the edge (see the mass strip). Settling is measured on this free \
                      response: the settling time is the last time |x| equals band·|x₀|, after \
                      which the body stays within ±band·|x₀| of rest (not the band around the \
                      final value of a step response).";

pub(super) const EQUATION: &str = "<math display=\"block\"><mrow>\
<mi>m</mi><mover><mi>x</mi><mo>¨</mo></mover><mo>+</mo><mi>c</mi><mover><mi>x</mi><mo>˙</mo></mover>\
<mo>+</mo><mi>k</mi><mi>x</mi><mo>=</mo><mn>0</mn><mo>,</mo><mspace width=\"1em\"/>\
<mi>c</mi><mo>=</mo><mn>2</mn><mi>ζ</mi><msqrt><mi>k</mi><mi>m</mi></msqrt></mrow></math>";

/// `v` rounded to two decimals and written with as few as needed (`5`, `2.5`, `0.65`), in
/// the interface language's digits.
fn short(v: f64) -> String {
    let rounded = (v * 100.0).round() / 100.0;
    let decimals = format!("{rounded}")
        .split_once('.')
        .map_or(0, |(_, f)| f.len());
    number::fixed(rounded, decimals)
}

/// A percentage as typed on the slider: `5` → `"5 %"`, `2.5` → `"2.5 %"`.
pub(super) fn pct(v: f64) -> String {
    format!("{} %", short(v))
}

/// The damping ratios of a family group, in [`FAMILY`] order.
fn group_zetas(group: &str) -> Vec<String> {
    FAMILY
        .iter()
        .filter(|(g, _)| *g == group)
        .map(|&(_, z)| short(z))
        .collect()
}

/// The legend entry of a family group.
pub(super) fn family_legend(group: &str) -> String {
    let z = group_zetas(group);
    let nth = |i: usize| z.get(i).cloned().unwrap_or_default();
    match group {
        "comfort" => t!("quarter-car-legend-comfort", low = nth(0), high = nth(1)),
        "performance" => t!(
            "quarter-car-legend-performance",
            low = nth(0),
            high = nth(1)
        ),
        "critical" => t!("quarter-car-legend-critical", zeta = nth(0)),
        _ => t!("quarter-car-legend-overdamped", zeta = nth(0)),
    }
}

/// How often the body swings through equilibrium before it settles (the solver counts
/// crossings before the settling time; a later rebound inside the band is not counted).
fn crossings_text(m: &FreeMetrics) -> String {
    match (m.zero_crossings, m.rebound_time) {
        (0, Some(_)) => t!("quarter-car-crossings-inside-band"),
        (n, _) => t!("quarter-car-crossings", count = n),
    }
}

/// The response plot in words: this design, then the family.
pub(super) fn describe_response(r: &Results) -> String {
    let car = &r.car;
    let regime = car.sys.regime();
    let band = pct(car.band_pct);
    let now = match r.metrics {
        Some(m) => {
            let settling = match m.settling_time {
                Some(t) => t!(
                    "quarter-car-settles-after",
                    band = &band,
                    time = si(t, "s", 3)
                ),
                None => t!("quarter-car-does-not-settle"),
            };
            let rebound = match m.rebound_time {
                Some(t) => t!(
                    "quarter-car-rebound",
                    rebound = si(100.0 * m.peak_rebound, "%", 3),
                    time = si(t, "s", 3)
                ),
                None => t!("quarter-car-no-rebound"),
            };
            t!(
                "quarter-car-describe-design",
                zeta = si(car.zeta(), "", 3),
                regime = format::regime(regime),
                crossings = crossings_text(&m),
                settling = settling,
                rebound = rebound
            )
        }
        None if regime == Regime::Undamped => t!(
            "quarter-car-describe-undamped",
            amplitude = si(car.x0.abs(), "m", 3),
            frequency = si(car.sys.natural_frequency_hz().unwrap_or(0.0), "Hz", 3)
        ),
        None => t!(
            "quarter-car-describe-unsettled",
            regime = format::regime(regime)
        ),
    };
    let separator = t!("quarter-car-list-separator");
    let fam: Vec<String> = r.family.iter().map(describe_member).collect();
    t!(
        "quarter-car-describe-response",
        design = now,
        band = band,
        family = fam.join(separator.as_str())
    )
}

/// A family group's name in the interface language.
fn group_name(group: &str) -> String {
    t!("quarter-car-group", group = group)
}

fn describe_member(f: &Member) -> String {
    match f.settling {
        Some(t) => t!(
            "quarter-car-member-settles",
            group = group_name(f.group),
            zeta = si(f.zeta, "", 2),
            time = si(t, "s", 3)
        ),
        None => t!(
            "quarter-car-member-unsettled",
            group = group_name(f.group),
            zeta = si(f.zeta, "", 2)
        ),
    }
}

/// Two sentences of a description, one after the other.
fn two_sentences(first: String, second: String) -> String {
    t!("quarter-car-two-sentences", first = first, second = second)
}

/// The settling-time plot in words.
pub(super) fn describe_settling(r: &Results) -> String {
    let band = pct(r.car.band_pct);
    let zeta = si(r.car.zeta(), "", 3);
    let curve = match r.optimum {
        Some(o) => t!(
            "quarter-car-settling-fastest",
            band = band,
            zeta = si(o.zeta, "", 3),
            time = si(o.settling_time, "s", 3)
        ),
        None => t!("quarter-car-settling-curve", band = band),
    };
    let design = match r.metrics.and_then(|m| m.settling_time) {
        Some(ts) => t!(
            "quarter-car-settling-design",
            zeta = zeta,
            time = si(ts, "s", 3)
        ),
        None => t!("quarter-car-settling-design-never", zeta = zeta),
    };
    two_sentences(curve, design)
}

/// The mass-sensitivity strip in words.
pub(super) fn describe_sensitivity(r: &Results, (m_lo, m_hi): (f64, f64)) -> String {
    let car = &r.car;
    let range = match r.mass_spread {
        Some(s) => t!(
            "quarter-car-sensitivity-range",
            low = si(m_lo, "kg", 3),
            high = si(m_hi, "kg", 3),
            variation = pct(car.dm_pct),
            min = si(s.min, "", 3),
            max = si(s.max, "", 3),
            nominal = si(s.nominal, "", 3),
            linear_min = si(s.linear_min, "", 3),
            linear_max = si(s.linear_max, "", 3)
        ),
        None => t!("quarter-car-sensitivity-undefined"),
    };
    match (r.optimum, r.mass_spread) {
        (Some(o), Some(s)) => {
            let z = o.zeta;
            let optimum = if s.min < z && z < s.max {
                t!("quarter-car-sensitivity-inside", zeta = si(z, "", 3))
            } else {
                t!("quarter-car-sensitivity-outside", zeta = si(z, "", 3))
            };
            two_sentences(range, optimum)
        }
        _ => range,
    }
}

/// The animated car in words.
pub(super) fn describe_schematic(x: f64, t: f64) -> String {
    t!(
        "quarter-car-schematic",
        time = si(t, "s", 3),
        displacement = si(x.abs(), "m", 3),
        side = if x > 0.0 { "above" } else { "below" }
    )
}
