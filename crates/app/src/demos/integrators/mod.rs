//! `integrators`: numerical error of five integrators on the free oscillator
//! `x'' + 2ζωₙ·x' + ωₙ²·x = 0`, `x(0) = x₀`, `x'(0) = 0`.
//!
//! Four fixed-step methods (forward Euler, symplectic Euler, Heun, RK4) run at the step `h`
//! and Dormand–Prince 5(4) runs adaptively to the tolerance `tol`. Plots: each method
//! against the exact solution, the error over time, a log–log convergence study with fitted
//! orders, a work–precision diagram (error against f-evaluations, all five methods) and the
//! stability regions `|R(z)| ≤ 1` with the system's `z = hλ`.
//!
//! Choices documented here (and in the figures' text alternatives):
//! - **Readouts of switched-off methods are still computed**; the toggles hide curves only.
//! - Every step is exactly `h`; when `h` does not divide `T` the last step is shorter, so
//!   the run ends at `T` (readouts `h_used` and `h_last`).
//! - `max_err_<method>` is `max |x_num − x_exact|` over the run's own grid points in
//!   `[0, T]` (for DP45, its accepted steps). A run that overflows shows `overflow` with an
//!   empty `data-value`; a run that grows but stays finite reports its (huge) error.
//! - The convergence study uses nested grids `h_j = T/(n₀·2ʲ)`, measuring the error at the
//!   `n₀ + 1` points common to all of them; it depends on ζ, ωₙ, T and x₀ only and is cached,
//!   so dragging `h`, `tol` or a toggle does not rerun it. Orders are fitted over the
//!   asymptotic range only: the finest levels whose local orders agree within 0.05.
//! - `order_dp45` is minus the slope of error against f-evaluations over a sweep of
//!   tolerances 10⁻² … 10⁻¹⁰ (an adaptive method has no single `h`), fitted only over runs
//!   whose steps the tolerance set; when stability sets them it is undefined.
//! - Symplectic Euler is not a scalar map `R(z)`: its stability comes from the spectral
//!   radius of its 2×2 step matrix and is described in words, not drawn as a region.
//!
//! - On a page the study is progressive (`progressive.rs`): a coarse study at once, marked
//!   provisional, and the full one in short slices; off (tests, snapshots) it runs in the step.
//!
//! `declaration.rs` declares the demo; `model.rs` is its step (solver calls only),
//! `runs.rs` the fixed-step runs at h (kept, and long ones in slices on a page),
//! `progressive.rs` runs the full study in slices on a page, `figures.rs`,
//! `convergence.rs`, `work.rs` and `stability.rs` build the plots, `text.rs` holds the
//! prose.

mod axes;
mod convergence;
mod declaration;
mod figures;
mod model;
mod progressive;
mod runs;
mod stability;
mod text;
mod work;

use super::progressive::{study_hooks, Progressive};
use super::Model;
use crate::declare::Declaration;
use crate::figure::Figure;
pub use model::Results;
use zeta_solver::Complex;

/// The integrators demo. Caches the convergence study (it depends on ζ, ωₙ, T and x₀
/// only) and the parameter-free stability-region boundaries.
#[derive(Debug, Default)]
pub struct Integrators {
    cache: model::Cache,
    /// The progressive study: a coarse one at once on a page, the full one left to
    /// `refine` (see `progressive.rs`).
    progress: Progressive<progressive::StudyJob>,
}

impl Integrators {
    /// A demo with nothing cached yet.
    pub fn new() -> Self {
        Self::default()
    }
}

/// Typed parameters, filled from the declaration.
#[derive(Debug, Default, Clone, Copy)]
pub struct P {
    /// Damping ratio ζ \[-\].
    zeta: f64,
    /// Natural frequency ωₙ \[rad/s\].
    wn: f64,
    /// Step size h \[s\].
    h: f64,
    /// Duration T \[s\].
    t_end: f64,
    /// Initial displacement x₀ \[m\].
    x0: f64,
    /// DP45 relative tolerance (absolute tol·x₀).
    tol: f64,
    /// Which methods are drawn: Euler, symplectic Euler, Heun, RK4, DP45.
    show: [bool; 5],
}

impl Model for Integrators {
    type Params = P;
    type Results = Results;

    fn step(&mut self, p: &P) -> Option<Results> {
        self.cache.step(p, &mut self.progress)
    }

    study_hooks!(refine_study);

    /// The fixed-step runs under way first (what the response and error plots show), then
    /// the study.
    fn refine(&mut self, budget_ms: f64) -> Option<f64> {
        match self.cache.runs.refine(budget_ms) {
            Some(done) => Some(done),
            None => self.refine_study(budget_ms),
        }
    }

    fn provisional(&self) -> Vec<&'static str> {
        let mut keys = self.progress.provisional(&progressive::PROVISIONAL);
        if self.cache.runs.pending() {
            keys.extend(runs::PROVISIONAL);
        }
        keys
    }

    /// The study's rounds and the runs'.
    fn study_round(&self) -> u32 {
        self.progress
            .rounds()
            .wrapping_add(self.cache.runs.rounds())
    }

    fn figure(&self, plot: usize, p: &P, r: &Results) -> Option<Figure> {
        let studied = match plot {
            0 => return Some(figures::response(p, r)),
            1 => return Some(figures::error(p, r)),
            2 => convergence::figure(p, r),
            3 => work::figure(p, r),
            4 => return Some(stability::figure(p, r, self.cache.regions())),
            _ => return None,
        };
        Some(match r.provisional {
            true => text::provisional(studied, &r.study.budget),
            false => studied,
        })
    }

    fn declare() -> Declaration<P, Results> {
        declaration::declaration()
    }
}

/// `z = hλ` for each pole.
fn h_lambda(r: &Results) -> Vec<Complex> {
    r.poles.iter().map(|&p| p * r.h).collect()
}

#[cfg(test)]
mod tests;
