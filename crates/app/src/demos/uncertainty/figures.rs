//! The tolerance demo's figures: the band of free responses at the ends of the ζ range, and
//! the Monte Carlo histograms with the spec and the 5th/95th percentiles marked.

use super::{text, HistOf, Results, System, P};
use crate::figure::{finite_extent, padded, Axis, Figure, LineStyle, Marker};
use crate::plot::Ink;
use crate::t;
use zeta_solver::design::monte_carlo::{histogram_into, McSamples};
use zeta_solver::grid::linspace;
use zeta_solver::metrics::SettlingBand;
use zeta_solver::FreeResponse;

pub(super) const BAND_TITLE: &str = "Band of free responses over the tolerance";
pub(super) const ZETA_HIST_TITLE: &str = "Monte Carlo: damping ratio ζ";

/// Samples per response curve.
const SAMPLES: usize = 500;
/// Histogram bins.
const BINS: usize = 40;

/// Free responses from rest at the lowest-ζ end, nominal and highest-ζ end, with the 5 %
/// settling band and a cross where each settles.
pub(super) fn band(p: &P, r: &Results) -> Figure {
    let ranges = &r.ranges;
    let x0 = ranges.x0;
    let (y_name, y_unit) = match p.system {
        System::Suspension => (t!("axis-displacement"), "m"),
        System::Rlc => (t!("uncertainty-axis-capacitor-voltage"), "V"),
    };
    let longest = ranges
        .band
        .iter()
        .filter_map(|m| m.settling_time)
        .fold(0.0f64, f64::max);
    let wn = ranges.band[1]
        .sys
        .and_then(|s| s.natural_frequency())
        .unwrap_or(1.0);
    let t_end = if longest > 0.0 {
        (1.3 * longest).min(200.0 / wn)
    } else {
        4.0 * std::f64::consts::TAU / wn
    };
    let styles = [
        LineStyle::dashed(Ink::Vermillion, 2.0),
        LineStyle::solid(Ink::Blue, 2.5),
        LineStyle::dotted(Ink::Green, 2.5),
    ];
    let h = SettlingBand::FREE_DEFAULT.fraction() * x0;
    let guide = LineStyle::dotted(Ink::Black, 1.2);
    let mut fig = Figure::plot(
        t!("uncertainty-plot-band"),
        Axis::linear(t!("axis-time"), "s", (0.0, t_end)),
        Axis::linear(y_name.clone(), y_unit, (0.0, 1.0)),
    )
    .with_line(
        t!("uncertainty-settling-band"),
        vec![(0.0, h), (t_end, h)],
        guide,
    )
    .with_line("", vec![(0.0, -h), (t_end, -h)], guide);
    for (member, style) in ranges.band.iter().zip(styles) {
        let Some(sys) = member.sys else { continue };
        let resp = FreeResponse::new(sys, x0, 0.0);
        fig = fig.with_line(
            text::band_label(member),
            resp.trace((0.0, t_end), SAMPLES),
            style,
        );
        if let Some(t) = member.settling_time.filter(|&t| t <= t_end) {
            // Where each curve enters the band for good (colours match the curves; the
            // times are in the caption).
            fig = fig.with_marker(Marker::cross("", (t, resp.displacement(t)), style.ink));
        }
    }
    let ys = fig.series.iter().flat_map(|s| s.points.iter().map(|p| p.1));
    let (lo, hi) = padded(finite_extent(ys).unwrap_or((-x0, x0)), 0.08);
    // Headroom for the legend box.
    fig.y = Axis::linear(y_name, y_unit, (lo, hi + 0.3 * (hi - lo)));
    fig.with_origin_lines()
        .described(text::describe_band(p, ranges))
}

/// A histogram of `h` over the draws, with the spec window (for ζ and settling time) and
/// the 5th/95th percentiles `pct` marked.
pub(super) fn histogram(
    p: &P,
    samples: &McSamples,
    h: HistOf,
    pct: [f64; 2],
    yield_pct: f64,
    title: String,
) -> Figure {
    let (name, unit) = h.label();
    let mut counts = Vec::with_capacity(BINS);
    let range = histogram_into(h.data(samples), BINS, None, &mut counts);
    let mut xs: Vec<f64> = Vec::with_capacity(6);
    let mut bars = Vec::with_capacity(2 * BINS + 2);
    let mut top = 1.0f64;
    if let Some((lo, hi)) = range {
        let edges = linspace(lo, hi, BINS + 1);
        bars.push((lo, 0.0));
        for (w, &c) in edges.windows(2).zip(&counts) {
            bars.push((w[0], c as f64));
            bars.push((w[1], c as f64));
        }
        bars.push((hi, 0.0));
        top = counts.iter().copied().max().unwrap_or(1).max(1) as f64;
        xs.extend([lo, hi]);
    }
    // Headroom above the bars for the legend box.
    let ymax = top * 1.5;
    let vline = |x: f64| vec![(x, 0.0), (x, ymax)];
    let spec_lines: Vec<f64> = match h {
        HistOf::Zeta => {
            let (lo, hi) = p.zeta_window();
            vec![lo, hi]
        }
        HistOf::SettlingTime => vec![p.ts_max],
        _ => Vec::new(),
    };
    xs.extend(&spec_lines);
    let xr = match range {
        Some(_) => padded(finite_extent(xs).unwrap_or((0.0, 1.0)), 0.06),
        None => (0.0, 1.0),
    };
    let mut fig = Figure::plot(
        title,
        Axis::linear(name, unit, xr),
        Axis::linear(t!("uncertainty-axis-draws"), "", (0.0, ymax)),
    );
    if range.is_some() {
        fig = fig.with_line(
            t!("uncertainty-series-bins", bins = BINS),
            bars,
            LineStyle::solid(Ink::Blue, 2.0),
        );
    } else {
        fig = fig.with_marker(Marker::text(
            t!("uncertainty-no-finite-values"),
            (0.5, 0.5),
            Ink::Black,
        ));
    }
    for (j, &x) in spec_lines.iter().enumerate() {
        let label = if j == 0 {
            t!("uncertainty-spec-limit")
        } else {
            String::new()
        };
        fig = fig.with_line(label, vline(x), LineStyle::dashed(Ink::Vermillion, 2.0));
    }
    for (j, &x) in pct.iter().enumerate() {
        if x.is_finite() {
            let label = if j == 0 {
                t!("uncertainty-percentiles")
            } else {
                String::new()
            };
            fig = fig.with_line(label, vline(x), LineStyle::dotted(Ink::Green, 2.0));
        }
    }
    let draws = samples.zeta.len();
    fig.described(text::describe_histogram(p, h, draws, range, pct, yield_pct))
}
