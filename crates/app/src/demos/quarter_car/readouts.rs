//! The quarter-car demo's readout table: key, label, unit, precision and getter, one row
//! each.

use super::Results;
use crate::declare::ReadoutDef;
use crate::demos::rows::readouts;

/// The readout table.
pub(super) fn table() -> Vec<ReadoutDef<Results>> {
    readouts! { Results, |r|;
        text "regime", "regime" => crate::format::regime(r.car.sys.regime());
        number "wn", "natural frequency ωₙ", "rad/s", 4 => r.car.sys.natural_frequency();
        number "fn", "natural frequency fₙ", "Hz", 4 => r.car.sys.natural_frequency_hz();
        number "zeta", "damping ratio ζ", "", 4 => r.car.sys.damping_ratio();
        number "c", "damper rate c in use", "N·s/m", 4 => Some(r.car.c);
        number "c_crit", "critical damping 2√(km)", "N·s/m", 4 => r.car.sys.critical_damping();
        number "wd", "damped frequency ω_d", "rad/s", 4 => r.car.sys.damped_frequency();
        number "settling_time", "settling time t_s into ±band·|x₀| (free response)", "s", 4
            => r.metrics.and_then(|m| m.settling_time);
        number "overshoot", "peak rebound (of x₀)", "%", 4
            => r.metrics.map(|m| 100.0 * m.peak_rebound);
        number "peak_time", "time of peak rebound", "s", 4
            => r.metrics.and_then(|m| m.rebound_time);
        number "zeta_argmin", "fastest-settling ζ (free response, same band)", "", 4
            => r.optimum.map(|o| o.zeta);
        number "settling_min", "its settling time", "s", 4 => r.optimum.map(|o| o.settling_time);
        number "zeta_lo", "ζ at mass +dm %", "", 4 => r.mass_spread.map(|s| s.min);
        number "zeta_hi", "ζ at mass −dm %", "", 4 => r.mass_spread.map(|s| s.max);
    }
}
