//! The `rlc` demo's declaration: parameters, readouts, plots and presets as tables, one row
//! each.

use super::{figures, text, Results, P};
use crate::declare::Declaration;
use crate::demos::rows::{self, readouts, sliders};
use crate::spec::Preset;

/// Defaults of L \[H\], C \[F\] and V₀ \[V\], which every preset keeps.
const L_DEFAULT: f64 = 0.5;
const C_DEFAULT: f64 = 0.02;
const V0_DEFAULT: f64 = 12.0;

/// Parameters, readouts, plots and presets of `rlc`.
pub(super) fn declaration() -> Declaration<P, Results> {
    Declaration {
        equation_mathml: text::EQUATION,
        params: sliders! { P;
            linear "R", "resistance", "R", "Ω", (0.0, 100.0, 0.1), 4.0 => r;
            linear "L", "inductance", "L", "H", (0.05, 5.0, 0.01), L_DEFAULT => l;
            log "C", "capacitance", "C", "F", (1e-4, 1.0, 1e-6), C_DEFAULT => cap;
            linear "V0", "initial capacitor voltage", "V₀", "V", (0.5, 48.0, 0.5), V0_DEFAULT => v0;
        },
        readouts: readouts! { Results, |r|;
            text "regime", "regime" => crate::format::regime(r.sys.regime());
            number "w0", "resonant frequency ω₀ = 1/√(LC)", "rad/s", 4 => r.sys.natural_frequency();
            number "f0", "resonant frequency f₀", "Hz", 4 => r.sys.natural_frequency_hz();
            number "alpha", "decay rate α = R/(2L)", "1/s", 4 => Some(r.sys.alpha());
            number "zeta", "damping ratio ζ", "", 4 => r.sys.damping_ratio();
            number "Q", "quality factor Q = 1/(2ζ)", "", 4 => r.sys.quality_factor();
            number "bandwidth", "current-resonance half-power bandwidth Δω = R/L", "rad/s", 4
                => r.sys.velocity_half_power_bandwidth();
            number "R_crit", "critical resistance 2√(L/C)", "Ω", 4 => r.sys.critical_damping();
            number "wd", "ringing frequency ω_d", "rad/s", 4 => r.sys.damped_frequency();
            number "settling_time", "v_C within 5 % of V₀ after", "s", 4
                => r.metrics.and_then(|m| m.settling_time);
        },
        // Key, title and width / height.
        plots: rows::plots(&[
            ("current", figures::CURRENT_TITLE, 1.35),
            ("voltage", figures::VOLTAGE_TITLE, 1.35),
        ]),
        // R alone changes; L, C and V₀ go back to their defaults.
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
