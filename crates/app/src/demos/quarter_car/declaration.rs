//! The `quarter-car` demo's declaration: parameters, readouts, plots and presets as tables,
//! one row each.

use super::{
    figures, readouts, response, text, Results, C_DEFAULT, C_RANGE, K_DEFAULT, M_DEFAULT, P,
    X0_DEFAULT, ZETA_DEFAULT, ZETA_RANGE,
};
use crate::declare::{Declaration, DAMPING_RATIO, INITIAL_DISPLACEMENT};
use crate::demos::rows::{self, sliders};
use crate::spec::Preset;
use zeta_solver::SecondOrder;

/// Parameters, readouts, plots and presets of `quarter-car`.
pub(super) fn declaration() -> Declaration<P, Results> {
    Declaration {
        equation_mathml: text::EQUATION,
        params: sliders! { P;
            linear "m", "sprung mass", "m", "kg", (100.0, 1000.0, 1.0), M_DEFAULT => m;
            linear "k", "spring rate", "k", "N/m", (5_000.0, 100_000.0, 100.0), K_DEFAULT => k;
            linear "c", "damper rate", "c", "N·s/m", C_RANGE, C_DEFAULT => c;
            quantity DAMPING_RATIO, ZETA_RANGE, ZETA_DEFAULT => zeta;
            quantity INITIAL_DISPLACEMENT, (0.005, 0.15, 0.001), X0_DEFAULT => x0;
            linear "band", "settling band around rest, relative to x₀", "±", "%", (1.0, 20.0, 0.5),
                5.0 => band;
            linear "dm", "sprung-mass variation", "±Δm", "%", (0.0, 40.0, 1.0), 10.0 => dm;
        },
        readouts: readouts::table(),
        // Key, title and width / height.
        plots: rows::plots(&[
            ("response", response::RESPONSE_TITLE, 1.3),
            ("settling", figures::SETTLING_TITLE, 1.6),
            ("sensitivity", figures::SENSITIVITY_TITLE, 2.0),
        ]),
        presets: presets(),
        schematic: true,
        ..Declaration::new("quarter-car", "Quarter-car suspension", text::SUMMARY)
    }
}

/// Presets: the textbook settings on the reference car, naming both views of the damper.
fn presets() -> Vec<Preset> {
    // c = ζ·2√(km) for the reference car, so each preset names both views consistently.
    let crit = SecondOrder::mechanical(M_DEFAULT, 0.0, K_DEFAULT)
        .ok()
        .and_then(|s| s.critical_damping())
        .unwrap_or(f64::NAN);
    [
        ("Comfort ζ = 0.3", 0.3),
        ("Comfort ζ = 0.4", 0.4),
        ("Performance ζ = 0.65", 0.65),
        ("Performance ζ = 0.7", 0.7),
        ("Critical ζ = 1", 1.0),
        ("Overdamped ζ = 2", 2.0),
    ]
    .into_iter()
    .map(|(label, z)| Preset {
        label,
        values: vec![
            ("m", M_DEFAULT),
            ("k", K_DEFAULT),
            ("x0", X0_DEFAULT),
            ("zeta", z),
            ("c", z * crit),
        ],
    })
    .collect()
}
