//! One coordinate type for every axis, linear or logarithmic.
//!
//! plotters gives a linear axis (`RangedCoordf64`) and a log axis (`LogCoord` with its key
//! points) different types, so a chart over each pairing of them (lin/lin, log/lin, lin/log,
//! log/log) compiled every drawing function four times per backend. [`Scale`] is one type
//! for both: values stay data values everywhere (series, markers, heatmap edges, legend
//! placement), and only the mapping to pixels and the grid differ. It computes exactly what
//! plotters' types compute, so every pixel stays where it was.

use crate::figure::{Axis, AxisScale};
use plotters::coord::ranged1d::{DefaultFormatting, KeyPointHint, Ranged};
use plotters::coord::types::RangedCoordf64;
use std::ops::Range;

/// A chart axis over data values: linear, or logarithmic with the labelled ticks of
/// [`log_ticks`](super::log_ticks) and a minor grid.
#[derive(Clone)]
pub(super) struct Scale {
    /// The data range shown.
    range: Range<f64>,
    /// Maps to pixels: over the data range (linear), or over the natural logarithms of
    /// the range (log, as plotters' `LogCoord`).
    pixels: RangedCoordf64,
    /// A log axis: its labelled ticks, its minor grid values (data values), and whether
    /// its range is negative (mapped mirrored, as `LogCoord` does).
    log: Option<LogTicks>,
}

#[derive(Clone)]
struct LogTicks {
    bold: Vec<f64>,
    light: Vec<f64>,
    negative: bool,
}

impl Scale {
    /// A linear axis over `lo..hi`.
    pub(super) fn linear(lo: f64, hi: f64) -> Self {
        Self {
            range: lo..hi,
            pixels: (lo..hi).into(),
            log: None,
        }
    }

    /// The axis of `axis` (its range and scale).
    pub(super) fn of(axis: &Axis) -> Self {
        let (lo, hi) = axis.range;
        match axis.scale {
            AxisScale::Linear => Self::linear(lo, hi),
            AxisScale::Log => Self::log(lo, hi),
        }
    }

    /// A log axis over `lo..hi` with the ticks of [`super::ticks::log_axis_ticks`]; the
    /// pixel mapping of plotters' `(lo..hi).log_scale()`.
    fn log(lo: f64, hi: f64) -> Self {
        let (bold, light) = super::ticks::log_axis_ticks(lo, hi);
        let (mut start, mut end) = (lo, hi);
        let negative = start < 0.0 || end < 0.0;
        if negative {
            (start, end) = (-start, -end);
        }
        if start < end {
            if start == 0.0 {
                start = start.max(end * 1e-5);
            }
        } else if end == 0.0 {
            end = end.max(start * 1e-5);
        }
        Self {
            range: lo..hi,
            pixels: (start.ln()..end.ln()).into(),
            log: Some(LogTicks {
                bold,
                light,
                negative,
            }),
        }
    }
}

impl Ranged for Scale {
    type FormatOption = DefaultFormatting;
    type ValueType = f64;

    fn map(&self, value: &f64, limit: (i32, i32)) -> i32 {
        match &self.log {
            None => self.pixels.map(value, limit),
            Some(t) => {
                let v = if t.negative { -*value } else { *value };
                self.pixels.map(&v.ln(), limit)
            }
        }
    }

    fn key_points<Hint: KeyPointHint>(&self, hint: Hint) -> Vec<f64> {
        match &self.log {
            None => self.pixels.key_points(hint),
            Some(t) if hint.weight().allow_light_points() => t.light.clone(),
            // A first module labels them all: thinning costs its download a quarter of a
            // KB it does not have, and the full module draws every plot again as it takes
            // over, within seconds (a short log axis is a phone's, rarely its first plot).
            // Only an axis asked for fewer labels than usual is thinned (a short plot's y
            // axis, see `chart::y_label_count`): every other keeps all of `log_ticks`.
            Some(t) if cfg!(feature = "first") || hint.max_num_points() >= super::chart::LABELS => {
                t.bold.clone()
            }
            Some(t) => super::ticks::thinned(&t.bold, hint.max_num_points()),
        }
    }

    fn range(&self) -> Range<f64> {
        self.range.clone()
    }
}
