//! `design`: the (k, c) design space of a quarter car. A heat map of one metric (settling
//! time, peak rebound, ride comfort on a random road, peak transmissibility) over a grid of
//! spring and damper rates, recomputed live as the sprung mass moves, with iso-ζ lines, the
//! Pareto front of comfort against settling, and the chosen design's response.
//!
//! Comfort is ISO 2631-1's `a_w`: the RMS body acceleration weighted by `W_k`, stationary on
//! the ISO 8608 road, of the two-DOF car (this body on the wheel and tyre set here) from its
//! Lyapunov equation — the same numbers as the `quarter-car-2dof` demo for the same car:
//! the selected design's readouts call the same [`zeta_solver::ride::stationary`], the map
//! cells [`zeta_solver::ride::Ride::stationary`]'s block solves of that equation (equal to rounding).
//!
//! `declaration.rs` declares the demo (parameters, readouts, plots and presets as data); this
//! file holds its model step (solver calls only) and the state kept between steps;
//! `cache.rs` keys the sweep and `progressive.rs` runs it (coarse first on a page);
//! `figures.rs` builds the plots, `text.rs` holds the prose.

mod cache;
mod choices;
mod comfort;
mod declaration;
mod figures;
mod progressive;
mod stopwatch;
mod text;

use cache::SweepKey;
pub use choices::{Metric, Road};
use comfort::Comfort;
pub(super) use declaration::sprung_mass;
pub(crate) use stopwatch::Stopwatch;

use super::progressive::{progressive_hooks, Progressive};
use super::Model;
use crate::declare::Declaration;
use crate::figure::Figure;
use std::cell::{Cell, OnceCell};
use zeta_solver::design::map::lowest;
use zeta_solver::design::pareto::nearest_on_front;
use zeta_solver::design::sweep::{KcMaps, KcSweepConfig, RoadInput};
use zeta_solver::metrics::{free::FreeMetrics, SettlingBand};
use zeta_solver::ride::{stationary, Stationary};
use zeta_solver::two_dof::{TwoDof, TwoDofConfig};
use zeta_solver::SecondOrder;

/// Initial displacement of the shown response \[m\] (the map's metrics are relative to it).
const X0: f64 = 0.06;
/// Corner of the one-DOF road filter the solver's (k, c) sweep needs for its own comfort
/// figure \[rad/s\]; the design map replaces that figure by the two-DOF `a_w`.
const CUTOFF: f64 = std::f64::consts::TAU * 10.0;
/// Map axes are in kN/m and kN·s/m so the tick labels stay short.
const KILO: f64 = 1e3;

/// Typed parameters, filled from the declaration.
#[derive(Debug, Default, Clone, Copy, PartialEq)]
pub struct P {
    /// Sprung mass \[kg\].
    m: f64,
    /// Wheel (unsprung) mass \[kg\] and tyre stiffness \[N/m\] of the two-DOF car behind
    /// the comfort metric.
    mu: f64,
    kt: f64,
    metric: Metric,
    /// Settling band \[% of x₀\].
    band: f64,
    road: Road,
    /// Speed over the road \[m/s\].
    v: f64,
    /// Map edges: spring rates \[N/m\] and damper rates \[N·s/m\].
    k_min: f64,
    k_max: f64,
    c_min: f64,
    c_max: f64,
    /// The selected design \[N/m\], \[N·s/m\].
    k: f64,
    c: f64,
    /// Grid cells per axis, as set (the sweep rounds it into 2–400).
    n: f64,
}

impl P {
    fn sweep_key(&self) -> Option<SweepKey> {
        let key = SweepKey {
            m: self.m,
            mu: self.mu,
            kt: self.kt,
            band: self.band,
            road: self.road,
            v: self.v,
            k: (self.k_min, self.k_max),
            c: (self.c_min, self.c_max),
            n: self.n.round().clamp(2.0, 400.0) as usize,
        };
        let ok = key.m > 0.0
            && key.mu > 0.0
            && key.kt > 0.0
            && key.v > 0.0
            && key.k.0 > 0.0
            && key.k.1 > key.k.0
            && key.c.0 > 0.0;
        (ok && key.c.1 > key.c.0).then_some(key)
    }

    /// Whether the selected design lies on the map.
    fn selected_inside(&self) -> bool {
        let inside = |v: f64, lo: f64, hi: f64| v >= lo && v <= hi;
        inside(self.k, self.k_min, self.k_max) && inside(self.c, self.c_min, self.c_max)
    }
}

/// The selected design's figures of merit.
struct Selected {
    sys: Option<SecondOrder>,
    zeta: Option<f64>,
    settling_time: Option<f64>,
    /// Peak rebound \[% of x₀\].
    overshoot: Option<f64>,
    /// Stationary comfort values of the two-DOF car (`a_w` and unweighted) \[m/s²\].
    ride: Option<Stationary>,
    /// `a_w` \[m/s²\]: the Pareto plot's comfort axis.
    accel_rms: Option<f64>,
}

/// What one step computes (the maps themselves stay in [`DesignSpace`]'s cache).
pub struct Results {
    /// The selected design \[N/m\], \[N·s/m\].
    k: f64,
    c: f64,
    key: SweepKey,
    band: SettlingBand,
    sel: Selected,
    /// `(k, c)` of the fastest-settling cell and its settling time \[s\].
    fastest: Option<((f64, f64), SecondOrder, Option<f64>)>,
    /// Duration of the last full sweep \[ms\] (wall clock).
    sweep_ms: f64,
    /// Cells per axis of the maps shown (fewer than `key.n` while provisional).
    grid: usize,
    /// Whether the maps shown are the coarse stand-in while the full sweep runs.
    provisional: bool,
}

/// The design-space demo. Holds the sweep's buffers so a slider move reuses them.
#[derive(Debug, Default)]
pub struct DesignSpace {
    k_axis: Vec<f64>,
    c_axis: Vec<f64>,
    /// The one-DOF maps of the cells (settling time, rebound, transmissibility, ζ); their
    /// `accel_rms` is the solver's one-DOF figure, not shown: comfort is [`Comfort`].
    maps: KcMaps,
    /// The comfort map and the Pareto front over the cells of `maps` (see
    /// [`DesignSpace::comfort`]).
    comfort: OnceCell<Comfort>,
    key: Option<SweepKey>,
    /// Duration of the last full sweep \[ms\].
    sweep_ms: f64,
    /// Number of sweeps performed (for tests of the cache).
    sweeps: u64,
    /// Axes of the last Pareto plot built, for picking the nearest front design.
    pareto_ranges: Cell<((f64, f64), (f64, f64))>,
    /// The progressive sweep: a coarse one first on a page, the full one left to `refine`
    /// (see `progressive.rs`).
    progress: Progressive<progressive::SweepJob>,
}

impl Model for DesignSpace {
    type Params = P;
    type Results = Results;

    fn step(&mut self, p: &P) -> Option<Results> {
        let key = p.sweep_key()?;
        let band = SettlingBand::new(p.band / 100.0).ok()?;
        let road = RoadInput::iso_class(p.road.0, p.v, CUTOFF).ok()?;
        self.sweep_for(
            key,
            KcSweepConfig {
                mass: key.m,
                band,
                road,
            },
        );
        let sys = SecondOrder::mechanical(p.m, p.c, p.k).ok();
        let metrics = sys.and_then(|s| FreeMetrics::exact(&s, X0, 0.0, band));
        // The quarter-car-2dof demo's own computation, for the same car.
        let car = TwoDof::new(TwoDofConfig {
            k_s: p.k,
            c_s: p.c,
            ..key.car()
        });
        let ride = car
            .ok()
            .and_then(|car| stationary(&car, p.road.0, p.v).ok());
        let sel = Selected {
            sys,
            zeta: sys.and_then(|s| s.damping_ratio()),
            settling_time: metrics.and_then(|m| m.settling_time),
            overshoot: metrics.map(|m| 100.0 * m.peak_rebound),
            ride,
            accel_rms: ride.map(|s| s.rms_weighted_body_acceleration),
        };
        let fastest = lowest(&self.maps.settling_time)
            .and_then(|(i, _)| self.design_at(i))
            .and_then(|(k, c)| {
                let s = SecondOrder::mechanical(p.m, c, k).ok()?;
                let ts = FreeMetrics::exact(&s, X0, 0.0, band).and_then(|m| m.settling_time);
                Some(((k, c), s, ts))
            });
        Some(Results {
            k: p.k,
            c: p.c,
            key,
            band,
            sel,
            fastest,
            sweep_ms: self.sweep_ms,
            grid: self.k_axis.len(),
            provisional: self.progress.is_provisional(),
        })
    }

    progressive_hooks!(progressive::PROVISIONAL, refine_sweep);

    fn figure(&self, plot: usize, p: &P, r: &Results) -> Option<Figure> {
        let fig = match plot {
            0 => figures::map(self, p, r),
            1 => figures::pareto(self, p, r),
            2 => figures::response(p, r),
            _ => return None,
        };
        Some(match r.provisional {
            true => text::provisional(fig, r),
            false => fig,
        })
    }

    fn pick(&mut self, plot: &str, x: f64, y: f64) -> Vec<(&'static str, f64)> {
        let Some(key) = self.key else {
            return Vec::new();
        };
        match plot {
            "map" => {
                let (k0, k1) = key.k;
                let (c0, c1) = key.c;
                let (x, y) = (x * KILO, y * KILO);
                if !(x >= k0 && x <= k1 && y >= c0 && y <= c1) {
                    return Vec::new();
                }
                // Round to 10 N/m and 1 N·s/m: finer than a cell, and tidy in the URL.
                vec![("k", (x / 10.0).round() * 10.0), ("c", y.round().max(1.0))]
            }
            "pareto" => {
                let ((x0, x1), (y0, y1)) = self.pareto_ranges.get();
                let comfort = self.comfort();
                let nearest = nearest_on_front(
                    &comfort.front,
                    &self.maps.settling_time,
                    &comfort.accel_rms,
                    (x, y),
                    (x1 - x0, y1 - y0),
                );
                match nearest.and_then(|i| self.design_at(i)) {
                    Some((k, c)) => vec![("k", k), ("c", c)],
                    None => Vec::new(),
                }
            }
            _ => Vec::new(),
        }
    }

    fn declare() -> Declaration<P, Results> {
        declaration::declaration()
    }
}

#[cfg(test)]
mod tests;
