//! `quarter-car-2dof`: sprung (body) and unsprung (wheel) mass on a suspension and a tyre
//! that cannot pull, driven by a bump, a step, a sinusoid or a random ISO 8608 road (all
//! maths in [`zeta_solver::two_dof`], [`zeta_solver::two_dof_exact`],
//! [`zeta_solver::road`] and [`zeta_solver::ride`]). Plots: body, wheel and road motion;
//! body acceleration; tyre deflection with the time off the road; and the frequency
//! responses with the two modes, body bounce and wheel hop.
//!
//! This file holds the model step; `declaration.rs` declares the demo (parameters and
//! plots as tables) and `readouts.rs` is its readout table; `run.rs` keeps the road and
//! the exact run between updates; `figures.rs` and `schematic.rs` draw; `text.rs` holds
//! the prose.

mod declaration;
mod figures;
mod readouts;
mod run;
mod schematic;
mod text;

use super::Model;
use crate::declare::{choice_enum, Choice, Declaration};
use crate::figure::Figure;
use run::Run;
use std::f64::consts::TAU;
use zeta_solver::ride::{stationary, Stationary};
use zeta_solver::two_dof::{Frf, IsoClass, TwoDof, TwoDofConfig};
use zeta_solver::two_dof_exact::ExactMetrics;

choice_enum! {
    /// Which road drives the car.
    pub enum RoadKind {
        /// A single `1 − cos` bump.
        #[default]
        Bump => ("bump", "single bump (1 − cos)"),
        /// A step (kerb).
        Step => ("step", "step (kerb)"),
        /// A sinusoid.
        Sine => ("sine", "sinusoid"),
        /// A random ISO 8608 road.
        Random => ("random", "random road (ISO 8608)"),
    }
}

impl Choice for IsoClass {
    const OPTIONS: &'static [(Self, &'static str, &'static str)] = &[
        (IsoClass::A, "A", "A (very good)"),
        (IsoClass::B, "B", "B (good)"),
        (IsoClass::C, "C", "C (average)"),
        (IsoClass::D, "D", "D (poor)"),
        (IsoClass::E, "E", "E (very poor)"),
        (IsoClass::F, "F", "F"),
        (IsoClass::G, "G", "G"),
        (IsoClass::H, "H", "H"),
    ];
}

/// Typed parameters, filled from the declaration.
#[derive(Debug, Clone, Copy)]
pub struct P {
    /// Body (sprung) mass m_s \[kg\].
    ms: f64,
    /// Wheel (unsprung) mass m_u \[kg\].
    mu: f64,
    /// Suspension stiffness k_s \[N/m\].
    ks: f64,
    /// Tyre stiffness k_t \[N/m\].
    kt: f64,
    /// Suspension damping c_s \[N·s/m\].
    cs: f64,
    road: RoadKind,
    /// Bump or step height, sine amplitude \[m\].
    h: f64,
    /// Bump length \[m\].
    l: f64,
    /// Speed \[m/s\].
    v: f64,
    /// Sine road frequency \[Hz\].
    f_road: f64,
    class: IsoClass,
    /// Random road seed.
    seed: f64,
}

impl Default for P {
    fn default() -> Self {
        Self {
            ms: 300.0,
            mu: 40.0,
            ks: 24_000.0,
            kt: 200_000.0,
            cs: 1_500.0,
            road: RoadKind::Bump,
            h: 0.05,
            l: 0.5,
            v: 10.0,
            f_road: 1.2,
            class: IsoClass::C,
            seed: 1.0,
        }
    }
}

impl P {
    fn car(&self) -> Option<TwoDof> {
        TwoDof::new(TwoDofConfig {
            sprung_mass: self.ms,
            unsprung_mass: self.mu,
            k_s: self.ks,
            c_s: self.cs,
            k_t: self.kt,
            c_t: 0.0,
        })
        .ok()
    }

    /// Length of the run \[s\]: long enough for the body to settle after a bump or step, a
    /// few road periods for a sinusoid.
    fn duration(&self) -> f64 {
        match self.road {
            RoadKind::Bump => self.l / self.v + 2.5,
            RoadKind::Step => 2.5,
            RoadKind::Sine => (6.0 / self.f_road).clamp(2.5, 6.0),
            RoadKind::Random => 3.0,
        }
    }
}

/// What one step computes.
pub struct Results {
    /// Undamped natural frequencies \[Hz\]: body bounce, wheel hop.
    f_body: f64,
    f_wheel: f64,
    metrics: Option<ExactMetrics>,
    /// Static tyre deflection \[m\].
    static_tyre: f64,
    /// RMS height of the random road \[m\].
    rms_road: Option<f64>,
    /// Stationary RMS values on the full ISO 8608 road of the chosen class and speed.
    stationary: Option<Stationary>,
    /// Frequency response at the sine road's frequency.
    sine_frf: Option<Frf>,
    /// End of the run \[s\].
    t_end: f64,
}

/// The two-degree-of-freedom quarter-car demo; keeps its run between updates.
#[derive(Debug, Clone, Default)]
pub struct QuarterCar2Dof {
    run: Run,
}

impl Model for QuarterCar2Dof {
    type Params = P;
    type Results = Results;

    fn step(&mut self, p: &P) -> Option<Results> {
        let car = p.car()?;
        let [f_body, f_wheel] = car.natural_frequencies_hz();
        self.run.set_road(p);
        let metrics = self.run.integrate(&car, p.duration());
        self.run.sweep(&car);
        let random = p.road == RoadKind::Random;
        let sine = p.road == RoadKind::Sine;
        Some(Results {
            f_body,
            f_wheel,
            metrics,
            static_tyre: car.static_tyre_deflection(),
            rms_road: self.run.random_road().filter(|_| random).map(|r| r.rms()),
            stationary: random
                .then(|| stationary(&car, p.class, p.v).ok())
                .flatten(),
            sine_frf: sine.then(|| car.frf(TAU * p.f_road)),
            t_end: self.run.t_end(),
        })
    }

    fn figure(&self, plot: usize, p: &P, r: &Results) -> Option<Figure> {
        match plot {
            0 => Some(figures::motion(&self.run, r.t_end, p.road)),
            1 => Some(figures::acceleration(
                &self.run,
                p.car().as_ref(),
                r.t_end,
                r.metrics,
            )),
            2 => {
                let sine = (p.road == RoadKind::Sine).then_some(p.f_road);
                Some(figures::frf(&self.run, r.f_body, r.f_wheel, sine))
            }
            3 => Some(figures::tyre(&self.run, r.t_end, r.static_tyre, r.metrics)),
            _ => None,
        }
    }

    fn time_span(&self, _p: &P, r: &Results) -> Option<(f64, f64)> {
        Some((0.0, r.t_end))
    }

    fn schematic(&self, p: &P, t: f64) -> Option<Figure> {
        p.car()?;
        let s = self.run.state_at(t)?;
        let road = self.run.road();
        let (u, _) = road.at(t);
        Some(schematic::car(
            s,
            u,
            self.run.reach(u),
            |dt| road.at(t + dt).0,
            p.v,
            t,
        ))
    }

    fn declare() -> Declaration<P, Results> {
        declaration::declaration()
    }
}

#[cfg(test)]
mod tests;
