//! The plot kit: what every demo's figures are built from, so that a figure function reads
//! as a short description of the figure. Named [`Ink`]s instead of palette indices, line
//! styles as constructors ([`crate::figure::LineStyle::solid`], `dashed`, `dotted`),
//! sampled curves ([`curve`], [`sampled`]), families of curves ([`family`]), fitted
//! ranges ([`fit_range`]) and log axes ([`crate::figure::Axis::log`]).
//!
//! ```
//! use zeta_app::figure::{Axis, Figure, LineStyle};
//! use zeta_app::plot::{curve, fit_range, Ink};
//! let x = curve((0.0, 1.0), 101, |t| t * t);
//! let fig = Figure::plot("t²", Axis::linear("time t", "s", (0.0, 1.0)),
//!     Axis::linear("y", "", fit_range(x.iter().map(|p| p.1), 0.05, 1e-6)))
//!     .with_line("y = t²", x, LineStyle::solid(Ink::Blue, 2.0));
//! assert!(fig.has_visible_data());
//! ```

// Drawing geometry (circles on the s-plane): not model maths.
#![allow(clippy::disallowed_methods)]

mod ink;

pub use ink::Ink;

use crate::figure::{finite_extent, padded};
use zeta_solver::grid::linspace;

/// `n` points `(x, f(x))` with `x` evenly spaced over `range`, both ends included.
pub fn curve(range: (f64, f64), n: usize, f: impl Fn(f64) -> f64) -> Vec<(f64, f64)> {
    linspace(range.0, range.1, n)
        .into_iter()
        .map(|x| (x, f(x)))
        .collect()
}

/// Points `(x, f(x))` at the given `xs` (e.g. a log-spaced frequency grid).
pub fn sampled(xs: &[f64], f: impl Fn(f64) -> f64) -> Vec<(f64, f64)> {
    xs.iter().map(|&x| (x, f(x))).collect()
}

/// The circle of radius `r` about the origin, as `n + 1` points (closed).
pub fn circle(r: f64, n: usize) -> Vec<(f64, f64)> {
    (0..=n)
        .map(|i| {
            let th = std::f64::consts::TAU * i as f64 / n.max(1) as f64;
            (r * th.cos(), r * th.sin())
        })
        .collect()
}

/// Pairs `xs[i]` with `ys[i]`.
pub fn zip(xs: &[f64], ys: &[f64]) -> Vec<(f64, f64)> {
    xs.iter().copied().zip(ys.iter().copied()).collect()
}

/// One member of a family of curves: the member, its ink and its points.
pub type Member<T> = (T, Ink, Vec<(f64, f64)>);

/// One curve per member of a family: `(member, points)` for each item, drawn with the
/// palette in order (e.g. a response for each of several damping ratios).
pub fn family<T: Copy>(members: &[T], points: impl Fn(T) -> Vec<(f64, f64)>) -> Vec<Member<T>> {
    members
        .iter()
        .enumerate()
        .map(|(i, &m)| (m, Ink::nth(i), points(m)))
        .collect()
}

/// A range that shows every finite value, padded by `pad` of its span on each side and at
/// least `±floor` wide around its centre; `(-floor, floor)` when there is no finite value.
pub fn fit_range(values: impl IntoIterator<Item = f64>, pad: f64, floor: f64) -> (f64, f64) {
    let (lo, hi) = finite_extent(values).unwrap_or((-floor, floor));
    let mid = 0.5 * (lo + hi);
    let (lo, hi) = (lo.min(mid - floor), hi.max(mid + floor));
    padded((lo, hi), pad)
}

/// Keeps every `k`-th point so that at most `max` remain (first and last always kept):
/// enough for a polyline on a canvas a few hundred pixels wide.
pub fn thin(points: &[(f64, f64)], max: usize) -> Vec<(f64, f64)> {
    if points.len() <= max || max < 2 {
        return points.to_vec();
    }
    let k = points.len().div_ceil(max - 1);
    let mut out: Vec<(f64, f64)> = points.iter().step_by(k).copied().collect();
    if let Some(&last) = points.last() {
        if out.last() != Some(&last) {
            out.push(last);
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn curves_hit_both_ends() {
        let c = curve((1.0, 3.0), 5, |x| 2.0 * x);
        assert_eq!(c.first(), Some(&(1.0, 2.0)));
        assert_eq!(c.last(), Some(&(3.0, 6.0)));
    }

    #[test]
    fn fitted_ranges_cover_the_data_and_the_floor() {
        let (lo, hi) = fit_range([1.0, 2.0, f64::NAN], 0.0, 0.1);
        assert_eq!((lo, hi), (1.0, 2.0));
        let (lo, hi) = fit_range([5.0], 0.0, 0.5);
        assert_eq!((lo, hi), (4.5, 5.5));
        assert_eq!(fit_range([f64::NAN], 0.0, 1.0), (-1.0, 1.0));
    }

    #[test]
    fn thinning_keeps_the_ends() {
        let pts: Vec<_> = (0..1000).map(|i| (i as f64, 0.0)).collect();
        let t = thin(&pts, 100);
        assert!(t.len() <= 101);
        assert_eq!(t.first(), pts.first());
        assert_eq!(t.last(), pts.last());
    }

    #[test]
    fn families_take_the_palette_in_order() {
        let f = family(&[0.1, 0.2], |z| vec![(0.0, z)]);
        assert_eq!(f[0].1, Ink::Blue);
        assert_eq!(f[1].1, Ink::Vermillion);
    }
}
