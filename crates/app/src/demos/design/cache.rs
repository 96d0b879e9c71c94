//! The design demo's sweep cache: the (k, c) maps and Pareto front, recomputed only when the
//! map's inputs change (moving the selected design or the metric reuses them).

use super::{DesignSpace, Road, Stopwatch};
use zeta_solver::design::map::nearest_index;
use zeta_solver::design::pareto::pareto_front_into;
use zeta_solver::design::sweep::{sweep_kc_into, KcSweepConfig, RoadInput};
use zeta_solver::grid::cell_centre;
use zeta_solver::metrics::SettlingBand;

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
    pub(super) fn sweep_if_needed(&mut self, key: SweepKey, band: SettlingBand, road: RoadInput) {
        if self.key == Some(key) {
            return;
        }
        let watch = Stopwatch::start();
        let cells = |(lo, hi): (f64, f64)| (0..key.n).map(move |i| cell_centre(lo, hi, key.n, i));
        self.k_axis.clear();
        self.k_axis.extend(cells(key.k));
        self.c_axis.clear();
        self.c_axis.extend(cells(key.c));
        let cfg = KcSweepConfig {
            mass: key.m,
            band,
            road,
        };
        sweep_kc_into(&self.k_axis, &self.c_axis, &cfg, &mut self.maps);
        pareto_front_into(
            &self.maps.settling_time,
            &self.maps.accel_rms,
            &mut self.front,
        );
        self.sweep_ms = watch.elapsed_ms();
        self.sweeps += 1;
        self.key = Some(key);
    }

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
