//! `rlc`: natural response of a series RLC loop. The capacitor starts charged to `V₀` with
//! no current; the loop then obeys `L·q'' + R·q' + q/C = 0` with `q(0) = C·V₀`, `q'(0) = 0`,
//! and the plots show the current `i = q'` and the capacitor voltage `v_C = q/C`, each with
//! the critically damped response of the same L and C for comparison.
//!
//! Files: `declaration.rs` declares the demo; this one holds the model step; `figures.rs`
//! builds the plots; `text.rs` holds the prose.

mod declaration;
mod figures;
mod text;

use super::Model;
use crate::declare::Declaration;
use crate::figure::Figure;
use zeta_solver::metrics::{free::FreeMetrics, SettlingBand};
use zeta_solver::{FreeResponse, SecondOrder};

/// Longest window in periods `2π/ω₀` for a ringing response (so each period keeps ~65 samples).
const MAX_PERIODS: f64 = 12.0;

/// The series RLC demo. Stateless: everything follows from the parameters.
#[derive(Debug, Default, Clone, Copy)]
pub struct Rlc;

/// Typed parameters, filled from the declaration.
#[derive(Debug, Default, Clone, Copy)]
pub struct P {
    /// Resistance R \[Ω\].
    r: f64,
    /// Inductance L \[H\].
    l: f64,
    /// Capacitance C \[F\].
    cap: f64,
    /// Initial capacitor voltage V₀ \[V\].
    v0: f64,
}

impl P {
    fn system(&self) -> Option<SecondOrder> {
        SecondOrder::electrical(self.l, self.r, self.cap).ok()
    }

    /// Initial charge `q₀ = C·V₀` \[C\].
    fn q0(&self) -> f64 {
        self.cap * self.v0
    }

    /// The charge `q(t)` released from `q₀` with no current.
    fn response(&self, sys: SecondOrder) -> FreeResponse {
        FreeResponse::new(sys, self.q0(), 0.0)
    }

    /// `V₀·√(C/L) = q₀·ω₀` \[A\]: the current if all the initial energy were in the
    /// inductor, a bound on `|i|` for every `R ≥ 0`.
    fn current_scale(&self, sys: &SecondOrder) -> f64 {
        self.q0().abs() * sys.natural_frequency().unwrap_or(1.0)
    }

    /// Settling time \[s\] of `sys` released from `q₀`, within 5 % of `q₀`.
    fn settling(&self, sys: &SecondOrder) -> Option<f64> {
        FreeMetrics::exact(sys, self.q0(), 0.0, SettlingBand::FREE_DEFAULT)
            .and_then(|m| m.settling_time)
    }
}

/// What one step computes.
pub struct Results {
    p: P,
    sys: SecondOrder,
    /// The critically damped loop with the same L and C.
    critical: Option<SecondOrder>,
    metrics: Option<FreeMetrics>,
    /// Plotted window \[s\] (see [`time_window`]).
    t_end: f64,
}

impl Results {
    /// The current bound `q₀·ω₀` \[A\] (see [`P::current_scale`]).
    fn current_scale(&self) -> f64 {
        self.p.current_scale(&self.sys)
    }
}

/// The time shown: until the slower of this loop and the critical one has settled, with
/// at most [`MAX_PERIODS`] periods of ringing (or 4 periods if it never settles).
fn time_window(p: &P, sys: &SecondOrder, critical: Option<SecondOrder>, own: Option<f64>) -> f64 {
    let period = std::f64::consts::TAU / sys.natural_frequency().unwrap_or(1.0);
    let base = critical
        .and_then(|s| p.settling(&s))
        .map_or(2.0 * period, |t| 1.25 * t);
    let own = match own {
        Some(ts) if sys.regime().oscillates() => (1.25 * ts).min(MAX_PERIODS * period),
        Some(ts) => 1.25 * ts,
        None => 4.0 * period,
    };
    base.max(own)
}

impl Model for Rlc {
    type Params = P;
    type Results = Results;

    fn step(&mut self, p: &P) -> Option<Results> {
        let sys = p.system()?;
        let critical = sys
            .as_electrical()
            .and_then(|(l, _, cap)| SecondOrder::electrical(l, sys.critical_damping()?, cap).ok());
        let metrics = FreeMetrics::exact(&sys, p.q0(), 0.0, SettlingBand::FREE_DEFAULT);
        let t_end = time_window(p, &sys, critical, metrics.and_then(|m| m.settling_time));
        Some(Results {
            p: *p,
            sys,
            critical,
            metrics,
            t_end,
        })
    }

    fn figure(&self, plot: usize, _p: &P, r: &Results) -> Option<Figure> {
        let signal = [figures::Signal::Current, figures::Signal::Voltage];
        signal.get(plot).map(|&s| figures::signal(r, s))
    }

    fn time_span(&self, _p: &P, r: &Results) -> Option<(f64, f64)> {
        Some((0.0, r.t_end))
    }

    fn schematic(&self, p: &P, t: f64) -> Option<Figure> {
        let sys = p.system()?;
        let state = p.response(sys).state(t);
        Some(figures::schematic(p, p.current_scale(&sys), state, t))
    }

    fn declare() -> Declaration<P, Results> {
        declaration::declaration()
    }
}

#[cfg(test)]
mod tests;
