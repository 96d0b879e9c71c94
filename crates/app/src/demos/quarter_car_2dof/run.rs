//! The run behind the plots: the road, the exact response with a tyre that cannot pull
//! ([`TwoDof::ride_exact`]) and the frequency sweep, kept between updates.
//!
//! Cost per update is bounded: the solver's road samples and exact pieces (a few thousand
//! at the defaults, at most ≈ 45 000 at the stiffest tyre on the slowest sine), a random
//! road of [`ROAD_COMPONENTS`] sinusoids rebuilt only when its class, speed or seed
//! changes, and a [`FRF_POINTS`]-point frequency sweep. The run is kept while the car, the
//! road and the duration stay the same, the sweep while the car does.

use super::{RoadKind, P};
use zeta_solver::grid::{interpolate, logspace_into};
use zeta_solver::road::SampledRoad;
use zeta_solver::two_dof::{Frf, IsoClass, RandomRoad, RandomRoadConfig, Road, TwoDof};
use zeta_solver::two_dof_exact::{ExactMetrics, Tyre};

/// Sinusoids in the random road.
pub(super) const ROAD_COMPONENTS: usize = 64;
/// Temporal frequency band of the random road \[Hz\] (both modes, up to wheel hop).
const ROAD_BAND: (f64, f64) = (0.5, 20.0);
/// Frequencies of the response sweep.
pub(super) const FRF_POINTS: usize = 320;
/// Sweep range \[Hz\].
pub(super) const FRF_RANGE: (f64, f64) = (0.1, 60.0);

/// Key of the cached random road: class, speed bits, seed.
type RoadKey = (IsoClass, u64, u64);

/// The last run and the buffers it reuses.
#[derive(Debug, Clone, Default)]
pub(super) struct Run {
    /// States `[z_s, z_u, z_s', z_u']` at `times`.
    pub states: Vec<[f64; 4]>,
    /// Times of the states \[s\]: every road sample and every lift-off and landing.
    pub times: Vec<f64>,
    /// Road height at each time \[m\].
    pub road_u: Vec<f64>,
    /// Whether the tyre pushes on the road just after each time.
    pub contact: Vec<bool>,
    /// The road's samples (reused by the solver).
    samples: SampledRoad,
    road: Road,
    random: Option<(RoadKey, RandomRoad)>,
    /// What the last run was of (car, road, end) and its metrics: a slider the run does not
    /// depend on (the sine's frequency on a bump road, say) costs no run.
    last_run: Option<(TwoDof, Road, f64, Option<ExactMetrics>)>,
    /// The car the last sweep was of.
    last_sweep: Option<TwoDof>,
    omegas: Vec<f64>,
    /// Frequency responses at `omegas`.
    pub frf: Vec<Frf>,
}

impl Run {
    /// The road of the last run.
    pub fn road(&self) -> &Road {
        &self.road
    }

    /// The random road, when the last run was on one.
    pub fn random_road(&self) -> Option<&RandomRoad> {
        match &self.road {
            Road::Random(r) => Some(r),
            _ => None,
        }
    }

    /// End of the run \[s\] (1 s before any run, never below 1 ms).
    pub fn t_end(&self) -> f64 {
        self.times.last().copied().unwrap_or(1.0).max(1e-3)
    }

    /// Builds the road; the random road is rebuilt only when its class, speed or seed change.
    pub fn set_road(&mut self, p: &P) {
        self.road = match p.road {
            RoadKind::Bump => Road::Bump {
                height: p.h,
                length: p.l,
                speed: p.v,
            },
            RoadKind::Step => Road::Step { height: p.h },
            RoadKind::Sine => Road::Sine {
                amplitude: p.h,
                frequency_hz: p.f_road,
            },
            RoadKind::Random => {
                let seed = p.seed.round().max(0.0) as u64;
                let key = (p.class, p.v.to_bits(), seed);
                let cached = match &self.random {
                    Some((k, r)) if *k == key => Some(r.clone()),
                    _ => None,
                };
                let built = cached.or_else(|| {
                    // The spatial frequencies that reach ROAD_BAND at this speed, within
                    // ISO 8608's 0.011–2.83 cycles/m.
                    let n_min = (ROAD_BAND.0 / p.v).clamp(0.011, 1.0);
                    let n_max = (ROAD_BAND.1 / p.v).clamp(n_min * 2.0, 2.83);
                    RandomRoad::new(RandomRoadConfig {
                        class: p.class,
                        speed: p.v,
                        n_min,
                        n_max,
                        components: ROAD_COMPONENTS,
                        seed,
                    })
                    .ok()
                });
                match built {
                    Some(r) => {
                        self.random = Some((key, r.clone()));
                        Road::Random(r)
                    }
                    None => Road::Flat,
                }
            }
        };
    }

    /// The exact response from rest over `[0, t_end]`, the tyre unable to pull; `None`
    /// (and an empty run) if the solver refuses the run. Kept while the car, the road and
    /// `t_end` stay the same.
    pub fn integrate(&mut self, car: &TwoDof, t_end: f64) -> Option<ExactMetrics> {
        if let Some((c, road, t, metrics)) = &self.last_run {
            if c == car && *road == self.road && *t == t_end {
                return *metrics;
            }
        }
        let metrics = self.run(car, t_end);
        self.last_run = Some((*car, self.road.clone(), t_end, metrics));
        metrics
    }

    fn run(&mut self, car: &TwoDof, t_end: f64) -> Option<ExactMetrics> {
        let run = car
            .ride_exact(&self.road, t_end, Tyre::Unilateral, &mut self.samples)
            .ok();
        self.states.clear();
        self.times.clear();
        self.road_u.clear();
        self.contact.clear();
        let run = run?;
        self.times = run.t;
        self.states = run.y;
        self.road_u = run.u;
        self.contact = run.contact;
        Some(run.metrics)
    }

    /// The frequency responses over [`FRF_RANGE`] at log-spaced frequencies (kept while the
    /// car stays the same).
    pub fn sweep(&mut self, car: &TwoDof) {
        if self.last_sweep.as_ref() == Some(car) {
            return;
        }
        self.last_sweep = Some(*car);
        let tau = std::f64::consts::TAU;
        self.omegas.clear();
        self.omegas.resize(FRF_POINTS, 0.0);
        if logspace_into(tau * FRF_RANGE.0, tau * FRF_RANGE.1, &mut self.omegas).is_err() {
            self.omegas.clear();
        }
        self.frf.clear();
        self.frf.resize(self.omegas.len(), Frf::default());
        car.frf_into(&self.omegas, &mut self.frf);
    }

    /// The state at `t` \[s\], linear between grid points; `None` before any run.
    pub fn state_at(&self, t: f64) -> Option<[f64; 4]> {
        if self.states.is_empty() || self.states.len() != self.times.len() {
            return None;
        }
        let mut s = [0.0; 4];
        let mut column = Vec::with_capacity(self.states.len());
        for (k, sk) in s.iter_mut().enumerate() {
            column.clear();
            column.extend(self.states.iter().map(|y| y[k]));
            *sk = interpolate(&self.times, &column, t)?;
        }
        Some(s)
    }

    /// The largest excursion of body, wheel or road `u` \[m\] (at least 1 µm): the scale of
    /// the schematic.
    pub fn reach(&self, u: f64) -> f64 {
        self.states
            .iter()
            .flat_map(|y| [y[0].abs(), y[1].abs()])
            .fold(u.abs(), f64::max)
            .max(1e-6)
    }
}
