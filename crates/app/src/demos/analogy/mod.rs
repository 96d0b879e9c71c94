//! `analogy`: one equation, two machines. A mass on a spring and damper and a series RLC
//! loop obey the same `a·y'' + b·y' + c·y = f(t)`; under the force–voltage analogy
//! (m ↔ L, c ↔ R, k ↔ 1/C, F ↔ E, x ↔ q) the circuit here is given the *same numbers* as
//! the mechanism — L \[H\] = m \[kg\], R \[Ω\] = c \[N·s/m\], 1/C \[1/F\] = k \[N/m\],
//! q₀ \[C\] = x₀ \[m\] — so both free responses, released from rest, are one curve on
//! normalised axes, and the energy swaps spring ↔ mass exactly as capacitor ↔ inductor.
//!
//! Files: `declaration.rs` declares the demo; this one holds the model step; `figures.rs`
//! builds the plots; `text.rs` holds the prose.

mod declaration;
mod figures;
mod text;

use super::Model;
use crate::declare::Declaration;
use crate::figure::Figure;
use std::f64::consts::TAU;
use zeta_solver::integrate::analysis::oscillator_energy;
use zeta_solver::{FreeResponse, Regime, SecondOrder};

/// Undamped periods shown while the system oscillates.
const PERIODS: f64 = 4.0;

/// The analogy demo. Stateless: everything follows from the parameters.
#[derive(Debug, Default, Clone, Copy)]
pub struct Analogy;

/// Typed parameters, filled from the declaration.
#[derive(Debug, Default, Clone, Copy)]
pub struct P {
    /// Mass m \[kg\] (≙ inductance L \[H\]).
    m: f64,
    /// Damping coefficient c \[N·s/m\] (≙ resistance R \[Ω\]).
    c: f64,
    /// Spring rate k \[N/m\] (≙ elastance 1/C \[1/F\]).
    k: f64,
    /// Initial displacement x₀ \[m\] (≙ initial charge q₀ \[C\]).
    x0: f64,
}

/// The two machines, built independently through the solver's mechanical and electrical
/// constructors.
#[derive(Debug, Clone, Copy)]
pub struct Results {
    mech: SecondOrder,
    elec: SecondOrder,
    /// Inductance \[H\], resistance \[Ω\], capacitance \[F\], read back from `elec`.
    lrc: (f64, f64, f64),
    /// Initial displacement \[m\].
    x0: f64,
    /// Initial charge \[C\].
    q0: f64,
    /// Plotted window \[s\] (see [`Results::window`]).
    t_end: f64,
}

impl P {
    /// The electrical twin of `(m, c, k, x0)` under the force–voltage analogy with unit
    /// scale factors: `L = m`, `R = c`, `C = 1/k`, `q₀ = x₀` (numbers equal, units H, Ω,
    /// F, C).
    fn twins(&self) -> Option<Results> {
        let mech = SecondOrder::mechanical(self.m, self.c, self.k).ok()?;
        let elec = SecondOrder::electrical(self.m, self.c, 1.0 / self.k).ok()?;
        let lrc = elec.as_electrical()?;
        (self.x0.is_finite() && self.x0 != 0.0).then(|| Results {
            mech,
            elec,
            lrc,
            x0: self.x0,
            q0: self.x0,
            t_end: Results::window(&mech),
        })
    }
}

impl Results {
    /// Both free responses, each released from rest: `x(t)` and `q(t)`.
    fn responses(&self) -> (FreeResponse, FreeResponse) {
        (
            FreeResponse::new(self.mech, self.x0, 0.0),
            FreeResponse::new(self.elec, self.q0, 0.0),
        )
    }

    /// ωₙ = √(k/m) \[rad/s\].
    fn wn(&self) -> f64 {
        self.mech.natural_frequency().unwrap_or(1.0)
    }

    /// ω₀ = 1/√(LC) \[rad/s\].
    fn w0(&self) -> f64 {
        self.elec.natural_frequency().unwrap_or(1.0)
    }

    /// Energy stored at release, `½kx₀²` \[J\] (equal to `½q₀²/C`).
    fn energy(&self) -> f64 {
        oscillator_energy(&self.mech, [self.x0, 0.0])
    }

    /// A few undamped periods while it oscillates; five slow time constants (capped) when
    /// it creeps back without oscillating.
    fn window(mech: &SecondOrder) -> f64 {
        let tn = TAU / mech.natural_frequency().unwrap_or(1.0);
        match mech.regime() {
            Regime::Overdamped | Regime::CriticallyDamped => {
                let slow = mech.time_constants()[0].unwrap_or(tn);
                (5.0 * slow).clamp(2.0 * tn, 50.0 * tn)
            }
            _ => PERIODS * tn,
        }
    }
}

/// One figure per declared plot, in order.
const FIGURES: [fn(&Results) -> Figure; 2] = [figures::responses, figures::energy];

impl Model for Analogy {
    type Params = P;
    type Results = Results;

    fn step(&mut self, p: &P) -> Option<Results> {
        p.twins()
    }

    fn figure(&self, plot: usize, _p: &P, r: &Results) -> Option<Figure> {
        FIGURES.get(plot).map(|draw| draw(r))
    }

    fn time_span(&self, _p: &P, r: &Results) -> Option<(f64, f64)> {
        Some((0.0, r.t_end))
    }

    fn schematic(&self, p: &P, t: f64) -> Option<Figure> {
        Some(figures::schematic(&p.twins()?, t))
    }

    fn declare() -> Declaration<P, Results> {
        declaration::declaration()
    }
}

#[cfg(test)]
mod tests;
