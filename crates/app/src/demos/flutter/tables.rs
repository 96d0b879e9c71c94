//! The flutter demo's parameter and readout tables.

use super::{text, Aero, Results, Section, P, SIMPLEST_SLOPE, U_MAX};
use crate::declare::{Param, ReadoutDef};
use zeta_solver::flutter::scanlan::{SATURATION_DEG, TACOMA_INERTIA, TACOMA_WIDTH};
use zeta_solver::flutter::{degrees, TACOMA_STRUCTURAL_DAMPING, TACOMA_TORSION_HZ};

/// The parameter table.
pub(super) fn params() -> Vec<Param<P>> {
    vec![
        Param::linear(
            "U",
            "wind speed",
            "U",
            "m/s",
            (0.0, U_MAX, 0.1),
            19.0,
            |p, v| p.u = v,
        ),
        Param::choice(
            "model",
            "model of the wind's moment",
            Aero::Derivatives,
            |p, v| p.aero = v,
        ),
        Param::choice("section", "deck cross-section", Section::H, |p, v| {
            p.section = v
        }),
        Param::linear(
            "B",
            "deck width",
            "B",
            "m",
            (5.0, 40.0, 0.1),
            TACOMA_WIDTH,
            |p, v| p.width = v,
        ),
        Param::log(
            "I",
            "mass moment of inertia per length (assumed for 1940)",
            "I",
            "kg·m²/m",
            (2.0e4, 5.0e6, 1_000.0),
            TACOMA_INERTIA,
            |p, v| p.inertia = v,
        ),
        Param::linear(
            "f0",
            "torsional frequency in still air",
            "f₀",
            "Hz",
            (0.05, 1.0, 0.001),
            TACOMA_TORSION_HZ,
            |p, v| p.f0 = v,
        ),
        Param::linear(
            "zeta_s",
            "structural damping ratio (assumed for 1940)",
            "ζ_s",
            "",
            (0.0, 0.05, 0.0005),
            TACOMA_STRUCTURAL_DAMPING,
            |p, v| p.zeta_s = v,
        ),
        Param::linear(
            "theta0",
            "initial twist",
            "θ₀",
            "°",
            (0.1, 10.0, 0.1),
            2.0,
            |p, v| p.theta0_deg = v,
        ),
        Param::linear(
            "theta_s",
            "twist at which the wind's damping halves (teaching assumption)",
            "θ_s",
            "°",
            (10.0, 90.0, 1.0),
            SATURATION_DEG,
            |p, v| p.sat_deg = v,
        ),
        Param::linear(
            "slope",
            "simplest picture: damping lost per m/s",
            "g",
            "s/m",
            (0.0, 0.001, 0.000_001),
            SIMPLEST_SLOPE,
            |p, v| p.slope = v,
        ),
    ]
}

/// The readout table.
pub(super) fn readouts() -> Vec<ReadoutDef<Results>> {
    vec![
        ReadoutDef::text("regime", "regime of a small twist", text::regime),
        ReadoutDef::number(
            "U_crit",
            "critical (flutter) speed U_crit, searched up to 100 m/s",
            "m/s",
            4,
            |r| r.u_crit,
        ),
        ReadoutDef::number(
            "zeta_eff",
            "effective damping ratio ζ_eff of a small twist",
            "",
            3,
            |r| r.state.map(|s| s.damping_ratio()),
        ),
        ReadoutDef::number(
            "growth_rate",
            "growth rate σ of a small twist (< 0 decays)",
            "1/s",
            3,
            |r| r.state.map(|s| s.growth_rate()),
        ),
        ReadoutDef::formatted("doubling_time", "a small twist doubles every", "s", |r| {
            let t = r.state?.doubling_time()?;
            Some((t, text::duration(t)))
        }),
        ReadoutDef::plain(
            "frequency",
            "torsional frequency in the wind f",
            "Hz",
            4,
            |r| r.state.map(|s| s.frequency_hz()),
        ),
        ReadoutDef::number("K", "reduced frequency K = Bω/U", "", 3, |r| {
            r.state
                .map(|s| s.reduced_frequency)
                .filter(|k| k.is_finite())
        }),
        ReadoutDef::number(
            "reduced_velocity",
            "reduced velocity U/(f·B) = 2π/K",
            "",
            3,
            |r| r.state.map(|s| s.reduced_velocity),
        ),
        ReadoutDef::number("A2", "flutter derivative A₂*(K)", "", 3, |r| {
            r.state.map(|s| s.a2)
        }),
        ReadoutDef::number("A3", "flutter derivative A₃*(K)", "", 3, |r| {
            r.state.map(|s| s.a3)
        }),
        ReadoutDef::plain(
            "limit_deg",
            "limit-cycle twist amplitude (with the assumed bound θ_s)",
            "°",
            3,
            |r| r.limit.map(degrees),
        ),
        ReadoutDef::formatted(
            "time_to_large",
            "time from θ₀ to 90 % of the limit cycle",
            "s",
            |r| r.t_large.map(|t| (t, text::duration(t))),
        ),
        ReadoutDef::plain(
            "amplitude_end_deg",
            "twist amplitude at the end of the plot",
            "°",
            3,
            |r| r.amplitude_end(),
        ),
    ]
}
