//! `resonance`: a mass on a spring and damper driven by a harmonic force
//! `F(t) = F₀·cos(ωt)`. The frequency response `|H(r)|` and phase for a family of damping
//! ratios (the current one highlighted, peak and half-power points marked), and the full
//! time response from rest at the chosen frequency ratio `r = ω/ωₙ`: build-up at resonance,
//! beating off resonance, with the steady-state amplitude and the slow envelope drawn.
//!
//! The mass is fixed at 1 kg, so `k = ωₙ²` \[N/m\], `c = 2ζωₙ` \[N·s/m\] and the static
//! deflection is `F₀/k`.
//!
//! Files: `declaration.rs` declares the demo; this one holds the model step;
//! `frequency.rs` draws the magnitude and phase plots, `time.rs` the response in time and
//! the schematic; `text.rs` holds the prose.

mod declaration;
mod frequency;
mod text;
mod time;

use super::Model;
use crate::declare::{choice_enum, Declaration};
use crate::figure::Figure;
use std::f64::consts::TAU;
use zeta_solver::forced::{HarmonicForce, HarmonicResponse};
use zeta_solver::{frf, SecondOrder};

/// The mass \[kg\]: fixed, so that `k = ωₙ²·m` and `c = 2ζωₙ·m` follow from ωₙ and ζ.
const MASS: f64 = 1.0;
/// Points per frequency-response curve (on a grid dense near `r = 1`).
const FRF_SAMPLES: usize = 801;
/// Shown range of the frequency ratio (also the range of the `r` slider).
const R_RANGE: (f64, f64) = (0.1, 10.0);
/// How strongly the frequency grid crowds towards `r = 1` (see [`frf::stretched_logspace`]).
const GRID_STRETCH: f64 = 5.0;
/// At most this many cycles (of the faster of drive and natural motion) in the time window.
const MAX_CYCLES: f64 = 40.0;

choice_enum! {
    /// How the magnitude is shown.
    pub enum View {
        /// The plain ratio |H|.
        #[default]
        Linear => ("linear", "linear |H|"),
        /// Decibels, 20·log₁₀|H|.
        Db => ("db", "decibels 20·log₁₀|H|"),
    }
}

/// Typed parameters, filled from the declaration.
#[derive(Debug, Default, Clone, Copy)]
pub struct P {
    /// Damping ratio ζ \[-\].
    zeta: f64,
    /// Frequency ratio r = ω/ωₙ \[-\].
    r: f64,
    /// Natural frequency ωₙ \[rad/s\].
    wn: f64,
    /// Force amplitude F₀ \[N\].
    f0: f64,
    /// Magnitude view.
    view: View,
}

impl P {
    /// The system and its response from rest to the drive; `None` for invalid values.
    fn response(&self) -> Option<HarmonicResponse> {
        let sys = SecondOrder::mechanical(
            MASS,
            2.0 * self.zeta * self.wn * MASS,
            self.wn * self.wn * MASS,
        )
        .ok()?;
        if !(self.r.is_finite() && self.r > 0.0 && self.f0.is_finite()) {
            return None;
        }
        let force = HarmonicForce::new(self.f0, self.r * self.wn).ok()?;
        Some(HarmonicResponse::new(sys, force, 0.0, 0.0))
    }

    /// Time window: long enough to see the build-up (five time constants `1/(ζωₙ)`) or a
    /// few slow beats, at least two drive and three natural periods, at most
    /// [`MAX_CYCLES`] cycles of the faster motion so every cycle keeps ~25 samples.
    fn window(&self, resp: &HarmonicResponse) -> f64 {
        let tn = TAU / self.wn;
        let tf = TAU / (self.r * self.wn);
        let mut want = if self.zeta > 0.0 {
            5.0 / (self.zeta * self.wn)
        } else {
            f64::INFINITY
        };
        if let Some(tb) = resp.beat_period() {
            if tb > 4.0 * tn.max(tf) {
                want = want.min(3.5 * tb);
            }
        }
        want.max(2.0 * tf)
            .max(3.0 * tn)
            .min(MAX_CYCLES * tn.min(tf))
    }
}

/// What one step computes.
pub struct Results {
    p: P,
    resp: HarmonicResponse,
    /// The resonant peak of |H|, where there is one at r > 0.
    peak: Option<frf::Peak>,
    /// Plotted time window \[s\].
    t_end: f64,
}

/// The forced-response demo. Holds its frequency grid and the family's curves on it so
/// updates do not rebuild them.
#[derive(Debug, Clone)]
pub struct Resonance {
    grid: Vec<f64>,
    family: frequency::Family,
}

impl Default for Resonance {
    fn default() -> Self {
        Self {
            grid: frf::stretched_logspace(R_RANGE.0, R_RANGE.1, FRF_SAMPLES, GRID_STRETCH)
                .unwrap_or_default(),
            family: frequency::Family::default(),
        }
    }
}

impl Model for Resonance {
    type Params = P;
    type Results = Results;

    fn step(&mut self, p: &P) -> Option<Results> {
        let resp = p.response()?;
        let peak = frf::peak(p.zeta).filter(|pk| pk.ratio > 0.0);
        self.family.update(&self.grid, p.view);
        Some(Results {
            p: *p,
            peak,
            t_end: p.window(&resp),
            resp,
        })
    }

    fn figure(&self, plot: usize, _p: &P, r: &Results) -> Option<Figure> {
        match plot {
            0 => Some(frequency::magnitude(r, &self.grid, &self.family)),
            1 => Some(frequency::phase(r, &self.grid, &self.family)),
            2 => Some(time::response(r)),
            _ => None,
        }
    }

    fn time_span(&self, _p: &P, r: &Results) -> Option<(f64, f64)> {
        Some((0.0, r.t_end))
    }

    fn schematic(&self, p: &P, t: f64) -> Option<Figure> {
        let resp = p.response()?;
        Some(time::schematic(p, &resp, p.window(&resp), t))
    }

    fn declare() -> Declaration<P, Results> {
        declaration::declaration()
    }
}

#[cfg(test)]
mod tests;
