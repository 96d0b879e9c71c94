//! The quarter-car demo's readout table: key, label, unit, precision and getter.

use super::Results;
use crate::declare::ReadoutDef;

/// The readout table.
pub(super) fn table() -> Vec<ReadoutDef<Results>> {
    let settling = |r: &Results| r.metrics.and_then(|m| m.settling_time);
    vec![
        ReadoutDef::text("regime", "regime", |r| {
            crate::format::regime(r.car.sys.regime())
        }),
        ReadoutDef::number("wn", "natural frequency ωₙ", "rad/s", 4, |r| {
            r.car.sys.natural_frequency()
        }),
        ReadoutDef::number("fn", "natural frequency fₙ", "Hz", 4, |r| {
            r.car.sys.natural_frequency_hz()
        }),
        ReadoutDef::number("zeta", "damping ratio ζ", "", 4, |r| {
            r.car.sys.damping_ratio()
        }),
        ReadoutDef::number("c", "damper rate c in use", "N·s/m", 4, |r| Some(r.car.c)),
        ReadoutDef::number("c_crit", "critical damping 2√(km)", "N·s/m", 4, |r| {
            r.car.sys.critical_damping()
        }),
        ReadoutDef::number("wd", "damped frequency ω_d", "rad/s", 4, |r| {
            r.car.sys.damped_frequency()
        }),
        ReadoutDef::number(
            "settling_time",
            "settling time t_s into ±band·|x₀| (free response)",
            "s",
            4,
            settling,
        ),
        ReadoutDef::number("overshoot", "peak rebound (of x₀)", "%", 4, |r| {
            r.metrics.map(|m| 100.0 * m.peak_rebound)
        }),
        ReadoutDef::number("peak_time", "time of peak rebound", "s", 4, |r| {
            r.metrics.and_then(|m| m.rebound_time)
        }),
        ReadoutDef::number(
            "zeta_argmin",
            "fastest-settling ζ (free response, same band)",
            "",
            4,
            |r| r.optimum.map(|o| o.zeta),
        ),
        ReadoutDef::number("settling_min", "its settling time", "s", 4, |r| {
            r.optimum.map(|o| o.settling_time)
        }),
        ReadoutDef::number("zeta_lo", "ζ at mass +dm %", "", 4, |r| {
            r.mass_spread.map(|s| s.min)
        }),
        ReadoutDef::number("zeta_hi", "ζ at mass −dm %", "", 4, |r| {
            r.mass_spread.map(|s| s.max)
        }),
    ]
}
