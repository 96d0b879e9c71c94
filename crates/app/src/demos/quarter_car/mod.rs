//! `quarter-car`: free response of a quarter-car suspension `m·x'' + c·x' + k·x = 0`
//! released from `x(0) = x₀`, `x'(0) = 0` (the body pushed down and let go, road fixed),
//! against the family of textbook damper settings; settling time against ζ with its
//! minimum; and how far ζ moves when the sprung mass changes by ±dm %.
//!
//! **`c` and `zeta` are two views of one quantity**, `c = 2ζ√(k·m)`. Both are sliders.
//! The damper rate `c` is the stored truth (it is the hardware: changing `m` or `k` keeps
//! the damper and moves ζ). In the model step the demo decides which of the two the user
//! moved, by comparing each with the value it saw at the previous update *and* with the
//! value it last asked the page to show ([`Model::derived_params`]):
//! - `c` moved → use it (this includes a preset, which gives both: `c` wins);
//! - else `zeta` moved → `c = 2ζ√(km)` (clamped to the `c` slider's range);
//! - else (`m`, `k` or nothing moved) → keep the previous `c`.
//!
//! On the first update (a fresh page or URL) nothing was seen before: `c` is used unless it
//! is at its default and `zeta` is not, i.e. **a URL giving both uses `c`**, a URL giving
//! only `zeta` uses `zeta`. The page moves the other slider after each update by applying
//! the derived parameters; the rules above make that write-back a no-op for the next update.
//!
//! Files: `declaration.rs` declares the demo (its readout table is `readouts.rs`); this one
//! holds the model step, with `coupling.rs` (which of `c` and `zeta` moved) and `sweep.rs`
//! (the cached settling-time sweep); `response.rs` and `figures.rs` build the plots;
//! `text.rs` holds the prose.

mod coupling;
mod declaration;
mod figures;
mod readouts;
mod response;
mod sweep;
mod text;

use super::Model;
use crate::declare::Declaration;
use crate::figure::Figure;
use coupling::Coupling;
use sweep::SweepCache;
use zeta_solver::design::sensitivity::{spread, Components, Quantity, Spread, Varied};
use zeta_solver::design::sweep::{ZetaOptimum, ZetaSweepConfig};
use zeta_solver::metrics::free::FreeMetrics;
use zeta_solver::metrics::SettlingBand;
use zeta_solver::{FreeResponse, SecondOrder};

/// Points of the settling-time sweep over ζ.
const SWEEP_POINTS: usize = 400;
/// Grid of the search for the fastest-settling ζ (then refined by the solver).
const OPTIMUM_GRID: usize = 240;
/// ζ range searched for the fastest-settling ζ: the optimum is 0.46…0.83 for bands of 20…1 %.
const OPTIMUM_RANGE: (f64, f64) = (0.05, 2.5);

const M_DEFAULT: f64 = 300.0;
const K_DEFAULT: f64 = 24_000.0;
const ZETA_DEFAULT: f64 = 0.3;
/// `2·0.3·√(24 000·300)` N·s/m, so the defaults of `c` and `zeta` agree (a test checks it).
const C_DEFAULT: f64 = 1_609.968_943_799_848_6;
const C_RANGE: (f64, f64, f64) = (0.0, 20_000.0, 10.0);
const ZETA_RANGE: (f64, f64, f64) = (0.0, 3.0, 0.01);
const X0_DEFAULT: f64 = 0.06;

/// The preset family, drawn on the current car: group, ζ.
const FAMILY: [(&str, f64); 6] = [
    ("comfort", 0.3),
    ("comfort", 0.4),
    ("performance", 0.65),
    ("performance", 0.7),
    ("critical", 1.0),
    ("overdamped", 2.0),
];

/// Typed parameters, filled from the declaration.
#[derive(Debug, Default, Clone, Copy)]
pub struct P {
    /// Sprung mass m \[kg\].
    m: f64,
    /// Spring rate k \[N/m\].
    k: f64,
    /// Damper rate c from its slider \[N·s/m\].
    c: f64,
    /// Damping ratio ζ from its slider \[-\].
    zeta: f64,
    /// Initial displacement x₀ \[m\].
    x0: f64,
    /// Settling band \[% of |x₀|\].
    band: f64,
    /// Sprung-mass variation ±dm \[%\].
    dm: f64,
}

/// The quarter-car demo. Holds the damper rate (see the module docs) and a sweep cache.
#[derive(Debug, Clone, Default)]
pub struct QuarterCar {
    /// Damper rate in use \[N·s/m\].
    c: f64,
    coupling: Option<Coupling>,
    sweep: SweepCache,
}

/// The car one update works from.
#[derive(Debug, Clone, Copy)]
struct Car {
    sys: SecondOrder,
    m: f64,
    k: f64,
    c: f64,
    x0: f64,
    band: SettlingBand,
    band_pct: f64,
    dm_pct: f64,
}

impl Car {
    fn new(p: &P, c: f64) -> Option<Car> {
        Some(Car {
            sys: SecondOrder::mechanical(p.m, c, p.k).ok()?,
            m: p.m,
            k: p.k,
            c,
            x0: p.x0,
            band: SettlingBand::new(p.band / 100.0).ok()?,
            band_pct: p.band,
            dm_pct: p.dm,
        })
    }

    fn wn(&self) -> f64 {
        self.sys.natural_frequency().unwrap_or(1.0)
    }

    fn zeta(&self) -> f64 {
        self.sys.damping_ratio().unwrap_or(0.0)
    }

    /// The same car with damping ratio `zeta`.
    fn with_zeta(&self, zeta: f64) -> Option<SecondOrder> {
        let c = self.sys.critical_damping()? * zeta;
        SecondOrder::mechanical(self.m, c, self.k).ok()
    }

    fn metrics(&self, sys: &SecondOrder) -> Option<FreeMetrics> {
        FreeMetrics::exact(sys, self.x0, 0.0, self.band)
    }

    /// The free response of `sys` from this car's release.
    fn release(&self, sys: &SecondOrder) -> FreeResponse {
        FreeResponse::new(*sys, self.x0, 0.0)
    }

    /// ζ of this car's spring and damper on sprung mass `m` (NaN when undefined).
    fn zeta_at_mass(&self, m: f64) -> f64 {
        SecondOrder::mechanical(m, self.c, self.k)
            .ok()
            .and_then(|s| s.damping_ratio())
            .unwrap_or(f64::NAN)
    }
}

/// One member of the preset family on this car: group, ζ, system, settling time.
struct Member {
    group: &'static str,
    zeta: f64,
    sys: Option<SecondOrder>,
    settling: Option<f64>,
}

/// The settling-time curve against ζ.
struct Sweep {
    /// `(ζ, t_s)` with NaN breaks at the jumps.
    points: Vec<(f64, f64)>,
    /// Upper end of the ζ axis.
    z_hi: f64,
    /// Settling time at the last sweep point with ζ ≤ 2 \[s\].
    at_two: f64,
}

/// What one step computes.
pub struct Results {
    car: Car,
    metrics: Option<FreeMetrics>,
    optimum: Option<ZetaOptimum>,
    mass_spread: Option<Spread>,
    family: Vec<Member>,
    sweep: Sweep,
    /// Plotted time window \[s\].
    t_end: f64,
}

/// One figure per declared plot, in order.
const FIGURES: [fn(&Results) -> Figure; 3] =
    [response::response, figures::settling, figures::sensitivity];

impl Model for QuarterCar {
    type Params = P;
    type Results = Results;

    fn step(&mut self, p: &P) -> Option<Results> {
        let c = self.resolve_c(p);
        let car = Car::new(p, c)?;
        let metrics = car.metrics(&car.sys);
        let cfg = ZetaSweepConfig {
            wn: car.wn(),
            x0: car.x0,
            v0: 0.0,
            band: car.band,
        };
        let optimum = self.optimum(&cfg);
        let sweep = self.sweep(&cfg, car.zeta());
        let mass_spread = spread(
            &Components::Mechanical {
                m: car.m,
                c: car.c,
                k: car.k,
            },
            Quantity::DampingRatio,
            Varied::One(0),
            car.dm_pct / 100.0,
        );
        let family: Vec<Member> = FAMILY
            .iter()
            .map(|&(group, zeta)| {
                let sys = car.with_zeta(zeta);
                let settling = sys.as_ref().and_then(|s| car.metrics(s)?.settling_time);
                Member {
                    group,
                    zeta,
                    sys,
                    settling,
                }
            })
            .collect();
        let slowest = family
            .iter()
            .filter_map(|f| f.settling)
            .fold(0.0f64, f64::max);
        let slowest = if slowest > 0.0 {
            slowest
        } else {
            6.0 / car.wn()
        };
        let ts_now = metrics.and_then(|m| m.settling_time);
        let t_end = 1.2 * slowest.max(ts_now.map_or(slowest, |t| t.min(2.5 * slowest)));
        Some(Results {
            car,
            metrics,
            optimum,
            mass_spread,
            family,
            sweep,
            t_end,
        })
    }

    fn figure(&self, plot: usize, _p: &P, r: &Results) -> Option<Figure> {
        FIGURES.get(plot).map(|draw| draw(r))
    }

    fn time_span(&self, _p: &P, r: &Results) -> Option<(f64, f64)> {
        Some((0.0, r.t_end))
    }

    fn schematic(&self, p: &P, t: f64) -> Option<Figure> {
        let car = Car::new(p, self.c)?;
        Some(figures::schematic(
            &car,
            car.release(&car.sys).displacement(t),
            t,
        ))
    }

    fn derived_params(&self) -> Vec<(&'static str, f64)> {
        match self.coupling {
            Some(cp) => vec![("c", cp.shown_c), ("zeta", cp.shown_zeta)],
            None => Vec::new(),
        }
    }

    fn declare() -> Declaration<P, Results> {
        declaration::declaration()
    }
}

#[cfg(test)]
mod tests;
