//! The design demo's figures: the metric map with iso-ζ lines, the Pareto front of comfort
//! against settling, and the selected design's free response.

use super::{text, DesignSpace, Results, KILO, P, X0};
use crate::figure::{finite_extent, padded, Axis, Figure, Heatmap, LineStyle, Marker};
use crate::format::{shortest, si};
use crate::plot::Ink;
use crate::t;
use zeta_solver::design::map::{lowest, MapColours};
use zeta_solver::design::sweep::{iso_zeta_line_into, iso_zeta_span};
use zeta_solver::grid::linspace;
use zeta_solver::FreeResponse;

pub(super) const MAP_TITLE: &str = "Metric over (k, c) with iso-ζ lines";
pub(super) const PARETO_TITLE: &str = "Comfort vs settling: Pareto front";
pub(super) const RESPONSE_TITLE: &str = "Selected design: free response x(t)";

/// Samples of each response curve.
const SAMPLES: usize = 600;
/// Points of each iso-ζ line.
const ISO_POINTS: usize = 120;
/// Damping ratios of the iso-ζ lines.
pub(super) const ISO_ZETAS: [f64; 5] = [0.2, 0.3, 0.5, 0.7, 1.0];
/// Blank strips beyond the map (fractions of its span) that hold the iso-ζ labels.
const RIGHT_STRIP: f64 = 0.13;
const TOP_STRIP: f64 = 0.09;

/// The chosen metric as a heat map over (k, c) in kN/m × kN·s/m, with dashed iso-ζ lines
/// labelled in the blank strips, × on the lowest cell and ● on the selected design.
pub(super) fn map(d: &DesignSpace, p: &P, r: &Results) -> Figure {
    let key = r.key;
    let (unit, factor) = p.metric.describe();
    let raw = p.metric.values(d);
    let colours = MapColours::new(raw, factor, p.metric.log_colour());
    let ((k0, k1), (c0, c1)) = (key.k, key.c);
    let mut fig = Figure::plot(
        p.metric.title(
            p.band,
            text::with_unit(colours.range.0, unit, 3),
            text::with_unit(colours.range.1, unit, 3),
        ),
        Axis::linear(
            t!("design-axis-spring-rate"),
            "kN/m",
            (k0 / KILO, (k1 + RIGHT_STRIP * (k1 - k0)) / KILO),
        ),
        Axis::linear(
            t!("design-axis-damper-rate"),
            "kN·s/m",
            (c0 / KILO, (c1 + TOP_STRIP * (c1 - c0)) / KILO),
        ),
    );
    for (j, &zeta) in ISO_ZETAS.iter().enumerate() {
        let Some((ka, kb)) = iso_zeta_span(zeta, key.m, key.k, key.c) else {
            continue;
        };
        let ks = linspace(ka, kb, ISO_POINTS);
        let mut cs = vec![f64::NAN; ISO_POINTS];
        iso_zeta_line_into(zeta, key.m, &ks, &mut cs);
        let points: Vec<(f64, f64)> = ks
            .iter()
            .zip(&cs)
            .map(|(&k, &c)| (k / KILO, c.clamp(c0, c1) / KILO))
            .collect();
        let end = points.last().copied().unwrap_or((kb / KILO, c1 / KILO));
        // Label in the blank strip where the line leaves the map (alternating heights on the
        // top strip so neighbours do not collide).
        let (dk, dc) = ((k1 - k0) / KILO, (c1 - c0) / KILO);
        let at = if kb >= k1 * (1.0 - 1e-9) {
            (k1 / KILO + 0.012 * dk, end.1 + 0.03 * dc)
        } else {
            let lift = if j % 2 == 0 { 0.085 } else { 0.045 };
            (end.0 - 0.03 * dk, c1 / KILO + lift * dc)
        };
        // Labelled on the plot itself; a legend box would cover the map.
        fig = fig
            .with_line("", points, LineStyle::dashed(Ink::Vermillion, 2.0))
            .with_marker(Marker::text(
                format!("ζ={}", shortest(zeta)),
                at,
                Ink::Black,
            ));
    }
    let best = lowest(raw).and_then(|(i, v)| Some((v * factor, d.design_at(i)?)));
    if let Some((_, (bk, bc))) = best {
        // Explained in the caption: a label here collides with the iso-ζ labels (the best
        // cell is usually on an edge).
        fig = fig.with_marker(Marker::cross("", (bk / KILO, bc / KILO), Ink::Black));
    }
    if p.selected_inside() {
        fig = fig.with_marker(Marker::dot(
            t!("design-marker-selected"),
            (p.k / KILO, p.c / KILO),
            Ink::Black,
        ));
    }
    let description = text::describe_map(p, r, best, colours.range, colours.log);
    fig.heatmap = Some(Heatmap {
        nx: r.grid,
        ny: r.grid,
        values: colours.values,
        x_edges: (k0 / KILO, k1 / KILO),
        y_edges: (c0 / KILO, c1 / KILO),
        scale: colours.scale,
        log: colours.log,
        label: p.metric.bar_label(p, colours.log),
    });
    fig.described(description)
}

/// `(settling time, a_w)` of the front's designs, in front order.
fn front_points(d: &DesignSpace) -> Vec<(f64, f64)> {
    let comfort = d.comfort();
    comfort
        .front
        .iter()
        .filter_map(|&i| Some((*d.maps.settling_time.get(i)?, *comfort.accel_rms.get(i)?)))
        .collect()
}

/// Axes of the Pareto plot: the front's points `pts` and the selected design `sel_pt`,
/// padded, from zero up.
fn pareto_ranges(pts: &[(f64, f64)], sel_pt: Option<(f64, f64)>) -> ((f64, f64), (f64, f64)) {
    let xs = pts.iter().map(|p| p.0).chain(sel_pt.map(|p| p.0));
    let ys = pts.iter().map(|p| p.1).chain(sel_pt.map(|p| p.1));
    let xr = padded(finite_extent(xs).unwrap_or((0.0, 1.0)), 0.08);
    let yr = padded(finite_extent(ys).unwrap_or((0.0, 1.0)), 0.1);
    ((xr.0.max(0.0), xr.1), (yr.0.max(0.0), yr.1))
}

/// The Pareto front of RMS acceleration against settling time, with the designs of the
/// selected spring and every damper on the grid (how c alone trades one for the other).
pub(super) fn pareto(d: &DesignSpace, p: &P, r: &Results) -> Figure {
    let pts = front_points(d);
    let sel_pt = r.sel.settling_time.zip(r.sel.accel_rms);
    let (xr, yr) = pareto_ranges(&pts, sel_pt);
    // For picking on this plot (`DesignSpace::pick`).
    d.pareto_ranges.set((xr, yr));
    let mut fig = Figure::plot(
        t!("design-plot-pareto"),
        Axis::linear(
            t!("design-axis-settling-time", band = text::pct(p.band)),
            "s",
            xr,
        ),
        Axis::linear(text::comfort_axis(), "m/s²", yr),
    );
    if let Some((ik, kcol)) = d.column_near(p.k) {
        let (n, comfort) = (d.k_axis.len(), d.comfort());
        let inside = |(x, y): (f64, f64)| x >= xr.0 && x <= xr.1 && y >= yr.0 && y <= yr.1;
        let points = (0..d.c_axis.len())
            .map(|ic| {
                let i = ic * n + ik;
                let at = |v: &[f64]| v.get(i).copied().unwrap_or(f64::NAN);
                let pt = (at(&d.maps.settling_time), at(&comfort.accel_rms));
                if inside(pt) {
                    pt
                } else {
                    (f64::NAN, f64::NAN)
                }
            })
            .collect();
        fig = fig.with_line(
            t!("design-series-column", k = si(kcol, "N/m", 3)),
            points,
            LineStyle::dotted(Ink::Green, 2.0),
        );
    }
    let description = text::describe_pareto(&pts, sel_pt, p);
    fig = fig.with_line(
        t!("design-series-pareto-front"),
        pts,
        LineStyle::solid(Ink::Blue, 2.5),
    );
    if let Some(pt) = sel_pt {
        fig = fig.with_marker(Marker::dot(
            t!("design-marker-selected"),
            pt,
            Ink::Vermillion,
        ));
    }
    fig.described(description)
}

/// The selected design released from x₀, beside the fastest design on the grid, with the
/// settling band and the moment the selected design settles.
pub(super) fn response(p: &P, r: &Results) -> Figure {
    let fastest_ts = r.fastest.as_ref().and_then(|f| f.2);
    let longest = r
        .sel
        .settling_time
        .into_iter()
        .chain(fastest_ts)
        .fold(0.0f64, f64::max);
    let t_end = if longest > 0.0 {
        (1.4 * longest).clamp(0.3, 30.0)
    } else {
        4.0
    };
    let release = |sys| {
        let resp = FreeResponse::new(sys, X0, 0.0);
        resp.trace((0.0, t_end), SAMPLES)
    };
    let h = r.band.fraction() * X0;
    let band = LineStyle::dotted(Ink::Black, 1.2);
    let mut fig = Figure::plot(
        t!("design-plot-response"),
        Axis::linear(t!("axis-time"), "s", (0.0, t_end)),
        Axis::linear(t!("axis-displacement"), "m", (0.0, 1.0)),
    )
    .with_line(
        t!("design-series-band", band = text::pct(p.band)),
        vec![(0.0, h), (t_end, h)],
        band,
    )
    .with_line("", vec![(0.0, -h), (t_end, -h)], band);
    if let Some((_, sys, _)) = r.fastest {
        fig = fig.with_line(
            t!("design-series-fastest"),
            release(sys),
            LineStyle::dashed(Ink::Green, 2.0),
        );
    }
    if let Some(sys) = r.sel.sys {
        fig = fig.with_line(
            t!("design-series-selected"),
            release(sys),
            LineStyle::solid(Ink::Blue, 2.5),
        );
        if let Some(t) = r.sel.settling_time.filter(|&t| t <= t_end) {
            let x = FreeResponse::new(sys, X0, 0.0).displacement(t);
            fig = fig.with_marker(Marker::cross(
                t!("design-marker-settled"),
                (t, x),
                Ink::Vermillion,
            ));
        }
    }
    let ys = fig.series.iter().flat_map(|s| s.points.iter().map(|p| p.1));
    let (lo, hi) = padded(finite_extent(ys).unwrap_or((-X0, X0)), 0.08);
    // Headroom above the curves for the legend box.
    fig.y = Axis::linear(t!("axis-displacement"), "m", (lo, hi + 0.55 * (hi - lo)));
    fig.with_origin_lines()
        .described(text::describe_response(p, r))
}
