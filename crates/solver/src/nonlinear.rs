//! Nonlinear quarter car: Duffing spring, asymmetric damper, Coulomb friction, bump stops.
//!
//! `m·x'' + F_d(x') + F_s(x) + F_f(x') + F_stop(x) = 0`, free response from `x(0) = x0`,
//! `x'(0) = v0`, with
//!
//! - spring `F_s = k·x + k3·x³` (Duffing: `k3 > 0` hardening, `k3 < 0` softening) (N);
//! - damper `F_d = c_compression·x'` for `x' < 0`, `c_rebound·x'` for `x' > 0` (N);
//! - Coulomb friction with a static/kinetic switch (stick–slip): while the mass slides,
//!   `F_f = F_c·sign(x')` with the kinetic force `F_c` (N); once it comes to rest it stays
//!   stuck — exactly, it does not creep — as long as the restoring force
//!   `|F_s(x) + F_stop(x)|` does not exceed the static force `F_static ≥ F_c` (N), and breaks
//!   away into a slide only when it does;
//! - bump stops `F_stop = k_stop·(x − gap)` for `x > gap`, `k_stop·(x + gap)` for
//!   `x < −gap`, else 0 (N).
//!
//! Sign convention: `x` (m) is the suspension extension from static equilibrium (body up
//! relative to the wheel); `x' > 0` is rebound (extension), `x' < 0` compression.
//!
//! Integration: RK4 on a fixed grid, with the contact state (sliding one way, sliding the
//! other, stuck) as a mode. Within a step the right-hand side is smooth; when the velocity
//! reaches zero inside a step, the instant is found by bisection on the step fraction (to
//! 10⁻¹³ of the step), the stick test is made there, and the rest of the step continues in
//! the new mode. Every reversal of the velocity — also of the asymmetric damper — is
//! therefore resolved, not smoothed.
//!
//! ```
//! use zeta_solver::nonlinear::{period_from_zero_crossings, NonlinearConfig, NonlinearModel};
//! // A hardening spring oscillates faster than the linear one at large amplitude.
//! let model = NonlinearModel::new(NonlinearConfig {
//!     k3: 2.0e6, ..NonlinearConfig::default()
//! }).unwrap();
//! let cmp = model.compare(0.08, 0.0, 5.0, 1e-3).unwrap();
//! assert!(cmp.period_ratio(period_from_zero_crossings).unwrap() < 1.0);
//! ```

use crate::error::{finite, non_negative, positive, ModelError};
use crate::free::FreeResponse;
use crate::integrate::{IntegrationError, Solution, Stats};
use crate::model::SecondOrder;

/// Parameters of [`NonlinearModel`]; SI units.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct NonlinearConfig {
    /// Sprung mass `m` (kg), > 0. Default 300.
    pub mass: f64,
    /// Linear spring rate `k` (N/m), finite. Default 24 000.
    pub k: f64,
    /// Cubic spring coefficient `k3` (N/m³), finite (> 0 hardening, < 0 softening).
    /// Default 0.
    pub k3: f64,
    /// Damper rate in compression (`x' < 0`) (N·s/m), finite. Default 1 610.
    pub c_compression: f64,
    /// Damper rate in rebound (`x' > 0`) (N·s/m), finite. Default 1 610.
    pub c_rebound: f64,
    /// Kinetic Coulomb friction force `F_c` (N) while sliding, ≥ 0. Default 0.
    pub friction: f64,
    /// Static friction force `F_static` (N) that holds the mass at rest, ≥ 0; values below
    /// `F_c` count as `F_c` (static friction is never weaker than kinetic). Default 0.
    pub static_friction: f64,
    /// Free travel before a bump stop engages, `gap` (m), > 0. Default 0.1.
    pub stop_gap: f64,
    /// Bump-stop rate `k_stop` (N/m), ≥ 0 (0 = no stops). Default 0.
    pub stop_stiffness: f64,
}

impl Default for NonlinearConfig {
    fn default() -> Self {
        Self {
            mass: 300.0,
            k: 24_000.0,
            k3: 0.0,
            c_compression: 1_610.0,
            c_rebound: 1_610.0,
            friction: 0.0,
            static_friction: 0.0,
            stop_gap: 0.1,
            stop_stiffness: 0.0,
        }
    }
}

/// A validated nonlinear quarter car; integrates as a [`System<2>`](crate::integrate::System) on `[x, x']`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct NonlinearModel {
    cfg: NonlinearConfig,
}

/// Where and when a mass held by Coulomb friction came to rest.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Sticking {
    /// Time of the stop from which the restoring force cannot break away (s).
    pub t: f64,
    /// Rest position `x` (m); `|F_s(x) + F_stop(x)| ≤ F_static` there.
    pub x: f64,
}

/// The friction contact during one step: sliding in direction `±1`, or stuck.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Contact {
    Sliding(f64),
    Stuck,
}

/// The nonlinear and the linear model from the same initial state on one time grid.
#[derive(Debug, Clone, PartialEq)]
pub struct Comparison {
    /// Time points (s).
    pub t: Vec<f64>,
    /// Nonlinear states `[x, x']` (RK4).
    pub nonlinear: Vec<[f64; 2]>,
    /// Linear states `[x, x']` (closed form, see [`NonlinearModel::linear_model`]).
    pub linear: Vec<[f64; 2]>,
    /// Whether the nonlinear run was cut short because it left the allowed travel or
    /// stopped being finite (see [`NonlinearModel::compare_steps`]).
    pub escaped: bool,
    /// Where and when friction stopped the nonlinear run for good (the exact event).
    pub sticking: Option<Sticking>,
}

/// The displacement `x` (m), the first component, of each `[x, v]` state.
fn displacements(states: &[[f64; 2]]) -> Vec<f64> {
    states.iter().map(|s| s[0]).collect()
}

/// A period measure of a displacement history, `(t, x) -> period` (s): e.g.
/// [`period_from_zero_crossings`] (mean spacing of the upward zero crossings) or
/// [`first_swing_period`].
pub type PeriodMeasure = fn(&[f64], &[f64]) -> Option<f64>;

impl Comparison {
    /// `measure` applied to the displacements of `states` (one of the two runs) on `t`.
    fn period_of(&self, states: &[[f64; 2]], measure: PeriodMeasure) -> Option<f64> {
        measure(&self.t, &displacements(states))
    }

    /// Period of the nonlinear response by `measure` (s); `None` where it finds none
    /// (e.g. fewer than two upward zero crossings).
    pub fn period_nonlinear(&self, measure: PeriodMeasure) -> Option<f64> {
        self.period_of(&self.nonlinear, measure)
    }

    /// Period of the linear response by `measure` (s): `2π/ω_d` for either measure here,
    /// since a damped sinusoid crosses zero every half damped period.
    pub fn period_linear(&self, measure: PeriodMeasure) -> Option<f64> {
        self.period_of(&self.linear, measure)
    }

    /// `T_nonlinear / T_linear` (-) by `measure`: below 1 for a hardening spring, above for
    /// softening.
    pub fn period_ratio(&self, measure: PeriodMeasure) -> Option<f64> {
        Some(self.period_nonlinear(measure)? / self.period_linear(measure)?)
    }

    /// Period of the first full swing of the nonlinear response (s), see
    /// [`first_swing_period`].
    pub fn first_swing_nonlinear(&self) -> Option<f64> {
        self.period_nonlinear(first_swing_period)
    }

    /// Period of the first full swing of the linear response (s): `2π/ω_d` exactly.
    pub fn first_swing_linear(&self) -> Option<f64> {
        self.period_linear(first_swing_period)
    }

    /// First-swing period ratio `T_nonlinear / T_linear` (-).
    pub fn first_swing_ratio(&self) -> Option<f64> {
        self.period_ratio(first_swing_period)
    }

    /// The largest finite `|x_nl(t) − x_lin(t)|` (m) and the first time (s) it occurs;
    /// `(0, 0)` on an empty run.
    pub fn largest_deviation(&self) -> (f64, f64) {
        self.nonlinear
            .iter()
            .zip(&self.linear)
            .zip(&self.t)
            .map(|((a, b), &t)| ((a[0] - b[0]).abs(), t))
            .filter(|d| d.0.is_finite())
            .fold((0.0, 0.0), |acc, d| if d.0 > acc.0 { d } else { acc })
    }

    /// The nonlinear displacement (m) at time `t` (s), linearly interpolated on the grid
    /// and held at the ends; `None` on an empty run.
    pub fn nonlinear_at(&self, t: f64) -> Option<f64> {
        let x = displacements(&self.nonlinear);
        crate::grid::interpolate(&self.t, &x, t)
    }

    /// `max |x_nl(t) − x_lin(t)|` over the grid (m).
    pub fn max_deviation(&self) -> f64 {
        self.nonlinear
            .iter()
            .zip(&self.linear)
            .map(|(a, b)| (a[0] - b[0]).abs())
            .fold(
                0.0,
                |acc: f64, d| if d.is_nan() { f64::NAN } else { acc.max(d) },
            )
    }
}

/// Period (s) of the first full swing of `x(t)`: the time from its first zero crossing to
/// its third (either direction, each located by linear interpolation; a sample exactly at
/// zero does not count as a crossing). `None` with fewer than three crossings. For a
/// decaying oscillation this reads the period while the amplitude is still large, where a
/// nonlinear spring shows most.
pub fn first_swing_period(t: &[f64], x: &[f64]) -> Option<f64> {
    let mut crossings = [0.0; 3];
    let mut n = 0;
    for (tw, xw) in t.windows(2).zip(x.windows(2)) {
        if let ([t0, t1], [x0, x1]) = (tw, xw) {
            if (*x0 < 0.0 && *x1 >= 0.0) || (*x0 > 0.0 && *x1 <= 0.0) {
                crossings[n] = t0 + (t1 - t0) * x0 / (x0 - x1);
                n += 1;
                if n == 3 {
                    return Some(crossings[2] - crossings[0]);
                }
            }
        }
    }
    None
}

/// Period (s) from the upward zero crossings of `x(t)` (`x[i] < 0 ≤ x[i+1]`), each located
/// by linear interpolation (error O(h³) at a crossing of an oscillator, where `x'' ≈ 0`):
/// `(t_last − t_first)/(n − 1)`. `None` with fewer than two crossings.
pub fn period_from_zero_crossings(t: &[f64], x: &[f64]) -> Option<f64> {
    let mut first = None;
    let mut last = 0.0;
    let mut count = 0usize;
    for (tw, xw) in t.windows(2).zip(x.windows(2)) {
        if let ([t0, t1], [x0, x1]) = (tw, xw) {
            if *x0 < 0.0 && *x1 >= 0.0 {
                let tc = t0 + (t1 - t0) * (-x0) / (x1 - x0);
                first.get_or_insert(tc);
                last = tc;
                count += 1;
            }
        }
    }
    let first = first?;
    (count >= 2).then(|| (last - first) / (count - 1) as f64)
}

/// Undamped period of the linear spring alone, `T = 2π·√(m/k)` (s), for mass `m` (kg) and
/// spring rate `k` (N/m); `None` unless both are positive and finite.
pub fn undamped_period(mass: f64, k: f64) -> Option<f64> {
    let t = std::f64::consts::TAU * (mass / k).sqrt();
    (mass > 0.0 && k > 0.0 && t.is_finite()).then_some(t)
}

impl NonlinearModel {
    /// Validates the configuration (see the field docs for the ranges).
    pub fn new(cfg: NonlinearConfig) -> Result<Self, ModelError> {
        positive("mass m", "kg", cfg.mass)?;
        finite("spring rate k", "N/m", cfg.k)?;
        finite("cubic spring coefficient k3", "N/m³", cfg.k3)?;
        finite("compression damping", "N·s/m", cfg.c_compression)?;
        finite("rebound damping", "N·s/m", cfg.c_rebound)?;
        non_negative("friction force F_c", "N", cfg.friction)?;
        non_negative("static friction force", "N", cfg.static_friction)?;
        positive("bump-stop gap", "m", cfg.stop_gap)?;
        non_negative("bump-stop rate", "N/m", cfg.stop_stiffness)?;
        Ok(Self { cfg })
    }

    /// The validated parameters.
    pub fn config(&self) -> NonlinearConfig {
        self.cfg
    }

    /// Spring plus bump-stop force `F_s(x) + F_stop(x)` (N) at extension `x` (m).
    pub fn elastic_force(&self, x: f64) -> f64 {
        let c = &self.cfg;
        let stop = if x > c.stop_gap {
            c.stop_stiffness * (x - c.stop_gap)
        } else if x < -c.stop_gap {
            c.stop_stiffness * (x + c.stop_gap)
        } else {
            0.0
        };
        c.k * x + c.k3 * x * x * x + stop
    }

    /// Damper plus sliding friction force `F_d(v) + F_c·sign(v)` (N) at velocity `v` (m/s)
    /// (0 at `v = 0`, where static friction holds up to [`Self::static_limit`]).
    pub fn dissipative_force(&self, v: f64) -> f64 {
        self.damper_force(v) + self.cfg.friction * sign(v)
    }

    /// Damper force `F_d(v)` (N): `c_compression·v` for `v < 0`, `c_rebound·v` otherwise.
    fn damper_force(&self, v: f64) -> f64 {
        let c = &self.cfg;
        if v < 0.0 {
            c.c_compression * v
        } else {
            c.c_rebound * v
        }
    }

    /// The largest restoring force static friction holds, `max(F_static, F_c)` (N).
    pub fn static_limit(&self) -> f64 {
        self.cfg.static_friction.max(self.cfg.friction)
    }

    /// Whether a mass at rest at `x` (m) stays stuck: `|F_s(x) + F_stop(x)| ≤ F_static`.
    pub fn holds_at(&self, x: f64) -> bool {
        self.elastic_force(x).abs() <= self.static_limit()
    }

    /// The contact of a mass at rest at `x`: stuck, or sliding away from the spring force.
    fn contact_at_rest(&self, x: f64) -> Contact {
        if self.holds_at(x) {
            Contact::Stuck
        } else {
            Contact::Sliding(-sign(self.elastic_force(x)))
        }
    }

    /// One RK4 step of length `h` sliding in direction `dir` (friction `−F_c·dir`).
    fn slide(&self, y: [f64; 2], h: f64, dir: f64) -> [f64; 2] {
        let m = self.cfg.mass;
        let f = |y: [f64; 2]| {
            let a =
                -(self.damper_force(y[1]) + self.cfg.friction * dir + self.elastic_force(y[0])) / m;
            [y[1], a]
        };
        let k1 = f(y);
        let k2 = f([y[0] + 0.5 * h * k1[0], y[1] + 0.5 * h * k1[1]]);
        let k3 = f([y[0] + 0.5 * h * k2[0], y[1] + 0.5 * h * k2[1]]);
        let k4 = f([y[0] + h * k3[0], y[1] + h * k3[1]]);
        [
            y[0] + h / 6.0 * (k1[0] + 2.0 * k2[0] + 2.0 * k3[0] + k4[0]),
            y[1] + h / 6.0 * (k1[1] + 2.0 * k2[1] + 2.0 * k3[1] + k4[1]),
        ]
    }

    /// Advances `y` by `h` from contact `mode`, resolving every stop inside the step;
    /// returns the new state and mode and, if the mass stuck in this step, how far into the
    /// step (s).
    fn advance(&self, y: [f64; 2], mode: Contact, h: f64) -> ([f64; 2], Contact, Option<f64>) {
        let (mut y, mut mode, mut left) = (y, mode, h);
        // A step holds at most a few reversals; the cap only guards against a loop.
        for _ in 0..8 {
            let Contact::Sliding(dir) = mode else {
                return ([y[0], 0.0], Contact::Stuck, None);
            };
            let next = self.slide(y, left, dir);
            if next[1] * dir > 0.0 || !next[1].is_finite() {
                return (next, mode, None);
            }
            // The velocity reached zero inside the step: bisect on the step fraction.
            let (mut lo, mut hi) = (0.0_f64, 1.0_f64);
            while hi - lo > 1e-13 {
                let mid = 0.5 * (lo + hi);
                if self.slide(y, mid * left, dir)[1] * dir > 0.0 {
                    lo = mid;
                } else {
                    hi = mid;
                }
            }
            let tau = hi * left;
            y = [self.slide(y, tau, dir)[0], 0.0];
            left -= tau;
            mode = self.contact_at_rest(y[0]);
            if mode == Contact::Stuck {
                return (y, mode, Some(h - left));
            }
            if left <= 0.0 {
                return (y, mode, None);
            }
        }
        (y, mode, None)
    }

    /// The contact at the start: sliding with `v0`, or from rest at `x0`.
    fn initial(&self, x0: f64, v0: f64) -> Contact {
        if v0 != 0.0 {
            Contact::Sliding(sign(v0))
        } else {
            self.contact_at_rest(x0)
        }
    }

    /// The free response from `[x0, v0]` on the grid `out[i]` = state at `i·h`, with the
    /// stick event if friction stops it for good: the allocation-free variant of
    /// [`Self::simulate`].
    pub fn simulate_into(
        &self,
        x0: f64,
        v0: f64,
        h: f64,
        out: &mut [[f64; 2]],
    ) -> Result<Option<Sticking>, IntegrationError> {
        if !(h.is_finite() && h > 0.0) {
            return Err(IntegrationError::InvalidStep { h });
        }
        if !(x0.is_finite() && v0.is_finite()) {
            return Err(IntegrationError::NonFinite { t: 0.0 });
        }
        let mut y = [x0, v0];
        let mut mode = self.initial(x0, v0);
        let mut sticking = (mode == Contact::Stuck).then_some(Sticking { t: 0.0, x: x0 });
        for (i, slot) in out.iter_mut().enumerate() {
            if i > 0 {
                let (next, m, stuck) = self.advance(y, mode, h);
                if !(next[0].is_finite() && next[1].is_finite()) {
                    return Err(IntegrationError::NonFinite { t: h * i as f64 });
                }
                if let Some(dt) = stuck {
                    sticking = Some(Sticking {
                        t: h * (i - 1) as f64 + dt,
                        x: next[0],
                    });
                }
                y = next;
                mode = m;
            }
            *slot = y;
        }
        Ok(sticking)
    }

    /// Potential energy `U(x) = ½k·x² + ¼k3·x⁴ + ½k_stop·(|x| − gap)²₊` (J).
    pub fn potential_energy(&self, x: f64) -> f64 {
        let c = &self.cfg;
        let over = (x.abs() - c.stop_gap).max(0.0);
        0.5 * c.k * x * x + 0.25 * c.k3 * x.powi(4) + 0.5 * c.stop_stiffness * over * over
    }

    /// Mechanical energy `½m·v² + U(x)` (J) of the state `[x, v]`.
    pub fn energy(&self, state: [f64; 2]) -> f64 {
        0.5 * self.cfg.mass * state[1] * state[1] + self.potential_energy(state[0])
    }

    /// The linear model `m·x'' + c̄·x' + k·x = 0` with the mean damper rate
    /// `c̄ = (c_compression + c_rebound)/2`, no cubic term, friction or stops.
    pub fn linear_model(&self) -> Result<SecondOrder, ModelError> {
        let c = &self.cfg;
        SecondOrder::mechanical(c.mass, 0.5 * (c.c_compression + c.c_rebound), c.k)
    }

    /// Free response from `[x0, v0]` over `[0, t_end]` by RK4 with the stick–slip switch
    /// (module doc), `n = ⌈t_end/h⌉` equal steps of `t_end/n` ≤ `h` (s) (resolve the fastest
    /// dynamics: the bump-stop frequency `√((k + k_stop)/m)`).
    pub fn simulate(
        &self,
        x0: f64,
        v0: f64,
        t_end: f64,
        h: f64,
    ) -> Result<Solution<2>, IntegrationError> {
        if !(t_end.is_finite() && t_end > 0.0) {
            return Err(IntegrationError::InvalidSpan { t0: 0.0, t_end });
        }
        if !(h.is_finite() && h > 0.0) {
            return Err(IntegrationError::InvalidStep { h });
        }
        let n = (t_end / h).ceil().max(1.0) as usize;
        let step = t_end / n as f64;
        let mut y = vec![[0.0; 2]; n + 1];
        self.simulate_into(x0, v0, step, &mut y)?;
        let t = (0..=n).map(|i| step * i as f64).collect();
        Ok(Solution {
            t,
            y,
            stats: Stats {
                n_accepted: n,
                ..Stats::default()
            },
        })
    }

    /// The nonlinear (RK4) and linear (closed-form) responses from the same `[x0, v0]`.
    pub fn compare(
        &self,
        x0: f64,
        v0: f64,
        t_end: f64,
        h: f64,
    ) -> Result<Comparison, IntegrationError> {
        let sol = self.simulate(x0, v0, t_end, h)?;
        let sticking = self.sticking(&sol);
        // A validated config always gives a valid linear model; fall back to NaN otherwise.
        let linear = match self.linear_model() {
            Ok(sys) => {
                let lin = FreeResponse::new(sys, x0, v0);
                sol.t.iter().map(|&t| lin.state(t)).collect()
            }
            Err(_) => vec![[f64::NAN; 2]; sol.t.len()],
        };
        Ok(Comparison {
            t: sol.t,
            nonlinear: sol.y,
            linear,
            escaped: false,
            sticking,
        })
    }

    /// Like [`Self::compare`], on the grid `t_i = i·h`, `i = 0 … steps`, and never failing:
    /// the nonlinear run is cut (and [`Comparison::escaped`] set) at the first state that
    /// is not finite or whose travel `|x|` exceeds `escape` (m) — a softening spring that
    /// gave way. The linear closed form fills the same (possibly shortened) grid.
    pub fn compare_steps(&self, x0: f64, v0: f64, h: f64, steps: usize, escape: f64) -> Comparison {
        let n = steps + 1;
        let mut nonlinear = vec![[0.0; 2]; n];
        let (mut valid, mut sticking) = match self.simulate_into(x0, v0, h, &mut nonlinear) {
            Ok(st) => (n, st),
            // Slot i holds the state at i·h; the failing step was the one to `t`.
            Err(IntegrationError::NonFinite { t }) => (((t / h).round() as usize).min(n), None),
            Err(_) => (0, None),
        };
        let mut escaped = valid < n;
        if let Some(i) = nonlinear[..valid]
            .iter()
            .position(|p| p[0].is_nan() || p[0].abs() > escape)
        {
            valid = i;
            escaped = true;
            sticking = None;
        }
        nonlinear.truncate(valid);
        let t: Vec<f64> = (0..valid).map(|i| i as f64 * h).collect();
        let linear = match self.linear_model() {
            Ok(sys) => {
                let lin = FreeResponse::new(sys, x0, v0);
                t.iter().map(|&t| lin.state(t)).collect()
            }
            Err(_) => vec![[f64::NAN; 2]; valid],
        };
        Comparison {
            t,
            nonlinear,
            linear,
            escaped,
            sticking,
        }
    }

    /// Period (s) of the free response from `x(0) = amplitude`, `x'(0) = 0`, measured from
    /// upward zero crossings over `cycles` estimated linear periods (at least 2) with RK4
    /// steps of `T_lin/steps_per_period`. `None` if the motion does not cross zero twice
    /// (overdamped, stuck, or `k ≤ 0`) or the run fails.
    pub fn period_at_amplitude(
        &self,
        amplitude: f64,
        cycles: u32,
        steps_per_period: u32,
    ) -> Option<f64> {
        let wn = self.linear_model().ok()?.natural_frequency()?;
        let t_lin = std::f64::consts::TAU / wn;
        let t_end = t_lin * f64::from(cycles.max(2) + 1);
        let h = t_lin / f64::from(steps_per_period.max(8));
        let sol = self.simulate(amplitude, 0.0, t_end, h).ok()?;
        let x = displacements(&sol.y);
        period_from_zero_crossings(&sol.t, &x)
    }

    /// The first grid point from which the mass stays at rest for the rest of the run,
    /// held by friction (`x' = 0` there and after, `|F_s(x) + F_stop(x)| ≤ F_static`); `None`
    /// without friction or if it never happens in `sol`. The event itself lies within the
    /// step before (see [`Comparison::sticking`] for the exact instant).
    pub fn sticking(&self, sol: &Solution<2>) -> Option<Sticking> {
        self.sticking_in(&sol.t, &sol.y)
    }

    /// [`Self::sticking`] on a run given as times `t` (s) and states `y` = `[x, x']`.
    pub fn sticking_in(&self, t: &[f64], y: &[[f64; 2]]) -> Option<Sticking> {
        if self.static_limit() <= 0.0 {
            return None;
        }
        let last = y.last()?;
        if last[1] != 0.0 || !self.holds_at(last[0]) {
            return None;
        }
        let first = y.iter().rposition(|s| s != last).map_or(0, |i| i + 1);
        Some(Sticking {
            t: *t.get(first)?,
            x: last[0],
        })
    }
}

/// `+1` for `v > 0`, `−1` for `v < 0`, `0` otherwise.
fn sign(v: f64) -> f64 {
    if v > 0.0 {
        1.0
    } else if v < 0.0 {
        -1.0
    } else {
        0.0
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn forces_follow_the_sign_convention() {
        let m = NonlinearModel::new(NonlinearConfig {
            c_compression: 1000.0,
            c_rebound: 3000.0,
            stop_stiffness: 1e5,
            stop_gap: 0.05,
            ..Default::default()
        })
        .unwrap();
        // Rebound (v > 0) uses c_rebound, compression c_compression; both oppose motion.
        assert_eq!(m.dissipative_force(0.1), 300.0);
        assert_eq!(m.dissipative_force(-0.1), -100.0);
        // Stops add k_stop·(|x| − gap) beyond the gap, symmetric.
        assert!((m.elastic_force(0.06) - (24_000.0 * 0.06 + 1e5 * 0.01)).abs() < 1e-9);
        assert!((m.elastic_force(-0.06) + m.elastic_force(0.06)).abs() < 1e-9);
        // U' = F: central difference of the potential.
        for &x in &[-0.08, -0.02, 0.03, 0.07] {
            let d = 1e-6;
            let du = (m.potential_energy(x + d) - m.potential_energy(x - d)) / (2.0 * d);
            assert!((du - m.elastic_force(x)).abs() < 1e-5 * m.elastic_force(x).abs().max(1.0));
        }
    }

    #[test]
    fn invalid_parameters_are_typed_errors() {
        let bad = |c: NonlinearConfig| NonlinearModel::new(c).is_err();
        let d = NonlinearConfig::default();
        assert!(bad(NonlinearConfig { mass: 0.0, ..d }));
        assert!(bad(NonlinearConfig { k3: f64::NAN, ..d }));
        assert!(bad(NonlinearConfig {
            friction: -1.0,
            ..d
        }));
        assert!(bad(NonlinearConfig {
            static_friction: f64::NAN,
            ..d
        }));
        assert!(bad(NonlinearConfig { stop_gap: 0.0, ..d }));
        assert!(bad(NonlinearConfig {
            stop_stiffness: -1.0,
            ..d
        }));
    }

    #[test]
    fn zero_crossing_period_of_a_sine() {
        let t: Vec<f64> = (0..=10_000).map(|i| i as f64 * 1e-3).collect();
        let x: Vec<f64> = t.iter().map(|&t| (2.0 * t - 0.3).sin()).collect();
        let p = period_from_zero_crossings(&t, &x).unwrap();
        assert!((p - std::f64::consts::PI).abs() < 1e-9, "{p}");
        assert_eq!(period_from_zero_crossings(&t[..10], &x[..10]), None);
    }
}
