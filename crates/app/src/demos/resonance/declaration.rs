//! The `resonance` demo's declaration: parameters, readouts, plots and presets as tables.

use super::{frequency, text, time, Results, View, P, R_RANGE};
use crate::declare::{Declaration, Param, ReadoutDef, DAMPING_RATIO, NATURAL_FREQUENCY};
use crate::spec::{PlotSpec, Preset};
use zeta_solver::frf;

/// Parameters, readouts, plots and presets of `resonance`.
pub(super) fn declaration() -> Declaration<P, Results> {
    Declaration {
        equation_mathml: text::EQUATION,
        params: vec![
            Param::quantity(DAMPING_RATIO, (0.01, 2.0, 0.001), 0.1, |p: &mut P, v| {
                p.zeta = v
            })
            .log_scale(),
            Param::log(
                "r",
                "forcing ratio ω/ωₙ",
                "r",
                "",
                (R_RANGE.0, R_RANGE.1, 0.001),
                1.0,
                |p, v| p.r = v,
            ),
            Param::quantity(NATURAL_FREQUENCY, (0.5, 20.0, 0.01), 6.0, |p, v| p.wn = v),
            Param::linear(
                "F0",
                "force amplitude",
                "F₀",
                "N",
                (0.1, 100.0, 0.1),
                10.0,
                |p, v| p.f0 = v,
            ),
            Param::choice("view", "magnitude view", View::Linear, |p, v| p.view = v),
        ],
        readouts: readouts(),
        plots: vec![
            PlotSpec {
                key: "magnitude",
                title: frequency::MAGNITUDE_TITLE,
                aspect: 1.4,
            },
            PlotSpec {
                key: "phase",
                title: frequency::PHASE_TITLE,
                aspect: 1.4,
            },
            PlotSpec {
                key: "time",
                title: time::TIME_TITLE,
                aspect: 1.9,
            },
        ],
        presets: [
            ("At resonance, ζ = 0.05", 0.05, 1.0),
            ("Beating near resonance, r = 0.9", 0.01, 0.9),
            ("No peak, ζ ≈ 1/√2", 0.7072, 1.0),
            ("Quasi-static, r = 0.2", 0.1, 0.2),
            ("Isolation, r = 3", 0.1, 3.0),
        ]
        .into_iter()
        .map(|(label, zeta, r)| Preset {
            label,
            values: vec![("zeta", zeta), ("r", r)],
        })
        .collect(),
        schematic: true,
        ..Declaration::new("resonance", "Forced resonance", text::SUMMARY)
    }
}

/// The readout table.
fn readouts() -> Vec<ReadoutDef<Results>> {
    vec![
        ReadoutDef::number("peak_gain", "resonant peak |H|max", "", 4, |r| {
            r.peak.map(|p| p.gain)
        }),
        ReadoutDef::number("peak_ratio", "peak at r = ω/ωₙ", "", 4, |r| {
            r.peak.map(|p| p.ratio)
        }),
        ReadoutDef::number("Q", "quality factor Q = 1/(2ζ)", "", 4, |r| {
            frf::quality_factor(r.p.zeta)
        }),
        ReadoutDef::number(
            "peak_width",
            "half-power width of the |H| peak r₂ − r₁ (ζ < 0.383)",
            "",
            4,
            |r| frf::half_power_width(r.p.zeta),
        ),
        ReadoutDef::number("gain_at_r", "gain |H(r)| at the drive", "", 4, |r| {
            Some(frf::magnitude(r.p.r, r.p.zeta))
        }),
        ReadoutDef::number("phase_at_r", "phase ∠H(r) at the drive", "rad", 4, |r| {
            Some(frf::phase(r.p.r, r.p.zeta))
        }),
        ReadoutDef::number(
            "amplitude",
            "steady amplitude X = |H|·F₀/k",
            "m",
            4,
            |r| r.resp.steady_state().map(|s| s.amplitude),
        ),
        ReadoutDef::number(
            "beat_period",
            "beat period 2π/|ω − ω_d| (while beats show)",
            "s",
            4,
            |r| r.resp.beats().period(),
        ),
        ReadoutDef::text("beats", "beats in x(t)", |r| text::beats(r.resp.beats())),
    ]
}
