//! `flutter`: the Tacoma Narrows deck in a steady wind, on Scanlan's flutter derivatives.
//!
//! One torsional mode whose damping and stiffness come from the flutter derivatives
//! `A₂*(K)`, `A₃*(K)` of the deck's section, its frequency iterated at each wind speed, with
//! an amplitude-dependent bound on the motion (all maths in
//! [`zeta_solver::flutter::scanlan`]). The linear model `ζ_eff = ζ_s − g·U` stays available
//! as the "simplest picture". Plots: `A₂*` against reduced velocity with the current point,
//! `ζ_eff(U)`, the root locus, and the twist over minutes; the schematic is the deck
//! cross-section twisting in the wind. Angles are in degrees throughout.
//!
//! This file holds the model step; `declaration.rs` declares the demo (parameters,
//! readouts, plots and presets as tables); `figures.rs` and `schematic.rs` draw; `text.rs`
//! holds the prose.

mod declaration;
mod figures;
mod schematic;
mod text;

use super::rows;
use super::Model;
use crate::declare::{choice_enum, Declaration};
use crate::figure::Figure;
use zeta_solver::flutter::scanlan::Aerodynamics;
use zeta_solver::flutter::{
    degrees, radians, DeckSection, FlutterState, ScanlanConfig, ScanlanModel, TwistHistory,
    TACOMA_FAILURE_WIND, TACOMA_STRUCTURAL_DAMPING,
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

choice_enum! {
    /// Which model of the wind's moment.
    pub enum Aero {
        /// Scanlan's flutter derivatives of the chosen section.
        #[default]
        Derivatives => ("scanlan", "flutter derivatives (Scanlan)"),
        /// The simplest picture `ζ_eff = ζ_s − g·U`.
        Simplest => ("linear", "simplest picture: ζ_eff = ζ_s − g·U"),
    }
}

choice_enum! {
    /// The deck section, which decides its flutter derivatives.
    pub enum Section {
        /// The 1940 H-section.
        #[default]
        H => ("h", "1940 H-section (plate girders)"),
        /// A streamlined box girder.
        Box => ("box", "streamlined box girder"),
    }
}

impl Section {
    fn deck(self) -> DeckSection {
        match self {
            Section::H => DeckSection::HSection,
            Section::Box => DeckSection::StreamlinedBox,
        }
    }
}

/// The Tacoma Narrows flutter demo. Keeps the last twist history for the animation, and
/// the critical speed and the locus while the deck and the aerodynamics stay the same.
#[derive(Debug, Clone, Default)]
pub struct Flutter {
    last: Option<TwistHistory>,
    small: Option<SmallAmplitude>,
}

/// What does not depend on the wind speed, the initial twist or `θ_s`: the critical speed
/// and the locus, for the model whose configuration (with `θ_s` set to 0) is the key.
#[derive(Debug, Clone)]
struct SmallAmplitude {
    key: ScanlanConfig,
    u_crit: Option<f64>,
    locus: Vec<FlutterState>,
}

impl Flutter {
    /// The critical speed and the locus of `model`, computed again only when its
    /// small-amplitude mode can have changed (not for `U`, `θ₀` or `θ_s`).
    fn small_amplitude(&mut self, model: &ScanlanModel) -> (Option<f64>, Vec<FlutterState>) {
        let key = ScanlanConfig {
            saturation: 0.0,
            ..model.config()
        };
        let small = match self.small.take() {
            Some(s) if s.key == key => s,
            _ => SmallAmplitude {
                key,
                u_crit: model.critical_speed(),
                locus: model.locus(0.0, U_MAX, LOCUS_SAMPLES),
            },
        };
        let out = (small.u_crit, small.locus.clone());
        self.small = Some(small);
        out
    }
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

impl Model for Flutter {
    type Params = P;
    type Results = Results;

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
        let (u_crit, locus) = self.small_amplitude(&model);
        Some(Results {
            model,
            p: *p,
            state,
            regime,
            u_crit,
            limit,
            t_large: limit.and_then(|lc| model.time_between(p.u, theta0, 0.9 * lc)),
            window,
            history,
            locus,
        })
    }

    fn figure(&self, plot: usize, _p: &P, r: &Results) -> Option<Figure> {
        rows::figure(&declaration::PLOTS, plot, r)
    }

    fn time_span(&self, _p: &P, r: &Results) -> Option<(f64, f64)> {
        Some((0.0, r.window))
    }

    fn schematic(&self, p: &P, t: f64) -> Option<Figure> {
        let history = self.last.as_ref()?;
        let peak = history.peak().max(radians(p.theta0_deg));
        Some(schematic::deck(history.theta_at(t), peak, p.u, t))
    }

    fn declare() -> Declaration<P, Results> {
        declaration::declaration()
    }
}

#[cfg(test)]
mod tests;
