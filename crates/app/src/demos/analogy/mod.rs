//! `analogy`: one equation, two machines. A mass on a spring and damper and a series RLC
//! loop obey the same `a·y'' + b·y' + c·y = f(t)`; under the force–voltage analogy
//! (m ↔ L, c ↔ R, k ↔ 1/C, F ↔ E, x ↔ q) the circuit here is given the *same numbers* as
//! the mechanism — L \[H\] = m \[kg\], R \[Ω\] = c \[N·s/m\], 1/C \[1/F\] = k \[N/m\],
//! q₀ \[C\] = x₀ \[m\] — so both free responses, released from rest, are one curve on
//! normalised axes, and the energy swaps spring ↔ mass exactly as capacitor ↔ inductor.

mod figures;
mod text;

use super::Model;
use crate::declare::{Declaration, Param, ReadoutDef};
use crate::figure::Figure;
use crate::spec::{PlotSpec, Preset};
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

impl Model for Analogy {
    type Params = P;
    type Results = Results;

    fn declare() -> Declaration<P, Results> {
        Declaration {
            equation_mathml: text::EQUATION,
            params: vec![
                Param::log(
                    "m",
                    "mass (≙ inductance L)",
                    "m",
                    "kg",
                    (0.1, 10.0, 0.01),
                    1.0,
                    |p, v| p.m = v,
                ),
                Param::linear(
                    "c",
                    "damping (≙ resistance R)",
                    "c",
                    "N·s/m",
                    (0.0, 50.0, 0.01),
                    2.0,
                    |p, v| p.c = v,
                ),
                Param::log(
                    "k",
                    "spring rate (≙ 1/C)",
                    "k",
                    "N/m",
                    (1.0, 1000.0, 0.1),
                    100.0,
                    |p, v| p.k = v,
                ),
                Param::linear(
                    "x0",
                    "initial displacement (≙ charge q₀)",
                    "x₀",
                    "m",
                    (0.001, 0.1, 0.001),
                    0.05,
                    |p, v| p.x0 = v,
                ),
            ],
            readouts: vec![
                ReadoutDef::number("m", "mass m", "kg", 4, |r| Some(r.mech.as_mechanical().0)),
                ReadoutDef::number("L", "inductance L (≙ mass m)", "H", 4, |r| Some(r.lrc.0)),
                ReadoutDef::number("c", "damping c", "N·s/m", 4, |r| {
                    Some(r.mech.as_mechanical().1)
                }),
                ReadoutDef::number("R", "resistance R (≙ damping c)", "Ω", 4, |r| {
                    Some(r.lrc.1)
                }),
                ReadoutDef::number("k", "spring rate k", "N/m", 4, |r| {
                    Some(r.mech.as_mechanical().2)
                }),
                ReadoutDef::number("elastance", "elastance 1/C (≙ k)", "1/F", 4, |r| {
                    Some(r.elec.stiffness())
                }),
                ReadoutDef::number("compliance", "compliance 1/k (≙ C)", "m/N", 4, |r| {
                    Some(1.0 / r.mech.as_mechanical().2)
                }),
                ReadoutDef::number("C", "capacitance C (≙ 1/k)", "F", 4, |r| Some(r.lrc.2)),
                ReadoutDef::number("x0", "initial displacement x₀", "m", 4, |r| Some(r.x0)),
                ReadoutDef::number("q0", "initial charge q₀ (≙ x₀)", "C", 4, |r| {
                    Some(r.q0)
                }),
                ReadoutDef::number(
                    "wn",
                    "natural frequency ωₙ = √(k/m)",
                    "rad/s",
                    4,
                    |r| r.mech.natural_frequency(),
                ),
                ReadoutDef::number(
                    "w0",
                    "resonant frequency ω₀ = 1/√(LC) (≙ ωₙ)",
                    "rad/s",
                    4,
                    |r| r.elec.natural_frequency(),
                ),
                ReadoutDef::number("zeta", "damping ratio ζ (both)", "", 4, |r| {
                    r.mech.damping_ratio()
                }),
                ReadoutDef::text("regime", "regime (both)", |r| {
                    crate::format::regime(r.mech.regime())
                }),
                ReadoutDef::number("Q", "quality factor Q (both)", "", 4, |r| {
                    r.mech.quality_factor()
                }),
                ReadoutDef::number(
                    "energy",
                    "stored energy ½kx₀² = ½q₀²/C",
                    "J",
                    4,
                    |r| Some(r.energy()),
                ),
            ],
            plots: vec![
                PlotSpec {
                    key: "responses",
                    title: figures::RESPONSES_TITLE,
                    aspect: 1.6,
                },
                PlotSpec {
                    key: "energy",
                    title: figures::ENERGY_TITLE,
                    aspect: 1.4,
                },
            ],
            presets: [
                ("Frictionless spring ↔ LC tank (c = R = 0)", 1.0, 0.0, 100.0),
                ("Light damping ζ = 0.05", 1.0, 1.0, 100.0),
                ("Critical ζ = 1 (c = 2√(mk), R = 2√(L/C))", 1.0, 20.0, 100.0),
                ("Overdamped ζ = 2", 1.0, 40.0, 100.0),
                (
                    "Heavy and soft: m = 4 kg ↔ L = 4 H, k = 25 N/m ↔ C = 40 mF",
                    4.0,
                    2.0,
                    25.0,
                ),
            ]
            .into_iter()
            .map(|(label, m, c, k)| Preset {
                label,
                values: vec![("m", m), ("c", c), ("k", k)],
            })
            .collect(),
            table: Some(text::analogy_table()),
            schematic: true,
            ..Declaration::new("analogy", "One equation, two machines", text::SUMMARY)
        }
    }

    fn step(&mut self, p: &P) -> Option<Results> {
        p.twins()
    }

    fn figures(&self, _p: &P, r: &Results) -> Vec<Figure> {
        vec![figures::responses(r), figures::energy(r)]
    }

    fn time_span(&self, _p: &P, r: &Results) -> Option<(f64, f64)> {
        Some((0.0, r.t_end))
    }

    fn schematic(&self, p: &P, t: f64) -> Option<Figure> {
        Some(figures::schematic(&p.twins()?, t))
    }
}

#[cfg(test)]
mod tests;
