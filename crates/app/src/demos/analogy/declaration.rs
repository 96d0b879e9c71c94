//! The `analogy` demo's declaration: parameters, readouts, plots and presets as tables,
//! one row each.

use super::{figures, text, Results, P};
use crate::declare::Declaration;
use crate::demos::rows::{self, readouts, sliders};
use crate::spec::Preset;

/// Parameters, readouts, plots and presets of `analogy`.
pub(super) fn declaration() -> Declaration<P, Results> {
    Declaration {
        equation_mathml: text::EQUATION,
        params: sliders! { P;
            log "m", "mass (≙ inductance L)", "m", "kg", (0.1, 10.0, 0.01), 1.0 => m;
            linear "c", "damping (≙ resistance R)", "c", "N·s/m", (0.0, 50.0, 0.01), 2.0 => c;
            log "k", "spring rate (≙ 1/C)", "k", "N/m", (1.0, 1000.0, 0.1), 100.0 => k;
            linear "x0", "initial displacement (≙ charge q₀)", "x₀", "m", (0.001, 0.1, 0.001), 0.05
                => x0;
        },
        // Each mechanical quantity, then its electrical twin.
        readouts: readouts! { Results, |r|;
            number "m", "mass m", "kg", 4 => Some(r.mech.as_mechanical().0);
            number "L", "inductance L (≙ mass m)", "H", 4 => Some(r.lrc.0);
            number "c", "damping c", "N·s/m", 4 => Some(r.mech.as_mechanical().1);
            number "R", "resistance R (≙ damping c)", "Ω", 4 => Some(r.lrc.1);
            number "k", "spring rate k", "N/m", 4 => Some(r.mech.as_mechanical().2);
            number "elastance", "elastance 1/C (≙ k)", "1/F", 4 => Some(r.elec.stiffness());
            number "compliance", "compliance 1/k (≙ C)", "m/N", 4
                => Some(1.0 / r.mech.as_mechanical().2);
            number "C", "capacitance C (≙ 1/k)", "F", 4 => Some(r.lrc.2);
            number "x0", "initial displacement x₀", "m", 4 => Some(r.x0);
            number "q0", "initial charge q₀ (≙ x₀)", "C", 4 => Some(r.q0);
            number "wn", "natural frequency ωₙ = √(k/m)", "rad/s", 4 => r.mech.natural_frequency();
            number "w0", "resonant frequency ω₀ = 1/√(LC) (≙ ωₙ)", "rad/s", 4
                => r.elec.natural_frequency();
            number "zeta", "damping ratio ζ (both)", "", 4 => r.mech.damping_ratio();
            text "regime", "regime (both)" => crate::format::regime(r.mech.regime());
            number "Q", "quality factor Q (both)", "", 4 => r.mech.quality_factor();
            number "energy", "stored energy ½kx₀² = ½q₀²/C", "J", 4 => Some(r.energy());
        },
        // Key, title and width / height.
        plots: rows::plots(&[
            ("responses", figures::RESPONSES_TITLE, 1.6),
            ("energy", figures::ENERGY_TITLE, 1.4),
        ]),
        presets: [
            ("Frictionless spring ↔ LC tank (c = R = 0)", 1.0, 0.0, 100.0),
            ("Light damping ζ = 0.05", 1.0, 1.0, 100.0),
            ("Critical ζ = 1 (c = 2√(mk), R = 2√(L/C))", 1.0, 20.0, 100.0),
            ("Overdamped ζ = 2", 1.0, 40.0, 100.0),
            (
                "Heavy and soft: m = 4 kg ↔ L = 4 H, k = 25 N/m ↔ C = 40 mF",
                4.0,
                2.0,
                25.0,
            ),
        ]
        .into_iter()
        .map(|(label, m, c, k)| Preset {
            label,
            values: vec![("m", m), ("c", c), ("k", k)],
        })
        .collect(),
        table: Some(text::analogy_table()),
        schematic: true,
        ..Declaration::new("analogy", "One equation, two machines", text::SUMMARY)
    }
}
