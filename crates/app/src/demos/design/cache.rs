//! The design demo's sweep cache key: the (k, c) maps and Pareto front are recomputed only
//! when the map's inputs change (moving the selected design or the metric reuses them; see
//! `progressive.rs`).

use super::{DesignSpace, Road};
use zeta_solver::design::map::nearest_index;

/// Everything the sweep depends on; the map is recomputed only when this changes.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct SweepKey {
    /// Sprung mass \[kg\].
    pub(super) m: f64,
    /// Settling band \[% of x₀\].
    pub(super) band: f64,
    pub(super) road: Road,
    /// Map edges \[N/m\] and \[N·s/m\].
    pub(super) k: (f64, f64),
    pub(super) c: (f64, f64),
    /// Cells per axis.
    pub(super) n: usize,
}

impl DesignSpace {
    /// `(k, c)` of grid cell `i`.
    pub(super) fn design_at(&self, i: usize) -> Option<(f64, f64)> {
        let n = self.k_axis.len().max(1);
        Some((*self.k_axis.get(i % n)?, *self.c_axis.get(i / n)?))
    }

    /// The grid column nearest spring rate `k`: its index and spring rate.
    pub(super) fn column_near(&self, k: f64) -> Option<(usize, f64)> {
        nearest_index(&self.k_axis, k).map(|i| (i, self.k_axis[i]))
    }
}
