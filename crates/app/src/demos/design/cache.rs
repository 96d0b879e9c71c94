//! The design demo's sweep cache key: the (k, c) maps and Pareto front are recomputed only
//! when the map's inputs change (moving the selected design or the metric reuses them; see
//! `progressive.rs`).

use super::{DesignSpace, Road};
use zeta_solver::design::map::nearest_index;
use zeta_solver::two_dof::TwoDofConfig;

/// Everything the sweep depends on; the map is recomputed only when this changes.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct SweepKey {
    /// Sprung mass \[kg\].
    pub(super) m: f64,
    /// Wheel mass \[kg\] and tyre stiffness \[N/m\] (comfort only).
    pub(super) mu: f64,
    pub(super) kt: f64,
    /// Settling band \[% of x₀\].
    pub(super) band: f64,
    pub(super) road: Road,
    /// Speed \[m/s\] (comfort only).
    pub(super) v: f64,
    /// Map edges \[N/m\] and \[N·s/m\].
    pub(super) k: (f64, f64),
    pub(super) c: (f64, f64),
    /// Cells per axis.
    pub(super) n: usize,
}

impl SweepKey {
    /// The two-DOF car of the comfort metric, with a placeholder suspension (each cell sets
    /// its own `k_s`, `c_s`); no tyre damping, as in the quarter-car-2dof demo.
    pub(super) fn car(&self) -> TwoDofConfig {
        TwoDofConfig {
            sprung_mass: self.m,
            unsprung_mass: self.mu,
            k_s: 1.0,
            c_s: 0.0,
            k_t: self.kt,
            c_t: 0.0,
        }
    }
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
