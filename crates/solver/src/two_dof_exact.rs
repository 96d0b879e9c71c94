//! Exact runs of the two-DOF quarter car ([`crate::two_dof`]) on a road held linear
//! between its samples ([`SampledRoad`]), with a tyre that can pull (bilateral, the linear
//! model) or cannot (unilateral: it leaves the road when its force would turn negative).
//!
//! Between two road samples the road is `u(t) = u_i + s_i·(t − t_i)`, so the car obeys the
//! linear system `z' = M·z` on the augmented state `z = [z_s, z_u, z_s', z_u', u, s, 1]`
//! (m, m, m/s, m/s, m, m/s, −) with
//!
//! ```text
//! m_s·z_s'' = −k_s·(z_s − z_u) − c_s·(z_s' − z_u')
//! m_u·z_u'' =  k_s·(z_s − z_u) + c_s·(z_s' − z_u') + F_t − P,   P = (m_s + m_u)·g,
//! F_t = P − k_t·(z_u − u) − c_t·(z_u' − u')        in contact (bilateral: always),
//! F_t = 0                                           in flight (unilateral, when F_t ≤ 0),
//! ```
//!
//! displacements from static equilibrium, upward positive; `F_t` is the whole tyre force,
//! static preload `P` included. Each piece is solved exactly, `z(t + τ) = e^{Mτ}·z(t)`
//! ([`crate::expm::expm`]); a switch between contact and flight is located inside the step
//! where `F_t` changes sign (false position on the exact flow, to 1e-12 of the step), and
//! the run continues from there with the other matrix. So the only approximation left is
//! the road's: a smooth road sampled every `Δt` is replaced by its chords, off by at most
//! `Δt²/8·max|u''|` — the caller chooses `Δt` (e.g. 128 samples per bump).
//!
//! Metrics are integrals over the run, not sums over a grid: on each exact piece of length
//! `τ` the squares of body acceleration and tyre deflection are integrated by 3-point
//! Gauss–Legendre quadrature, relative error ≈ `(2ωτ)⁶/2·10⁶` for content at `ω`
//! (below 1e-12 at 200 pieces per wheel-hop period); the peak suspension travel is refined
//! between the quadrature points by golden-section search on the exact flow.
//!
//! ```
//! use zeta_solver::road::SampledRoad;
//! use zeta_solver::two_dof::{Road, TwoDof, TwoDofConfig};
//! use zeta_solver::two_dof_exact::{ExactConfig, Tyre};
//! let car = TwoDof::new(TwoDofConfig::default()).unwrap();
//! let mut road = SampledRoad::default();
//! road.fill_uniform(&Road::Step { height: 0.05 }, 1000.0, 2.0);
//! let run = car.run_exact(&road, ExactConfig { tyre: Tyre::Unilateral, max_step: 2e-3 }).unwrap();
//! assert_eq!(run.metrics.window, 2.0);
//! // An ideal 5 cm kerb (met within the first 1 ms sample) throws the wheel for a moment.
//! assert!(run.metrics.airborne_time > 0.0 && run.metrics.airborne_time < 0.01);
//! assert!((run.y.last().unwrap()[0] - 0.05).abs() < 1e-3); // the body settles on the kerb
//! ```

use crate::expm::{expm, mat_vec};
use crate::road::SampledRoad;
use crate::two_dof::{Road, TwoDof, G};
use std::fmt;

/// Size of the augmented state `[z_s, z_u, z_s', z_u', u, s, 1]`.
const NZ: usize = 7;
type Mat = [[f64; NZ]; NZ];
type Z = [f64; NZ];

/// Gauss–Legendre nodes on `[0, 1]`: `½ ∓ √15/10` and `½`.
const NODES: [f64; 3] = [0.112_701_665_379_258_3, 0.5, 0.887_298_334_620_741_7];
/// Their weights `5/18, 8/18, 5/18`.
const WEIGHTS: [f64; 3] = [5.0 / 18.0, 8.0 / 18.0, 5.0 / 18.0];
/// Most exact pieces a run may take.
pub const MAX_PIECES: usize = 400_000;
/// Most contact switches located inside one step (beyond, the step ends in its mode).
const MAX_SWITCHES_PER_STEP: usize = 8;
/// Pieces whose lengths differ by less than this fraction share one flow: sample times
/// rounded at `t ≈ 10 s` make equal steps differ by ~1e-11 of a 0.1 ms step, and using the
/// cached step moves the state by under 1e-9 of a step's motion.
const SAME_STEP: f64 = 1e-9;
/// Iterations of the switch location.
const ITERATIONS: usize = 60;

/// How the tyre meets the road.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Tyre {
    /// A linear spring (and damper) that can pull the wheel down onto the road.
    Bilateral,
    /// The tyre can only push: its force `max(0, P − k_t·(z_u − u) − c_t·(z_u' − u'))`.
    Unilateral,
}

/// Settings of [`TwoDof::run_exact`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ExactConfig {
    /// Tyre contact model.
    pub tyre: Tyre,
    /// Longest exact piece (s), > 0: road intervals longer than this are split, so that a
    /// contact switch is looked for, and the states are reported, at least this often
    /// (e.g. a fortieth of the wheel-hop period).
    pub max_step: f64,
}

/// Why a run could not be made.
#[derive(Debug, Clone, PartialEq)]
pub enum ExactError {
    /// Fewer than two road samples, or times not increasing and finite.
    InvalidRoad,
    /// `max_step` not finite and positive (s).
    InvalidStep {
        /// The step given (s).
        h: f64,
    },
    /// The run would need more than [`MAX_PIECES`] pieces.
    TooManySteps {
        /// Pieces needed.
        needed: f64,
    },
}

impl fmt::Display for ExactError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ExactError::InvalidRoad => write!(
                f,
                "the road needs at least two samples at increasing, finite times"
            ),
            ExactError::InvalidStep { h } => {
                write!(f, "the longest step must be positive, got {h} s")
            }
            ExactError::TooManySteps { needed } => write!(
                f,
                "the run would take {needed} steps, more than the limit of {MAX_PIECES}"
            ),
        }
    }
}

impl std::error::Error for ExactError {}

/// Ride and road-holding measures of an exact run over its whole window `[t₀, t_end]`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ExactMetrics {
    /// Length of the window `T = t_end − t₀` (s) that the RMS values average over.
    pub window: f64,
    /// `√(∫ z_s''² dt / T)` (m/s²) — ride comfort, unweighted.
    pub rms_body_acceleration: f64,
    /// `√(∫ (z_u − u)² dt / T)` (m) — road holding; `z_u − u` above the static deflection
    /// `δ₀` is the wheel off the road.
    pub rms_tyre_deflection: f64,
    /// `max |z_s − z_u|` over the window (m) — rattle space used.
    pub max_suspension_travel: f64,
    /// When the largest travel occurs (s).
    pub time_of_max_travel: f64,
    /// Total time the tyre force is zero (unilateral) or would be negative (bilateral) (s).
    pub airborne_time: f64,
    /// First time the tyre force reaches zero (s), if it does.
    pub first_lift_off: Option<f64>,
    /// Number of lift-offs.
    pub lift_offs: usize,
}

/// An exact run: states at every road sample, every split of a long interval and every
/// contact switch, and its metrics.
#[derive(Debug, Clone, PartialEq)]
pub struct ExactRun {
    /// Times (s), increasing.
    pub t: Vec<f64>,
    /// States `[z_s, z_u, z_s', z_u']` at `t`.
    pub y: Vec<[f64; 4]>,
    /// Road height `u` at `t` (m).
    pub u: Vec<f64>,
    /// Whether the tyre pushes on the road (`F_t > 0`) just after `t`.
    pub contact: Vec<bool>,
    /// Integrals and extremes over the run.
    pub metrics: ExactMetrics,
}

/// `e^{Mτ}` at the Gauss nodes and at the end of a piece of length `τ`.
type Flow = [Mat; 4];

fn flow(m: &Mat, tau: f64) -> Flow {
    let at = |c: f64| expm(&scaled(m, c * tau));
    [at(NODES[0]), at(NODES[1]), at(NODES[2]), at(1.0)]
}

fn scaled(m: &Mat, s: f64) -> Mat {
    let mut out = *m;
    out.iter_mut().flatten().for_each(|v| *v *= s);
    out
}

/// `F·z` for a flow `F = e^{Mτ}` of the augmented system, `free` when `M` is the matrix
/// in flight: [`mat_vec`] without the terms that are exactly zero. `M` is block
/// upper-triangular — the road `(u, s, 1)` does not depend on the car; `s` and `1` are
/// constant — and [`expm`]'s sums and products keep its zeros exactly zero, so in every
/// flow rows 5 and 6 are those of the identity, row 4 is zero in columns 0–3, and rows 0–3
/// are zero in column 6 in contact (no gravity term) and in columns 4–5 in flight (no road
/// term). The sums of the remaining terms, in the same order, are the same numbers.
fn apply(f: &Mat, z: &Z, free: bool) -> Z {
    let mut out = *z;
    for (o, r) in out[..4].iter_mut().zip(&f[..4]) {
        let car = r[0] * z[0] + r[1] * z[1] + r[2] * z[2] + r[3] * z[3];
        *o = if free {
            car + r[6] * z[6]
        } else {
            car + r[4] * z[4] + r[5] * z[5]
        };
    }
    let r = &f[4];
    out[4] = r[4] * z[4] + r[5] * z[5] + r[6] * z[6];
    out
}

/// The states at a piece's Gauss nodes and end, from its start `z` ([`apply`]).
fn at_nodes(f: &Flow, z: &Z, free: bool) -> [Z; 4] {
    [
        apply(&f[0], z, free),
        apply(&f[1], z, free),
        apply(&f[2], z, free),
        apply(&f[3], z, free),
    ]
}

/// Most terms of a [`TravelSeries`].
const SERIES_TERMS: usize = 40;

/// The suspension travel `z_s − z_u` along the exact flow `e^{Mτ}·z` as its Taylor series
/// `Σ_k c_k·τ^k`, `c_k = (M^k·z)_0/k! − (M^k·z)_1/k!`, for `0 ≤ τ ≤ reach`: one cheap
/// polynomial instead of a matrix exponential per evaluation.
struct TravelSeries {
    coefficients: Vec<f64>,
}

impl TravelSeries {
    /// The series, summed until two successive terms of the state, `(M^k·z)·reach^k/k!`
    /// (displacements, and velocities times `reach`), are below `1e-17·scale` (m); `None`
    /// when that takes more than [`SERIES_TERMS`] terms. On a piece (`reach` at most a
    /// two-hundredth of the wheel-hop period) the terms fall by `|λ|·reach/k ≲ 0.03/k` a
    /// step, so a dozen terms do.
    fn new(m: &Mat, z: &Z, reach: f64, scale: f64) -> Option<Self> {
        let tol = 1e-17 * scale;
        let (mut v, mut power, mut small) = (*z, 1.0, 0);
        let mut coefficients = vec![v[0] - v[1]];
        for k in 1..SERIES_TERMS {
            let inv = 1.0 / k as f64;
            v = mat_vec(m, &v).map(|x| x * inv);
            power *= reach;
            coefficients.push(v[0] - v[1]);
            let size = (v[0].abs() + v[1].abs() + reach * (v[2].abs() + v[3].abs())) * power;
            small = if size <= tol { small + 1 } else { 0 };
            if small == 2 && k >= 3 {
                return Some(Self { coefficients });
            }
        }
        None
    }

    /// `z_s − z_u` at `τ` (Horner).
    fn at(&self, tau: f64) -> f64 {
        self.coefficients
            .iter()
            .rev()
            .fold(0.0, |acc, c| acc * tau + c)
    }
}

/// The running integrals and extremes.
struct Tally {
    acc2: f64,
    defl2: f64,
    airborne: f64,
    first_lift_off: Option<f64>,
    lift_offs: usize,
    /// Largest |travel| seen at a quadrature point or piece end.
    peak: f64,
    /// Where the peak lies: the piece (start state, flight?, start time) and the bracket
    /// `(τ_lo, τ_hi)` around the best point; a second one when the best point ends a piece
    /// (the true peak may then lie just inside the next piece).
    brackets: [Option<Bracket>; 2],
    /// The best point ended the last piece: bracket the start of the next one too.
    peak_at_end: bool,
}

/// A piece of the run and an interval of it, `(start state, flight?, start time, (τ_lo, τ_hi))`.
type Bracket = (Z, bool, f64, (f64, f64));

struct Runner<'a> {
    car: &'a TwoDof,
    unilateral: bool,
    contact_m: Mat,
    flight_m: Mat,
    /// Flows of full pieces, by piece length.
    cache: Vec<(f64, Flow, Option<Flow>)>,
    preload: f64,
    tally: Tally,
    out: ExactRun,
}

impl Runner<'_> {
    /// Whether the mode's matrix is the one in flight (only with a unilateral tyre).
    fn free(&self, flight: bool) -> bool {
        flight && self.unilateral
    }

    fn matrix(&self, flight: bool) -> &Mat {
        if self.free(flight) {
            &self.flight_m
        } else {
            &self.contact_m
        }
    }

    /// Tyre force `F_t = P − k_t·(z_u − u) − c_t·(z_u' − u')` (N) as the contact law would
    /// have it (positive = pushing).
    fn tyre_force(&self, z: &Z) -> f64 {
        let c = self.car.config();
        self.preload - c.k_t * (z[1] - z[4]) - c.c_t * (z[3] - z[5])
    }

    fn body_acceleration(&self, z: &Z) -> f64 {
        self.car.body_acceleration(&[z[0], z[1], z[2], z[3]])
    }

    /// The flow over a full piece of length `h`, from the cache when a piece of the same
    /// length (to 1e-12) was seen.
    fn cached(&mut self, h: f64, flight: bool) -> &Flow {
        let want_flight = self.free(flight);
        let hit = self
            .cache
            .iter()
            .position(|(hc, _, _)| (hc - h).abs() <= SAME_STEP * hc);
        let i = match hit {
            Some(i) => i,
            None => {
                if self.cache.len() >= 8 {
                    self.cache.remove(0);
                }
                self.cache.push((h, flow(&self.contact_m, h), None));
                self.cache.len() - 1
            }
        };
        let (_, contact, in_flight) = &mut self.cache[i];
        if !want_flight {
            return contact;
        }
        in_flight.get_or_insert_with(|| flow(&self.flight_m, h))
    }

    /// Whether state `z` would leave the current mode: contact → flight when `F_t < 0`,
    /// flight → contact when `F_t > 0`; as a signed distance, positive when it would.
    fn leaving(&self, z: &Z, flight: bool) -> f64 {
        let f = self.tyre_force(z);
        if flight {
            f
        } else {
            -f
        }
    }

    /// Advances `z` over one step of length `h` from `t`, switching modes where the tyre
    /// force changes sign; integrates the metrics and records the states.
    fn step(&mut self, z: &mut Z, t: f64, h: f64, flight: &mut bool) {
        let (mut t, mut rem, mut switches) = (t, h, 0);
        loop {
            let free = self.free(*flight);
            let pts = if rem == h {
                at_nodes(self.cached(h, *flight), z, free)
            } else {
                at_nodes(&flow(self.matrix(*flight), rem), z, free)
            };
            let taus = [NODES[0] * rem, NODES[1] * rem, NODES[2] * rem, rem];
            let hit = pts.iter().position(|p| self.leaving(p, *flight) > 0.0);
            if let (Some(k), true) = (hit, switches < MAX_SWITCHES_PER_STEP) {
                let lo = if k == 0 { 0.0 } else { taus[k - 1] };
                let tau = self.locate(z, *flight, lo, taus[k], h);
                if tau > 0.0 {
                    let pts = at_nodes(&flow(self.matrix(*flight), tau), z, free);
                    let end = self.piece(z, t, tau, &pts, *flight);
                    *z = end;
                    t += tau;
                    rem -= tau;
                }
                *flight = !*flight;
                if *flight {
                    self.tally.lift_offs += 1;
                    self.tally.first_lift_off.get_or_insert(t);
                }
                switches += 1;
                self.push(t, z, *flight);
                if rem > 1e-12 * h {
                    continue;
                }
                return;
            }
            let end = self.piece(z, t, rem, &pts, *flight);
            *z = end;
            self.push(t + rem, z, *flight);
            return;
        }
    }

    /// Integrates the metrics over one exact piece from `z` at `t`, length `tau`, given the
    /// states `pts` at its Gauss nodes and its end, and returns the end.
    fn piece(&mut self, z: &Z, t: f64, tau: f64, pts: &[Z; 4], flight: bool) -> Z {
        for (p, w) in pts.iter().zip(WEIGHTS) {
            let a = self.body_acceleration(p);
            let d = p[1] - p[4];
            self.tally.acc2 += w * tau * a * a;
            self.tally.defl2 += w * tau * d * d;
        }
        if flight {
            self.tally.airborne += tau;
        }
        let end = pts[3];
        // Peak travel: the largest of the five points, bracketed by its neighbours.
        let taus = [0.0, NODES[0] * tau, NODES[1] * tau, NODES[2] * tau, tau];
        let vals = [z, &pts[0], &pts[1], &pts[2], &end].map(|p| (p[0] - p[1]).abs());
        if self.tally.peak_at_end {
            self.tally.brackets[1] = Some((*z, flight, t, (0.0, taus[1])));
            self.tally.peak_at_end = false;
        }
        for (k, &v) in vals.iter().enumerate() {
            if v > self.tally.peak {
                let lo = taus[k.saturating_sub(1)];
                let hi = taus[(k + 1).min(4)];
                self.tally.peak = v;
                self.tally.brackets = [Some((*z, flight, t, (lo, hi))), None];
                self.tally.peak_at_end = k == 4;
            }
        }
        end
    }

    /// First `τ` in `(lo, hi]` where the state flowing from `z` leaves its mode (false
    /// position, Illinois variant, on the exact flow), to 1e-12 of the step `h`.
    fn locate(&self, z: &Z, flight: bool, mut lo: f64, mut hi: f64, h: f64) -> f64 {
        let m = *self.matrix(flight);
        let g = |tau: f64| self.leaving(&mat_vec(&expm(&scaled(&m, tau)), z), flight);
        let (mut glo, mut ghi) = (g(lo).min(0.0), g(hi));
        let mut side = 0;
        for _ in 0..ITERATIONS {
            if hi - lo <= 1e-12 * h || ghi <= 0.0 {
                break;
            }
            let mut mid = hi - ghi * (hi - lo) / (ghi - glo);
            if !(mid > lo && mid < hi) {
                mid = 0.5 * (lo + hi);
            }
            let gm = g(mid);
            if gm > 0.0 {
                hi = mid;
                ghi = gm;
                if side == 1 {
                    glo *= 0.5;
                }
                side = 1;
            } else {
                lo = mid;
                glo = gm.min(0.0);
                if side == -1 {
                    ghi *= 0.5;
                }
                side = -1;
            }
        }
        hi
    }

    fn push(&mut self, t: f64, z: &Z, flight: bool) {
        self.out.t.push(t);
        self.out.y.push([z[0], z[1], z[2], z[3]]);
        self.out.u.push(z[4]);
        self.out.contact.push(!flight);
    }

    /// The largest |travel| and its time, refined by golden-section search on the exact
    /// flow within each bracket.
    fn refined_peak(&self) -> (f64, f64) {
        let mut best = (self.tally.peak, 0.0);
        if let Some((_, _, t0, (lo, hi))) = self.tally.brackets[0] {
            best.1 = t0 + 0.5 * (lo + hi);
        }
        for &(z, flight, t0, (lo, hi)) in self.tally.brackets.iter().flatten() {
            let m = *self.matrix(flight);
            let found = match TravelSeries::new(&m, &z, hi, self.tally.peak) {
                Some(series) => crate::search::maximise(|tau| series.at(tau).abs(), lo, hi),
                None => crate::search::maximise(
                    |tau| {
                        let p = mat_vec(&expm(&scaled(&m, tau)), &z);
                        (p[0] - p[1]).abs()
                    },
                    lo,
                    hi,
                ),
            };
            if let Some((tau, v)) = found {
                if v > best.0 {
                    best = (v, t0 + tau);
                }
            }
        }
        best
    }
}

impl TwoDof {
    /// The augmented matrix `M` of the module docs, in contact or in flight.
    fn augmented(&self, flight: bool) -> Mat {
        let c = self.config();
        let (ms, mu) = (c.sprung_mass, c.unsprung_mass);
        let mut m = [[0.0; NZ]; NZ];
        m[0][2] = 1.0;
        m[1][3] = 1.0;
        m[2] = [
            -c.k_s / ms,
            c.k_s / ms,
            -c.c_s / ms,
            c.c_s / ms,
            0.0,
            0.0,
            0.0,
        ];
        m[3] = [
            c.k_s / mu,
            -c.k_s / mu,
            c.c_s / mu,
            -c.c_s / mu,
            0.0,
            0.0,
            0.0,
        ];
        if flight {
            m[3][6] = -(ms + mu) * G / mu;
        } else {
            m[3][1] -= c.k_t / mu;
            m[3][3] -= c.c_t / mu;
            m[3][4] = c.k_t / mu;
            m[3][5] = c.c_t / mu;
        }
        m[4][5] = 1.0;
        m
    }

    /// The exact response to the road `road`, linear between its samples, over the
    /// samples' span, from rest in static equilibrium on the road's first height
    /// (`z_s = z_u = u(t₀)`, tyre in contact); see the module docs.
    pub fn run_exact(&self, road: &SampledRoad, cfg: ExactConfig) -> Result<ExactRun, ExactError> {
        let (ts, us) = (road.times(), road.heights());
        let valid = ts.len() >= 2
            && ts.iter().all(|t| t.is_finite())
            && us.iter().all(|u| u.is_finite())
            && ts.windows(2).all(|w| w[1] > w[0]);
        if !valid {
            return Err(ExactError::InvalidRoad);
        }
        if !(cfg.max_step.is_finite() && cfg.max_step > 0.0) {
            return Err(ExactError::InvalidStep { h: cfg.max_step });
        }
        let needed: f64 = ts
            .windows(2)
            .map(|w| ((w[1] - w[0]) / cfg.max_step * (1.0 - 1e-9)).ceil())
            .sum();
        if needed > MAX_PIECES as f64 {
            return Err(ExactError::TooManySteps { needed });
        }
        let capacity = needed as usize + 16;
        let mut r = Runner {
            car: self,
            unilateral: cfg.tyre == Tyre::Unilateral,
            contact_m: self.augmented(false),
            flight_m: self.augmented(true),
            cache: Vec::new(),
            preload: self.static_tyre_deflection() * self.config().k_t,
            tally: Tally {
                acc2: 0.0,
                defl2: 0.0,
                airborne: 0.0,
                first_lift_off: None,
                lift_offs: 0,
                peak: 0.0,
                brackets: [None, None],
                peak_at_end: false,
            },
            out: ExactRun {
                t: Vec::with_capacity(capacity),
                y: Vec::with_capacity(capacity),
                u: Vec::with_capacity(capacity),
                contact: Vec::with_capacity(capacity),
                metrics: ExactMetrics {
                    window: 0.0,
                    rms_body_acceleration: 0.0,
                    rms_tyre_deflection: 0.0,
                    max_suspension_travel: 0.0,
                    time_of_max_travel: ts[0],
                    airborne_time: 0.0,
                    first_lift_off: None,
                    lift_offs: 0,
                },
            },
        };
        // At rest in static equilibrium on the road as it is at the start.
        let mut z: Z = [us[0], us[0], 0.0, 0.0, us[0], 0.0, 1.0];
        let mut flight = r.tyre_force(&z) <= 0.0;
        if flight {
            r.tally.lift_offs = 1;
            r.tally.first_lift_off = Some(ts[0]);
        }
        r.push(ts[0], &z, flight);
        for (w, v) in ts.windows(2).zip(us.windows(2)) {
            let span = w[1] - w[0];
            let n = (span / cfg.max_step * (1.0 - 1e-9)).ceil().max(1.0);
            let h = span / n;
            let slope = (v[1] - v[0]) / span;
            for j in 0..n as usize {
                // Restart each step on the road's chord, so rounding never accumulates in u.
                let s = j as f64 * h;
                z[4] = v[0] + slope * s;
                z[5] = slope;
                z[6] = 1.0;
                r.step(&mut z, w[0] + s, h, &mut flight);
            }
        }
        let window = ts[ts.len() - 1] - ts[0];
        let (peak, at) = r.refined_peak();
        let at = at.max(ts[0]);
        let t = &r.tally;
        r.out.metrics = ExactMetrics {
            window,
            rms_body_acceleration: (t.acc2 / window).sqrt(),
            rms_tyre_deflection: (t.defl2 / window).sqrt(),
            max_suspension_travel: peak,
            time_of_max_travel: at,
            airborne_time: t.airborne,
            first_lift_off: t.first_lift_off,
            lift_offs: t.lift_offs,
        };
        Ok(r.out)
    }
}

/// Road samples (and exact pieces) per wheel-hop period at least. The wheel follows the
/// road below wheel hop, so the tyre deflection `z_u − u ≈ −(m_u/k_t)·u''` is small, and a
/// chord's sag `Δt²·u''/8` is `(ω_hop·Δt)²/8 ≈ 1.2e-4` of it at 200 per period: this
/// bounds the relative error of the tyre deflection on any smooth road.
pub const PIECES_PER_HOP: f64 = 200.0;
/// Road samples over one `1 − cos` bump: its chords are off by at most
/// `h·π²/(4·128²) ≈ 1.5e-4·h`, and their area is exact (trapezoid rule on a periodic
/// function).
pub const SAMPLES_PER_BUMP: usize = 128;
/// Road samples per period of a sinusoid (the sine road, or the random road's highest
/// component): the chords' fundamental is `sinc²(1/100) ≈ 1 − 3.3e-4` of the sinusoid.
pub const SAMPLES_PER_PERIOD: f64 = 100.0;

impl TwoDof {
    /// The exact response over `[0, t_end]` (s) to `road`, sampled so that every feature is
    /// resolved: the longest chord is a two-hundredth ([`PIECES_PER_HOP`]) of the wheel-hop
    /// period, a bump gets [`SAMPLES_PER_BUMP`] chords, a sinusoid (or the random road's
    /// highest component) [`SAMPLES_PER_PERIOD`] per period. `samples` is reused for the
    /// road's samples. Errors as [`Self::run_exact`].
    pub fn ride_exact(
        &self,
        road: &Road,
        t_end: f64,
        tyre: Tyre,
        samples: &mut SampledRoad,
    ) -> Result<ExactRun, ExactError> {
        let hop = self.natural_frequencies_hz()[1];
        let max_step = 1.0 / (PIECES_PER_HOP * hop);
        if !(t_end.is_finite() && t_end > 0.0) {
            return Err(ExactError::InvalidRoad);
        }
        let pieces = |span: f64, h: f64| {
            let n = (span / h * (1.0 - 1e-9)).ceil();
            if n.is_finite() && n <= MAX_PIECES as f64 {
                Ok((n as usize).max(1))
            } else {
                Err(ExactError::TooManySteps { needed: n })
            }
        };
        match road {
            Road::Bump { length, speed, .. } if *length > 0.0 && *speed > 0.0 => {
                let on = (length / speed).min(t_end);
                let fine = (on / SAMPLES_PER_BUMP as f64).min(max_step);
                samples.fill_segments(
                    road,
                    &[
                        (on, pieces(on, fine)?),
                        (t_end, pieces(t_end - on, max_step)?),
                    ],
                );
            }
            Road::Sine { frequency_hz, .. } => {
                let h = max_step.min(1.0 / (SAMPLES_PER_PERIOD * frequency_hz.abs()));
                samples.fill_segments(road, &[(t_end, pieces(t_end, h)?)]);
            }
            Road::Random(r) => {
                let h = max_step.min(1.0 / (SAMPLES_PER_PERIOD * r.highest_frequency_hz()));
                samples.fill_segments(road, &[(t_end, pieces(t_end, h)?)]);
            }
            _ => samples.fill_segments(road, &[(t_end, pieces(t_end, max_step)?)]),
        }
        self.run_exact(
            samples,
            ExactConfig {
                tyre,
                max_step: max_step * (1.0 + 1e-9),
            },
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::two_dof::TwoDofConfig;

    fn car() -> TwoDof {
        let c_t = 300.0;
        TwoDof::new(TwoDofConfig {
            c_t,
            ..TwoDofConfig::default()
        })
        .unwrap()
    }

    #[test]
    fn apply_gives_the_same_numbers_as_the_full_product() {
        let z: Z = [0.031, -0.017, 0.42, -1.3, 0.012, 0.25, 1.0];
        for free in [false, true] {
            let m = car().augmented(free);
            for tau in [1e-4, 4.2e-4, 3e-3, 0.05] {
                for f in flow(&m, tau) {
                    let (full, fast) = (mat_vec(&f, &z), apply(&f, &z, free));
                    // Equal as numbers (a zero's sign aside).
                    assert!(
                        full.iter().zip(&fast).all(|(a, b)| a == b),
                        "{full:?} {fast:?}"
                    );
                }
            }
        }
    }

    #[test]
    fn the_travel_series_follows_the_exact_flow() {
        let z: Z = [0.031, -0.017, 0.42, -1.3, 0.012, 0.25, 1.0];
        for free in [false, true] {
            let m = car().augmented(free);
            let reach = 4.2e-4;
            let series = TravelSeries::new(&m, &z, reach, 0.05).unwrap();
            for k in 0..=10 {
                let tau = reach * f64::from(k) / 10.0;
                let p = mat_vec(&expm(&scaled(&m, tau)), &z);
                let exact = p[0] - p[1];
                assert!((series.at(tau) - exact).abs() < 1e-15, "{tau}");
            }
        }
    }
}
