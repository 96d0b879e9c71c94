//! `flutter`: the Tacoma Narrows bridge as single-degree-of-freedom torsional flutter.
//!
//! One torsional mode `θ'' + 2ζ_eff(U)·ω·θ' + ω²·θ = 0` with `ζ_eff(U) = ζ_s − g·U`
//! (all maths in [`zeta_solver::flutter`]). Plots: the effective damping against wind
//! speed with the critical speed, the root locus as the wind rises, and the twist `θ(t)`;
//! a table contrasts self-excited flutter with forced resonance; the schematic is the deck
//! cross-section twisting in the wind.
//!
//! Units: `U` in m/s, `omega` in rad/s, `slope` in s/m (damping ratio lost per m/s of
//! wind), `theta0` in degrees.

mod figures;
mod schematic;
mod text;

use super::Model;
use crate::declare::{Declaration, Param, ReadoutDef};
use crate::figure::Figure;
use crate::spec::{PlotSpec, Preset};
use zeta_solver::flutter::{
    radians, FlutterConfig, FlutterModel, LocusPoint, TACOMA_FAILURE_WIND,
    TACOMA_STRUCTURAL_DAMPING,
};
use zeta_solver::Regime;

/// Samples of the time response (≈ 16 per period over [`PERIODS`] periods).
const SAMPLES: usize = 1000;
/// Torsional periods shown in the time response and the animation.
const PERIODS: f64 = 60.0;
/// Samples of the damping line and the root locus.
const LOCUS_SAMPLES: usize = 201;
/// Highest wind speed on the slider and the plots \[m/s\].
const U_MAX: f64 = 40.0;

/// The Tacoma Narrows flutter demo. Stateless: everything follows from the parameters.
#[derive(Debug, Clone, Copy, Default)]
pub struct Flutter;

/// Typed parameters, filled from the declaration.
#[derive(Debug, Default, Clone, Copy)]
pub struct P {
    /// Wind speed `U` \[m/s\].
    u: f64,
    /// Structural damping ratio `ζ_s` \[-\].
    zeta_s: f64,
    /// Torsional natural frequency `ω` \[rad/s\].
    omega: f64,
    /// Aerodynamic slope `g` \[s/m\].
    slope: f64,
    /// Initial twist `θ₀` \[deg\].
    theta0_deg: f64,
}

impl P {
    fn model(&self) -> Option<FlutterModel> {
        FlutterModel::new(FlutterConfig {
            omega: self.omega,
            structural_damping: self.zeta_s,
            aero_slope: self.slope,
        })
        .ok()
    }
}

/// What one step computes.
pub struct Results {
    model: FlutterModel,
    /// Wind speed \[m/s\].
    u: f64,
    /// Initial twist \[rad\].
    theta0: f64,
    zeta: f64,
    sigma: f64,
    regime: Option<Regime>,
    doubling: Option<f64>,
    /// Envelope of the twist at the end of the window \[rad\].
    amplitude_end: f64,
    /// Plotted window \[s\]: [`PERIODS`] torsional periods.
    t_end: f64,
    /// Root locus from calm air to [`U_MAX`]; empty if it could not be computed.
    locus: Vec<LocusPoint>,
}

fn tacoma_preset(label: &'static str, u: f64) -> Preset {
    let c = FlutterConfig::tacoma_1940();
    Preset {
        label,
        values: vec![
            ("U", u),
            ("zeta_s", c.structural_damping),
            ("omega", c.omega),
            ("slope", c.aero_slope),
            ("theta0", 2.0),
        ],
    }
}

impl Model for Flutter {
    type Params = P;
    type Results = Results;

    fn declare() -> Declaration<P, Results> {
        let tacoma = FlutterConfig::tacoma_1940();
        Declaration {
            equation_mathml: text::EQUATION,
            params: vec![
                Param::linear(
                    "U",
                    "wind speed",
                    "U",
                    "m/s",
                    (0.0, U_MAX, 0.1),
                    10.0,
                    |p, v| p.u = v,
                ),
                Param::linear(
                    "zeta_s",
                    "structural damping ratio",
                    "ζ_s",
                    "",
                    (0.0, 0.05, 0.0005),
                    TACOMA_STRUCTURAL_DAMPING,
                    |p, v| p.zeta_s = v,
                ),
                Param::linear(
                    "omega",
                    "torsional natural frequency",
                    "ω",
                    "rad/s",
                    (0.2, 6.0, 0.001),
                    tacoma.omega,
                    |p, v| p.omega = v,
                ),
                Param::linear(
                    "slope",
                    "aerodynamic slope (damping lost per m/s)",
                    "g",
                    "s/m",
                    (0.0, 0.001, 0.000_001),
                    tacoma.aero_slope,
                    |p, v| p.slope = v,
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
            ],
            readouts: vec![
                ReadoutDef::number("zeta_eff", "effective damping ratio ζ_eff", "", 3, |r| {
                    Some(r.zeta)
                }),
                ReadoutDef::number("U_crit", "critical (flutter) speed U_crit", "m/s", 4, |r| {
                    r.model.critical_speed()
                }),
                ReadoutDef::number(
                    "growth_rate",
                    "growth rate σ (< 0 decays)",
                    "1/s",
                    3,
                    |r| Some(r.sigma),
                ),
                ReadoutDef::text("regime", "regime", |r| {
                    r.regime
                        .map_or("invalid parameters", |g: Regime| g.key())
                        .to_string()
                }),
                ReadoutDef::number("doubling_time", "amplitude doubles every", "s", 3, |r| {
                    r.doubling
                }),
                ReadoutDef::number(
                    "amplitude_end",
                    "twist amplitude at the end of the plot",
                    "rad",
                    3,
                    |r| Some(r.amplitude_end),
                ),
            ],
            plots: vec![
                PlotSpec {
                    key: "damping",
                    title: figures::DAMPING_TITLE,
                    aspect: 2.0,
                },
                PlotSpec {
                    key: "locus",
                    title: figures::LOCUS_TITLE,
                    aspect: 1.25,
                },
                PlotSpec {
                    key: "response",
                    title: figures::RESPONSE_TITLE,
                    aspect: 2.2,
                },
            ],
            presets: vec![
                tacoma_preset("Tacoma 1940, 10 m/s (stable)", 10.0),
                tacoma_preset("Tacoma 1940 at U_crit", TACOMA_FAILURE_WIND),
                tacoma_preset("Tacoma 1940, 19 m/s (failure day, ≈ 42 mph)", 19.0),
                tacoma_preset("Tacoma 1940, 30 m/s gale", 30.0),
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

    fn step(&mut self, p: &P) -> Option<Results> {
        let model = p.model()?;
        let u = p.u;
        let theta0 = radians(p.theta0_deg);
        let t_end = PERIODS * model.torsional_period();
        let mut locus = vec![LocusPoint::default(); LOCUS_SAMPLES];
        if model.root_locus_into(0.0, U_MAX, &mut locus).is_err() {
            locus.clear();
        }
        Some(Results {
            model,
            u,
            theta0,
            zeta: model.effective_damping(u),
            sigma: model.growth_rate(u),
            regime: model.regime(u).ok(),
            doubling: model.doubling_time(u),
            amplitude_end: model.envelope(u, theta0, t_end),
            t_end,
            locus,
        })
    }

    fn figures(&self, _p: &P, r: &Results) -> Vec<Figure> {
        vec![figures::damping(r), figures::locus(r), figures::response(r)]
    }

    fn time_span(&self, _p: &P, r: &Results) -> Option<(f64, f64)> {
        Some((0.0, r.t_end))
    }

    fn schematic(&self, p: &P, t: f64) -> Option<Figure> {
        let model = p.model()?;
        let theta0 = radians(p.theta0_deg);
        let theta = model.response(p.u, theta0, 0.0).ok()?.displacement(t);
        let t_end = PERIODS * model.torsional_period();
        // Largest |θ| on the window: the envelope at its larger end.
        let peak = model
            .envelope(p.u, theta0, t_end)
            .max(model.envelope_amplitude(p.u, theta0));
        Some(schematic::deck(theta, peak, p.u, t))
    }
}

#[cfg(test)]
mod tests;
