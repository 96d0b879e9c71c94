//! The `regimes` demo's declaration: parameters, readouts, plots and presets as tables.

use super::{figures, text, Results, P};
use crate::declare::{
    Declaration, Param, ReadoutDef, DAMPING_RATIO, INITIAL_DISPLACEMENT, INITIAL_VELOCITY,
    NATURAL_FREQUENCY,
};
use crate::format;
use crate::spec::{PlotSpec, Preset};

/// Parameters, readouts, plots and presets of `regimes`.
pub(super) fn declaration() -> Declaration<P, Results> {
    Declaration {
        equation_mathml: text::EQUATION,
        params: vec![
            Param::quantity(NATURAL_FREQUENCY, (0.5, 20.0, 0.01), 6.0, |p, v| p.wn = v),
            Param::quantity(DAMPING_RATIO, (-0.5, 3.0, 0.01), 0.3, |p, v| p.zeta = v),
            Param::quantity(INITIAL_DISPLACEMENT, (-0.1, 0.1, 0.001), 0.06, |p, v| {
                p.x0 = v
            }),
            Param::quantity(INITIAL_VELOCITY, (-2.0, 2.0, 0.01), 0.0, |p, v| p.v0 = v),
        ],
        readouts: vec![
            ReadoutDef::text("regime", "regime", |r| format::regime(r.regime)),
            ReadoutDef::number("wn", "natural frequency ωₙ", "rad/s", 4, |r| {
                r.sys.natural_frequency()
            }),
            ReadoutDef::number("zeta", "damping ratio ζ", "", 3, |r| r.sys.damping_ratio()),
            ReadoutDef::number("wd", "damped frequency ω_d", "rad/s", 4, |r| {
                r.sys.damped_frequency()
            }),
            ReadoutDef::number("pole_re", "pole real part", "1/s", 4, |r| {
                Some(r.poles[0].re)
            }),
            ReadoutDef::number("pole_im", "pole imaginary part", "rad/s", 4, |r| {
                Some(r.poles[0].im)
            }),
        ],
        plots: vec![
            PlotSpec {
                key: "response",
                title: figures::RESPONSE_TITLE,
                aspect: 1.9,
            },
            PlotSpec {
                key: "poles",
                title: figures::POLES_TITLE,
                aspect: 1.25,
            },
        ],
        primary_plot: "response",
        presets: [
            ("Undamped ζ = 0", 0.0),
            ("Underdamped ζ = 0.2", 0.2),
            ("Critically damped ζ = 1", 1.0),
            ("Overdamped ζ = 2", 2.0),
            ("Negative damping ζ = −0.1", -0.1),
        ]
        .into_iter()
        .map(|(label, z)| Preset {
            label,
            values: vec![("zeta", z), ("x0", 0.06), ("v0", 0.0)],
        })
        .collect(),
        table: Some(text::regime_table()),
        schematic: true,
        ..Declaration::new("regimes", "Damping regimes", text::SUMMARY)
    }
}
