//! Ride comfort as engineers measure it: the RMS body acceleration of the two-DOF quarter
//! car ([`crate::two_dof`]) on an ISO 8608 road, frequency-weighted by ISO 2631-1's `W_k`
//! (vertical whole-body vibration, seated), beside the unweighted value, as stationary
//! values from a Lyapunov equation.
//!
//! **The weighting** (ISO 2631-1:1997 Annex A, Table A.1; the same parameters in ISO 8041
//! Table 3.1) is the product of four second-order sections in `s = iω` (rad/s):
//!
//! ```text
//! band limiting   H_h = s²/(s² + ω₁s/Q₁ + ω₁²)          f₁ = 0.4 Hz, Q₁ = 1/√2
//!                 H_l = ω₂²/(s² + ω₂s/Q₂ + ω₂²)          f₂ = 100 Hz, Q₂ = 1/√2
//! a–v transition  H_t = (1 + s/ω₃)/(1 + s/(Q₄ω₄) + s²/ω₄²)   f₃ = f₄ = 12.5 Hz, Q₄ = 0.63
//! upward step     H_s = (s² + ω₅s/Q₅ + ω₅²)/(s² + ω₆s/Q₆ + ω₆²)   f₅ = 2.37 Hz, Q₅ = 0.91,
//!                                                           f₆ = 3.35 Hz, Q₆ = 0.91
//! W_k = K·H_h·H_l·H_t·H_s,  K = 1,  ωᵢ = 2π·fᵢ.
//! ```
//!
//! **The road** of ISO 8608 has the one-sided displacement PSD `G_d(n) = G_d(n₀)·(n₀/n)²`
//! (m³, `n` in cycles/m, `n₀ = 0.1`); driven at `V` (m/s) its height has the temporal PSD
//! `G_u(f) = G_d(n₀)·n₀²·V/f²` (m²/Hz), i.e. the road velocity is white with
//! `G_u' = (2π·n₀)²·G_d(n₀)·V`. So that the height stays stationary, the road is the
//! shaping filter `u' = −2π·n_c·V·u + w` with `n_c` = [`ROAD_CUT_ON`] (ISO 8608's lowest
//! band), white `w` of intensity `q = G_u'/2` (two-sided); above `n_c·V` its spectrum is
//! ISO 8608's.
//!
//! **Stationary values**: with the state `x` = car `[z_s, z_u, z_s', z_u']`, road `u` and
//! the eight states of `W_k` (input: the body acceleration), `x' = A·x + b·w`; the
//! stationary covariance `P` solves the Lyapunov equation `A·P + P·Aᵀ + q·b·bᵀ = 0`
//! (solved as the linear system `(I ⊗ A + A ⊗ I)·vec P = −q·vec(b·bᵀ)`), and each RMS is
//! `√(c·P·cᵀ)` for its output row `c`.
//!
//! ```
//! use zeta_solver::ride::{stationary, W_K};
//! use zeta_solver::two_dof::{IsoClass, TwoDof, TwoDofConfig};
//! // ISO 2631-1 Table 3: W_k = 1.039 at 5 Hz, 0.482 at 1 Hz.
//! assert!((W_K.magnitude(5.0118723) - 1.039).abs() < 2e-3);
//! let car = TwoDof::new(TwoDofConfig::default()).unwrap();
//! let r = stationary(&car, IsoClass::C, 20.0).unwrap();
//! assert!(r.rms_weighted_body_acceleration < r.rms_body_acceleration);
//! ```

use crate::complex::Complex;
use crate::error::{positive, ModelError};
use crate::two_dof::{IsoClass, TwoDof, TwoDofConfig, ISO_N0};
use std::f64::consts::{FRAC_1_SQRT_2, TAU};

/// A frequency weighting of ISO 2631-1 / ISO 8041 by its parameters (Hz, -).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Weighting {
    /// High-pass corner `f₁` (Hz) and quality `Q₁`.
    pub f1: f64,
    /// Quality of the high pass.
    pub q1: f64,
    /// Low-pass corner `f₂` (Hz).
    pub f2: f64,
    /// Quality of the low pass.
    pub q2: f64,
    /// a–v transition zero `f₃` (Hz).
    pub f3: f64,
    /// a–v transition pole `f₄` (Hz).
    pub f4: f64,
    /// Quality of the a–v transition.
    pub q4: f64,
    /// Upward-step zero `f₅` (Hz).
    pub f5: f64,
    /// Quality of the step's zero.
    pub q5: f64,
    /// Upward-step pole `f₆` (Hz).
    pub f6: f64,
    /// Quality of the step's pole.
    pub q6: f64,
    /// Gain `K`.
    pub k: f64,
}

/// `W_k`, vertical (z-axis) whole-body vibration of a seated person (ISO 2631-1:1997
/// Table A.1).
pub const W_K: Weighting = Weighting {
    f1: 0.4,
    q1: FRAC_1_SQRT_2,
    f2: 100.0,
    q2: FRAC_1_SQRT_2,
    f3: 12.5,
    f4: 12.5,
    q4: 0.63,
    f5: 2.37,
    q5: 0.91,
    f6: 3.35,
    q6: 0.91,
    k: 1.0,
};

/// `(b₂s² + b₁s + b₀)/(s² + a₁s + a₀)`.
#[derive(Debug, Clone, Copy)]
struct Section {
    b: [f64; 3],
    a: [f64; 2],
}

impl Section {
    fn at(&self, s: Complex) -> Complex {
        let num = s * s * self.b[2] + s * self.b[1] + Complex::real(self.b[0]);
        let den = s * s + s * self.a[1] + Complex::real(self.a[0]);
        num / den
    }
}

impl Weighting {
    /// The four sections `H_h, H_l, H_t, H_s` as ratios of monic quadratics.
    /// Writes the sections in series into the state matrix `a` (dimension `M`), section `n`
    /// in the states `i = first + 2n` and `j = i + 1` (`x_i' = x_j`,
    /// `x_j' = −a₀·x_i − a₁·x_j + input`), where `input` is the first section's input as a
    /// combination of the `M` states. Returns the last section's output as such a
    /// combination, without the gain `k`: each section outputs
    /// `(b₀ − b₂a₀)·x_i + (b₁ − b₂a₁)·x_j + b₂·input`.
    fn cascade<const M: usize>(
        &self,
        a: &mut [[f64; M]; M],
        first: usize,
        mut input: [f64; M],
    ) -> [f64; M] {
        for (n, sec) in self.sections().iter().enumerate() {
            let (i, j) = (first + 2 * n, first + 2 * n + 1);
            a[i][j] = 1.0;
            for (k, &w) in input.iter().enumerate() {
                a[j][k] += w;
            }
            a[j][i] -= sec.a[0];
            a[j][j] -= sec.a[1];
            let mut out = input.map(|w| sec.b[2] * w);
            out[i] += sec.b[0] - sec.b[2] * sec.a[0];
            out[j] += sec.b[1] - sec.b[2] * sec.a[1];
            input = out;
        }
        input
    }

    fn sections(&self) -> [Section; 4] {
        let w = |f: f64| TAU * f;
        let (w1, w2, w3, w4, w5, w6) = (
            w(self.f1),
            w(self.f2),
            w(self.f3),
            w(self.f4),
            w(self.f5),
            w(self.f6),
        );
        [
            Section {
                b: [0.0, 0.0, 1.0],
                a: [w1 * w1, w1 / self.q1],
            },
            Section {
                b: [w2 * w2, 0.0, 0.0],
                a: [w2 * w2, w2 / self.q2],
            },
            // (1 + s/ω₃)/(1 + s/(Q₄ω₄) + s²/ω₄²) = ω₄²(1 + s/ω₃)/(s² + ω₄s/Q₄ + ω₄²).
            Section {
                b: [w4 * w4, w4 * w4 / w3, 0.0],
                a: [w4 * w4, w4 / self.q4],
            },
            Section {
                b: [w5 * w5, w5 / self.q5, 1.0],
                a: [w6 * w6, w6 / self.q6],
            },
        ]
    }

    /// The weighting's frequency response `W(i·2πf)` at `f` (Hz).
    pub fn response(&self, f_hz: f64) -> Complex {
        let s = Complex::new(0.0, TAU * f_hz);
        self.sections()
            .iter()
            .fold(Complex::real(self.k), |acc, sec| acc * sec.at(s))
    }

    /// `|W(i·2πf)|` (-) at `f` (Hz): the factor ISO 2631-1 Table 3 tabulates (×1000).
    pub fn magnitude(&self, f_hz: f64) -> f64 {
        self.response(f_hz).abs()
    }
}

/// Lowest spatial frequency of the road model `n_c = 0.011` cycles/m (ISO 8608's band):
/// the shaping filter's corner, below which the road's PSD levels off.
pub const ROAD_CUT_ON: f64 = 0.011;

/// Stationary RMS responses of the two-DOF car on an ISO 8608 road.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Stationary {
    /// Unweighted RMS body acceleration (m/s²).
    pub rms_body_acceleration: f64,
    /// RMS body acceleration weighted by `W_k` (m/s²): ISO 2631-1's comfort measure `a_w`.
    pub rms_weighted_body_acceleration: f64,
    /// RMS tyre deflection `z_u − u` (m).
    pub rms_tyre_deflection: f64,
    /// RMS suspension travel `z_s − z_u` (m).
    pub rms_suspension_travel: f64,
}

/// Car (4) + road (1) + `W_k` (8) states.
const N: usize = 13;

/// The stationary RMS responses of `car` driven at `speed` (m/s) over a road of `class`,
/// weighted by [`W_K`] (see the module docs). Errors: a non-positive speed, or a car whose
/// response does not settle (no damping at all: `c_s = c_t = 0`).
pub fn stationary(car: &TwoDof, class: IsoClass, speed: f64) -> Result<Stationary, ModelError> {
    stationary_weighted(car, class, speed, &W_K)
}

/// [`stationary`] with another weighting.
pub fn stationary_weighted(
    car: &TwoDof,
    class: IsoClass,
    speed: f64,
    weighting: &Weighting,
) -> Result<Stationary, ModelError> {
    let v = positive("speed", "m/s", speed)?;
    let c = car.config();
    let (ms, mu) = (c.sprung_mass, c.unsprung_mass);
    let mut a = [[0.0; N]; N];
    let mut b = [0.0; N];
    // Car: rows 0–3; road: row 4.
    a[0][2] = 1.0;
    a[1][3] = 1.0;
    let accel = [-c.k_s / ms, c.k_s / ms, -c.c_s / ms, c.c_s / ms, 0.0];
    a[2][..5].copy_from_slice(&accel);
    let road_pole = TAU * ROAD_CUT_ON * v;
    a[3][..5].copy_from_slice(&[
        c.k_s / mu,
        -(c.k_s + c.k_t) / mu,
        c.c_s / mu,
        -(c.c_s + c.c_t) / mu,
        (c.k_t - c.c_t * road_pole) / mu,
    ]);
    b[3] = c.c_t / mu;
    a[4][4] = -road_pole;
    b[4] = 1.0;
    // W_k, driven by the body acceleration.
    let mut input = [0.0; N];
    input[..5].copy_from_slice(&accel);
    let weighted = weighting.cascade(&mut a, 5, input).map(|w| weighting.k * w);
    let q = 0.5 * (TAU * ISO_N0).powi(2) * class.g_d_n0() * v;
    let p = lyapunov(&a, &b, q).ok_or(ModelError::OutOfRange {
        name: "suspension damping",
        reason: "the response to a random road never settles without damping",
    })?;
    let rms = |row: &[f64; N]| {
        let mut s = 0.0;
        for (i, ri) in row.iter().enumerate() {
            for (j, rj) in row.iter().enumerate() {
                s += ri * p[i * N + j] * rj;
            }
        }
        s.max(0.0).sqrt()
    };
    let mut accel_row = [0.0; N];
    accel_row[..5].copy_from_slice(&accel);
    let mut tyre = [0.0; N];
    tyre[1] = 1.0;
    tyre[4] = -1.0;
    let mut travel = [0.0; N];
    travel[0] = 1.0;
    travel[1] = -1.0;
    Ok(Stationary {
        rms_body_acceleration: rms(&accel_row),
        rms_weighted_body_acceleration: rms(&weighted),
        rms_tyre_deflection: rms(&tyre),
        rms_suspension_travel: rms(&travel),
    })
}

/// Index of the unknown `P[i][j] = P[j][i]` among the `N(N+1)/2` of a symmetric matrix.
fn sym(i: usize, j: usize) -> usize {
    let (lo, hi) = if i <= j { (i, j) } else { (j, i) };
    lo * N - lo * (lo + 1) / 2 + hi
}

/// The solution `P` (row-major, `N×N`) of `A·P + P·Aᵀ + q·b·bᵀ = 0`: the `N(N+1)/2`
/// equations `Σₖ A[i][k]·P[k][j] + Σₖ A[j][k]·P[i][k] = −q·bᵢ·bⱼ` (`i ≤ j`) in the as
/// many unknowns of the symmetric `P`, by Gaussian elimination with partial pivoting;
/// `None` when singular (eigenvalues with `λᵢ + λⱼ = 0`, e.g. an undamped mode) or when a
/// variance comes out negative or not finite (`A` not stable).
fn lyapunov(a: &[[f64; N]; N], b: &[f64; N], q: f64) -> Option<Vec<f64>> {
    let n = N * (N + 1) / 2;
    let mut m = vec![0.0; n * n];
    let mut rhs = vec![0.0; n];
    for i in 0..N {
        for j in i..N {
            let r = sym(i, j);
            for k in 0..N {
                m[r * n + sym(k, j)] += a[i][k];
                m[r * n + sym(i, k)] += a[j][k];
            }
            rhs[r] = -q * b[i] * b[j];
        }
    }
    let scale = m.iter().fold(0.0f64, |s, v| s.max(v.abs()));
    for col in 0..n {
        let pivot =
            (col..n).max_by(|&x, &y| m[x * n + col].abs().total_cmp(&m[y * n + col].abs()))?;
        let pv = m[pivot * n + col];
        if !pv.is_finite() || pv.abs() <= 1e-14 * scale {
            return None;
        }
        if pivot != col {
            for k in 0..n {
                m.swap(col * n + k, pivot * n + k);
            }
            rhs.swap(col, pivot);
        }
        for row in col + 1..n {
            let f = m[row * n + col] / pv;
            if f != 0.0 {
                for k in col..n {
                    m[row * n + k] -= f * m[col * n + k];
                }
                rhs[row] -= f * rhs[col];
            }
        }
    }
    let mut x = vec![0.0; n];
    for r in (0..n).rev() {
        let s: f64 = (r + 1..n).map(|k| m[r * n + k] * x[k]).sum();
        x[r] = (rhs[r] - s) / m[r * n + r];
    }
    let p: Vec<f64> = (0..N * N).map(|ij| x[sym(ij / N, ij % N)]).collect();
    let stable = (0..N).all(|i| p[i * N + i].is_finite() && p[i * N + i] >= 0.0);
    stable.then_some(p)
}

/// States of the car and road (`[z_s, z_u, z_s', z_u', u]`) and of the weighting.
const NC: usize = 5;
const NW: usize = 8;

/// [`stationary_weighted`] for many cars at the cost of a few small solves each: the same
/// Lyapunov equation, split into the blocks of its structure, with the weighting's own block
/// solved once in [`Ride::new`].
///
/// The state is `[x_c; x_w]` (car and road, 5; weighting, 8) with `A = [A_cc 0; A_wc A_ww]`
/// (the weighting is driven by the body acceleration and drives nothing back), noise
/// `b = [b_c; 0]`, and the weighted output `y = [c_c c_w]·x`. Its variance is
/// `q·b_cᵀ·Q_cc·b_c` with `Q` the observability Gramian, `Aᵀ·Q + Q·A + cᵀ·c = 0`, whose
/// blocks solve in turn:
///
/// ```text
/// A_wwᵀ·Q_ww + Q_ww·A_ww + c_wᵀ·c_w = 0                       (weighting only: once)
/// A_ccᵀ·Q_cw + Q_cw·A_ww + A_wcᵀ·Q_ww + c_cᵀ·c_w = 0          (Sylvester, 5×8, by 2-column
///                                                             blocks: A_ww is block lower
///                                                             triangular, one section each)
/// A_ccᵀ·Q_cc + Q_cc·A_cc + M = 0,  M = S + Sᵀ + c_cᵀ·c_c,  S = Q_cw·A_wc   (5×5)
/// ```
///
/// and `q·b_cᵀ·Q_cc·b_c = trace(M·P)` with `P` the car's own covariance, `A_cc·P + P·A_ccᵀ +
/// q·b_c·b_cᵀ = 0` (the last equation is never solved), which also gives the unweighted
/// values. So each car costs one 15-unknown and four 10-unknown solves. Agrees with
/// [`stationary_weighted`] to rounding (tests: 1e-9 relative).
#[derive(Debug, Clone, PartialEq)]
pub struct Ride {
    /// `A_ww`, row-major.
    a_ww: [[f64; NW]; NW],
    /// `A_wc = g·aᵀ` with `a` the body-acceleration row of the car: `g`.
    g: [f64; NW],
    /// `c_c = h·aᵀ`: `h` (the weighting's direct feed-through).
    h: f64,
    /// `c_w`.
    c_w: [f64; NW],
    /// `Q_ww`.
    q_ww: [[f64; NW]; NW],
}

impl Ride {
    /// The weighting's blocks and its Gramian block. Errors if the weighting is not stable
    /// (a corner frequency or quality not positive).
    pub fn new(weighting: &Weighting) -> Result<Self, ModelError> {
        // The weighting alone in the states `[a; x_w]`, `a` the body acceleration: row `1 + r`
        // holds `g[r]` in column 0 and `A_ww[r]` after it, and each section's input is
        // `h·a + w·x_w`, as in `stationary_weighted`.
        let mut a_full = [[0.0; 1 + NW]; 1 + NW];
        let mut body = [0.0; 1 + NW];
        body[0] = 1.0;
        let out = weighting.cascade(&mut a_full, 1, body);
        let g: [f64; NW] = std::array::from_fn(|r| a_full[1 + r][0]);
        let a_ww: [[f64; NW]; NW] =
            std::array::from_fn(|r| std::array::from_fn(|s| a_full[1 + r][1 + s]));
        let c_w: [f64; NW] = std::array::from_fn(|r| weighting.k * out[1 + r]);
        let h = weighting.k * out[0];
        let mut a_t = [[0.0; NW]; NW];
        let mut m = [[0.0; NW]; NW];
        for r in 0..NW {
            for s in 0..NW {
                a_t[r][s] = a_ww[s][r];
                m[r][s] = c_w[r] * c_w[s];
            }
        }
        let q_ww = lyapunov_small::<NW, 36>(&a_t, &m).ok_or(ModelError::OutOfRange {
            name: "frequency weighting",
            reason: "the weighting filter must be stable (positive corners and qualities)",
        })?;
        Ok(Self {
            a_ww,
            g,
            h,
            c_w,
            q_ww,
        })
    }

    /// `Ride` for ISO 2631-1's [`W_K`].
    pub fn w_k() -> Self {
        // W_K's sections are stable; the fallback is never taken.
        Self::new(&W_K).unwrap_or(Self {
            a_ww: [[0.0; NW]; NW],
            g: [0.0; NW],
            h: 0.0,
            c_w: [0.0; NW],
            q_ww: [[0.0; NW]; NW],
        })
    }

    /// The stationary RMS responses of `car` at `speed` (m/s) over a road of `class`:
    /// [`stationary_weighted`] with this weighting, by the block solves above. Errors as
    /// [`stationary`].
    pub fn stationary(
        &self,
        car: &TwoDof,
        class: IsoClass,
        speed: f64,
    ) -> Result<Stationary, ModelError> {
        let sys = CarRoad::new(car, class, speed)?;
        let undamped = || ModelError::OutOfRange {
            name: "suspension damping",
            reason: "the response to a random road never settles without damping",
        };
        let p = sys.covariance().ok_or_else(undamped)?;
        let weighted = self.weighted_variance(&sys, &p).ok_or_else(undamped)?;
        let rms = |var: f64| var.max(0.0).sqrt();
        Ok(Stationary {
            rms_body_acceleration: rms(quad(&p, &sys.accel)),
            rms_weighted_body_acceleration: rms(weighted),
            rms_tyre_deflection: rms(quad(&p, &[0.0, 1.0, 0.0, 0.0, -1.0])),
            rms_suspension_travel: rms(quad(&p, &[1.0, -1.0, 0.0, 0.0, 0.0])),
        })
    }

    /// The weighted body acceleration's variance `q·b_cᵀ·Q_cc·b_c` (m²/s⁴) by the
    /// Sylvester solve of the type docs, given the car's covariance `p`; `None` if singular.
    fn weighted_variance(&self, sys: &CarRoad, p: &[[f64; NC]; NC]) -> Option<f64> {
        let (a, accel) = (&sys.a, &sys.accel);
        // Sylvester: A_ccᵀ·X + X·A_ww = R, R = −a·(Q_ww·g + h·c_w)ᵀ.
        let qg: [f64; NW] = std::array::from_fn(|s| {
            let row: f64 = (0..NW).map(|t| self.q_ww[s][t] * self.g[t]).sum();
            row + self.h * self.c_w[s]
        });
        // By 2-column blocks, last first: with D the block's 2×2 of A_ww (D₀₁ = 1 by
        // construction) and known right-hand sides r₀, r₁, the block's columns solve
        // Aᵀx₀ + D₀₀x₀ + D₁₀x₁ = r₀, Aᵀx₁ + D₀₁x₀ + D₁₁x₁ = r₁; eliminating x₀ leaves
        // ((Aᵀ)² + tr D·Aᵀ + det D·I)·x₁ = (Aᵀ + D₀₀)·r₁ − D₀₁·r₀ (5 unknowns).
        let at: [[f64; NC]; NC] = std::array::from_fn(|r| std::array::from_fn(|k| a[k][r]));
        let at2: [[f64; NC]; NC] = std::array::from_fn(|r| {
            std::array::from_fn(|k| (0..NC).map(|t| at[r][t] * at[t][k]).sum())
        });
        let mul = |m: &[[f64; NC]; NC], v: &[f64; NC]| -> [f64; NC] {
            std::array::from_fn(|r| (0..NC).map(|k| m[r][k] * v[k]).sum())
        };
        let mut x = [[0.0; NW]; NC];
        for blk in (0..NW / 2).rev() {
            let (s0, s1) = (2 * blk, 2 * blk + 1);
            let d = |p: usize, q: usize| self.a_ww[p][q];
            let (d00, d01, d10, d11) = (d(s0, s0), d(s0, s1), d(s1, s0), d(s1, s1));
            if d01 == 0.0 {
                return None;
            }
            let rhs = |s: usize| -> [f64; NC] {
                std::array::from_fn(|r| {
                    let later: f64 = (2 * blk + 2..NW).map(|p| x[r][p] * self.a_ww[p][s]).sum();
                    -accel[r] * qg[s] - later
                })
            };
            let (r0, r1) = (rhs(s0), rhs(s1));
            let (tr, det) = (d00 + d11, d00 * d11 - d01 * d10);
            let mut m: [[f64; NC]; NC] = std::array::from_fn(|r| {
                std::array::from_fn(|k| at2[r][k] + tr * at[r][k] + if r == k { det } else { 0.0 })
            });
            let atr1 = mul(&at, &r1);
            let mut v: [f64; NC] = std::array::from_fn(|r| atr1[r] + d00 * r1[r] - d01 * r0[r]);
            let x1 = gauss(&mut m, &mut v)?;
            let atx1 = mul(&at, &x1);
            for r in 0..NC {
                x[r][s1] = x1[r];
                x[r][s0] = (r1[r] - atx1[r] - d11 * x1[r]) / d01;
            }
        }
        // q·b_cᵀ·Q_cc·b_c with A_ccᵀ·Q_cc + Q_cc·A_cc + M = 0, M = S + Sᵀ + h²·a·aᵀ and
        // S = X·g·aᵀ, equals trace(M·P) with P the car's covariance (A_cc·P + P·A_ccᵀ +
        // q·b_c·b_cᵀ = 0): trace(Q·q·b·bᵀ) = −trace(Q·(A·P + P·Aᵀ)) = trace(M·P).
        let xg: [f64; NC] = std::array::from_fn(|r| (0..NW).map(|t| x[r][t] * self.g[t]).sum());
        let h2 = self.h * self.h;
        let mut trace = 0.0;
        for r in 0..NC {
            for t in 0..NC {
                let m = xg[r] * accel[t] + accel[r] * xg[t] + h2 * accel[r] * accel[t];
                trace += m * p[t][r];
            }
        }
        Some(trace)
    }

    /// RMS weighted body acceleration (m/s², as
    /// [`Stationary::rms_weighted_body_acceleration`]) of the car `base` with each suspension
    /// `(k_s, c_s)` of the grid `k_axis × c_axis`, rows `rows` of `c_axis`, written to
    /// `out[row·k_axis.len() + col]` (NaN where the car is invalid or does not settle;
    /// indices beyond `out` are skipped). The unweighted value goes to `unweighted` alike
    /// (an empty slice skips it).
    #[allow(clippy::too_many_arguments)]
    pub fn weighted_rows(
        &self,
        base: TwoDofConfig,
        class: IsoClass,
        speed: f64,
        (k_axis, c_axis): (&[f64], &[f64]),
        rows: std::ops::Range<usize>,
        out: &mut [f64],
        unweighted: &mut [f64],
    ) {
        let nk = k_axis.len();
        for (row, &c_s) in c_axis.iter().enumerate().take(rows.end).skip(rows.start) {
            for (col, &k_s) in k_axis.iter().enumerate() {
                let car = TwoDof::new(TwoDofConfig { k_s, c_s, ..base });
                let s = car.and_then(|car| self.stationary(&car, class, speed));
                let (w, u) = s.map_or((f64::NAN, f64::NAN), |s| {
                    (s.rms_weighted_body_acceleration, s.rms_body_acceleration)
                });
                let idx = row * nk + col;
                if let Some(slot) = out.get_mut(idx) {
                    *slot = w;
                }
                if let Some(slot) = unweighted.get_mut(idx) {
                    *slot = u;
                }
            }
        }
    }
}

/// The car and road block of [`stationary_weighted`]'s system: `A_cc`, `b_c`, the body
/// acceleration row `a` and the noise intensity `q`.
struct CarRoad {
    a: [[f64; NC]; NC],
    b: [f64; NC],
    accel: [f64; NC],
    q: f64,
}

impl CarRoad {
    fn new(car: &TwoDof, class: IsoClass, speed: f64) -> Result<Self, ModelError> {
        let v = positive("speed", "m/s", speed)?;
        let c = car.config();
        let (ms, mu) = (c.sprung_mass, c.unsprung_mass);
        let road_pole = TAU * ROAD_CUT_ON * v;
        let accel = [-c.k_s / ms, c.k_s / ms, -c.c_s / ms, c.c_s / ms, 0.0];
        let mut a = [[0.0; NC]; NC];
        a[0][2] = 1.0;
        a[1][3] = 1.0;
        a[2] = accel;
        a[3] = [
            c.k_s / mu,
            -(c.k_s + c.k_t) / mu,
            c.c_s / mu,
            -(c.c_s + c.c_t) / mu,
            (c.k_t - c.c_t * road_pole) / mu,
        ];
        a[4][4] = -road_pole;
        let mut b = [0.0; NC];
        b[3] = c.c_t / mu;
        b[4] = 1.0;
        let q = 0.5 * (TAU * ISO_N0).powi(2) * class.g_d_n0() * v;
        Ok(Self { a, b, accel, q })
    }

    /// The car and road's covariance `P`: `A_cc·P + P·A_ccᵀ + q·b_c·b_cᵀ = 0`.
    fn covariance(&self) -> Option<[[f64; NC]; NC]> {
        let m: [[f64; NC]; NC] =
            std::array::from_fn(|r| std::array::from_fn(|s| self.q * self.b[r] * self.b[s]));
        lyapunov_small::<NC, 15>(&self.a, &m)
    }
}

/// `uᵀ·X·u`.
fn quad(x: &[[f64; NC]; NC], u: &[f64; NC]) -> f64 {
    let mut s = 0.0;
    for r in 0..NC {
        for t in 0..NC {
            s += u[r] * x[r][t] * u[t];
        }
    }
    s
}

/// Solves the `N×N` system `m·x = rhs` by Gaussian elimination with partial pivoting, on
/// the stack; `None` when (numerically) singular.
fn gauss<const N: usize>(m: &mut [[f64; N]; N], rhs: &mut [f64; N]) -> Option<[f64; N]> {
    let scale = m.iter().flatten().fold(0.0f64, |s, v| s.max(v.abs()));
    for col in 0..N {
        let pivot = (col..N).max_by(|&x, &y| m[x][col].abs().total_cmp(&m[y][col].abs()))?;
        let pv = m[pivot][col];
        if !pv.is_finite() || pv.abs() <= 1e-14 * scale {
            return None;
        }
        m.swap(col, pivot);
        rhs.swap(col, pivot);
        let (top, rest) = m.split_at_mut(col + 1);
        let prow = &top[col];
        for (k, row) in rest.iter_mut().enumerate() {
            let f = row[col] / pv;
            if f != 0.0 {
                for (x, p) in row[col..].iter_mut().zip(&prow[col..]) {
                    *x -= f * p;
                }
                rhs[col + 1 + k] -= f * rhs[col];
            }
        }
    }
    let mut x = [0.0; N];
    for r in (0..N).rev() {
        let s: f64 = (r + 1..N).map(|k| m[r][k] * x[k]).sum();
        x[r] = (rhs[r] - s) / m[r][r];
    }
    x.iter().all(|v| v.is_finite()).then_some(x)
}

/// The symmetric `X` with `A·X + X·Aᵀ + M = 0` (`M` symmetric), as [`lyapunov`] for a
/// `K×K` system in its `NN = K(K+1)/2` unknowns; `None` when singular or a diagonal entry
/// is negative or not finite.
fn lyapunov_small<const K: usize, const NN: usize>(
    a: &[[f64; K]; K],
    m: &[[f64; K]; K],
) -> Option<[[f64; K]; K]> {
    if NN != K * (K + 1) / 2 {
        return None;
    }
    let idx = |i: usize, j: usize| {
        let (lo, hi) = if i <= j { (i, j) } else { (j, i) };
        lo * K - lo * (lo + 1) / 2 + hi
    };
    let mut mat = [[0.0; NN]; NN];
    let mut rhs = [0.0; NN];
    for i in 0..K {
        for j in i..K {
            let r = idx(i, j);
            for k in 0..K {
                mat[r][idx(k, j)] += a[i][k];
                mat[r][idx(i, k)] += a[j][k];
            }
            rhs[r] = -m[i][j];
        }
    }
    let x = gauss(&mut mat, &mut rhs)?;
    let out: [[f64; K]; K] = std::array::from_fn(|i| std::array::from_fn(|j| x[idx(i, j)]));
    (0..K).all(|i| out[i][i] >= 0.0).then_some(out)
}
