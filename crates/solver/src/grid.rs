//! Grids, interpolation and decibels: the small numeric tools every figure needs.
//!
//! ```
//! use zeta_solver::grid::{centres, decibels, interpolate, linspace};
//! assert_eq!(linspace(0.0, 1.0, 3), vec![0.0, 0.5, 1.0]);
//! assert_eq!(centres(&[0.0, 1.0, 3.0]), vec![0.5, 2.0]);
//! assert_eq!(interpolate(&[0.0, 2.0], &[0.0, 4.0], 0.5), Some(1.0));
//! assert!((decibels(10.0) - 20.0).abs() < 1e-12);
//! ```

pub use crate::free::linspace;
pub use crate::frf::{logspace, logspace_into};

/// `t_i = t_end·i/(n − 1)` for `i = 0 … n − 1`: `n` sample times from 0 to `t_end` \[s\]
/// inclusive, with both ends exact.
pub fn times(t_end: f64, n: usize) -> Vec<f64> {
    linspace(0.0, t_end, n)
}

/// Midpoints of consecutive `edges` (`n` edges give `n − 1` centres), e.g. the centre of
/// each cell of a map or each bin of a histogram.
pub fn centres(edges: &[f64]) -> Vec<f64> {
    edges.windows(2).map(|w| 0.5 * (w[0] + w[1])).collect()
}

/// The centre of cell `i` of `n` equal cells spanning `(lo, hi)`:
/// `lo + (i + ½)·(hi − lo)/n`.
pub fn cell_centre(lo: f64, hi: f64, n: usize, i: usize) -> f64 {
    lo + (i as f64 + 0.5) * (hi - lo) / n.max(1) as f64
}

/// Piecewise-linear interpolation of the samples `(xs[i], ys[i])` at `x`; `xs` ascending.
/// Outside `[xs[0], xs[last]]` the end value is held. `None` for empty or mismatched input.
pub fn interpolate(xs: &[f64], ys: &[f64], x: f64) -> Option<f64> {
    if xs.is_empty() || xs.len() != ys.len() || x.is_nan() {
        return None;
    }
    let last = xs.len() - 1;
    if x <= xs[0] {
        return Some(ys[0]);
    }
    if x >= xs[last] {
        return Some(ys[last]);
    }
    // First index with xs[i] > x; 1 ≤ i ≤ last here.
    let i = xs.partition_point(|&xi| xi <= x);
    let (x0, x1, y0, y1) = (xs[i - 1], xs[i], ys[i - 1], ys[i]);
    let span = x1 - x0;
    Some(if span > 0.0 {
        y0 + (y1 - y0) * (x - x0) / span
    } else {
        y1
    })
}

/// `y0 + (y1 − y0)·s`: the point a fraction `s` of the way from `y0` to `y1`.
pub fn lerp(y0: f64, y1: f64, s: f64) -> f64 {
    y0 + (y1 - y0) * s
}

/// A gain as decibels, `20·log₁₀|g|` \[dB\] (−∞ for `g = 0`).
pub fn decibels(gain: f64) -> f64 {
    20.0 * gain.abs().log10()
}

/// The gain of `db` decibels, `10^(db/20)`.
pub fn from_decibels(db: f64) -> f64 {
    10f64.powf(db / 20.0)
}

/// `10^x`: the value at a position `x` on a log₁₀ axis.
pub fn exp10(x: f64) -> f64 {
    10f64.powf(x)
}

/// `log₁₀ x`: the position of `x` on a log₁₀ axis (`x > 0`).
pub fn log10(x: f64) -> f64 {
    x.log10()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn interpolation_is_exact_at_samples_and_linear_between() {
        let xs = [0.0, 1.0, 3.0];
        let ys = [1.0, 3.0, -1.0];
        for (x, y) in xs.iter().zip(&ys) {
            assert_eq!(interpolate(&xs, &ys, *x), Some(*y));
        }
        assert_eq!(interpolate(&xs, &ys, 2.0), Some(1.0));
        assert_eq!(interpolate(&xs, &ys, -5.0), Some(1.0));
        assert_eq!(interpolate(&xs, &ys, 9.0), Some(-1.0));
        assert_eq!(interpolate(&xs, &ys[..2], 0.5), None);
        assert_eq!(interpolate(&[], &[], 0.5), None);
        assert_eq!(interpolate(&xs, &ys, f64::NAN), None);
    }

    #[test]
    fn cells_and_centres_agree() {
        let edges = linspace(2.0, 4.0, 5);
        let c = centres(&edges);
        for (i, ci) in c.iter().enumerate() {
            assert!((ci - cell_centre(2.0, 4.0, 4, i)).abs() < 1e-15);
        }
    }

    #[test]
    fn decibels_round_trip() {
        for g in [1e-3, 0.5, 1.0, 7.0, 1e4] {
            assert!((from_decibels(decibels(g)) / g - 1.0).abs() < 1e-14);
        }
        assert_eq!(decibels(1.0), 0.0);
        assert!((decibels(0.1) + 20.0).abs() < 1e-12);
        assert_eq!(decibels(0.0), f64::NEG_INFINITY);
    }
}
