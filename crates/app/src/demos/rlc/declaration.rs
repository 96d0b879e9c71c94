//! The `rlc` demo's declaration: parameters, readouts, plots and presets as tables.

use super::{figures, text, Results, P};
use crate::declare::{Declaration, Param, ReadoutDef};
use crate::spec::{PlotSpec, Preset};

/// Defaults of L \[H\], C \[F\] and V₀ \[V\], which every preset keeps.
const L_DEFAULT: f64 = 0.5;
const C_DEFAULT: f64 = 0.02;
const V0_DEFAULT: f64 = 12.0;

/// Parameters, readouts, plots and presets of `rlc`.
pub(super) fn declaration() -> Declaration<P, Results> {
    Declaration {
        equation_mathml: text::EQUATION,
        params: vec![
            Param::linear(
                "R",
                "resistance",
                "R",
                "Ω",
                (0.0, 100.0, 0.1),
                4.0,
                |p, v| p.r = v,
            ),
            Param::linear(
                "L",
                "inductance",
                "L",
                "H",
                (0.05, 5.0, 0.01),
                L_DEFAULT,
                |p, v| p.l = v,
            ),
            Param::log(
                "C",
                "capacitance",
                "C",
                "F",
                (1e-4, 1.0, 1e-6),
                C_DEFAULT,
                |p, v| p.cap = v,
            ),
            Param::linear(
                "V0",
                "initial capacitor voltage",
                "V₀",
                "V",
                (0.5, 48.0, 0.5),
                V0_DEFAULT,
                |p, v| p.v0 = v,
            ),
        ],
        readouts: vec![
            ReadoutDef::text("regime", "regime", |r| {
                crate::format::regime(r.sys.regime())
            }),
            ReadoutDef::number(
                "w0",
                "resonant frequency ω₀ = 1/√(LC)",
                "rad/s",
                4,
                |r| r.sys.natural_frequency(),
            ),
            ReadoutDef::number("f0", "resonant frequency f₀", "Hz", 4, |r| {
                r.sys.natural_frequency_hz()
            }),
            ReadoutDef::number("alpha", "decay rate α = R/(2L)", "1/s", 4, |r| {
                Some(r.sys.alpha())
            }),
            ReadoutDef::number("zeta", "damping ratio ζ", "", 4, |r| r.sys.damping_ratio()),
            ReadoutDef::number("Q", "quality factor Q = 1/(2ζ)", "", 4, |r| {
                r.sys.quality_factor()
            }),
            ReadoutDef::number(
                "bandwidth",
                "current-resonance half-power bandwidth Δω = R/L",
                "rad/s",
                4,
                |r| r.sys.velocity_half_power_bandwidth(),
            ),
            ReadoutDef::number("R_crit", "critical resistance 2√(L/C)", "Ω", 4, |r| {
                r.sys.critical_damping()
            }),
            ReadoutDef::number("wd", "ringing frequency ω_d", "rad/s", 4, |r| {
                r.sys.damped_frequency()
            }),
            ReadoutDef::number(
                "settling_time",
                "v_C within 5 % of V₀ after",
                "s",
                4,
                |r| r.metrics.and_then(|m| m.settling_time),
            ),
        ],
        plots: vec![
            PlotSpec {
                key: "current",
                title: figures::CURRENT_TITLE,
                aspect: 1.35,
            },
            PlotSpec {
                key: "voltage",
                title: figures::VOLTAGE_TITLE,
                aspect: 1.35,
            },
        ],
        presets: [
            ("Lossless LC, R = 0", 0.0),
            ("Ringing, R = 2 Ω", 2.0),
            ("Underdamped, R = 5 Ω", 5.0),
            ("Critical, R = 10 Ω", 10.0),
            ("Overdamped, R = 20 Ω", 20.0),
        ]
        .into_iter()
        .map(|(label, r)| Preset {
            label,
            values: vec![
                ("R", r),
                ("L", L_DEFAULT),
                ("C", C_DEFAULT),
                ("V0", V0_DEFAULT),
            ],
        })
        .collect(),
        schematic: true,
        ..Declaration::new("rlc", "Series RLC circuit", text::SUMMARY)
    }
}
