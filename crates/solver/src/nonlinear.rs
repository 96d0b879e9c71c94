//! Nonlinear quarter car: Duffing spring, asymmetric damper, Coulomb friction, bump stops.
//!
//! `m·x'' + F_d(x') + F_s(x) + F_f(x') + F_stop(x) = 0`, free response from `x(0) = x0`,
//! `x'(0) = v0`, with
//!
//! - spring `F_s = k·x + k3·x³` (Duffing: `k3 > 0` hardening, `k3 < 0` softening) (N);
//! - damper `F_d = c_compression·x'` for `x' < 0`, `c_rebound·x'` for `x' > 0` (N);
//! - Coulomb friction `F_f = F_c·tanh(x'/v_ε)` (N), a smooth stand-in for `F_c·sign(x')`
//!   (the regularisation keeps the right-hand side smooth enough for RK4; within
//!   `|x'| ≲ v_ε` the friction is smaller than `F_c`, so a "stuck" mass creeps slowly);
//! - bump stops `F_stop = k_stop·(x − gap)` for `x > gap`, `k_stop·(x + gap)` for
//!   `x < −gap`, else 0 (N).
//!
//! Sign convention: `x` (m) is the suspension extension from static equilibrium (body up
//! relative to the wheel); `x' > 0` is rebound (extension), `x' < 0` compression.
//!
//! ```
//! use zeta_solver::nonlinear::{NonlinearConfig, NonlinearModel};
//! // A hardening spring oscillates faster than the linear one at large amplitude.
//! let model = NonlinearModel::new(NonlinearConfig {
//!     k3: 2.0e6, ..NonlinearConfig::default()
//! }).unwrap();
//! let cmp = model.compare(0.08, 0.0, 5.0, 1e-3).unwrap();
//! assert!(cmp.period_ratio().unwrap() < 1.0);
//! ```

use crate::error::{finite, non_negative, positive, ModelError};
use crate::free::FreeResponse;
use crate::integrate::{FixedStep, IntegrationError, Rk4, Solution, System};
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
    /// Coulomb friction force `F_c` (N), ≥ 0. Default 0.
    pub friction: f64,
    /// Friction regularisation velocity `v_ε` (m/s), > 0. Default 1e−3.
    pub friction_velocity: f64,
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
            friction_velocity: 1e-3,
            stop_gap: 0.1,
            stop_stiffness: 0.0,
        }
    }
}

/// A validated nonlinear quarter car; integrates as a [`System<2>`] on `[x, x']`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct NonlinearModel {
    cfg: NonlinearConfig,
}

/// Where and when a mass held by Coulomb friction came to rest.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Sticking {
    /// Time of the first stop from which the restoring force cannot break away (s).
    pub t: f64,
    /// Rest position `x` (m); `|F_s(x) + F_stop(x)| ≤ F_c` there.
    pub x: f64,
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
}

impl Comparison {
    /// Period of the nonlinear response from its upward zero crossings (s); `None` with
    /// fewer than two.
    pub fn period_nonlinear(&self) -> Option<f64> {
        let x: Vec<f64> = self.nonlinear.iter().map(|s| s[0]).collect();
        period_from_zero_crossings(&self.t, &x)
    }

    /// Period of the linear response, measured the same way (s) (equals `2π/ω_d`).
    pub fn period_linear(&self) -> Option<f64> {
        let x: Vec<f64> = self.linear.iter().map(|s| s[0]).collect();
        period_from_zero_crossings(&self.t, &x)
    }

    /// `T_nonlinear / T_linear` (-): below 1 for a hardening spring, above for softening.
    pub fn period_ratio(&self) -> Option<f64> {
        Some(self.period_nonlinear()? / self.period_linear()?)
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
        let x: Vec<f64> = self.nonlinear.iter().map(|s| s[0]).collect();
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
        positive(
            "friction regularisation velocity",
            "m/s",
            cfg.friction_velocity,
        )?;
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

    /// Damper plus friction force `F_d(v) + F_f(v)` (N) at velocity `v` (m/s).
    pub fn dissipative_force(&self, v: f64) -> f64 {
        let c = &self.cfg;
        let damper = if v < 0.0 {
            c.c_compression * v
        } else {
            c.c_rebound * v
        };
        damper + c.friction * (v / c.friction_velocity).tanh()
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

    /// Free response from `[x0, v0]` over `[0, t_end]` by RK4 with step at most `h` (s)
    /// (resolve the fastest dynamics: the bump-stop frequency `√((k + k_stop)/m)` and the
    /// friction layer `m·v_ε/F_c`).
    pub fn simulate(
        &self,
        x0: f64,
        v0: f64,
        t_end: f64,
        h: f64,
    ) -> Result<Solution<2>, IntegrationError> {
        Rk4.solve(self, [x0, v0], 0.0, t_end, h)
    }

    /// Allocation-free variant of [`Self::simulate`]: `out[i]` is the state at `i·h`.
    pub fn simulate_into(
        &self,
        x0: f64,
        v0: f64,
        h: f64,
        out: &mut [[f64; 2]],
    ) -> Result<(), IntegrationError> {
        Rk4.solve_into(self, [x0, v0], 0.0, h, out).map(|_| ())
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
        })
    }

    /// Like [`Self::compare`], on the grid `t_i = i·h`, `i = 0 … steps`, and never failing:
    /// the nonlinear run is cut (and [`Comparison::escaped`] set) at the first state that
    /// is not finite or whose travel `|x|` exceeds `escape` (m) — a softening spring that
    /// gave way. The linear closed form fills the same (possibly shortened) grid.
    pub fn compare_steps(&self, x0: f64, v0: f64, h: f64, steps: usize, escape: f64) -> Comparison {
        let n = steps + 1;
        let mut nonlinear = vec![[0.0; 2]; n];
        let mut valid = match self.simulate_into(x0, v0, h, &mut nonlinear) {
            Ok(()) => n,
            // Slot i holds the state at i·h; the failing step was the one to `t`.
            Err(IntegrationError::NonFinite { t }) => ((t / h).round() as usize).min(n),
            Err(_) => 0,
        };
        let mut escaped = valid < n;
        if let Some(i) = nonlinear[..valid]
            .iter()
            .position(|p| p[0].is_nan() || p[0].abs() > escape)
        {
            valid = i;
            escaped = true;
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
        let x: Vec<f64> = sol.y.iter().map(|s| s[0]).collect();
        period_from_zero_crossings(&sol.t, &x)
    }

    /// The first time the mass stops where friction can hold it: a grid point at which the
    /// velocity reverses sign or `|x'| ≤ v_ε` while `|F_s(x) + F_stop(x)| ≤ F_c`. `None`
    /// without friction or if it never happens in `sol`.
    pub fn sticking(&self, sol: &Solution<2>) -> Option<Sticking> {
        self.sticking_in(&sol.t, &sol.y)
    }

    /// [`Self::sticking`] on a run given as times `t` (s) and states `y` = `[x, x']`.
    pub fn sticking_in(&self, t: &[f64], y: &[[f64; 2]]) -> Option<Sticking> {
        let c = &self.cfg;
        if c.friction <= 0.0 {
            return None;
        }
        let mut prev_v: Option<f64> = None;
        for (&t, s) in t.iter().zip(y) {
            let [x, v] = *s;
            let reversed = prev_v.is_some_and(|p| p * v < 0.0);
            let slow = v.abs() <= c.friction_velocity;
            if (reversed || slow) && prev_v.is_some() && self.elastic_force(x).abs() <= c.friction {
                return Some(Sticking { t, x });
            }
            prev_v = Some(v);
        }
        None
    }
}

impl System<2> for NonlinearModel {
    fn rhs(&self, _t: f64, y: &[f64; 2], dy: &mut [f64; 2]) {
        dy[0] = y[1];
        dy[1] = -(self.dissipative_force(y[1]) + self.elastic_force(y[0])) / self.cfg.mass;
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
            friction_velocity: 0.0,
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
