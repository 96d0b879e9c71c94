//! Logarithmic axes whose tick labels carry no rounding tails. Pure drawing: which decades
//! to show so that plotters' tick labels print cleanly.

use crate::figure::{sane_range, Axis, AxisScale};
use zeta_solver::grid::{exp10, log10};

/// Longest tick label accepted as free of rounding tails (`1e-11`, `10000.0`).
const CLEAN_TICK: usize = 8;

/// Length of the longest of plotters' tick labels for this log range (6 requested,
/// printed with `{:?}` as the renderer does): long ones carry rounding tails such as
/// `1.0000000000000002e-6`.
fn log_tick_width(lo: f64, hi: f64) -> usize {
    use plotters::coord::combinators::IntoLogRange;
    use plotters::coord::ranged1d::Ranged;
    let coord: plotters::coord::combinators::LogCoord<f64> = (lo..hi).log_scale().into();
    coord
        .key_points(6usize)
        .iter()
        .map(|v| format!("{v:?}").len())
        .max()
        .unwrap_or(0)
}

/// A logarithmic axis over whole decades, widened by up to three decades at either end
/// when that gives tick labels without rounding tails (the renderer prints ticks with
/// `{:?}`, and the rounding of `powf` differs between native code and wasm).
pub(super) fn log_axis(label: &str, unit: &'static str, range: (f64, f64)) -> Axis {
    let (lo, hi) = sane_range(range, AxisScale::Log);
    let (dlo, dhi) = (log10(lo).floor(), log10(hi).ceil());
    let mut best = (usize::MAX, 0.0, 0.0);
    'search: for widen in 0..=6 {
        for a in 0..=widen.min(3) {
            let b = widen - a;
            if b > 3 {
                continue;
            }
            let (a, b) = (f64::from(a), f64::from(b));
            let w = log_tick_width(exp10(dlo - a), exp10(dhi + b));
            if w < best.0 {
                best = (w, a, b);
            }
            if w <= CLEAN_TICK {
                break 'search;
            }
        }
    }
    Axis::log(label, unit, (exp10(dlo - best.1), exp10(dhi + best.2)))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn log_axes_get_clean_tick_labels() {
        for (lo, hi) in [
            (3e-13, 1e5),
            (1e-12, 1e0),
            (2e-9, 1e3),
            (1e-10, 1e4),
            (1e-6, 1e2),
        ] {
            let a = log_axis("y", "", (lo, hi));
            assert!(a.range.0 <= lo && a.range.1 >= hi);
            assert!(
                log_tick_width(a.range.0, a.range.1) <= CLEAN_TICK,
                "{lo:e}..{hi:e} -> {:?}",
                a.range
            );
        }
    }
}
