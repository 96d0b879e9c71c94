//! `regimes`: free response of `x'' + 2ζωₙ·x' + ωₙ²·x = 0` in every damping regime, with
//! the two poles in the s-plane, a table of the regimes and an animated mass on a spring.
//!
//! The shape every demo follows, one job per file: `declaration.rs` declares the demo
//! (parameters, readouts, plots and presets as tables, one row each: the `sliders!` and
//! `readouts!` rows and the plot rows of `demos::rows`); this file holds its model step
//! (solver calls only); `figures.rs` builds the plots from the results; `text.rs` holds the
//! prose.

mod declaration;
mod figures;
mod text;

use super::Model;
use crate::declare::Declaration;
use crate::figure::Figure;
use zeta_solver::metrics::{free::FreeMetrics, SettlingBand};
use zeta_solver::{Complex, FreeResponse, Regime, SecondOrder};

/// Periods of the undamped oscillation shown.
const PERIODS: f64 = 4.0;

/// The damping-regimes demo. Stateless: everything follows from the parameters.
#[derive(Debug, Default, Clone, Copy)]
pub struct Regimes;

/// Typed parameters, filled from the declaration.
#[derive(Debug, Default, Clone, Copy)]
pub struct P {
    /// Natural frequency ωₙ \[rad/s\].
    wn: f64,
    /// Damping ratio ζ \[-\].
    zeta: f64,
    /// Initial displacement x₀ \[m\].
    x0: f64,
    /// Initial velocity v₀ \[m/s\].
    v0: f64,
}

/// What one step computes.
pub struct Results {
    sys: SecondOrder,
    response: FreeResponse,
    regime: Regime,
    poles: [Complex; 2],
    /// Plotted window \[s\]: [`PERIODS`] undamped periods.
    t_end: f64,
    /// Settling, rebound and crossings of the free response, where it settles.
    metrics: Option<FreeMetrics>,
    /// How far the response can reach \[m\] (see [`P::reach`]).
    reach: f64,
}

impl P {
    fn system(&self) -> Option<SecondOrder> {
        SecondOrder::from_natural(self.wn, self.zeta).ok()
    }

    /// The larger of |x₀| and |v₀|/ωₙ \[m\]: how far the response can reach, to normalise by.
    fn reach(&self) -> f64 {
        self.x0.abs().max(self.v0.abs() / self.wn).max(1e-9)
    }
}

/// One figure per declared plot, in order.
const FIGURES: [fn(&Results) -> Figure; 2] = [figures::response, figures::poles];

impl Model for Regimes {
    type Params = P;
    type Results = Results;

    fn step(&mut self, p: &P) -> Option<Results> {
        let sys = p.system()?;
        let t_end = PERIODS * std::f64::consts::TAU / sys.natural_frequency().unwrap_or(1.0);
        Some(Results {
            sys,
            response: FreeResponse::new(sys, p.x0, p.v0),
            regime: sys.regime(),
            poles: sys.poles(),
            t_end,
            metrics: FreeMetrics::exact(&sys, p.x0, p.v0, SettlingBand::FREE_DEFAULT),
            reach: p.reach(),
        })
    }

    fn figure(&self, plot: usize, _p: &P, r: &Results) -> Option<Figure> {
        FIGURES.get(plot).map(|draw| draw(r))
    }

    fn time_span(&self, _p: &P, r: &Results) -> Option<(f64, f64)> {
        Some((0.0, r.t_end))
    }

    fn schematic(&self, p: &P, t: f64) -> Option<Figure> {
        let response = FreeResponse::new(p.system()?, p.x0, p.v0);
        Some(figures::schematic(response.displacement(t), p.reach(), t))
    }

    fn sonify(&self, p: &P, t: f64) -> Option<f64> {
        Some(FreeResponse::new(p.system()?, p.x0, p.v0).displacement(t) / p.reach())
    }

    fn declare() -> Declaration<P, Results> {
        declaration::declaration()
    }
}

#[cfg(test)]
mod tests;
