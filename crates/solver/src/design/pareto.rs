//! Pareto (non-dominated) front of points with two objectives, both minimised — e.g. RMS
//! body acceleration against settling time.
//!
//! Point `p` dominates `q` when `p` is no worse in both objectives and strictly better in
//! one. The front is found in `O(n log n)`: sort by the first objective (ties by the second),
//! then sweep, keeping a point when its second objective is below every one seen before.
//! Points with a non-finite objective are skipped. Identical points do not dominate each
//! other, so duplicates of a front point are all on the front.
//!
//! ```
//! use zeta_solver::design::pareto::pareto_front;
//! let comfort = [3.0, 1.0, 2.0, 2.5, f64::NAN];
//! let settling = [1.0, 3.0, 2.0, 2.5, 0.0];
//! // (2.5, 2.5) is dominated by (2, 2); the NaN point is skipped.
//! assert_eq!(pareto_front(&comfort, &settling), vec![1, 2, 0]);
//! ```

use std::cmp::Ordering;

/// Indices of the non-dominated points of `(f1[i], f2[i])`, ordered along the front by
/// increasing `f1` (so decreasing `f2`). Only the first `min(f1.len(), f2.len())` points
/// are considered.
pub fn pareto_front(f1: &[f64], f2: &[f64]) -> Vec<usize> {
    let mut out = Vec::new();
    pareto_front_into(f1, f2, &mut out);
    out
}

/// As [`pareto_front`], writing into `out` (cleared first; its capacity is reused).
pub fn pareto_front_into(f1: &[f64], f2: &[f64], out: &mut Vec<usize>) {
    out.clear();
    let get = |v: &[f64], i: usize| v.get(i).copied().unwrap_or(f64::NAN);
    out.extend(
        f1.iter()
            .zip(f2)
            .enumerate()
            .filter(|(_, (a, b))| a.is_finite() && b.is_finite())
            .map(|(i, _)| i),
    );
    let cmp = |x: f64, y: f64| x.partial_cmp(&y).unwrap_or(Ordering::Equal);
    out.sort_unstable_by(|&i, &j| {
        cmp(get(f1, i), get(f1, j))
            .then(cmp(get(f2, i), get(f2, j)))
            .then(i.cmp(&j))
    });
    let mut best = f64::INFINITY;
    let mut last: Option<(f64, f64)> = None;
    out.retain(|&i| {
        let p = (get(f1, i), get(f2, i));
        let keep = p.1 < best || last == Some(p);
        if keep {
            best = p.1;
            last = Some(p);
        }
        keep
    });
}

/// The point of `front` (indices into `f1`, `f2`) nearest `(x, y)` when distances along
/// each objective are divided by `scale = (s1, s2)` (e.g. the plotted spans, so "nearest"
/// means nearest on screen): the index minimising `((f1 − x)/s1)² + ((f2 − y)/s2)²`.
/// Scales below 1e-12 count as 1e-12. `None` when no front point is finite.
pub fn nearest_on_front(
    front: &[usize],
    f1: &[f64],
    f2: &[f64],
    (x, y): (f64, f64),
    scale: (f64, f64),
) -> Option<usize> {
    let (s1, s2) = (scale.0.max(1e-12), scale.1.max(1e-12));
    front
        .iter()
        .filter_map(|&i| {
            let dx = (*f1.get(i)? - x) / s1;
            let dy = (*f2.get(i)? - y) / s2;
            let d = dx * dx + dy * dy;
            d.is_finite().then_some((i, d))
        })
        .min_by(|a, b| a.1.total_cmp(&b.1))
        .map(|(i, _)| i)
}

/// Whether `(a1, a2)` dominates `(b1, b2)` for minimised objectives.
pub fn dominates(a1: f64, a2: f64, b1: f64, b2: f64) -> bool {
    a1 <= b1 && a2 <= b2 && (a1 < b1 || a2 < b2)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn duplicates_and_ties_are_handled() {
        let f1 = [1.0, 1.0, 1.0, 2.0];
        let f2 = [2.0, 2.0, 3.0, 1.0];
        // The two (1, 2) are both on the front; (1, 3) is dominated by them.
        assert_eq!(pareto_front(&f1, &f2), vec![0, 1, 3]);
        assert!(pareto_front(&[], &[]).is_empty());
        assert_eq!(pareto_front(&[f64::INFINITY, 1.0], &[0.0, 1.0]), vec![1]);
    }
}
