//! Two-degree-of-freedom quarter car: sprung and unsprung mass on a tyre spring.
//!
//! ```text
//! m_s·z_s'' = −k_s·(z_s − z_u) − c_s·(z_s' − z_u')
//! m_u·z_u'' =  k_s·(z_s − z_u) + c_s·(z_s' − z_u') − k_t·(z_u − u) − c_t·(z_u' − u')
//! ```
//!
//! State `[z_s, z_u, z_s', z_u']` (m, m/s), displacements from static equilibrium, upward
//! positive; `u(t)` is the road height under the tyre (m). Road inputs: a 1 − cos bump, a
//! step, a sinusoid, and a random ISO 8608 profile.
//!
//! ```
//! use zeta_solver::two_dof::{TwoDof, TwoDofConfig};
//! let car = TwoDof::new(TwoDofConfig::default()).unwrap();
//! let [body, wheel] = car.natural_frequencies_hz();
//! assert!(body > 1.0 && body < 1.5);   // body bounce
//! assert!(wheel > 10.0 && wheel < 15.0); // wheel hop
//! // At low frequency the body follows the road.
//! assert!((car.frf(1e-3).body.abs() - 1.0).abs() < 1e-6);
//! ```

use crate::complex::Complex;
use crate::design::rng::Rng;
use crate::error::{non_negative, positive, ModelError};
use crate::integrate::{FixedStep, IntegrationError, Rk4, Solution, System};
use std::f64::consts::TAU;

/// Parameters of [`TwoDof`]; SI units.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TwoDofConfig {
    /// Sprung (body) mass `m_s` (kg), > 0. Default 300.
    pub sprung_mass: f64,
    /// Unsprung (wheel) mass `m_u` (kg), > 0. Default 40.
    pub unsprung_mass: f64,
    /// Suspension spring rate `k_s` (N/m), > 0. Default 24 000.
    pub k_s: f64,
    /// Suspension damper rate `c_s` (N·s/m), ≥ 0. Default 1 500.
    pub c_s: f64,
    /// Tyre vertical stiffness `k_t` (N/m), > 0. Default 200 000.
    pub k_t: f64,
    /// Tyre damping `c_t` (N·s/m), ≥ 0. Default 0.
    pub c_t: f64,
}

impl Default for TwoDofConfig {
    fn default() -> Self {
        Self {
            sprung_mass: 300.0,
            unsprung_mass: 40.0,
            k_s: 24_000.0,
            c_s: 1_500.0,
            k_t: 200_000.0,
            c_t: 0.0,
        }
    }
}

/// A validated two-degree-of-freedom quarter car.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TwoDof {
    cfg: TwoDofConfig,
}

/// Road-roughness class of ISO 8608.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum IsoClass {
    /// Very good.
    A,
    /// Good.
    B,
    /// Average.
    C,
    /// Poor.
    D,
    /// Very poor.
    E,
    /// F.
    F,
    /// G.
    G,
    /// H.
    H,
}

impl IsoClass {
    /// Every class, smoothest first.
    pub const ALL: [IsoClass; 8] = [
        IsoClass::A,
        IsoClass::B,
        IsoClass::C,
        IsoClass::D,
        IsoClass::E,
        IsoClass::F,
        IsoClass::G,
        IsoClass::H,
    ];

    /// Degree of roughness `G_d(n0)` (m³) at `n0 = 0.1` cycles/m: the geometric mean of the
    /// class, `16·4ᵏ·10⁻⁶` for A (k = 0) … H (k = 7), i.e. 16, 64, 256, 1 024, 4 096,
    /// 16 384, 65 536, 262 144 × 10⁻⁶ m³ (ISO 8608:2016, degree-of-roughness table; class
    /// limits are the geometric means ÷/× 2).
    pub fn g_d_n0(self) -> f64 {
        let k = match self {
            IsoClass::A => 0,
            IsoClass::B => 1,
            IsoClass::C => 2,
            IsoClass::D => 3,
            IsoClass::E => 4,
            IsoClass::F => 5,
            IsoClass::G => 6,
            IsoClass::H => 7,
        };
        16e-6 * f64::from(4u32.pow(k))
    }
}

/// Standard gravity `g = 9.806 65 m/s²` (CGPM 1901).
pub const G: f64 = 9.806_65;

/// Reference spatial frequency of ISO 8608, `n0 = 0.1` cycles/m.
pub const ISO_N0: f64 = 0.1;

/// Most sinusoids a random road may sum (each `u(t)` costs one cosine per component).
pub const MAX_ROAD_COMPONENTS: usize = 10_000;

/// Settings of a random ISO 8608 road.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RandomRoadConfig {
    /// Roughness class.
    pub class: IsoClass,
    /// Vehicle speed `V` (m/s), > 0.
    pub speed: f64,
    /// Lowest spatial frequency (cycles/m), > 0. Default 0.011 (ISO 8608 band).
    pub n_min: f64,
    /// Highest spatial frequency (cycles/m), > `n_min`. Default 2.83 (ISO 8608 band).
    pub n_max: f64,
    /// Number of sinusoids, 1 … [`MAX_ROAD_COMPONENTS`]. Default 256.
    pub components: usize,
    /// Seed of the random phases.
    pub seed: u64,
}

impl Default for RandomRoadConfig {
    fn default() -> Self {
        Self {
            class: IsoClass::C,
            speed: 20.0,
            n_min: 0.011,
            n_max: 2.83,
            components: 256,
            seed: 1,
        }
    }
}

/// A random road profile `u(x) = Σ Aᵢ·cos(2π·nᵢ·x + φᵢ)` at `x = V·t`, with `nᵢ` the
/// midpoints of `components` equal bands of width `Δn` over `[n_min, n_max]`,
/// `Aᵢ = √(2·G_d(nᵢ)·Δn)` from the ISO 8608 displacement PSD
/// `G_d(n) = G_d(n0)·(n/n0)⁻²` (waviness 2), and phases `φᵢ` uniform on `[0, 2π)` from a
/// seeded [`Rng`]. Its variance is `Σ Aᵢ²/2 ≈ ∫ G_d dn`.
#[derive(Debug, Clone, PartialEq)]
pub struct RandomRoad {
    speed: f64,
    /// `(2π·nᵢ·V, Aᵢ, φᵢ)`: temporal angular frequency (rad/s), amplitude (m), phase (rad).
    terms: Vec<(f64, f64, f64)>,
}

impl RandomRoad {
    /// Builds the profile (allocates `components` terms once).
    pub fn new(cfg: RandomRoadConfig) -> Result<Self, ModelError> {
        let speed = positive("speed", "m/s", cfg.speed)?;
        let n_min = positive("lowest spatial frequency", "cycles/m", cfg.n_min)?;
        let n_max = positive("highest spatial frequency", "cycles/m", cfg.n_max)?;
        if n_max <= n_min {
            return Err(ModelError::OutOfRange {
                name: "spatial frequency band",
                reason: "the highest frequency must exceed the lowest",
            });
        }
        if cfg.components == 0 || cfg.components > MAX_ROAD_COMPONENTS {
            return Err(ModelError::OutOfRange {
                name: "number of road components",
                reason: "must be between 1 and 10 000",
            });
        }
        let g0 = cfg.class.g_d_n0();
        let dn = (n_max - n_min) / cfg.components as f64;
        let mut rng = Rng::new(cfg.seed);
        let terms = (0..cfg.components)
            .map(|i| {
                let n = n_min + (i as f64 + 0.5) * dn;
                let g = g0 * (ISO_N0 / n) * (ISO_N0 / n);
                (
                    TAU * n * speed,
                    (2.0 * g * dn).sqrt(),
                    rng.uniform_in(0.0, TAU),
                )
            })
            .collect();
        Ok(Self { speed, terms })
    }

    /// Vehicle speed (m/s).
    pub fn speed(&self) -> f64 {
        self.speed
    }

    /// Variance of the profile `Σ Aᵢ²/2` (m²).
    pub fn variance(&self) -> f64 {
        self.terms.iter().map(|&(_, a, _)| 0.5 * a * a).sum()
    }

    /// RMS height `√(Σ Aᵢ²/2)` (m).
    pub fn rms(&self) -> f64 {
        self.variance().sqrt()
    }

    /// `(u(t), u'(t))` (m, m/s).
    pub fn at(&self, t: f64) -> (f64, f64) {
        self.terms.iter().fold((0.0, 0.0), |(u, du), &(w, a, phi)| {
            let (s, c) = (w * t + phi).sin_cos();
            (u + a * c, du - a * w * s)
        })
    }

    /// Heights `out[i] = u(t0 + i·dt)` (m) on a uniform grid, fast: each term's phasor
    /// `e^{i(ωᵢt + φᵢ)}` is advanced by one complex multiplication per sample instead of a
    /// `sin_cos`, and recomputed exactly every [`RESYNC`] samples, so the rounding drift
    /// stays below ≈ `RESYNC·ε` of each amplitude (≈ 3e-14). The terms are summed in the
    /// same order as [`Self::at`].
    pub fn sample_uniform(&self, t0: f64, dt: f64, out: &mut [f64]) {
        out.iter_mut().for_each(|u| *u = 0.0);
        for &(w, a, phi) in &self.terms {
            let (rs, rc) = (w * dt).sin_cos();
            let (mut s, mut c) = (0.0, 0.0);
            for (i, u) in out.iter_mut().enumerate() {
                if i % RESYNC == 0 {
                    (s, c) = (w * (t0 + i as f64 * dt) + phi).sin_cos();
                } else {
                    (s, c) = (s * rc + c * rs, c * rc - s * rs);
                }
                *u += a * c;
            }
        }
    }

    /// Highest temporal frequency in the profile, `n_max·V` at the top band's midpoint (Hz).
    pub fn highest_frequency_hz(&self) -> f64 {
        self.terms.iter().fold(0.0, |m, &(w, _, _)| m.max(w / TAU))
    }
}

/// Samples between exact re-evaluations of the phasors in [`RandomRoad::sample_uniform`].
pub const RESYNC: usize = 256;

/// Road height under the tyre as a function of time.
#[derive(Debug, Clone, PartialEq, Default)]
pub enum Road {
    /// `u = 0`.
    #[default]
    Flat,
    /// One `1 − cos` bump: `u = (h/2)·(1 − cos(2π·V·t/L))` for `0 ≤ V·t ≤ L`, else 0;
    /// `height` h (m), `length` L (m), `speed` V (m/s).
    Bump {
        /// Height h (m).
        height: f64,
        /// Length L (m), > 0.
        length: f64,
        /// Speed V (m/s), > 0.
        speed: f64,
    },
    /// `u = height` (m) for `t > 0`, `u(0) = 0`: the car starts at rest on the level road
    /// and meets the kerb at once. The impulse `c_t·height·δ(t)` through tyre damping is
    /// neglected (`u' = 0`).
    Step {
        /// Step height (m).
        height: f64,
    },
    /// `u = amplitude·sin(2π·f·t)`, amplitude (m), frequency `f` (Hz).
    Sine {
        /// Amplitude (m).
        amplitude: f64,
        /// Frequency (Hz).
        frequency_hz: f64,
    },
    /// A random ISO 8608 profile.
    Random(RandomRoad),
}

impl Road {
    /// [`Road::Bump`] of height `height` (m), length `length` (m) crossed at `speed` (m/s).
    pub const fn bump(height: f64, length: f64, speed: f64) -> Self {
        Road::Bump {
            height,
            length,
            speed,
        }
    }

    /// [`Road::Sine`] of amplitude `amplitude` (m) at `frequency_hz` (Hz).
    pub const fn sine(amplitude: f64, frequency_hz: f64) -> Self {
        Road::Sine {
            amplitude,
            frequency_hz,
        }
    }

    /// `(u(t), u'(t))` (m, m/s). Zero for `t < 0`; a bump with a non-positive length or
    /// speed is flat.
    pub fn at(&self, t: f64) -> (f64, f64) {
        if t < 0.0 {
            return (0.0, 0.0);
        }
        match self {
            Road::Flat => (0.0, 0.0),
            Road::Bump {
                height,
                length,
                speed,
            } => {
                let x = speed * t;
                if !(*length > 0.0 && *speed > 0.0) || x > *length {
                    return (0.0, 0.0);
                }
                let k = TAU / length;
                let (s, c) = (k * x).sin_cos();
                (0.5 * height * (1.0 - c), 0.5 * height * k * speed * s)
            }
            Road::Step { height } => (if t > 0.0 { *height } else { 0.0 }, 0.0),
            Road::Sine {
                amplitude,
                frequency_hz,
            } => {
                let w = TAU * frequency_hz;
                let (s, c) = (w * t).sin_cos();
                (amplitude * s, amplitude * w * c)
            }
            Road::Random(r) => r.at(t),
        }
    }
}

/// Complex frequency responses per unit road amplitude at one angular frequency.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Frf {
    /// Angular frequency ω (rad/s).
    pub omega: f64,
    /// Body displacement / road, `Z_s/U` (-).
    pub body: Complex,
    /// Body acceleration / road, `−ω²·Z_s/U` (1/s²).
    pub body_acceleration: Complex,
    /// Tyre deflection / road, `(Z_u − U)/U` (-).
    pub tyre_deflection: Complex,
    /// Suspension travel / road, `(Z_s − Z_u)/U` (-).
    pub suspension_travel: Complex,
}

/// Ride and road-holding measures of one run.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RunMetrics {
    /// RMS body acceleration over the grid points (m/s²) — ride comfort.
    pub rms_body_acceleration: f64,
    /// RMS tyre deflection `z_u − u` over the grid points (m) — road holding (compare with
    /// the static deflection `(m_s + m_u)·g/k_t`).
    pub rms_tyre_deflection: f64,
    /// Largest `|z_s − z_u|` (m) — rattle space used.
    pub max_suspension_travel: f64,
}

/// The car driven by a road: a [`System<4>`] on `[z_s, z_u, z_s', z_u']`.
#[derive(Debug, Clone, Copy)]
pub struct Driven<'a> {
    car: &'a TwoDof,
    road: &'a Road,
}

impl System<4> for Driven<'_> {
    fn rhs(&self, t: f64, y: &[f64; 4], dy: &mut [f64; 4]) {
        let (u, du) = self.road.at(t);
        self.car.rhs(y, u, du, dy);
    }
}

impl TwoDof {
    /// Validates the configuration (see the field docs for the ranges).
    pub fn new(cfg: TwoDofConfig) -> Result<Self, ModelError> {
        positive("sprung mass", "kg", cfg.sprung_mass)?;
        positive("unsprung mass", "kg", cfg.unsprung_mass)?;
        positive("suspension stiffness", "N/m", cfg.k_s)?;
        non_negative("suspension damping", "N·s/m", cfg.c_s)?;
        positive("tyre stiffness", "N/m", cfg.k_t)?;
        non_negative("tyre damping", "N·s/m", cfg.c_t)?;
        Ok(Self { cfg })
    }

    /// The validated parameters.
    pub fn config(&self) -> TwoDofConfig {
        self.cfg
    }

    /// Static tyre deflection `δ₀ = (m_s + m_u)·g/k_t` (m) under the car's weight, with
    /// standard gravity [`G`]: a dynamic deflection `z_u − u` above it would need the tyre
    /// to pull, so the wheel leaves the road.
    pub fn static_tyre_deflection(&self) -> f64 {
        let c = &self.cfg;
        (c.sprung_mass + c.unsprung_mass) * G / c.k_t
    }

    /// The equations of motion on `y = [z_s, z_u, z_s', z_u']` over road height `u` (m)
    /// rising at `du` (m/s): with the suspension force `F_s = k_s·(z_s − z_u) + c_s·(z_s' − z_u')`
    /// and the tyre force `F_t = k_t·(z_u − u) + c_t·(z_u' − u')` (N),
    /// `dy = [z_s', z_u', −F_s/m_s, (F_s − F_t)/m_u]`.
    pub(crate) fn rhs(&self, y: &[f64; 4], u: f64, du: f64, dy: &mut [f64; 4]) {
        let c = &self.cfg;
        let susp = c.k_s * (y[0] - y[1]) + c.c_s * (y[2] - y[3]);
        let tyre = c.k_t * (y[1] - u) + c.c_t * (y[3] - du);
        dy[0] = y[2];
        dy[1] = y[3];
        dy[2] = -susp / c.sprung_mass;
        dy[3] = (susp - tyre) / c.unsprung_mass;
    }

    /// The car on `road`, ready to integrate.
    pub fn driven<'a>(&'a self, road: &'a Road) -> Driven<'a> {
        Driven { car: self, road }
    }

    /// Undamped natural frequencies `[ω_body, ω_wheel]` (rad/s), exact roots of
    /// `det(K − ω²M) = m_s·m_u·λ² − (k_s·m_u + (k_s + k_t)·m_s)·λ + k_s·k_t = 0`, `λ = ω²`
    /// (larger root from the quadratic formula, smaller from the product of roots, so
    /// neither cancels).
    pub fn natural_frequencies(&self) -> [f64; 2] {
        let c = &self.cfg;
        let a = c.sprung_mass * c.unsprung_mass;
        let b = c.k_s * c.unsprung_mass + (c.k_s + c.k_t) * c.sprung_mass;
        let prod = c.k_s * c.k_t;
        // b² − 4a·prod > 0 always (two distinct positive roots); clamp rounding.
        let disc = (b * b - 4.0 * a * prod).max(0.0).sqrt();
        let hi = (b + disc) / (2.0 * a);
        let lo = prod / (a * hi);
        [lo.sqrt(), hi.sqrt()]
    }

    /// [`Self::natural_frequencies`] in Hz: `[body bounce, wheel hop]`.
    pub fn natural_frequencies_hz(&self) -> [f64; 2] {
        self.natural_frequencies().map(|w| w / TAU)
    }

    /// Frequency responses at `omega` (rad/s) from the complex 2×2 system
    /// `(K + iωC − ω²M)·Z = [0, k_t + iωc_t]ᵀ·U`, solved by Cramer's rule.
    pub fn frf(&self, omega: f64) -> Frf {
        let c = &self.cfg;
        let w2 = omega * omega;
        let s = Complex::new(c.k_s, omega * c.c_s);
        let t = Complex::new(c.k_t, omega * c.c_t);
        let a11 = s + Complex::real(-w2 * c.sprung_mass);
        let a22 = s + t + Complex::real(-w2 * c.unsprung_mass);
        // det = a11·a22 − s²; right-hand side [0, t].
        let det = a11 * a22 - s * s;
        let zs = s * t / det;
        let zu = a11 * t / det;
        Frf {
            omega,
            body: zs,
            body_acceleration: zs * (-w2),
            tyre_deflection: zu - Complex::real(1.0),
            suspension_travel: zs - zu,
        }
    }

    /// Allocation-free sweep: `out[i] = frf(omegas[i])` for `i < min(len)`.
    pub fn frf_into(&self, omegas: &[f64], out: &mut [Frf]) {
        for (o, &w) in out.iter_mut().zip(omegas) {
            *o = self.frf(w);
        }
    }

    /// Response to `road` from rest at static equilibrium over `[0, t_end]` by RK4 with steps
    /// of at most `h` (s); resolve the wheel-hop period (`h ≲ 1/(20·f_wheel)`).
    pub fn simulate(
        &self,
        road: &Road,
        t_end: f64,
        h: f64,
    ) -> Result<Solution<4>, IntegrationError> {
        Rk4.solve(&self.driven(road), [0.0; 4], 0.0, t_end, h)
    }

    /// Body acceleration `z_s'' = −(k_s·(z_s − z_u) + c_s·(z_s' − z_u'))/m_s` (m/s²).
    pub fn body_acceleration(&self, y: &[f64; 4]) -> f64 {
        let c = &self.cfg;
        -(c.k_s * (y[0] - y[1]) + c.c_s * (y[2] - y[3])) / c.sprung_mass
    }

    /// Mechanical energy `½m_s·z_s'² + ½m_u·z_u'² + ½k_s·(z_s − z_u)² + ½k_t·(z_u − u)²` (J).
    pub fn energy(&self, y: &[f64; 4], u: f64) -> f64 {
        let c = &self.cfg;
        let ds = y[0] - y[1];
        let dt = y[1] - u;
        0.5 * (c.sprung_mass * y[2] * y[2]
            + c.unsprung_mass * y[3] * y[3]
            + c.k_s * ds * ds
            + c.k_t * dt * dt)
    }

    /// Power dissipated in the dampers `c_s·(z_s' − z_u')² + c_t·(z_u' − u')²` (W), ≥ 0.
    pub fn dissipated_power(&self, y: &[f64; 4], du: f64) -> f64 {
        let c = &self.cfg;
        let vs = y[2] - y[3];
        let vt = y[3] - du;
        c.c_s * vs * vs + c.c_t * vt * vt
    }

    /// Power the road puts in, `−(k_t·(z_u − u) + c_t·(z_u' − u'))·u'` (W), so that
    /// `dE/dt = road power − dissipated power`.
    pub fn road_power(&self, y: &[f64; 4], u: f64, du: f64) -> f64 {
        let c = &self.cfg;
        -(c.k_t * (y[1] - u) + c.c_t * (y[3] - du)) * du
    }

    /// RMS body acceleration, RMS tyre deflection and peak suspension travel of a run on
    /// `road`, over its grid points (equal weights: use a uniform grid). `None` for an empty
    /// run.
    pub fn metrics(&self, road: &Road, sol: &Solution<4>) -> Option<RunMetrics> {
        let heights: Vec<f64> = sol.t.iter().map(|&t| road.at(t).0).collect();
        self.sampled_metrics(&sol.y, &heights)
    }

    /// [`Self::metrics`] from slices: `states[i]` and the road height `road[i]` (m) at the
    /// same instant, equally weighted (a uniform grid):
    /// `RMS a = √(Σ z_s''ᵢ²/n)`, `RMS d = √(Σ (z_u,ᵢ − uᵢ)²/n)`, travel `max |z_s − z_u|`.
    /// `None` when empty or the lengths differ.
    pub fn sampled_metrics(&self, states: &[[f64; 4]], road: &[f64]) -> Option<RunMetrics> {
        if states.is_empty() || states.len() != road.len() {
            return None;
        }
        let (mut acc2, mut tyre2, mut travel) = (0.0, 0.0, 0.0f64);
        for (y, &u) in states.iter().zip(road) {
            let a = self.body_acceleration(y);
            let d = y[1] - u;
            acc2 += a * a;
            tyre2 += d * d;
            travel = travel.max((y[0] - y[1]).abs());
        }
        let n = states.len() as f64;
        Some(RunMetrics {
            rms_body_acceleration: (acc2 / n).sqrt(),
            rms_tyre_deflection: (tyre2 / n).sqrt(),
            max_suspension_travel: travel,
        })
    }
}

/// Time the tyre spends on a `1 − cos` bump, `L/V` (s); `None` unless both are positive.
pub fn bump_duration(length: f64, speed: f64) -> Option<f64> {
    (length > 0.0 && speed > 0.0 && (length / speed).is_finite()).then(|| length / speed)
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::PI;

    #[test]
    fn iso_classes_quadruple() {
        assert!((IsoClass::A.g_d_n0() - 16e-6).abs() < 1e-20);
        assert!((IsoClass::H.g_d_n0() - 262_144e-6).abs() < 1e-15);
        for w in IsoClass::ALL.windows(2) {
            assert!((w[1].g_d_n0() / w[0].g_d_n0() - 4.0).abs() < 1e-12);
        }
    }

    #[test]
    fn bump_profile_shape() {
        let r = Road::bump(0.1, 2.0, 10.0);
        assert_eq!(r.at(-1.0), (0.0, 0.0));
        let (u_mid, du_mid) = r.at(0.1); // x = 1 m: crest
        assert!((u_mid - 0.1).abs() < 1e-15 && du_mid.abs() < 1e-12);
        assert_eq!(r.at(0.21), (0.0, 0.0));
        // Peak slope u' = (h/2)(2π/L)V at x = L/4.
        let (_, du) = r.at(0.05);
        assert!((du - 0.05 * PI * 10.0).abs() < 1e-12);
    }

    #[test]
    fn invalid_parameters_are_typed_errors() {
        let d = TwoDofConfig::default();
        assert!(TwoDof::new(TwoDofConfig {
            unsprung_mass: 0.0,
            ..d
        })
        .is_err());
        assert!(TwoDof::new(TwoDofConfig { c_s: -1.0, ..d }).is_err());
        assert!(TwoDof::new(TwoDofConfig { k_t: f64::NAN, ..d }).is_err());
        let r = RandomRoadConfig::default();
        assert!(RandomRoad::new(RandomRoadConfig { n_max: 0.001, ..r }).is_err());
        assert!(RandomRoad::new(RandomRoadConfig { components: 0, ..r }).is_err());
        assert!(RandomRoad::new(RandomRoadConfig { speed: -3.0, ..r }).is_err());
    }
}
