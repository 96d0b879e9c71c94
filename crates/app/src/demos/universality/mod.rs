//! `universality`: one equation, many machines. Two slots, A and B, each hold one of six
//! machines — mass–spring–damper, series RLC circuit, U-tube manometer, DC-motor position
//! servo, building storey, two-capacity thermal system — set by its own physical
//! parameters. The solver maps each to `a·y'' + b·y' + c·y = f(t)`
//! (`zeta_solver::machines`); the page shows a, b, c, ωₙ and ζ of both, their normalised
//! free responses against ωₙt and in real time, and both machines drawn side by side.
//! "Match" tunes B by the solver's inverse so that its ωₙ and ζ equal A's; the tuned
//! sliders are published as derived parameters, so the page moves them.
//!
//! Files: this one holds the model step; `declaration.rs` declares the demo (readouts,
//! plots and presets), `params.rs` is the parameter table, `machine.rs` the solver glue;
//! `figures.rs` and `drawings.rs` (schematics of the new machines) draw; `text.rs` holds
//! the prose.

mod declaration;
mod drawings;
mod figures;
mod machine;
mod params;
mod text;

use super::rows;
use super::Model;
use crate::declare::Declaration;
use crate::figure::Figure;
use params::{Kind, Values, P};
use zeta_solver::machines::{MatchError, Target};
use zeta_solver::SecondOrder;

/// Normalised window ωₙt shown at least: four undamped periods.
const MIN_WINDOW: f64 = 8.0 * std::f64::consts::PI;
/// Normalised window ωₙt shown at most (very heavy damping creeps for ever).
const MAX_WINDOW: f64 = 200.0;

/// The universality demo. Remembers the parameters "match" derived at the last step.
#[derive(Debug, Default, Clone)]
pub struct Universality {
    derived: Vec<(&'static str, f64)>,
}

/// One machine as computed: its kind, slider values (tuned, for a matched B) and
/// coefficients.
#[derive(Debug, Clone, Copy)]
pub struct One {
    kind: Kind,
    v: Values,
    sys: SecondOrder,
}

impl One {
    fn new(kind: Kind, v: Values) -> Option<Self> {
        Some(Self {
            kind,
            v,
            sys: machine::system(kind, &v).ok()?,
        })
    }

    fn wn(&self) -> f64 {
        self.sys.natural_frequency().unwrap_or(1.0)
    }

    /// Normalised window ωₙt: four periods if it oscillates, else five slow time constants.
    fn window(&self) -> f64 {
        let slow = self.sys.time_constants()[0];
        match (self.sys.damped_frequency(), slow) {
            (None, Some(tau)) => (5.0 * tau * self.wn()).clamp(MIN_WINDOW, MAX_WINDOW),
            _ => MIN_WINDOW,
        }
    }
}

/// What "match" did.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Matching {
    /// Not asked for.
    Off,
    /// B now has A's ωₙ and ζ.
    Exact,
    /// B cannot be damped as lightly as A with its other parameters kept.
    TooLight {
        /// The least damping ratio B can reach.
        zeta_min: f64,
        /// A's damping ratio.
        zeta: f64,
    },
    /// A tuned value lies outside its slider.
    OutOfRange {
        /// Symbol of the tuned parameter.
        symbol: &'static str,
        /// Its unit.
        unit: &'static str,
        /// The value it would need.
        value: f64,
        /// Its slider's range.
        range: (f64, f64),
    },
    /// No target (A has no natural frequency) or no valid tuned machine.
    Impossible,
}

/// What one step computes.
pub struct Results {
    /// Machines A and B (B as tuned when matched).
    m: [One; 2],
    matching: Matching,
    /// Normalised window ωₙt.
    tau_end: f64,
    /// Real-time window \[s\]: the normalised window on A's time scale.
    t_end: f64,
}

impl Model for Universality {
    type Params = P;
    type Results = Results;

    fn step(&mut self, p: &P) -> Option<Results> {
        self.derived.clear();
        let (m, matching, derived) = resolve(p)?;
        self.derived = derived;
        let tau_end = m[0].window().max(m[1].window());
        Some(Results {
            m,
            matching,
            tau_end,
            t_end: tau_end / m[0].wn(),
        })
    }

    fn figure(&self, plot: usize, _p: &P, r: &Results) -> Option<Figure> {
        rows::figure(&declaration::PLOTS, plot, r)
    }

    fn time_span(&self, _p: &P, r: &Results) -> Option<(f64, f64)> {
        Some((0.0, r.t_end))
    }

    fn schematic(&self, p: &P, t: f64) -> Option<Figure> {
        Some(figures::schematic(&resolve(p)?.0, t))
    }

    fn derived_params(&self) -> Vec<(&'static str, f64)> {
        self.derived.clone()
    }

    fn sonify(&self, p: &P, t: f64) -> Option<f64> {
        Some(figures::normalised_at(&resolve(p)?.0[0], t))
    }

    fn declare() -> Declaration<P, Results> {
        declaration::declaration()
    }
}

/// Machines A and B, B tuned to A when "match" is on and the tuning lands inside B's
/// sliders; what matching did; and the tuned sliders to publish.
type Resolved = ([One; 2], Matching, Vec<(&'static str, f64)>);

fn resolve(p: &P) -> Option<Resolved> {
    let a = One::new(p.slots[0].kind, p.slots[0].v)?;
    let kind_b = p.slots[1].kind;
    let mut v_b = p.slots[1].v;
    let mut derived = Vec::new();
    let matching = if !p.matched {
        Matching::Off
    } else {
        match Target::of(&a.sys).map(|t| machine::tune(kind_b, &v_b, t)) {
            Some(Ok(tuned)) => {
                let moved = machine::tuned(kind_b, 1, &tuned);
                let outside = moved
                    .iter()
                    .find(|t| !(t.range.0..=t.range.1).contains(&t.value));
                match outside {
                    Some(t) => Matching::OutOfRange {
                        symbol: t.symbol,
                        unit: t.unit,
                        value: t.value,
                        range: t.range,
                    },
                    None => {
                        derived = moved.iter().map(|t| (t.key, t.value)).collect();
                        v_b = tuned;
                        Matching::Exact
                    }
                }
            }
            Some(Err(MatchError::DampingTooLow { zeta_min, zeta })) => {
                Matching::TooLight { zeta_min, zeta }
            }
            Some(Err(MatchError::Model(_))) | None => Matching::Impossible,
        }
    };
    Some(([a, One::new(kind_b, v_b)?], matching, derived))
}

#[cfg(test)]
mod tests;
