//! The quarter-car demo's prose: summary, equation and the figures' text alternatives.

use super::{Member, Results};
use crate::format::si;
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

/// A percentage as typed on the slider: `5` → `"5 %"`, `2.5` → `"2.5 %"`.
pub(super) fn pct(v: f64) -> String {
    format!("{} %", (v * 100.0).round() / 100.0)
}

/// The legend entry of a family group.
pub(super) fn family_legend(group: &str) -> &'static str {
    match group {
        "comfort" => "comfort 0.3, 0.4",
        "performance" => "performance 0.65, 0.7",
        "critical" => "critical 1 (×)",
        _ => "overdamped 2 (●)",
    }
}

/// How often the body swings through equilibrium before it settles (the solver counts
/// crossings before the settling time; a later rebound inside the band is not counted).
fn crossings_text(m: &FreeMetrics) -> String {
    match (m.zero_crossings, m.rebound_time) {
        (0, None) => "does not cross equilibrium".to_string(),
        (0, Some(_)) => {
            "settles before crossing equilibrium (its rebound stays inside the band)".to_string()
        }
        (1, _) => "crosses equilibrium once before settling".to_string(),
        (n, _) => format!("crosses equilibrium {n} times before settling"),
    }
}

/// The response plot in words: this design, then the family.
pub(super) fn describe_response(r: &Results) -> String {
    let car = &r.car;
    let regime = car.sys.regime();
    let band = pct(car.band_pct);
    let now = match r.metrics {
        Some(m) => {
            let settle = m
                .settling_time
                .map(|t| {
                    format!(
                        "stays within ±{band} of x₀ around rest after {}",
                        si(t, "s", 3)
                    )
                })
                .unwrap_or_else(|| "does not settle".to_string());
            let rebound = match m.rebound_time {
                Some(t) => format!(
                    "peak rebound {} at {}",
                    si(100.0 * m.peak_rebound, "%", 3),
                    si(t, "s", 3)
                ),
                None => "no rebound".to_string(),
            };
            format!(
                "This design (ζ = {}, {}): {}, {}, {}.",
                si(car.zeta(), "", 3),
                regime.key(),
                crossings_text(&m),
                settle,
                rebound
            )
        }
        None if regime == Regime::Undamped => format!(
            "This design (ζ = 0, undamped): oscillates forever between ±{} at {}.",
            si(car.x0.abs(), "m", 3),
            si(car.sys.natural_frequency_hz().unwrap_or(0.0), "Hz", 3)
        ),
        None => format!("This design ({}): does not settle.", regime.key()),
    };
    let fam: Vec<String> = r.family.iter().map(describe_member).collect();
    format!(
        "{now} Preset family on this car, settling into ±{band} of x₀: {}.",
        fam.join("; ")
    )
}

fn describe_member(f: &Member) -> String {
    match f.settling {
        Some(t) => format!("{} ζ = {} in {}", f.group, si(f.zeta, "", 2), si(t, "s", 3)),
        None => format!("{} ζ = {} does not settle", f.group, si(f.zeta, "", 2)),
    }
}

/// The settling-time plot in words.
pub(super) fn describe_settling(r: &Results) -> String {
    let band = pct(r.car.band_pct);
    let zeta = r.car.zeta();
    let mut description = match r.optimum {
        Some(o) => format!(
            "Free-response settling time into ±{band} of x₀ against ζ for this car: fastest \
             at ζ = {} ({}), just past a jump; it jumps down each time a rebound drops inside the band.",
            si(o.zeta, "", 3),
            si(o.settling_time, "s", 3)
        ),
        None => format!("Free-response settling time into ±{band} of x₀ against ζ."),
    };
    description.push_str(&match r.metrics.and_then(|m| m.settling_time) {
        Some(ts) => format!(
            " This design, ζ = {}, settles in {}.",
            si(zeta, "", 3),
            si(ts, "s", 3)
        ),
        None => format!(" This design, ζ = {}, never settles.", si(zeta, "", 3)),
    });
    description
}

/// The mass-sensitivity strip in words.
pub(super) fn describe_sensitivity(r: &Results, (m_lo, m_hi): (f64, f64)) -> String {
    let car = &r.car;
    let mut description = match r.mass_spread {
        Some(s) => format!(
            "With the sprung mass between {} and {} (±{}) and the same damper and spring, ζ \
             ranges from {} to {} (nominal {}); the linear estimate is {} to {}.",
            si(m_lo, "kg", 3),
            si(m_hi, "kg", 3),
            pct(car.dm_pct),
            si(s.min, "", 3),
            si(s.max, "", 3),
            si(s.nominal, "", 3),
            si(s.linear_min, "", 3),
            si(s.linear_max, "", 3)
        ),
        None => "The damping-ratio range is undefined for this design.".to_string(),
    };
    if let (Some(o), Some(s)) = (r.optimum, r.mass_spread) {
        let z = o.zeta;
        description.push_str(&if s.min < z && z < s.max {
            format!(
                " The fastest-settling ζ = {} lies inside this range: loads that push ζ below \
                 it settle markedly later.",
                si(z, "", 3)
            )
        } else {
            format!(
                " The fastest-settling ζ = {} lies outside this range.",
                si(z, "", 3)
            )
        });
    }
    description
}

/// The animated car in words.
pub(super) fn describe_schematic(x: f64, t: f64) -> String {
    format!(
        "Quarter car at t = {}: the body is {} from rest ({}), road fixed.",
        si(t, "s", 3),
        si(x.abs(), "m", 3),
        if x > 0.0 { "above" } else { "below" }
    )
}
