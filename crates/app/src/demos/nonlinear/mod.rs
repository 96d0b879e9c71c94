//! `nonlinear`: the quarter car beyond the linear model — a Duffing spring, an asymmetric
//! damper, Coulomb friction and bump stops, integrated with RK4 and drawn against the
//! linear model from the same initial state (all maths in [`zeta_solver::nonlinear`]).
//!
//! Cost per update is bounded: `STEPS` RK4 steps. Coulomb friction sticks and slips: the
//! solver switches between a kinetic force `F_c` while sliding and a static force
//! `F_static = ratio·F_c` that holds the mass once it stops.
//!
//! This file holds the model step; `declaration.rs` declares the demo (parameters,
//! readouts and plots as tables); `figures.rs` draws; `text.rs` holds the prose.

mod declaration;
mod figures;
mod text;

use super::rows;
use super::Model;
use crate::declare::Declaration;
use crate::figure::{finite_extent, Figure};
use zeta_solver::nonlinear::{undamped_period, Comparison, NonlinearConfig, NonlinearModel};

/// Default static-to-kinetic friction ratio (dry sliding joints hold about a fifth more
/// than they drag).
pub(super) const STICK_RATIO: f64 = 1.2;
/// RK4 steps per update.
const STEPS: usize = 3600;
/// Undamped linear periods shown.
const PERIODS: f64 = 5.0;
/// Travel beyond which a trajectory counts as escaped (a softening spring that gave way) \[m\].
const ESCAPE: f64 = 1.0;

/// The nonlinear quarter-car demo. Keeps the last run for the animated schematic.
#[derive(Debug, Clone, Default)]
pub struct Nonlinear {
    last: Option<Comparison>,
}

/// Typed parameters, filled from the declaration.
#[derive(Debug, Default, Clone, Copy)]
pub struct P {
    m: f64,
    k: f64,
    k3: f64,
    c_comp: f64,
    c_reb: f64,
    friction: f64,
    /// Static-to-kinetic friction ratio `F_static/F_c` \[-\].
    stick_ratio: f64,
    gap: f64,
    k_stop: f64,
    x0: f64,
    v0: f64,
}

impl P {
    /// The model and the step `h` \[s\] that covers [`PERIODS`] linear periods in [`STEPS`].
    fn model(&self) -> Option<(NonlinearModel, f64)> {
        let h = PERIODS * undamped_period(self.m, self.k)? / STEPS as f64;
        let model = NonlinearModel::new(NonlinearConfig {
            mass: self.m,
            k: self.k,
            k3: self.k3,
            c_compression: self.c_comp,
            c_rebound: self.c_reb,
            friction: self.friction,
            static_friction: self.stick_ratio * self.friction,
            stop_gap: self.gap,
            stop_stiffness: self.k_stop,
        })
        .ok()?;
        Some((model, h))
    }
}

/// What one step computes.
pub struct Results {
    model: NonlinearModel,
    cmp: Comparison,
    /// Largest |x| of the nonlinear run \[m\].
    max_travel: Option<f64>,
    /// The table row that names the dominant effect.
    effect: &'static str,
    /// End of the plotted window \[s\].
    t_end: f64,
}

/// Which departure from the linear model dominates (the table's row key).
fn effect(cfg: &NonlinearConfig, max_travel: f64, escaped: bool) -> &'static str {
    if escaped {
        return "escaped";
    }
    let mut found = Vec::with_capacity(5);
    if cfg.k3 > 0.0 {
        found.push("hardening spring");
    }
    if cfg.k3 < 0.0 {
        found.push("softening spring");
    }
    if cfg.friction > 0.0 {
        found.push("stick-slip");
    }
    if cfg.stop_stiffness > 0.0 && max_travel > cfg.stop_gap {
        found.push("bump-stop impact");
    }
    if cfg.c_compression != cfg.c_rebound {
        found.push("asymmetric damper");
    }
    match found.as_slice() {
        [] => "linear",
        [one] => one,
        _ => "several at once",
    }
}

impl Model for Nonlinear {
    type Params = P;
    type Results = Results;

    fn step(&mut self, p: &P) -> Option<Results> {
        let Some((model, h)) = p.model() else {
            self.last = None;
            return None;
        };
        let cmp = model.compare_steps(p.x0, p.v0, h, STEPS, ESCAPE);
        let max_travel = finite_extent(cmp.nonlinear.iter().map(|s| s[0].abs())).map(|e| e.1);
        let effect = effect(&model.config(), max_travel.unwrap_or(0.0), cmp.escaped);
        self.last = Some(cmp.clone());
        Some(Results {
            model,
            cmp,
            max_travel,
            effect,
            t_end: STEPS as f64 * h,
        })
    }

    fn figure(&self, plot: usize, _p: &P, r: &Results) -> Option<Figure> {
        rows::figure(&declaration::PLOTS, plot, r)
    }

    fn time_span(&self, _p: &P, r: &Results) -> Option<(f64, f64)> {
        Some((0.0, r.t_end))
    }

    fn schematic(&self, p: &P, t: f64) -> Option<Figure> {
        let (model, _) = p.model()?;
        let cmp = self.last.as_ref()?;
        let x = cmp.nonlinear_at(t)?;
        let reach = cmp
            .nonlinear
            .iter()
            .map(|s| s[0].abs())
            .fold(p.x0.abs(), f64::max)
            .max(1e-6);
        Some(figures::schematic(&model.config(), x, reach, t))
    }

    fn declare() -> Declaration<P, Results> {
        declaration::declaration()
    }
}

#[cfg(test)]
mod tests;
