//! The design demo's prose: summary, equation, metric names and the figures' text
//! alternatives.

use super::{Metric, Results, SweepKey, P, X0};
use crate::figure::Figure;
use crate::format::{si, significant};
use crate::spec::Preset;

pub(super) const SUMMARY: &str =
    "Every cell of the map is one quarter car (sprung mass m on spring k and \
                      damper c), coloured by the chosen metric: settling time and peak rebound \
                      of the free response released from rest at x₀ = 60 mm (not a step \
                      response: the band and the rebound are relative to x₀), peak \
                      transmissibility, or ride comfort as ISO 2631-1 measures it: a_w, the \
                      RMS body acceleration weighted by the W_k filter (how much a seated \
                      person feels each frequency), stationary on a random ISO 8608 road at \
                      speed V. For comfort each cell is the two-DOF car (this body on the \
                      wheel m_u and tyre k_t set below, from the Lyapunov equation): the same \
                      numbers as the quarter-car-2dof demo for the same car; the readouts \
                      also give the unweighted RMS. Dashed lines join designs of equal damping ratio \
                      ζ = c/(2√(km)). The Pareto front holds the designs no other beats in both \
                      comfort and settling. Click the map (or a point of the front) to choose a \
                      design; move the mass to see the whole map shift.";

pub(super) const EQUATION: &str = "<math display=\"block\"><mrow>\
<mi>m</mi><mover><mi>x</mi><mo>¨</mo></mover><mo>+</mo><mi>c</mi><mover><mi>x</mi><mo>˙</mo></mover>\
<mo>+</mo><mi>k</mi><mi>x</mi><mo>=</mo><mn>0</mn><mo>,</mo><mspace width=\"1em\"/>\
<mi>ζ</mi><mo>=</mo><mfrac><mi>c</mi><mrow><mn>2</mn><msqrt><mi>k</mi><mi>m</mi></msqrt></mrow></mfrac>\
</mrow></math>";

impl Metric {
    /// Name, unit and factor from the solver's value to the shown one.
    pub(super) fn describe(self) -> (&'static str, &'static str, f64) {
        match self {
            Metric::SettlingTime => ("settling time", "s", 1.0),
            Metric::PeakRebound => ("peak rebound", "%", 100.0),
            Metric::AccelRms => (
                "comfort a_w (W_k-weighted RMS body acceleration)",
                "m/s²",
                1.0,
            ),
            Metric::PeakTransmissibility => ("peak transmissibility |X/U|", "", 1.0),
        }
    }

    /// The unit of the colour bar: what one unit of the shown value is.
    fn bar_unit(self) -> &'static str {
        match self {
            Metric::SettlingTime => "s",
            Metric::PeakRebound => "% of x₀",
            Metric::AccelRms => "m/s²",
            Metric::PeakTransmissibility => "m/m",
        }
    }

    /// What the metric is relative to, after its name: the free response and its band
    /// (`band` in % of x₀), or the car and road of the comfort metric. Empty for peak
    /// transmissibility.
    fn relative_to(self, p: &P) -> String {
        let band = p.band;
        match self {
            Metric::SettlingTime => format!(
                " of the free response from x₀ = {} into ±{band} % of x₀,",
                si(X0, "m", 2)
            ),
            Metric::PeakRebound => format!(
                " of the free response from x₀ = {}, in % of x₀,",
                si(X0, "m", 2)
            ),
            Metric::AccelRms => format!(
                " of the two-DOF car (wheel {} kg, tyre {} kN/m), stationary on {},",
                p.mu,
                p.kt / 1e3,
                road_text(p)
            ),
            Metric::PeakTransmissibility => String::new(),
        }
    }

    /// The colour bar's label: the metric, relative to what, its unit and the scale.
    pub(super) fn bar_label(self, p: &P, log: bool) -> String {
        let band = p.band;
        let name = match self {
            // Short enough for the bar's height; the caption says the rest.
            Metric::AccelRms => COMFORT_AXIS,
            _ => self.describe().0,
        };
        let of = match self {
            Metric::SettlingTime => format!(" into ±{band} % of x₀, free response from rest"),
            Metric::PeakRebound => ", free response from rest".to_string(),
            Metric::AccelRms => String::new(),
            Metric::PeakTransmissibility => String::new(),
        };
        let scale = if log { ", logarithmic colours" } else { "" };
        format!("{name}{of} [{}]{scale}", self.bar_unit())
    }

    /// Short name for the plot title, saying what the value is relative to.
    pub(super) fn short(self, band: f64) -> String {
        match self {
            Metric::SettlingTime => format!("Settling into ±{band} % of x₀"),
            Metric::PeakRebound => "Peak rebound (% of x₀)".into(),
            Metric::AccelRms => "a_w (W_k)".into(),
            Metric::PeakTransmissibility => "Peak transmissibility |X/U|".into(),
        }
    }

    /// Whether the colours follow the logarithm (metrics spanning decades).
    pub(super) fn log_colour(self) -> bool {
        !matches!(self, Metric::PeakRebound)
    }
}

/// The comfort metric's road: "an ISO 8608 class C road at 10 m/s".
pub(super) fn road_text(p: &P) -> String {
    format!("an ISO 8608 class {} road at {} m/s", p.road.letter(), p.v)
}

/// An acceleration readout with its road: "1.01 m/s² (class C road, 10 m/s)".
pub(super) fn with_road(a: f64, key: &SweepKey) -> String {
    format!(
        "{} (class {} road, {} m/s)",
        with_unit(a, "m/s²", 3),
        key.road.letter(),
        key.v
    )
}

/// The Pareto plot's comfort axis (its road is in the caption and the map's).
pub(super) const COMFORT_AXIS: &str = "a_w (W_k-weighted RMS)";

/// `v` with its unit; accelerations stay in m/s² (no "mm/s²").
pub(super) fn with_unit(v: f64, unit: &str, sig: usize) -> String {
    if unit == "m/s²" {
        format!("{} m/s²", significant(v, sig))
    } else {
        si(v, unit, sig)
    }
}

/// `(lo, hi)` as "10–60 kN/m": both ends in the unit prefix of `hi`, trailing zeros dropped.
pub(super) fn span_text(lo: f64, hi: f64, unit: &str) -> String {
    let shown = si(hi, unit, 3);
    let full_unit = shown.split_once(' ').map_or("", |(_, u)| u).to_string();
    let prefix = full_unit.strip_suffix(unit).unwrap_or("");
    let scale = match prefix {
        "G" => 1e9,
        "M" => 1e6,
        "k" => 1e3,
        "m" => 1e-3,
        "µ" => 1e-6,
        _ => 1.0,
    };
    let trim = |v: f64| {
        let t = significant(v / scale, 3);
        if t.contains('.') {
            t.trim_end_matches('0').trim_end_matches('.').to_string()
        } else {
            t
        }
    };
    format!("{}–{} {}", trim(lo), trim(hi), full_unit)
}

fn capitalise(s: &str) -> String {
    let mut c = s.chars();
    match c.next() {
        Some(f) => f.to_uppercase().chain(c).collect(),
        None => String::new(),
    }
}

/// The map in words: what it shows, its lowest cell, the selected design and the colours.
pub(super) fn describe_map(
    p: &P,
    r: &Results,
    lowest: Option<(f64, (f64, f64))>,
    range: (f64, f64),
    log: bool,
) -> String {
    let key = r.key;
    let (name, unit, _) = p.metric.describe();
    let shown = |v: f64| with_unit(v, unit, 3);
    let best_text = match lowest {
        Some((v, (bk, bc))) => format!(
            "lowest {} at k = {}, c = {}",
            shown(v),
            si(bk, "N/m", 3),
            si(bc, "N·s/m", 3)
        ),
        None => String::from("no cell is defined"),
    };
    let selected_text = match (r.sel.zeta, r.sel.settling_time) {
        (Some(z), Some(t)) => format!(
            "selected design ζ = {} settles into ±{} % of x₀ in {}",
            significant(z, 2),
            p.band,
            si(t, "s", 3)
        ),
        (Some(z), None) => format!("selected design ζ = {} does not settle", significant(z, 2)),
        _ => "no valid design selected".to_string(),
    };
    let outside = if p.selected_inside() {
        ""
    } else {
        " (outside the map)"
    };
    format!(
        "{}{} over k {} and c {} ({} × {} grid, m = {}): {}; {}{}. Colour from dark purple \
         ({}) to yellow ({}){}. Dashed iso-ζ lines for ζ = 0.2, 0.3, 0.5, 0.7 and 1; × marks the lowest \
         cell, ● the selected design.",
        capitalise(name),
        p.metric.relative_to(p),
        span_text(key.k.0, key.k.1, "N/m"),
        span_text(key.c.0, key.c.1, "N·s/m"),
        r.grid,
        r.grid,
        si(key.m, "kg", 3),
        best_text,
        selected_text,
        outside,
        shown(range.0),
        shown(range.1),
        if log { " on a logarithmic scale" } else { "" },
    )
}

/// The Pareto front in words, from its points `(settling time, a_w)` in front order.
pub(super) fn describe_pareto(front: &[(f64, f64)], selected: Option<(f64, f64)>, p: &P) -> String {
    let band = p.band;
    let accel = |a: f64| with_unit(a, "m/s²", 3);
    let front_len = front.len();
    match (front.first(), front.last()) {
        (Some(a), Some(b)) => format!(
            "Pareto front of {} non-dominated designs: from the fastest, settling into ±{band} % \
             of x₀ in {} with a_w = {}, to the smoothest, {} with a_w = {}. {} Comfort a_w: \
             the W_k-weighted RMS body acceleration of the two-DOF car on {}.",
            front_len,
            si(a.0, "s", 3),
            accel(a.1),
            si(b.0, "s", 3),
            accel(b.1),
            match selected {
                Some((t, a)) => format!(
                    "The selected design settles into ±{band} % of x₀ in {} with a_w = {}.",
                    si(t, "s", 3),
                    accel(a)
                ),
                None => "The selected design has no settling time.".into(),
            },
            road_text(p),
        ),
        _ => "No design on the grid has both a settling time and a comfort value a_w.".into(),
    }
}

/// The selected design's response in words, beside the fastest design on the grid.
pub(super) fn describe_response(p: &P, r: &Results) -> String {
    let fastest = r.fastest.as_ref().and_then(|&((k, c), _, ts)| {
        ts.map(|tb| {
            format!(
                "; the fastest design on the grid (k = {}, c = {}) settles in {}",
                si(k, "N/m", 3),
                si(c, "N·s/m", 3),
                si(tb, "s", 3)
            )
        })
    });
    match (r.sel.zeta, r.sel.settling_time, r.sel.overshoot) {
        (Some(z), Some(t), Some(o)) => format!(
            "Selected design (ζ = {}) released from rest at x₀ = {} (a free response, not a \
             step): rebounds {} of x₀ and stays within ±{} % of x₀ after {}{}.",
            significant(z, 3),
            si(X0, "m", 2),
            si(o, "%", 3),
            p.band,
            si(t, "s", 3),
            fastest.unwrap_or_default()
        ),
        _ => "The selected design does not settle.".into(),
    }
}

/// A figure drawn from the coarse sweep while the full one runs, marked as provisional in
/// its description (its title is left as it is: the map's already fills a phone's width).
pub(super) fn provisional(mut fig: Figure, r: &Results) -> Figure {
    let (g, n) = (r.grid, r.key.n);
    fig.description = format!(
        "Provisional: from a coarse {g} × {g} grid while the {n} × {n} sweep runs. {}",
        fig.description
    );
    fig
}

/// The preset buttons.
pub(super) fn presets() -> Vec<Preset> {
    vec![
        Preset {
            label: "Settling-time map, 300 kg, ζ ≈ 0.37",
            values: vec![
                ("m", 300.0),
                ("metric", 0.0),
                ("k", 24_000.0),
                ("c", 2_000.0),
            ],
        },
        Preset {
            label: "Laden car 500 kg, same parts",
            values: vec![
                ("m", 500.0),
                ("metric", 0.0),
                ("k", 24_000.0),
                ("c", 2_000.0),
            ],
        },
        Preset {
            label: "Comfort map on a class C road",
            values: vec![("metric", 2.0), ("road", 2.0), ("m", 300.0)],
        },
        Preset {
            label: "Peak-rebound map, ζ = 0.7 design",
            values: vec![
                ("metric", 1.0),
                ("m", 300.0),
                ("k", 24_000.0),
                ("c", 3_760.0),
            ],
        },
        Preset {
            label: "Fine grid 160 × 160",
            values: vec![("n", 160.0), ("metric", 0.0)],
        },
    ]
}
