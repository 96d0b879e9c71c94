//! The `regimes` demo's declaration: parameters, readouts, plots and presets as tables,
//! one row each.

use super::{figures, text, Results, P};
use crate::declare::{
    Declaration, DAMPING_RATIO, INITIAL_DISPLACEMENT, INITIAL_VELOCITY, NATURAL_FREQUENCY,
};
use crate::demos::rows::{self, readouts, sliders};
use crate::format;
use crate::spec::Preset;

/// Parameters, readouts, plots and presets of `regimes`.
pub(super) fn declaration() -> Declaration<P, Results> {
    Declaration {
        equation_mathml: text::EQUATION,
        params: sliders! { P;
            quantity NATURAL_FREQUENCY, (0.5, 20.0, 0.01), 6.0 => wn;
            quantity DAMPING_RATIO, (-0.5, 3.0, 0.01), 0.3 => zeta;
            quantity INITIAL_DISPLACEMENT, (-0.1, 0.1, 0.001), 0.06 => x0;
            quantity INITIAL_VELOCITY, (-2.0, 2.0, 0.01), 0.0 => v0;
        },
        readouts: readouts! { Results, |r|;
            text "regime", "regime" => format::regime(r.regime);
            number "wn", "natural frequency ωₙ", "rad/s", 4 => r.sys.natural_frequency();
            number "zeta", "damping ratio ζ", "", 3 => r.sys.damping_ratio();
            number "wd", "damped frequency ω_d", "rad/s", 4 => r.sys.damped_frequency();
            number "pole_re", "pole real part", "1/s", 4 => Some(r.poles[0].re);
            number "pole_im", "pole imaginary part", "rad/s", 4 => Some(r.poles[0].im);
        },
        // Key, title and width / height.
        plots: rows::plots(&[
            ("response", figures::RESPONSE_TITLE, 1.9),
            ("poles", figures::POLES_TITLE, 1.25),
        ]),
        // One per regime, each released from x₀ = 0.06 m at rest (ωₙ stays).
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
