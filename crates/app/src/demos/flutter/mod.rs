//! `flutter`: the Tacoma Narrows deck in a steady wind, on Scanlan's flutter derivatives.
//!
//! One torsional mode whose damping and stiffness come from the flutter derivatives
//! `A₂*(K)`, `A₃*(K)` of the deck's section, its frequency iterated at each wind speed, with
//! an amplitude-dependent bound on the motion (all maths in
//! [`zeta_solver::flutter::scanlan`]). The linear model `ζ_eff = ζ_s − g·U` stays available
//! as the "simplest picture". Plots: `A₂*` against reduced velocity with the current point,
//! `ζ_eff(U)`, the root locus, and the twist over minutes; the schematic is the deck
//! cross-section twisting in the wind. Angles are in degrees throughout.

mod figures;
mod schematic;
mod tables;
mod text;

use super::Model;
use crate::declare::{Choice, Declaration};
use crate::figure::Figure;
use crate::spec::{PlotSpec, Preset};
use zeta_solver::flutter::scanlan::{Aerodynamics, SATURATION_DEG, TACOMA_INERTIA, TACOMA_WIDTH};
use zeta_solver::flutter::{
    degrees, radians, DeckSection, FlutterState, ScanlanConfig, ScanlanModel, TwistHistory,
    TACOMA_FAILURE_WIND, TACOMA_STRUCTURAL_DAMPING, TACOMA_TORSION_HZ,
};
use zeta_solver::{Regime, SecondOrder};

/// Samples of `ζ_eff(U)`, the root locus and the `A₂*` curve over the wind range.
const LOCUS_SAMPLES: usize = 201;
/// Highest wind speed on the slider and the plots \[m/s\].
const U_MAX: f64 = 40.0;
/// RK4 steps per period of the simulated twist.
const STEPS_PER_PERIOD: usize = 20;
/// Damping ratio lost per m/s in the simplest picture's preset: `U_crit` at the failure wind.
const SIMPLEST_SLOPE: f64 = TACOMA_STRUCTURAL_DAMPING / TACOMA_FAILURE_WIND;

/// Which model of the wind's moment.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub enum Aero {
    /// Scanlan's flutter derivatives of the chosen section.
    #[default]
    Derivatives,
    /// The simplest picture `ζ_eff = ζ_s − g·U`.
    Simplest,
}

impl Choice for Aero {
    const OPTIONS: &'static [(Self, &'static str, &'static str)] = &[
        (
            Aero::Derivatives,
            "scanlan",
            "flutter derivatives (Scanlan)",
        ),
        (
            Aero::Simplest,
            "linear",
            "simplest picture: ζ_eff = ζ_s − g·U",
        ),
    ];
}

/// The deck section, which decides its flutter derivatives.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub enum Section {
    /// The 1940 H-section.
    #[default]
    H,
    /// A streamlined box girder.
    Box,
}

impl Choice for Section {
    const OPTIONS: &'static [(Self, &'static str, &'static str)] = &[
        (Section::H, "h", "1940 H-section (plate girders)"),
        (Section::Box, "box", "streamlined box girder"),
    ];
}

impl Section {
    fn deck(self) -> DeckSection {
        match self {
            Section::H => DeckSection::HSection,
            Section::Box => DeckSection::StreamlinedBox,
        }
    }
}

/// The Tacoma Narrows flutter demo. Keeps the last twist history for the animation.
#[derive(Debug, Clone, Default)]
pub struct Flutter {
    last: Option<TwistHistory>,
}

/// Typed parameters, filled from the declaration.
#[derive(Debug, Default, Clone, Copy)]
pub struct P {
    /// Wind speed `U` \[m/s\].
    u: f64,
    aero: Aero,
    section: Section,
    /// Deck width `B` \[m\].
    width: f64,
    /// Mass moment of inertia per length `I` \[kg·m²/m\].
    inertia: f64,
    /// Still-air torsional frequency `f₀` \[Hz\].
    f0: f64,
    /// Structural damping ratio `ζ_s` \[-\].
    zeta_s: f64,
    /// Initial twist `θ₀` \[deg\].
    theta0_deg: f64,
    /// Twist at which the wind's damping term halves `θ_s` \[deg\].
    sat_deg: f64,
    /// Simplest picture's slope `g` \[s/m\].
    slope: f64,
}

impl P {
    fn model(&self) -> Option<ScanlanModel> {
        ScanlanModel::new(ScanlanConfig {
            width: self.width,
            inertia: self.inertia,
            frequency: self.f0,
            structural_damping: self.zeta_s,
            air_density: zeta_solver::flutter::scanlan::AIR_DENSITY,
            saturation: radians(self.sat_deg),
            aerodynamics: match self.aero {
                Aero::Derivatives => Aerodynamics::Derivatives(self.section.deck()),
                Aero::Simplest => Aerodynamics::SimplestPicture { slope: self.slope },
            },
        })
        .ok()
    }
}

/// What one step computes.
pub struct Results {
    model: ScanlanModel,
    p: P,
    /// The small-amplitude mode at `U`; `None` if the wind leaves no oscillation.
    state: Option<FlutterState>,
    regime: Option<Regime>,
    u_crit: Option<f64>,
    /// Limit-cycle amplitude \[rad\].
    limit: Option<f64>,
    /// Time from θ₀ to 90 % of the limit cycle \[s\].
    t_large: Option<f64>,
    /// Plotted window \[s\].
    window: f64,
    history: TwistHistory,
    /// The mode from calm air to [`U_MAX`].
    locus: Vec<FlutterState>,
}

impl Results {
    fn amplitude_end(&self) -> Option<f64> {
        self.history.amplitude.last().map(|&a| degrees(a))
    }
}

fn preset(label: &'static str, u: f64, aero: Aero, section: Section) -> Preset {
    Preset {
        label,
        values: vec![
            ("U", u),
            ("model", aero.index() as f64),
            ("section", section.index() as f64),
            ("B", TACOMA_WIDTH),
            ("I", TACOMA_INERTIA),
            ("f0", TACOMA_TORSION_HZ),
            ("zeta_s", TACOMA_STRUCTURAL_DAMPING),
            ("theta0", 2.0),
            ("theta_s", SATURATION_DEG),
            ("slope", SIMPLEST_SLOPE),
        ],
    }
}

impl Model for Flutter {
    type Params = P;
    type Results = Results;

    fn declare() -> Declaration<P, Results> {
        Declaration {
            equation_mathml: text::EQUATION,
            params: tables::params(),
            readouts: tables::readouts(),
            plots: vec![
                PlotSpec {
                    key: "derivative",
                    title: figures::DERIVATIVE_TITLE,
                    aspect: 1.6,
                },
                PlotSpec {
                    key: "damping",
                    title: figures::DAMPING_TITLE,
                    aspect: 1.6,
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
            primary_plot: "response",
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

    fn step(&mut self, p: &P) -> Option<Results> {
        let model = p.model()?;
        let theta0 = radians(p.theta0_deg);
        let state = model.state(p.u);
        let regime = state
            .and_then(|s| SecondOrder::new(1.0, s.damping, s.stiffness).ok())
            .map(|sys| sys.regime());
        let limit = model.limit_cycle(p.u);
        let window = model.window(p.u, theta0);
        let history = model
            .simulate(p.u, theta0, window, STEPS_PER_PERIOD)
            .unwrap_or_default();
        self.last = Some(history.clone());
        Some(Results {
            model,
            p: *p,
            state,
            regime,
            u_crit: model.critical_speed(),
            limit,
            t_large: limit.and_then(|lc| model.time_between(p.u, theta0, 0.9 * lc)),
            window,
            history,
            locus: model.locus(0.0, U_MAX, LOCUS_SAMPLES),
        })
    }

    fn figures(&self, _p: &P, r: &Results) -> Vec<Figure> {
        vec![
            figures::derivative(r),
            figures::damping(r),
            figures::locus(r),
            figures::response(r),
        ]
    }

    fn time_span(&self, _p: &P, r: &Results) -> Option<(f64, f64)> {
        Some((0.0, r.window))
    }

    fn schematic(&self, p: &P, t: f64) -> Option<Figure> {
        let history = self.last.as_ref()?;
        let peak = history.peak().max(radians(p.theta0_deg));
        Some(schematic::deck(history.theta_at(t), peak, p.u, t))
    }
}

#[cfg(test)]
mod tests;
