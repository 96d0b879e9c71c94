//! The resonance demo's frequency-response plots: |H(r)| (linear or dB) and ∠H(r) for a
//! family of damping ratios, the current one highlighted with its peak and half-power band.

use super::{text, Results, View, R_RANGE};
use crate::demos::digits::trimmed;
use crate::figure::{Axis, Figure, LineStyle, Marker, Series};
use crate::plot::{sampled, Ink};
use crate::t;
use std::f64::consts::FRAC_1_SQRT_2;
use zeta_solver::frf;
use zeta_solver::grid::decibels;

pub(super) const MAGNITUDE_TITLE: &str = "Amplification |H(r)|";
pub(super) const PHASE_TITLE: &str = "Phase ∠H(r)";

/// The family of damping ratios drawn thin behind the current one.
const FAMILY: [f64; 8] = [0.01, 0.05, 0.1, 0.2, 0.3, 0.5, 0.707, 1.0];
/// Members of the family labelled on the magnitude plot.
const LABELLED: [f64; 4] = [0.01, 0.05, 0.2, 0.707];
/// Fixed dB range: holds every curve of the family (and of the ζ slider) for r in R_RANGE.
const DB_RANGE: (f64, f64) = (-45.0, 40.0);
/// Phase axis \[°\].
const PHASE_RANGE: (f64, f64) = (-190.0, 10.0);

fn ratio_axis() -> Axis {
    Axis::log(t!("resonance-axis-ratio"), "", R_RANGE)
}

/// `|H|` in the current view (plain ratio or dB).
fn gain(r: f64, zeta: f64, view: View) -> f64 {
    match view {
        View::Linear => frf::magnitude(r, zeta),
        View::Db => frf::magnitude_db(r, zeta),
    }
}

/// A ratio as it is plotted in the current view.
fn level(g: f64, view: View) -> f64 {
    match view {
        View::Linear => g,
        View::Db => decibels(g).clamp(frf::DB_FLOOR, frf::DB_CEILING),
    }
}

/// The legend entry of the family of damping ratios.
fn family_label() -> String {
    t!(
        "resonance-family",
        from = trimmed(FAMILY[0], 3),
        to = trimmed(FAMILY[FAMILY.len() - 1], 3)
    )
}

/// The magnitude plot's y range and its top (where the family's labels stop and the
/// markers are pinned), in the view and for the current ζ's resonant peak.
fn magnitude_range(view: View, peak: Option<frf::Peak>) -> ((f64, f64), f64) {
    match view {
        View::Db => (DB_RANGE, DB_RANGE.1),
        View::Linear => {
            let top = (1.2 * peak.map_or(1.0, |p| p.gain)).max(2.5);
            ((0.0, top), top)
        }
    }
}

/// The family's curves on the frequency grid, kept between updates: the phases never
/// change, the magnitudes only with the view (so moving `zeta`, `r`, `wn` or `F0`
/// recomputes none of them). They run past the axes' top (the lightly damped peaks reach
/// 50); the renderer cuts them at whatever range the plot is drawn with, which a held drag
/// can keep wider than this ζ's own.
#[derive(Debug, Clone, Default)]
pub(super) struct Family {
    /// View of `magnitude`.
    key: Option<View>,
    /// |H(r)| per member of [`FAMILY`].
    magnitude: Vec<Vec<(f64, f64)>>,
    /// ∠H(r) \[°\] per member of [`FAMILY`].
    phase: Vec<Vec<(f64, f64)>>,
}

impl Family {
    /// Brings the curves up to date for this view.
    pub(super) fn update(&mut self, grid: &[f64], view: View) {
        if self.key != Some(view) {
            self.key = Some(view);
            self.magnitude = FAMILY
                .iter()
                .map(|&zf| sampled(grid, |r| gain(r, zf, view)))
                .collect();
        }
        if self.phase.is_empty() {
            self.phase = FAMILY.iter().map(|&zf| degrees(grid, zf)).collect();
        }
    }
}

/// ∠H(r) in degrees on the grid.
fn degrees(grid: &[f64], zeta: f64) -> Vec<(f64, f64)> {
    sampled(grid, |r| frf::phase(r, zeta).to_degrees())
}

/// |H(r)| for the family and the current ζ, with the peak, the half-power band and the drive.
pub(super) fn magnitude(res: &Results, grid: &[f64], family: &Family) -> Figure {
    let (z, view) = (res.p.zeta, res.p.view);
    let top_gain = res.peak.map_or(1.0, |p| p.gain);
    let (y_range, top) = magnitude_range(view, res.peak);
    let mut series = Vec::with_capacity(FAMILY.len() + 4);
    let mut markers = Vec::new();
    for (i, (&zf, pts)) in FAMILY.iter().zip(&family.magnitude).enumerate() {
        let pts = pts.clone();
        let label = if i == 0 {
            family_label()
        } else {
            String::new()
        };
        series.push(Series::new(label, pts, LineStyle::dotted(Ink::Black, 1.2)));
        if LABELLED.contains(&zf) {
            // Beside the peaks, level with |H(1)| = 1/(2ζ); in the linear view only where
            // the curves are far enough apart to tell which label is which.
            let at = (1.3, gain(1.0, zf, view));
            let floor = match view {
                View::Db => y_range.0,
                View::Linear => 0.12 * top,
            };
            if at.1 < 0.93 * top && at.1 > floor {
                markers.push(Marker::text(
                    format!("ζ = {}", trimmed(zf, 3)),
                    at,
                    Ink::Black,
                ));
            }
        }
    }
    // The half-power level |H|max/√2 between its crossings (from r_min if there is no lower
    // one); without a peak, the −3 dB level of the static gain.
    let mut band_text = String::new();
    if let Some(h) = frf::half_power_points(z) {
        let lvl = level(top_gain * FRAC_1_SQRT_2, view);
        let lo = h.lower.unwrap_or(R_RANGE.0).max(R_RANGE.0);
        let hi = h.upper.min(R_RANGE.1);
        let width = frf::half_power_width(z);
        let has_peak = res.peak.is_some();
        series.push(Series::new(
            text::band_legend(&h, width, has_peak),
            vec![(lo, lvl), (hi, lvl)],
            LineStyle::dashed(Ink::Purple, 2.0),
        ));
        for r in h.lower.into_iter().chain([h.upper]) {
            markers.push(Marker::cross("", (r, lvl), Ink::Purple));
        }
        band_text = text::describe_band(&h, width, has_peak);
    }
    let cur = sampled(grid, |r| gain(r, z, view));
    series.push(Series::new(
        t!("resonance-current", zeta = trimmed(z, 3)),
        cur,
        LineStyle::solid(Ink::Blue, 3.0),
    ));
    let drive = res.p.r;
    series.push(Series::new(
        t!("resonance-drive", ratio = trimmed(drive, 3)),
        vec![(drive, y_range.0), (drive, y_range.1)],
        LineStyle::dashed(Ink::Vermillion, 1.5),
    ));
    markers.push(Marker::dot(
        "",
        (drive, gain(drive, z, view).min(top)),
        Ink::Vermillion,
    ));
    if let Some(p) = res.peak {
        markers.push(Marker::cross(
            t!("resonance-peak"),
            (p.ratio.max(R_RANGE.0), level(p.gain, view).min(top)),
            Ink::Green,
        ));
    }
    let (title, y) = match view {
        View::Db => (
            t!("resonance-plot-magnitude-db"),
            Axis::linear(t!("resonance-axis-magnitude-db"), "dB", y_range),
        ),
        View::Linear => (
            t!("resonance-plot-magnitude"),
            Axis::linear(t!("resonance-axis-amplification"), "", y_range),
        ),
    };
    Figure {
        series,
        backdrop: FAMILY.len(),
        markers,
        ..Figure::plot(title, ratio_axis(), y)
    }
    .described(text::describe_magnitude(res, &band_text))
}

/// ∠H(r) in degrees for the family and the current ζ, with the drive.
pub(super) fn phase(res: &Results, grid: &[f64], family: &Family) -> Figure {
    let z = res.p.zeta;
    let mut fig = Figure::plot(
        t!("resonance-plot-phase"),
        ratio_axis(),
        Axis::linear(t!("resonance-axis-phase"), "°", PHASE_RANGE),
    );
    for (i, pts) in family.phase.iter().enumerate() {
        let label = if i == 0 {
            family_label()
        } else {
            String::new()
        };
        fig = fig.with_line(label, pts.clone(), LineStyle::dotted(Ink::Black, 1.2));
    }
    let fig = fig.with_backdrop();
    let drive = res.p.r;
    let ph = frf::phase(drive, z);
    fig.with_line(
        t!("resonance-current", zeta = trimmed(z, 3)),
        degrees(grid, z),
        LineStyle::solid(Ink::Blue, 3.0),
    )
    .with_line(
        t!("resonance-drive", ratio = trimmed(drive, 3)),
        vec![(drive, PHASE_RANGE.0), (drive, PHASE_RANGE.1)],
        LineStyle::dashed(Ink::Vermillion, 1.5),
    )
    .with_marker(Marker::dot("", (drive, ph.to_degrees()), Ink::Vermillion))
    .with_marker(Marker::cross(
        t!("resonance-quadrature"),
        (1.0, -90.0),
        Ink::Green,
    ))
    .described(text::describe_phase(res, ph))
}
