//! The nonlinear demo's declaration: parameters, readouts and plots as tables; the presets
//! and the effects table of `text.rs`.

use super::{figures, text, Results, P, STICK_RATIO};
use crate::declare::Declaration;
use crate::demos::rows::{self, readouts, sliders, Drawn};

/// The demo's declaration.
pub(super) fn declaration() -> Declaration<P, Results> {
    let params = sliders! { P;
        linear "m", "sprung mass", "m", "kg", (100.0, 600.0, 1.0), 300.0 => m;
        linear "k", "linear spring rate", "k", "N/m",
            (5_000.0, 60_000.0, 100.0), 24_000.0 => k;
        linear "k3", "cubic spring coefficient (+ hardening, − softening)", "k₃", "N/m³",
            (-4.0e6, 4.0e6, 10_000.0), 1.0e6 => k3;
        linear "c_comp", "damper rate in compression", "c_c", "N·s/m",
            (0.0, 6_000.0, 10.0), 1_500.0 => c_comp;
        linear "c_reb", "damper rate in rebound", "c_r", "N·s/m",
            (0.0, 6_000.0, 10.0), 1_500.0 => c_reb;
        linear "friction", "Coulomb friction force while sliding", "F_c", "N",
            (0.0, 1_500.0, 10.0), 0.0 => friction;
        linear "stick_ratio", "static-to-sliding friction ratio", "F_static/F_c", "",
            (1.0, 2.0, 0.05), STICK_RATIO => stick_ratio;
        linear "gap", "bump-stop clearance", "gap", "m", (0.01, 0.2, 0.001), 0.06 => gap;
        linear "k_stop", "bump-stop rate (0 = no stops)", "k_stop", "N/m",
            (0.0, 500_000.0, 1_000.0), 0.0 => k_stop;
        linear "x0", "initial extension", "x₀", "m", (-0.15, 0.15, 0.001), 0.08 => x0;
        linear "v0", "initial velocity", "v₀", "m/s", (-2.0, 2.0, 0.01), 0.0 => v0;
    };
    let defaults = rows::defaults(&params);
    Declaration {
        equation_mathml: text::EQUATION,
        params,
        readouts: readouts! { Results, |r|;
            text "effect", "dominant nonlinearity" => text::effect_name(r.effect);
            number "period_ratio", "first-swing period ratio T_nonlinear / T_linear", "", 4
                => r.cmp.first_swing_ratio();
            number "max_deviation", "largest |x_nonlinear − x_linear|", "m", 3
                => (!r.cmp.t.is_empty()).then(|| r.cmp.max_deviation());
            number "period_nonlinear",
                "nonlinear period of the first full swing (three zero crossings)", "s", 4
                => r.cmp.first_swing_nonlinear();
            number "period_linear", "linear period of the first full swing (= 2π/ω_d)", "s", 4
                => r.cmp.first_swing_linear();
            number "max_travel", "largest |x| (nonlinear)", "m", 3 => r.max_travel;
            number "stick_position", "friction holds the mass at", "m", 3
                => r.cmp.sticking.map(|st| st.x);
        },
        plots: rows::drawn_plots(&PLOTS),
        presets: text::presets(&defaults),
        table: Some(text::table()),
        schematic: true,
        ..Declaration::new("nonlinear", "Beyond the linear model", text::SUMMARY)
    }
}

/// The plots, in order: key, title and width / height, and the figure each shows.
pub(super) const PLOTS: [Drawn<Results>; 4] = [
    (
        ("response", "Nonlinear and linear response x(t)", 2.0),
        figures::response,
    ),
    (("phase", "Phase plane (x, v)", 1.25), figures::phase),
    (
        ("spring", "Spring and bump-stop force", 2.0),
        figures::spring,
    ),
    (
        ("damper", "Damper and friction force", 1.25),
        figures::damper,
    ),
];
