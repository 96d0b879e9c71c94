//! The design demo's prose: summary, equation, metric names and the figures' text
//! alternatives.

use super::figures::ISO_ZETAS;
use super::{Metric, Results, SweepKey, P, X0};
use crate::figure::Figure;
use crate::format::{shortest, si, significant, significant_plain};
use crate::t;

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
    /// Unit and factor from the solver's value to the shown one.
    pub(super) fn describe(self) -> (&'static str, f64) {
        match self {
            Metric::SettlingTime => ("s", 1.0),
            Metric::PeakRebound => ("%", 100.0),
            Metric::AccelRms => ("m/s²", 1.0),
            Metric::PeakTransmissibility => ("", 1.0),
        }
    }

    /// The metric's selector value in the catalogues' messages.
    fn id(self) -> &'static str {
        match self {
            Metric::SettlingTime => "settling-time",
            Metric::PeakRebound => "peak-rebound",
            Metric::AccelRms => "accel-rms",
            Metric::PeakTransmissibility => "peak-transmissibility",
        }
    }

    /// The colour bar's label: the metric, relative to what, its unit and the scale.
    pub(super) fn bar_label(self, p: &P, log: bool) -> String {
        t!(
            "design-bar-label",
            metric = self.id(),
            band = pct(p.band),
            scale = scale(log)
        )
    }

    /// Short name for the plot title, saying what the value is relative to, with the
    /// range of the map's values.
    pub(super) fn title(self, band: f64, low: String, high: String) -> String {
        t!(
            "design-map-title",
            metric = self.id(),
            band = pct(band),
            low = low,
            high = high
        )
    }

    /// Whether the colours follow the logarithm (metrics spanning decades).
    pub(super) fn log_colour(self) -> bool {
        !matches!(self, Metric::PeakRebound)
    }
}

/// The selector value of a colour scale.
fn scale(log: bool) -> &'static str {
    if log {
        "log"
    } else {
        "linear"
    }
}

/// A percentage the user set (`5 %`), in the interface language's digits.
pub(super) fn pct(v: f64) -> String {
    format!("{} %", shortest(v))
}

/// The comfort metric's road: "an ISO 8608 class C road at 10 m/s".
pub(super) fn road_text(p: &P) -> String {
    t!(
        "design-road",
        class = p.road.letter(),
        speed = format!("{} m/s", shortest(p.v))
    )
}

/// An acceleration readout with its road: "1.01 m/s² (class C road, 10 m/s)".
pub(super) fn with_road(a: f64, key: &SweepKey) -> String {
    t!(
        "design-with-road",
        value = with_unit(a, "m/s²", 3),
        class = key.road.letter(),
        speed = format!("{} m/s", shortest(key.v))
    )
}

/// The grid-size readout: "100 × 100 = 10000", and the full grid still on the way while
/// the maps shown are the coarse stand-in.
pub(super) fn grid_size(r: &Results) -> String {
    let (n, cells) = (r.grid, r.grid * r.grid);
    match r.provisional {
        false => t!("design-grid-size", n = n, cells = cells),
        true => t!(
            "design-grid-size-provisional",
            n = n,
            cells = cells,
            full = r.key.n
        ),
    }
}

/// The Pareto plot's comfort axis (its road is in the caption and the map's).
pub(super) fn comfort_axis() -> String {
    t!("design-axis-comfort")
}

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
    // Three significant digits, then the shortest form of that (trailing zeros dropped),
    // in the interface language's digits.
    let trim = |v: f64| {
        let plain = significant_plain(v / scale, 3);
        plain.parse::<f64>().map_or(plain, shortest)
    };
    format!("{}–{} {}", trim(lo), trim(hi), full_unit)
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
    let (unit, _) = p.metric.describe();
    let shown = |v: f64| with_unit(v, unit, 3);
    let lowest = match lowest {
        Some((v, (bk, bc))) => t!(
            "design-map-lowest",
            value = shown(v),
            k = si(bk, "N/m", 3),
            c = si(bc, "N·s/m", 3)
        ),
        None => t!("design-map-no-cell"),
    };
    let selected = match (r.sel.zeta, r.sel.settling_time) {
        (Some(z), Some(t)) => t!(
            "design-map-selected-settles",
            zeta = significant(z, 2),
            band = pct(p.band),
            time = si(t, "s", 3)
        ),
        (Some(z), None) => t!("design-map-selected-unsettled", zeta = significant(z, 2)),
        _ => t!("design-map-no-selection"),
    };
    let [z1, z2, z3, z4, z5] = ISO_ZETAS.map(shortest);
    t!(
        "design-describe-map",
        metric = p.metric.id(),
        x0 = si(X0, "m", 2),
        band = pct(p.band),
        wheel = format!("{} kg", shortest(p.mu)),
        tyre = format!("{} kN/m", shortest(p.kt / 1e3)),
        road = road_text(p),
        k_span = span_text(key.k.0, key.k.1, "N/m"),
        c_span = span_text(key.c.0, key.c.1, "N·s/m"),
        grid = r.grid,
        mass = si(key.m, "kg", 3),
        lowest = lowest,
        selected = selected,
        outside = if p.selected_inside() { "no" } else { "yes" },
        low = shown(range.0),
        high = shown(range.1),
        scale = scale(log),
        z1 = z1,
        z2 = z2,
        z3 = z3,
        z4 = z4,
        z5 = z5
    )
}

/// The Pareto front in words, from its points `(settling time, a_w)` in front order.
pub(super) fn describe_pareto(front: &[(f64, f64)], selected: Option<(f64, f64)>, p: &P) -> String {
    let band = pct(p.band);
    let accel = |a: f64| with_unit(a, "m/s²", 3);
    match (front.first(), front.last()) {
        (Some(a), Some(b)) => t!(
            "design-describe-pareto",
            count = front.len(),
            band = band.clone(),
            fast_time = si(a.0, "s", 3),
            fast_accel = accel(a.1),
            smooth_time = si(b.0, "s", 3),
            smooth_accel = accel(b.1),
            selected = match selected {
                Some((t, a)) => t!(
                    "design-pareto-selected",
                    band = band,
                    time = si(t, "s", 3),
                    accel = accel(a)
                ),
                None => t!("design-pareto-selected-unsettled"),
            },
            road = road_text(p)
        ),
        _ => t!("design-pareto-empty"),
    }
}

/// The selected design's response in words, beside the fastest design on the grid.
pub(super) fn describe_response(p: &P, r: &Results) -> String {
    let fastest = r
        .fastest
        .as_ref()
        .and_then(|&((k, c), _, ts)| ts.map(|tb| (k, c, tb)));
    match (r.sel.zeta, r.sel.settling_time, r.sel.overshoot) {
        (Some(z), Some(t), Some(o)) => {
            let (zeta, x0, rebound) = (significant(z, 3), si(X0, "m", 2), si(o, "%", 3));
            let (band, time) = (pct(p.band), si(t, "s", 3));
            match fastest {
                Some((k, c, tb)) => t!(
                    "design-describe-response-fastest",
                    zeta = zeta,
                    x0 = x0,
                    rebound = rebound,
                    band = band,
                    time = time,
                    k = si(k, "N/m", 3),
                    c = si(c, "N·s/m", 3),
                    fastest_time = si(tb, "s", 3)
                ),
                None => t!(
                    "design-describe-response",
                    zeta = zeta,
                    x0 = x0,
                    rebound = rebound,
                    band = band,
                    time = time
                ),
            }
        }
        _ => t!("design-response-unsettled"),
    }
}

/// A figure drawn from the coarse sweep while the full one runs, marked as provisional in
/// its description (its title is left as it is: the map's already fills a phone's width).
pub(super) fn provisional(mut fig: Figure, r: &Results) -> Figure {
    fig.description = t!(
        "design-provisional",
        coarse = r.grid,
        full = r.key.n,
        description = std::mem::take(&mut fig.description)
    );
    fig
}
