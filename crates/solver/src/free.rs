//! Closed-form free response of `a·x'' + b·x' + c·x = 0` from `x(0) = x0`, `x'(0) = v0`.
//!
//! One formula covers every regime. With `α = b/(2a)`, `ω_n² = c/a` and `d = α² − ω_n²`,
//!
//! `x(t) = e^{−αt}·[x0·C(t) + (v0 + α·x0)·S(t)]`,
//!
//! where `C` and `S` solve `C' = d·S`, `S' = C`, `C(0) = 1`, `S(0) = 0`:
//! `C = cos(ω_d t)`, `S = sin(ω_d t)/ω_d` when `d < 0` (`ω_d = √−d`);
//! `C = 1`, `S = t` when `d = 0`; `C = cosh(μt)`, `S = sinh(μt)/μ` when `d > 0` (`μ = √d`).
//! Both are continuous in `d`, so nothing blows up or cancels as `ζ → 1` or `ζ → 0` from
//! either side. Units: `x` in the unit of `x0`, `t` in s, `v0` in that unit per s.
//!
//! ```
//! use zeta_solver::{FreeResponse, SecondOrder};
//! let sys = SecondOrder::from_natural(2.0, 0.0).unwrap();
//! let r = FreeResponse::new(sys, 1.0, 0.0);
//! // Undamped: x(t) = cos(2t).
//! assert!((r.displacement(0.3) - (0.6f64).cos()).abs() < 1e-15);
//! ```

use crate::model::SecondOrder;

/// Below this `|d|·t²` the series for `cos`/`cosh` and `sin(x)/x` are used: they are exact
/// to double precision there and avoid `0/0` at `d = 0`.
const SERIES_LIMIT: f64 = 1e-4;

/// The basis pair `(C(t), S(t))` for `d = α² − ω_n²`, both multiplied by `e^{−αt}`.
///
/// For `d > 0` and large `μt` the exponentials are combined (`e^{(μ−α)t}`) so a decaying
/// overdamped response never forms `∞·0`.
fn damped_basis(alpha: f64, d: f64, t: f64) -> (f64, f64) {
    let x = d * t * t;
    if x.abs() < SERIES_LIMIT {
        // cos/cosh(√d t) = 1 + x/2 + x²/24 + x³/720;  S/t = 1 + x/6 + x²/120 + x³/5040.
        let e = (-alpha * t).exp();
        let c = 1.0 + x * (0.5 + x * (1.0 / 24.0 + x / 720.0));
        let s = t * (1.0 + x * (1.0 / 6.0 + x * (1.0 / 120.0 + x / 5040.0)));
        return (e * c, e * s);
    }
    if d < 0.0 {
        let wd = (-d).sqrt();
        let e = (-alpha * t).exp();
        let (sn, cs) = (wd * t).sin_cos();
        (e * cs, e * sn / wd)
    } else {
        let mu = d.sqrt();
        if mu * t < 1.0 {
            let e = (-alpha * t).exp();
            (e * (mu * t).cosh(), e * (mu * t).sinh() / mu)
        } else {
            let grow = ((mu - alpha) * t).exp();
            let fall = ((-mu - alpha) * t).exp();
            (0.5 * (grow + fall), 0.5 * (grow - fall) / mu)
        }
    }
}

/// The free response of one system from one initial state.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FreeResponse {
    alpha: f64,
    wn2: f64,
    d: f64,
    x0: f64,
    v0: f64,
}

impl FreeResponse {
    /// Free response of `sys` from displacement `x0` and velocity `v0`.
    ///
    /// Non-finite initial conditions give non-finite samples; the app validates them first.
    pub fn new(sys: SecondOrder, x0: f64, v0: f64) -> Self {
        let alpha = sys.alpha();
        let wn2 = sys.omega_n_squared();
        // Exactly critical within the regime tolerance: use d = 0 so the critically
        // damped solution is the one drawn.
        let d = if sys.regime() == crate::Regime::CriticallyDamped {
            0.0
        } else {
            alpha * alpha - wn2
        };
        Self {
            alpha,
            wn2,
            d,
            x0,
            v0,
        }
    }

    /// Displacement `x(t)`.
    pub fn displacement(&self, t: f64) -> f64 {
        let (c, s) = damped_basis(self.alpha, self.d, t);
        self.x0 * c + (self.v0 + self.alpha * self.x0) * s
    }

    /// Velocity `x'(t) = e^{−αt}·[v0·C(t) − (ω_n²·x0 + α·v0)·S(t)]`.
    pub fn velocity(&self, t: f64) -> f64 {
        let (c, s) = damped_basis(self.alpha, self.d, t);
        self.v0 * c - (self.wn2 * self.x0 + self.alpha * self.v0) * s
    }

    /// Acceleration `x''(t) = e^{−αt}·[m·C(t) + (v0·d − α·m)·S(t)]` with
    /// `m = −(ω_n²·x0 + 2α·v0)`: differentiated from the velocity, not taken from the ODE,
    /// so the ODE residual is an independent check.
    pub fn acceleration(&self, t: f64) -> f64 {
        let (c, s) = damped_basis(self.alpha, self.d, t);
        let m = -(self.wn2 * self.x0 + self.alpha * self.v0);
        (m - self.alpha * self.v0) * c + (self.v0 * self.d - self.alpha * m) * s
    }

    /// The decay envelope `A·e^{−αt}` of an oscillating response (`ζ < 1`), with
    /// `A = √(x0² + ((v0 + α·x0)/ω_d)²)` and `ω_d = √(ω_n² − α²)` \[rad/s\]: the response
    /// touches `±` this curve once per half period. `None` when the response does not
    /// oscillate (`ζ ≥ 1`).
    pub fn envelope(&self, t: f64) -> Option<f64> {
        Some(self.envelope_amplitude()? * (-self.alpha * t).exp())
    }

    /// The amplitude `A` of [`FreeResponse::envelope`] at `t = 0`, in the unit of `x0`;
    /// `None` when the response does not oscillate.
    pub fn envelope_amplitude(&self) -> Option<f64> {
        (self.d < 0.0).then(|| {
            let wd = (-self.d).sqrt();
            let s = (self.v0 + self.alpha * self.x0) / wd;
            (self.x0 * self.x0 + s * s).sqrt()
        })
    }

    /// State `[x, x']` at `t`.
    pub fn state(&self, t: f64) -> [f64; 2] {
        let (c, s) = damped_basis(self.alpha, self.d, t);
        [
            self.x0 * c + (self.v0 + self.alpha * self.x0) * s,
            self.v0 * c - (self.wn2 * self.x0 + self.alpha * self.v0) * s,
        ]
    }

    /// Fills `out[i] = x(t[i])`; `out` and `t` must have the same length (extra entries of
    /// the longer one are left alone). Allocation-free, for redraws while a slider moves.
    pub fn sample_into(&self, t: &[f64], out: &mut [f64]) {
        for (o, &ti) in out.iter_mut().zip(t) {
            *o = self.displacement(ti);
        }
    }

    /// `(t_i, x(t_i))` at the `n` times `t_i = start + i·Δ`, `Δ = (end − start)/(n − 1)`
    /// ([`linspace`]'s), by the exact step from one to the next instead of the closed form
    /// at each: `[x, x']_{i+1} = Φ·[x, x']_i` with the transition matrix
    ///
    /// `Φ = [[C + α·S, S], [−ω_n²·S, C − α·S]]`, `(C, S)` the damped basis at `Δ` (module
    /// docs), which is the closed form's own map from one state to the state `Δ` later.
    ///
    /// One basis evaluation (an `exp` and a `sin_cos`) instead of one per point, then four
    /// products per point: a redraw samples several curves of hundreds of points each per
    /// frame (about 1 µs a point in the browser at 4× CPU slowdown). Each step rounds once
    /// more, so the error grows with the number of points: against the closed form the
    /// points agree within `2·(n + 8)·ε` of the curve's largest `|x|` (`ε` = 2.2e-16;
    /// 2.3e-13 of it at 500 points), tested across the regimes, growing ones included.
    /// Units as [`FreeResponse::displacement`].
    pub fn trace(&self, (start, end): (f64, f64), n: usize) -> Vec<(f64, f64)> {
        let times = linspace(start, end, n);
        let Some(&t0) = times.first() else {
            return Vec::new();
        };
        let step = if n > 1 {
            (end - start) / (n - 1) as f64
        } else {
            0.0
        };
        let (c, s) = damped_basis(self.alpha, self.d, step);
        let phi = [[c + self.alpha * s, s], [-self.wn2 * s, c - self.alpha * s]];
        let mut z = self.state(t0);
        times
            .into_iter()
            .map(|t| {
                let x = z[0];
                z = [
                    phi[0][0] * z[0] + phi[0][1] * z[1],
                    phi[1][0] * z[0] + phi[1][1] * z[1],
                ];
                (t, x)
            })
            .collect()
    }
}

/// `n ≥ 2` evenly spaced points from `start` to `end` inclusive (`n < 2` gives `[start]`
/// or nothing).
pub fn linspace(start: f64, end: f64, n: usize) -> Vec<f64> {
    match n {
        0 => Vec::new(),
        1 => vec![start],
        _ => {
            let step = (end - start) / (n - 1) as f64;
            (0..n).map(|i| start + step * i as f64).collect()
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn residual(a: f64, b: f64, c: f64, x0: f64, v0: f64, t: f64) -> f64 {
        let sys = SecondOrder::new(a, b, c).unwrap();
        let r = FreeResponse::new(sys, x0, v0);
        let (x, v, acc) = (r.displacement(t), r.velocity(t), r.acceleration(t));
        let scale = (a * acc.abs())
            .max(b.abs() * v.abs())
            .max(c.abs() * x.abs())
            .max(1e-300);
        (a * acc + b * v + c * x).abs() / scale
    }

    #[test]
    fn satisfies_the_ode_in_every_regime() {
        for &zeta in &[
            -0.5, -0.01, 0.0, 1e-12, 0.05, 0.3, 0.7, 0.999_999, 1.0, 1.000_001, 1.5, 3.0,
        ] {
            let wn = 8.944_271_909_999_16;
            for &t in &[0.0, 1e-6, 0.01, 0.1, 0.37, 1.0, 2.5] {
                let res = residual(1.0, 2.0 * zeta * wn, wn * wn, 0.06, -0.3, t);
                assert!(res < 1e-12, "ζ={zeta} t={t}: relative residual {res}");
            }
        }
        // Neutral and divergent systems.
        assert!(residual(1.0, 1.0, 0.0, 1.0, 1.0, 0.8) < 1e-12);
        assert!(residual(1.0, 1.0, -4.0, 1.0, 1.0, 0.8) < 1e-12);
    }

    #[test]
    fn a_trace_follows_the_closed_form_in_every_regime() {
        let wn = 8.944_271_909_999_16;
        let zetas = [
            -0.3, -0.01, 0.0, 1e-9, 0.05, 0.3, 0.999_999, 1.0, 1.000_001, 2.0, 1e3,
        ];
        for &zeta in &zetas {
            let r = FreeResponse::new(SecondOrder::from_natural(wn, zeta).unwrap(), 0.06, -0.4);
            for &(range, n) in &[((0.0, 3.0), 500), ((0.0, 3.0), 10_000), ((0.25, 1.5), 2)] {
                let traced = r.trace(range, n);
                assert_eq!(traced.len(), n);
                let biggest = traced.iter().fold(0.0f64, |m, p| m.max(p.1.abs()));
                // Measured: at most 0.62·n·ε for n ≥ 500, 13·ε for one step.
                let bound = 2.0 * (n as f64 + 8.0) * f64::EPSILON * biggest;
                for (&(t, x), tk) in traced.iter().zip(linspace(range.0, range.1, n)) {
                    assert_eq!(t, tk);
                    let err = (x - r.displacement(t)).abs();
                    assert!(err <= bound, "ζ={zeta} n={n} t={t}: off by {err:e}");
                }
            }
        }
        let r = FreeResponse::new(SecondOrder::from_natural(wn, 0.3).unwrap(), 1.0, 0.0);
        assert!(r.trace((0.0, 1.0), 0).is_empty());
        assert_eq!(r.trace((0.5, 1.0), 1), vec![(0.5, r.displacement(0.5))]);
    }

    #[test]
    fn meets_initial_conditions() {
        for &zeta in &[-0.2, 0.0, 0.5, 1.0, 2.0] {
            let r = FreeResponse::new(SecondOrder::from_natural(3.0, zeta).unwrap(), 0.06, 1.5);
            assert_eq!(r.displacement(0.0), 0.06);
            assert_eq!(r.velocity(0.0), 1.5);
        }
    }

    #[test]
    fn continuous_across_critical_damping() {
        let x = |z: f64, t: f64| {
            FreeResponse::new(
                SecondOrder::from_natural(8.944_271_909_999_16, z).unwrap(),
                0.06,
                0.0,
            )
            .displacement(t)
        };
        for &t in &[0.01, 0.1, 0.3, 1.0, 3.0] {
            let x1 = x(1.0, t);
            for &z in &[1.0 - 1e-9, 1.0 + 1e-9, 1.0 - 1e-6, 1.0 + 1e-6] {
                let tol = if (z - 1.0f64).abs() < 1e-8 {
                    1e-7
                } else {
                    1e-5
                };
                assert!((x(z, t) - x1).abs() <= tol * 0.06, "ζ={z} t={t}");
            }
        }
    }

    #[test]
    fn critical_matches_textbook_form() {
        // ζ = 1: x(t) = (x0 + (v0 + ω_n x0) t) e^{−ω_n t}.
        let (wn, x0, v0) = (4.0, 0.5, -1.0);
        let r = FreeResponse::new(SecondOrder::from_natural(wn, 1.0).unwrap(), x0, v0);
        for &t in &[0.0, 0.2, 1.0, 5.0] {
            let exact = (x0 + (v0 + wn * x0) * t) * (-wn * t).exp();
            assert!((r.displacement(t) - exact).abs() < 1e-15);
        }
    }

    #[test]
    fn underdamped_matches_textbook_form() {
        // x(t) = e^{−ζω_n t}[x0 cos ω_d t + (v0 + ζω_n x0)/ω_d sin ω_d t].
        let (wn, z, x0, v0) = (8.944_271_909_999_16, 0.3_f64, 0.06, 0.0);
        let wd = wn * (1.0 - z * z).sqrt();
        let r = FreeResponse::new(SecondOrder::from_natural(wn, z).unwrap(), x0, v0);
        for &t in &[0.1, 0.5, 1.3] {
            let e = (-z * wn * t).exp();
            let exact = e * (x0 * (wd * t).cos() + (v0 + z * wn * x0) / wd * (wd * t).sin());
            assert!((r.displacement(t) - exact).abs() < 1e-15);
        }
    }

    #[test]
    fn heavily_overdamped_decays_without_overflow() {
        let r = FreeResponse::new(SecondOrder::from_natural(1.0, 1e6).unwrap(), 1.0, 0.0);
        let x = r.displacement(1e3);
        assert!(x.is_finite() && x > 0.0 && x <= 1.0);
        let tail = r.displacement(1e8);
        assert!(tail.is_finite() && tail < 1.0);
    }

    #[test]
    fn the_envelope_bounds_the_response_and_touches_it() {
        let sys = SecondOrder::from_natural(3.0, 0.2).unwrap();
        let r = FreeResponse::new(sys, 0.05, 0.4);
        let mut touched = 0;
        for i in 0..4000 {
            let t = i as f64 * 1e-3;
            let (x, e) = (r.displacement(t), r.envelope(t).unwrap());
            assert!(x.abs() <= e * (1.0 + 1e-12));
            if (x.abs() - e).abs() < 1e-4 * e {
                touched += 1;
            }
        }
        assert!(touched > 0);
        let over = FreeResponse::new(SecondOrder::from_natural(3.0, 1.5).unwrap(), 0.05, 0.0);
        assert_eq!(over.envelope(1.0), None);
    }

    #[test]
    fn linspace_ends_exactly() {
        let g = linspace(0.0, 2.0, 5);
        assert_eq!(g, vec![0.0, 0.5, 1.0, 1.5, 2.0]);
        assert!(linspace(0.0, 1.0, 0).is_empty());
    }
}
