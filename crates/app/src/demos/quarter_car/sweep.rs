//! The settling-time sweep over ζ and the fastest-settling ζ, cached between updates.
//!
//! Both are computed at `ω_n = 1` rad/s and scaled: for a release from rest the settling
//! time is `T(ζ, band)/ω_n` (the response is `x₀·f(ω_n·t; ζ)`), so moving the mass or the
//! spring rescales the cached curve instead of sweeping again. Its breaks are the jumps
//! in closed form ([`settling_time_jumps_from_rest`]).

use super::{QuarterCar, Sweep, OPTIMUM_GRID, OPTIMUM_RANGE, SWEEP_POINTS};
use zeta_solver::design::sweep::{
    fastest_settling_zeta, sweep_zeta_into, ZetaCurves, ZetaOptimum, ZetaSweepConfig,
};
use zeta_solver::grid::linspace;
use zeta_solver::metrics::free::settling_time_jumps_from_rest;

/// The settling-time sweep at `ω_n = 1`, kept while the band and the ζ range stay the same
/// (moving `m`, `k`, `c` or `zeta` alone then costs no sweep).
#[derive(Debug, Clone, Default)]
pub(super) struct SweepCache {
    key: Option<[f64; 3]>,
    zetas: Vec<f64>,
    curves: ZetaCurves,
    /// `(ζ, ω_n·t_s)` with a NaN break at every jump of the settling time.
    points: Vec<(f64, f64)>,
    /// The fastest-settling ζ for the band, at `ω_n = 1`.
    optimum: Option<(f64, Option<ZetaOptimum>)>,
}

/// `cfg` at `ω_n = 1` rad/s.
fn unit(cfg: &ZetaSweepConfig) -> ZetaSweepConfig {
    ZetaSweepConfig { wn: 1.0, ..*cfg }
}

impl QuarterCar {
    /// The fastest-settling ζ for this car's ωₙ and band (cached per band).
    pub(super) fn optimum(&mut self, cfg: &ZetaSweepConfig) -> Option<ZetaOptimum> {
        let key = cfg.band.fraction();
        let found = match self.sweep.optimum {
            Some((k, found)) if k == key => found,
            _ => {
                let found = fastest_settling_zeta(
                    &unit(cfg),
                    OPTIMUM_RANGE.0,
                    OPTIMUM_RANGE.1,
                    OPTIMUM_GRID,
                );
                self.sweep.optimum = Some((key, found));
                found
            }
        };
        found.map(|o| ZetaOptimum {
            settling_time: o.settling_time / cfg.wn,
            ..o
        })
    }

    /// Settling time against ζ over a range that shows this design, broken at every jump
    /// (cached while the band and the range stay the same).
    pub(super) fn sweep(&mut self, cfg: &ZetaSweepConfig, zeta: f64) -> Sweep {
        let z_hi = (1.3 * zeta).clamp(2.0, 15.0);
        let z_lo = (0.9 * zeta).clamp(0.02, 0.1);
        let key = [cfg.band.fraction(), z_lo, z_hi];
        let cache = &mut self.sweep;
        if cache.key != Some(key) {
            cache.key = Some(key);
            cache.zetas = linspace(z_lo, z_hi, SWEEP_POINTS);
            let cfg = unit(cfg);
            sweep_zeta_into(&cache.zetas, &cfg, &mut cache.curves);
            let jumps = settling_time_jumps_from_rest(cfg.band, z_lo, z_hi);
            cache.points.clear();
            let mut next_jump = jumps.iter().peekable();
            for (&z, &ts) in cache.zetas.iter().zip(&cache.curves.settling_time) {
                // A break before the first grid point past each jump.
                let mut jumped = false;
                while next_jump.next_if(|&&j| j <= z).is_some() {
                    jumped = true;
                }
                if jumped && !cache.points.is_empty() {
                    cache.points.push((f64::NAN, f64::NAN));
                }
                cache.points.push((z, ts));
            }
        }
        let at_two = cache
            .zetas
            .iter()
            .zip(&cache.curves.settling_time)
            .filter(|(z, _)| **z <= 2.0)
            .map(|(_, t)| *t / cfg.wn)
            .next_back()
            .unwrap_or(f64::NAN);
        Sweep {
            points: cache.points.iter().map(|&(z, t)| (z, t / cfg.wn)).collect(),
            z_hi,
            at_two,
        }
    }
}
