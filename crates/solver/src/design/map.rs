//! Reading a (k, c) map: its lowest cell, the axis cell nearest a value, and the colour
//! coordinates of its values on a linear or logarithmic colour bar.
//!
//! ```
//! use zeta_solver::design::map::{lowest, nearest_index, MapColours};
//! let values = [3.0, f64::NAN, 1.0, 2.0];
//! assert_eq!(lowest(&values), Some((2, 1.0)));
//! assert_eq!(nearest_index(&[0.5, 1.5, 2.5], 1.9), Some(1));
//! let c = MapColours::new(&[1.0, 10.0, 100.0], 1.0, true);
//! assert!(c.log && (c.scale.1 - 100f64.ln()).abs() < 1e-15);
//! ```

/// The index and value of the lowest finite entry of `values`; `None` when none is finite.
/// Ties go to the first.
pub fn lowest(values: &[f64]) -> Option<(usize, f64)> {
    values
        .iter()
        .copied()
        .enumerate()
        .filter(|(_, v)| v.is_finite())
        .min_by(|a, b| a.1.total_cmp(&b.1))
}

/// The index of the entry of `axis` nearest `x` (ties to the first); `None` for an empty
/// axis or NaN `x`.
pub fn nearest_index(axis: &[f64], x: f64) -> Option<usize> {
    if x.is_nan() {
        return None;
    }
    axis.iter()
        .enumerate()
        .min_by(|a, b| (a.1 - x).abs().total_cmp(&(b.1 - x).abs()))
        .map(|(i, _)| i)
}

/// A map's values as positions on its colour bar.
#[derive(Debug, Clone, PartialEq)]
pub struct MapColours {
    /// Lowest and highest finite shown value `factor·v` (`(0, 1)` when none is finite).
    pub range: (f64, f64),
    /// Whether the bar is logarithmic: asked for, and every finite shown value positive.
    pub log: bool,
    /// Colour coordinate of each value: `ln(factor·v)` on a logarithmic bar, else
    /// `factor·v` (non-finite where the value is).
    pub values: Vec<f64>,
    /// The bar's ends in the same coordinate: `range`, or its natural logarithms.
    pub scale: (f64, f64),
}

impl MapColours {
    /// Colour coordinates of `values` shown scaled by `factor` (e.g. 100 for a fraction
    /// shown in %), on a natural-log bar when `log` is asked for and the smallest finite
    /// shown value is positive (a metric spanning decades), else on a linear bar.
    pub fn new(values: &[f64], factor: f64, log: bool) -> Self {
        let (lo, hi) = values
            .iter()
            .map(|v| v * factor)
            .filter(|v| v.is_finite())
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| {
                (a.min(v), b.max(v))
            });
        let range = if lo <= hi { (lo, hi) } else { (0.0, 1.0) };
        let log = log && range.0 > 0.0;
        let coordinate = |v: f64| if log { v.ln() } else { v };
        Self {
            range,
            log,
            values: values.iter().map(|v| coordinate(v * factor)).collect(),
            scale: (coordinate(range.0), coordinate(range.1)),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lowest_skips_non_finite_values() {
        assert_eq!(lowest(&[f64::NAN, f64::INFINITY]), None);
        assert_eq!(lowest(&[2.0, -1.0, -1.0]), Some((1, -1.0)));
    }

    #[test]
    fn nearest_index_handles_edges() {
        assert_eq!(nearest_index(&[], 1.0), None);
        assert_eq!(nearest_index(&[1.0, 2.0], f64::NAN), None);
        assert_eq!(nearest_index(&[1.0, 2.0], -9.0), Some(0));
        assert_eq!(nearest_index(&[1.0, 2.0], 1.5), Some(0));
    }

    #[test]
    fn colours_fall_back_to_linear_for_non_positive_values() {
        let c = MapColours::new(&[0.0, 0.5, f64::NAN], 100.0, true);
        assert!(!c.log);
        assert_eq!(c.range, (0.0, 50.0));
        assert_eq!(c.values[1], 50.0);
        assert!(c.values[2].is_nan());
        let none = MapColours::new(&[f64::NAN], 1.0, true);
        assert_eq!((none.range, none.log), ((0.0, 1.0), false));
        let log = MapColours::new(&[0.1, 10.0], 1.0, true);
        assert!((log.values[0] - 0.1f64.ln()).abs() < 1e-15);
        assert!((log.scale.0 - 0.1f64.ln()).abs() < 1e-15);
    }
}
