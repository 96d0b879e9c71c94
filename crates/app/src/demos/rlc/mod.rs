//! `rlc`: natural response of a series RLC loop. The capacitor starts charged to `V₀` with
//! no current; the loop then obeys `L·q'' + R·q' + q/C = 0` with `q(0) = C·V₀`, `q'(0) = 0`,
//! and the plots show the current `i = q'` and the capacitor voltage `v_C = q/C`, each with
//! the critically damped response of the same L and C for comparison.

mod figures;
mod text;

use super::Model;
use crate::declare::{Declaration, Param, ReadoutDef};
use crate::figure::Figure;
use crate::spec::{PlotSpec, Preset};
use zeta_solver::metrics::{free::FreeMetrics, SettlingBand};
use zeta_solver::{FreeResponse, SecondOrder};

/// Longest window in periods `2π/ω₀` for a ringing response (so each period keeps ~65 samples).
const MAX_PERIODS: f64 = 12.0;

const L_DEFAULT: f64 = 0.5;
const C_DEFAULT: f64 = 0.02;
const V0_DEFAULT: f64 = 12.0;

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

    fn declare() -> Declaration<P, Results> {
        Declaration {
            equation_mathml: text::EQUATION,
            params: vec![
                Param::linear(
                    "R",
                    "resistance",
                    "R",
                    "Ω",
                    (0.0, 100.0, 0.1),
                    4.0,
                    |p, v| p.r = v,
                ),
                Param::linear(
                    "L",
                    "inductance",
                    "L",
                    "H",
                    (0.05, 5.0, 0.01),
                    L_DEFAULT,
                    |p, v| p.l = v,
                ),
                Param::log(
                    "C",
                    "capacitance",
                    "C",
                    "F",
                    (1e-4, 1.0, 1e-6),
                    C_DEFAULT,
                    |p, v| p.cap = v,
                ),
                Param::linear(
                    "V0",
                    "initial capacitor voltage",
                    "V₀",
                    "V",
                    (0.5, 48.0, 0.5),
                    V0_DEFAULT,
                    |p, v| p.v0 = v,
                ),
            ],
            readouts: vec![
                ReadoutDef::text("regime", "regime", |r| {
                    crate::format::regime(r.sys.regime())
                }),
                ReadoutDef::number(
                    "w0",
                    "resonant frequency ω₀ = 1/√(LC)",
                    "rad/s",
                    4,
                    |r| r.sys.natural_frequency(),
                ),
                ReadoutDef::number("f0", "resonant frequency f₀", "Hz", 4, |r| {
                    r.sys.natural_frequency_hz()
                }),
                ReadoutDef::number("alpha", "decay rate α = R/(2L)", "1/s", 4, |r| {
                    Some(r.sys.alpha())
                }),
                ReadoutDef::number("zeta", "damping ratio ζ", "", 4, |r| r.sys.damping_ratio()),
                ReadoutDef::number("Q", "quality factor Q = 1/(2ζ)", "", 4, |r| {
                    r.sys.quality_factor()
                }),
                ReadoutDef::number(
                    "bandwidth",
                    "current-resonance half-power bandwidth Δω = R/L",
                    "rad/s",
                    4,
                    |r| r.sys.velocity_half_power_bandwidth(),
                ),
                ReadoutDef::number("R_crit", "critical resistance 2√(L/C)", "Ω", 4, |r| {
                    r.sys.critical_damping()
                }),
                ReadoutDef::number("wd", "ringing frequency ω_d", "rad/s", 4, |r| {
                    r.sys.damped_frequency()
                }),
                ReadoutDef::number(
                    "settling_time",
                    "v_C within 5 % of V₀ after",
                    "s",
                    4,
                    |r| r.metrics.and_then(|m| m.settling_time),
                ),
            ],
            plots: vec![
                PlotSpec {
                    key: "current",
                    title: figures::CURRENT_TITLE,
                    aspect: 1.35,
                },
                PlotSpec {
                    key: "voltage",
                    title: figures::VOLTAGE_TITLE,
                    aspect: 1.35,
                },
            ],
            presets: [
                ("Lossless LC, R = 0", 0.0),
                ("Ringing, R = 2 Ω", 2.0),
                ("Underdamped, R = 5 Ω", 5.0),
                ("Critical, R = 10 Ω", 10.0),
                ("Overdamped, R = 20 Ω", 20.0),
            ]
            .into_iter()
            .map(|(label, r)| Preset {
                label,
                values: vec![
                    ("R", r),
                    ("L", L_DEFAULT),
                    ("C", C_DEFAULT),
                    ("V0", V0_DEFAULT),
                ],
            })
            .collect(),
            schematic: true,
            ..Declaration::new("rlc", "Series RLC circuit", text::SUMMARY)
        }
    }

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

    fn figures(&self, _p: &P, r: &Results) -> Vec<Figure> {
        vec![
            figures::signal(r, figures::Signal::Current),
            figures::signal(r, figures::Signal::Voltage),
        ]
    }

    fn time_span(&self, _p: &P, r: &Results) -> Option<(f64, f64)> {
        Some((0.0, r.t_end))
    }

    fn schematic(&self, p: &P, t: f64) -> Option<Figure> {
        let sys = p.system()?;
        let state = p.response(sys).state(t);
        Some(figures::schematic(p, p.current_scale(&sys), state, t))
    }
}

#[cfg(test)]
mod tests;
