//! The flutter demo's declaration: parameters, readouts, plots and presets as tables.

use super::{figures, text, Aero, Results, Section, P, SIMPLEST_SLOPE, U_MAX};
use crate::declare::{Choice, Declaration, Param, ReadoutDef};
use crate::demos::rows::{self, readouts, sliders, Drawn};
use zeta_solver::flutter::scanlan::{SATURATION_DEG, TACOMA_INERTIA, TACOMA_WIDTH};
use zeta_solver::flutter::{degrees, TACOMA_STRUCTURAL_DAMPING, TACOMA_TORSION_HZ};

/// The demo's declaration.
pub(super) fn declaration() -> Declaration<P, Results> {
    let params = params();
    let defaults = rows::defaults(&params);
    // The Tacoma deck as declared, at wind speed `u` with this model and section.
    let preset = |label, u, aero: Aero, section: Section| {
        let changes = [
            ("U", u),
            ("model", aero.index() as f64),
            ("section", section.index() as f64),
        ];
        rows::preset(label, &defaults, &changes)
    };
    Declaration {
        equation_mathml: text::EQUATION,
        params,
        readouts: readouts(),
        plots: rows::drawn_plots(&PLOTS),
        presets: vec![
            preset(
                "Tacoma 1940, 10 m/s (stable)",
                10.0,
                Aero::Derivatives,
                Section::H,
            ),
            preset(
                "Tacoma 1940, 19 m/s (failure day, ≈ 42 mph)",
                19.0,
                Aero::Derivatives,
                Section::H,
            ),
            preset(
                "Tacoma 1940, 30 m/s gale",
                30.0,
                Aero::Derivatives,
                Section::H,
            ),
            preset(
                "Streamlined box deck, 19 m/s",
                19.0,
                Aero::Derivatives,
                Section::Box,
            ),
            preset(
                "Streamlined box deck, 40 m/s",
                40.0,
                Aero::Derivatives,
                Section::Box,
            ),
            preset(
                "Simplest picture, 19 m/s (ζ_eff = ζ_s − g·U)",
                19.0,
                Aero::Simplest,
                Section::H,
            ),
        ],
        table: Some(text::table()),
        schematic: true,
        ..Declaration::new(
            "flutter",
            "Flutter: the Tacoma Narrows bridge",
            text::SUMMARY,
        )
    }
}

/// The parameter table: the wind and its model, then the deck.
fn params() -> Vec<Param<P>> {
    let mut params = sliders! { P;
        linear "U", "wind speed", "U", "m/s", (0.0, U_MAX, 0.1), 19.0 => u;
    };
    params.push(Param::choice(
        "model",
        "model of the wind's moment",
        Aero::Derivatives,
        |p, v| p.aero = v,
    ));
    params.push(Param::choice(
        "section",
        "deck cross-section",
        Section::H,
        |p, v| p.section = v,
    ));
    params.extend(sliders! { P;
        linear "B", "deck width", "B", "m", (5.0, 40.0, 0.1), TACOMA_WIDTH => width;
        log "I", "mass moment of inertia per length (assumed for 1940)", "I", "kg·m²/m",
            (2.0e4, 5.0e6, 1_000.0), TACOMA_INERTIA => inertia;
        linear "f0", "torsional frequency in still air", "f₀", "Hz", (0.05, 1.0, 0.001),
            TACOMA_TORSION_HZ => f0;
        linear "zeta_s", "structural damping ratio (assumed for 1940)", "ζ_s", "",
            (0.0, 0.05, 0.0005), TACOMA_STRUCTURAL_DAMPING => zeta_s;
        linear "theta0", "initial twist", "θ₀", "°", (0.1, 10.0, 0.1), 2.0 => theta0_deg;
        linear "theta_s", "twist at which the wind's damping halves (teaching assumption)",
            "θ_s", "°", (10.0, 90.0, 1.0), SATURATION_DEG => sat_deg;
        linear "slope", "simplest picture: damping lost per m/s", "g", "s/m",
            (0.0, 0.001, 0.000_001), SIMPLEST_SLOPE => slope;
    });
    params
}

/// The readout table.
fn readouts() -> Vec<ReadoutDef<Results>> {
    readouts! { Results, |r|;
        text "regime", "regime of a small twist" => text::regime(r);
        number "U_crit", "critical (flutter) speed U_crit, searched up to 100 m/s", "m/s", 4
            => r.u_crit;
        number "zeta_eff", "effective damping ratio ζ_eff of a small twist", "", 3
            => r.state.map(|s| s.damping_ratio());
        number "growth_rate", "growth rate σ of a small twist (< 0 decays)", "1/s", 3
            => r.state.map(|s| s.growth_rate());
        formatted "doubling_time", "a small twist doubles every", "s"
            => r.state.and_then(|s| s.doubling_time()).map(|t| (t, text::duration(t)));
        plain "frequency", "torsional frequency in the wind f", "Hz", 4
            => r.state.map(|s| s.frequency_hz());
        number "K", "reduced frequency K = Bω/U", "", 3
            => r.state.map(|s| s.reduced_frequency).filter(|k| k.is_finite());
        number "reduced_velocity", "reduced velocity U/(f·B) = 2π/K", "", 3
            => r.state.map(|s| s.reduced_velocity);
        number "A2", "flutter derivative A₂*(K)", "", 3 => r.state.map(|s| s.a2);
        number "A3", "flutter derivative A₃*(K)", "", 3 => r.state.map(|s| s.a3);
        plain "limit_deg", "limit-cycle twist amplitude (with the assumed bound θ_s)", "°", 3
            => r.limit.map(degrees);
        formatted "time_to_large", "time from θ₀ to 90 % of the limit cycle", "s"
            => r.t_large.map(|t| (t, text::duration(t)));
        plain "amplitude_end_deg", "twist amplitude at the end of the plot", "°", 3
            => r.amplitude_end();
    }
}

/// The plots, in order (the primary one first): key, title and width / height, and the
/// figure each shows.
pub(super) const PLOTS: [Drawn<Results>; 4] = [
    (
        ("response", "Deck twist θ(t) over minutes", 2.2),
        figures::response,
    ),
    (
        (
            "derivative",
            "Flutter derivative A₂* and the flutter threshold",
            1.6,
        ),
        figures::derivative,
    ),
    (
        ("damping", "Effective damping against wind speed", 1.6),
        figures::damping,
    ),
    (
        ("locus", "Root locus as the wind rises", 1.25),
        figures::locus,
    ),
];
