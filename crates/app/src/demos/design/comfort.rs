//! The comfort map — `a_w`, the `W_k`-weighted RMS body acceleration of the two-DOF car on
//! the ISO 8608 road, per cell — and the Pareto front of comfort against settling time.
//!
//! The costliest part of a sweep (a block Lyapunov solve per cell, about six times the
//! one-DOF metrics), and needed only by the Pareto plot, the comfort map and a pick on the
//! Pareto plot. So a coarse sweep on a page leaves it to the first of those that asks
//! ([`DesignSpace::comfort`]): while a map input is dragged with only the settling map in
//! view (a phone), no event computes it. A full sweep computes it with the other maps.

use super::cache::SweepKey;
use super::DesignSpace;
use zeta_solver::design::pareto::pareto_front_into;
use zeta_solver::ride::Ride;

/// The comfort map of a sweep's cells and the front over it.
#[derive(Debug, Clone, Default)]
pub(super) struct Comfort {
    /// `a_w` per cell \[m/s²\], laid out as the sweep's maps (`row·n_k + col`); NaN where
    /// the car is invalid or never settles.
    pub(super) accel_rms: Vec<f64>,
    /// Cell indices on the Pareto front of (settling time, `a_w`), by increasing settling
    /// time.
    pub(super) front: Vec<usize>,
}

impl Comfort {
    /// The comfort map `accel_rms` and its front against the settling times `settling`.
    pub(super) fn new(accel_rms: Vec<f64>, settling: &[f64]) -> Self {
        let mut front = Vec::new();
        pareto_front_into(settling, &accel_rms, &mut front);
        Self { accel_rms, front }
    }
}

/// Rows `rows` of the comfort map of the car of `key` over `k_axis × c_axis`, written into
/// `out` (`row·k_axis.len() + col`).
pub(super) fn comfort_rows(
    ride: &Ride,
    key: &SweepKey,
    (k_axis, c_axis): (&[f64], &[f64]),
    rows: std::ops::Range<usize>,
    out: &mut [f64],
) {
    ride.weighted_rows(
        key.car(),
        key.road.0,
        key.v,
        (k_axis, c_axis),
        rows,
        out,
        &mut [],
    );
}

impl DesignSpace {
    /// The comfort map and front of the cells shown, computed on the first call after a
    /// sweep that left them out (empty before any sweep).
    pub(super) fn comfort(&self) -> &Comfort {
        self.comfort.get_or_init(|| {
            let Some(key) = self.key else {
                return Comfort::default();
            };
            let mut accel_rms = vec![f64::NAN; self.k_axis.len() * self.c_axis.len()];
            let axes = (&self.k_axis[..], &self.c_axis[..]);
            comfort_rows(
                &Ride::w_k(),
                &key,
                axes,
                0..self.c_axis.len(),
                &mut accel_rms,
            );
            Comfort::new(accel_rms, &self.maps.settling_time)
        })
    }
}
