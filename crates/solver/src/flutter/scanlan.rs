//! Torsional flutter of a bridge deck on Scanlan's flutter derivatives, with an
//! amplitude-dependent bound on the motion.
//!
//! Per unit length, a deck of width `B` \[m\] and mass moment of inertia `I` \[kg·m²/m\],
//! still-air torsional frequency `ω₀ = 2π·f₀` \[rad/s\] and structural damping ratio `ζ_s`,
//! twisting by `θ` \[rad\] in a steady wind `U` \[m/s\] of density `ρ` \[kg/m³\], obeys
//!
//! `I·(θ'' + 2ζ_s·ω₀·θ' + ω₀²·θ) = ½ρU²B²·[K·A₂*(K)·B·θ'/U + K²·A₃*(K)·θ]`,  `K = B·ω/U`,
//!
//! (the moment of [`super::derivatives`]), i.e. `θ'' + c·θ' + k·θ = 0` with
//!
//! `c = 2ζ_s·ω₀ − q·ω·A₂*(K)`,  `k = ω₀² − q·ω²·A₃*(K)`,  `q = ρB⁴/(2I)`.
//!
//! The derivatives depend on the frequency `ω` of the motion itself, so at each `U` the
//! frequency is found by iteration (the p–k method): start from `ω₀`, evaluate `c` and `k`,
//! take `ω = Im λ` of the roots `λ = −c/2 ± i·√(k − c²/4)`, repeat until `ω` no longer
//! changes. The effective damping ratio is then `ζ_eff = c/(2ω_n)`, `ω_n = √k`, which is
//! `ζ_s − ρB⁴A₂*(K)/(4I)` to first order in the aerodynamic terms; the growth rate is
//! `σ = Re λ = −c/2` \[1/s\]; flutter starts at the critical speed `U_crit` where `σ = 0`.
//!
//! **Amplitude-dependent bound (a teaching assumption).** Linear theory lets a fluttering
//! twist grow for ever. Wind-tunnel tests of H-sections show that the self-excited forces
//! change with amplitude and bound the motion in a limit cycle (e.g. Hu, Zhao & Ge, "Wind-
//! induced instability mechanism of Old Tacoma Narrows Bridge from aerodynamic work
//! perspective", J. Bridge Eng. ASCE, 2022, doi 10.1061/(ASCE)BE.1943-5592.0001858). Here that
//! is modelled in the simplest way, not fitted to those tests: the aerodynamic damping term
//! is divided by `1 + (a/θ_s)²`, where `a = √(θ² + (θ'/ω)²)` is the instantaneous amplitude
//! and `θ_s` \[rad\] the amplitude at which the wind's damping term has halved. Averaging over
//! a cycle (Krylov–Bogoliubov) gives, with `x = (a/θ_s)²`, `c_a = q·ω·A₂*` and `c_s = 2ζ_s·ω₀`,
//!
//! `dx/dt = x·(c_a/(1 + x) − c_s)`,
//!
//! so above `U_crit` the twist settles at the limit cycle `a_LC = θ_s·√(c_a/c_s − 1)`, and the
//! time from `a₀` to `a₁` is (with `α = c_a − c_s`, `β = c_s`)
//!
//! `t = ln(x₁/x₀)/α − (α + β)/(αβ)·ln((α − βx₁)/(α − βx₀))`.
//!
//! The *simplest picture* ([`Aerodynamics::SimplestPicture`]) replaces the derivatives by
//! the straight line `ζ_eff = ζ_s − g·U` of [`super::FlutterModel`] (`c_a = 2ω₀·g·U`, `k = ω₀²`).
//!
//! ```
//! use zeta_solver::flutter::{ScanlanConfig, ScanlanModel};
//! let deck = ScanlanModel::new(ScanlanConfig::tacoma_1940()).unwrap();
//! let u_crit = deck.critical_speed().unwrap();
//! assert!(u_crit > 17.0 && u_crit < 19.0); // ≈ 40 mph
//! assert!(deck.state(19.0).unwrap().growth_rate() > 0.0);
//! ```

use super::derivatives::DeckSection;
use crate::complex::Complex;
use crate::error::{non_negative, positive, ModelError};
use crate::integrate::{FixedStep, Rk4, System};
use std::f64::consts::TAU;

/// Density of air at sea level, 15 °C (ISA) \[kg/m³\].
pub const AIR_DENSITY: f64 = 1.225;
/// Width of the 1940 Tacoma deck, 39 ft between the plate girders \[m\].
pub const TACOMA_WIDTH: f64 = 11.9;
/// Mass moment of inertia per length of the 1940 deck \[kg·m²/m\]: an **assumed** value of
/// the right order (a few tonnes per metre at a radius of gyration of about 5–6 m), not a
/// measured one.
pub const TACOMA_INERTIA: f64 = 1.8e5;
/// Torsional frequency of the 1940 deck, ≈ 0.2 Hz as recorded on the day \[Hz\].
pub const TACOMA_TORSION_HZ: f64 = super::TACOMA_TORSION_HZ;
/// Amplitude at which the wind's damping term halves, 45° (teaching assumption) \[deg\].
pub const SATURATION_DEG: f64 = 45.0;
/// Highest wind speed searched for the critical speed \[m/s\].
pub const CRITICAL_SEARCH_MAX: f64 = 100.0;

/// Step of the scan for the critical speed \[m/s\].
const SCAN_STEP: f64 = 0.25;
/// Iteration cap of the frequency iteration.
const MAX_ITERATIONS: usize = 500;
/// Most RK4 steps of one simulated twist history.
const MAX_STEPS: usize = 60_000;

/// What the wind does to the twisting deck.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Aerodynamics {
    /// Scanlan's flutter derivatives of this section.
    Derivatives(DeckSection),
    /// The simplest picture: aerodynamic damping ratio `g·U`, `g` \[s/m\], no stiffness.
    SimplestPicture {
        /// Damping ratio removed per m/s of wind \[s/m\].
        slope: f64,
    },
}

/// Parameters of [`ScanlanModel`] (validated by [`ScanlanModel::new`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ScanlanConfig {
    /// Deck width `B` \[m\], > 0.
    pub width: f64,
    /// Mass moment of inertia per unit length `I` \[kg·m²/m\], > 0.
    pub inertia: f64,
    /// Still-air torsional frequency `f₀` \[Hz\], > 0.
    pub frequency: f64,
    /// Structural damping ratio `ζ_s` \[-\], ≥ 0.
    pub structural_damping: f64,
    /// Air density `ρ` \[kg/m³\], > 0.
    pub air_density: f64,
    /// Amplitude `θ_s` at which the wind's damping term halves \[rad\], > 0.
    pub saturation: f64,
    /// The wind's action.
    pub aerodynamics: Aerodynamics,
}

impl ScanlanConfig {
    /// The 1940 Tacoma deck: `B` = 11.9 m, `I` = 1.8·10⁵ kg·m²/m (assumed), `f₀` = 0.2 Hz,
    /// `ζ_s` = 0.5 % (assumed), H-section derivatives, `θ_s` = 45° (assumed).
    pub fn tacoma_1940() -> Self {
        Self {
            width: TACOMA_WIDTH,
            inertia: TACOMA_INERTIA,
            frequency: TACOMA_TORSION_HZ,
            structural_damping: super::TACOMA_STRUCTURAL_DAMPING,
            air_density: AIR_DENSITY,
            saturation: super::radians(SATURATION_DEG),
            aerodynamics: Aerodynamics::Derivatives(DeckSection::HSection),
        }
    }

    /// The same deck with a streamlined box section (the fix: `A₂*` stays negative).
    pub fn streamlined_box() -> Self {
        Self {
            aerodynamics: Aerodynamics::Derivatives(DeckSection::StreamlinedBox),
            ..Self::tacoma_1940()
        }
    }
}

/// The small-amplitude motion at one wind speed, with the frequency iterated to
/// consistency.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FlutterState {
    /// Wind speed `U` \[m/s\].
    pub wind_speed: f64,
    /// Frequency of the oscillation `ω = Im λ` \[rad/s\].
    pub omega: f64,
    /// Reduced frequency `K = B·ω/U` \[-\] (infinite in still air).
    pub reduced_frequency: f64,
    /// Reduced velocity `U/(f·B) = 2π/K` \[-\], `f = ω/2π`.
    pub reduced_velocity: f64,
    /// `A₂*(K)` \[-\] (for the simplest picture, the `A₂*` that gives the same damping).
    pub a2: f64,
    /// `A₃*(K)` \[-\] (0 for the simplest picture).
    pub a3: f64,
    /// Damping coefficient `c` of `θ'' + c·θ' + k·θ = 0` \[1/s\].
    pub damping: f64,
    /// Its aerodynamic part `c_a` \[1/s\] (`c = c_s − c_a`; `c_a > 0` feeds the twist).
    pub aero_damping: f64,
    /// Stiffness `k` \[1/s²\].
    pub stiffness: f64,
    /// Iterations the frequency took to settle.
    pub iterations: usize,
}

impl FlutterState {
    /// Natural frequency of the mode in the wind, `ω_n = √k` \[rad/s\].
    pub fn natural_frequency(&self) -> f64 {
        self.stiffness.sqrt()
    }

    /// Effective damping ratio `ζ_eff = c/(2ω_n)` \[-\]; negative means flutter.
    pub fn damping_ratio(&self) -> f64 {
        self.damping / (2.0 * self.natural_frequency())
    }

    /// Growth rate `σ = Re λ = −c/2` \[1/s\] of the small-amplitude twist.
    pub fn growth_rate(&self) -> f64 {
        -0.5 * self.damping
    }

    /// Frequency of the oscillation `f = ω/2π` \[Hz\].
    pub fn frequency_hz(&self) -> f64 {
        self.omega / TAU
    }

    /// The two poles `λ = −c/2 ± i·ω` \[1/s\], upper first.
    pub fn poles(&self) -> [Complex; 2] {
        let re = self.growth_rate();
        [Complex::new(re, self.omega), Complex::new(re, -self.omega)]
    }

    /// Time for a growing twist to double, `ln 2/σ` \[s\]; `None` unless `σ > 0`.
    pub fn doubling_time(&self) -> Option<f64> {
        let s = self.growth_rate();
        (s > 0.0).then(|| std::f64::consts::LN_2 / s)
    }
}

/// A simulated twist: samples `θ(t)` and the amplitude `a(t) = √(θ² + (θ'/ω)²)`.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct TwistHistory {
    /// Times \[s\].
    pub t: Vec<f64>,
    /// Twist `θ` \[rad\].
    pub theta: Vec<f64>,
    /// Amplitude `a` \[rad\].
    pub amplitude: Vec<f64>,
}

impl TwistHistory {
    /// `θ` \[rad\] at time `t` \[s\], linearly interpolated (ends held); 0 when empty.
    pub fn theta_at(&self, t: f64) -> f64 {
        crate::grid::interpolate(&self.t, &self.theta, t).unwrap_or(0.0)
    }

    /// Largest amplitude over the run \[rad\] (0 when empty).
    pub fn peak(&self) -> f64 {
        self.amplitude.iter().copied().fold(0.0, f64::max)
    }
}

/// The validated deck in the wind (see the module doc).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ScanlanModel {
    cfg: ScanlanConfig,
    omega0: f64,
    q: f64,
}

/// `θ'' + (c_s − c_a/(1 + (a/θ_s)²))·θ' + k·θ = 0` on `[θ, θ']`.
struct Twist {
    c_s: f64,
    c_a: f64,
    k: f64,
    omega: f64,
    inv_sat2: f64,
}

impl Twist {
    fn amplitude2(&self, y: &[f64; 2]) -> f64 {
        let r = y[1] / self.omega;
        y[0] * y[0] + r * r
    }
}

impl System<2> for Twist {
    fn rhs(&self, _t: f64, y: &[f64; 2], dy: &mut [f64; 2]) {
        let g = 1.0 / (1.0 + self.amplitude2(y) * self.inv_sat2);
        dy[0] = y[1];
        dy[1] = -(self.c_s - self.c_a * g) * y[1] - self.k * y[0];
    }
}

impl ScanlanModel {
    /// Checks `cfg`: `B`, `I`, `f₀`, `ρ`, `θ_s` finite and > 0; `ζ_s` finite and ≥ 0; the
    /// simplest picture's slope finite.
    pub fn new(cfg: ScanlanConfig) -> Result<Self, ModelError> {
        let b = positive("deck width B", "m", cfg.width)?;
        let i = positive("mass moment of inertia I", "kg·m²/m", cfg.inertia)?;
        let f = positive("torsional frequency f₀", "Hz", cfg.frequency)?;
        non_negative("structural damping ratio ζ_s", "", cfg.structural_damping)?;
        let rho = positive("air density ρ", "kg/m³", cfg.air_density)?;
        positive("saturation amplitude θ_s", "rad", cfg.saturation)?;
        if let Aerodynamics::SimplestPicture { slope } = cfg.aerodynamics {
            crate::error::finite("aerodynamic slope g", "s/m", slope)?;
        }
        let q = rho * b * b * b * b / (2.0 * i);
        if !q.is_finite() {
            return Err(ModelError::OutOfRange {
                name: "ρB⁴/(2I)",
                reason: "too large to compute with",
            });
        }
        Ok(Self {
            cfg,
            omega0: TAU * f,
            q,
        })
    }

    /// The parameters.
    pub fn config(&self) -> ScanlanConfig {
        self.cfg
    }

    /// Still-air torsional frequency `ω₀ = 2π·f₀` \[rad/s\].
    pub fn still_air_omega(&self) -> f64 {
        self.omega0
    }

    /// The aerodynamic factor `q = ρB⁴/(2I)` \[-\].
    pub fn aero_factor(&self) -> f64 {
        self.q
    }

    /// `(c_a, k, A₂*, A₃*)` at wind speed `U` when the deck oscillates at `ω`.
    fn coefficients(&self, u: f64, omega: f64) -> (f64, f64, f64, f64, f64) {
        let w0 = self.omega0;
        let vr = if u > 0.0 {
            u * TAU / (self.cfg.width * omega)
        } else {
            0.0
        };
        match self.cfg.aerodynamics {
            Aerodynamics::Derivatives(section) => {
                let (a2, a3) = (section.a2(vr), section.a3(vr));
                (
                    self.q * omega * a2,
                    w0 * w0 - self.q * omega * omega * a3,
                    a2,
                    a3,
                    vr,
                )
            }
            Aerodynamics::SimplestPicture { slope } => {
                let c_a = 2.0 * w0 * slope * u;
                (c_a, w0 * w0, c_a / (self.q * omega), 0.0, vr)
            }
        }
    }

    /// The small-amplitude motion at wind speed `U` \[m/s\], its frequency iterated to
    /// consistency (see the module doc). `None` for a negative or non-finite `U`, when the
    /// wind leaves no oscillation (`k ≤ c²/4`: torsional divergence or overdamping), or if
    /// the iteration does not settle to `10⁻¹²·ω₀` within its cap.
    pub fn state(&self, wind_speed: f64) -> Option<FlutterState> {
        if !(wind_speed.is_finite() && wind_speed >= 0.0) {
            return None;
        }
        let c_s = 2.0 * self.cfg.structural_damping * self.omega0;
        let mut omega = self.omega0;
        for n in 1..=MAX_ITERATIONS {
            let (c_a, k, _, _, _) = self.coefficients(wind_speed, omega);
            let c = c_s - c_a;
            let disc = k - 0.25 * c * c;
            if !(k > 0.0 && disc > 0.0) {
                return None;
            }
            let next = disc.sqrt();
            let settled = (next - omega).abs() <= 1e-12 * self.omega0;
            // Damped update: converges also where the plain iteration would oscillate.
            omega = if n > 50 { 0.5 * (omega + next) } else { next };
            if settled {
                let (c_a, k, a2, a3, vr) = self.coefficients(wind_speed, omega);
                let c = c_s - c_a;
                let disc = k - 0.25 * c * c;
                if !(k > 0.0 && disc > 0.0) {
                    return None;
                }
                return Some(FlutterState {
                    wind_speed,
                    omega: disc.sqrt(),
                    reduced_frequency: if vr > 0.0 { TAU / vr } else { f64::INFINITY },
                    reduced_velocity: vr,
                    a2,
                    a3,
                    damping: c,
                    aero_damping: c_a,
                    stiffness: k,
                    iterations: n,
                });
            }
        }
        None
    }

    /// The lowest wind speed \[m/s\] at which the growth rate turns positive (flutter
    /// onset), found by a scan in steps of 0.25 m/s up to [`CRITICAL_SEARCH_MAX`] and
    /// bisection to `10⁻⁹` m/s. `None` if the twist never grows in that range.
    pub fn critical_speed(&self) -> Option<f64> {
        let sigma = |u: f64| self.state(u).map(|s| s.growth_rate());
        let mut lo = 0.0;
        let mut s_lo = sigma(lo)?;
        if s_lo > 0.0 {
            return Some(0.0);
        }
        let n = (CRITICAL_SEARCH_MAX / SCAN_STEP) as usize;
        for i in 1..=n {
            let hi = SCAN_STEP * i as f64;
            let s_hi = sigma(hi)?;
            if s_hi > 0.0 {
                let mut hi = hi;
                for _ in 0..80 {
                    let mid = 0.5 * (lo + hi);
                    if hi - lo <= 1e-9 {
                        break;
                    }
                    match sigma(mid) {
                        Some(s) if s > 0.0 => hi = mid,
                        Some(_) => lo = mid,
                        None => return None,
                    }
                }
                return Some(0.5 * (lo + hi));
            }
            lo = hi;
            s_lo = s_hi;
        }
        let _ = s_lo;
        None
    }

    /// The poles at `n` wind speeds evenly spaced over `[u_min, u_max]` \[m/s\], as
    /// `(U, state)`; speeds without an oscillating mode are left out.
    pub fn locus(&self, u_min: f64, u_max: f64, n: usize) -> Vec<FlutterState> {
        crate::grid::linspace(u_min, u_max, n)
            .into_iter()
            .filter_map(|u| self.state(u))
            .collect()
    }

    /// Amplitude \[rad\] of the limit cycle at wind speed `U`,
    /// `a_LC = θ_s·√(c_a/c_s − 1)`: `None` below the critical speed (the twist dies away)
    /// or with no structural damping (nothing bounds it).
    pub fn limit_cycle(&self, wind_speed: f64) -> Option<f64> {
        let s = self.state(wind_speed)?;
        let c_s = 2.0 * self.cfg.structural_damping * self.omega0;
        (c_s > 0.0 && s.aero_damping > c_s)
            .then(|| self.cfg.saturation * (s.aero_damping / c_s - 1.0).sqrt())
    }

    /// Time \[s\] for the amplitude to go from `a0` to `a1` \[rad\] at wind speed `U`, from
    /// the cycle-averaged amplitude equation (closed form in the module doc). `None` when
    /// the amplitude never reaches `a1` from `a0` (e.g. `a1` beyond the limit cycle, or a
    /// rise asked of a decaying twist) or an amplitude is not positive.
    pub fn time_between(&self, wind_speed: f64, a0: f64, a1: f64) -> Option<f64> {
        let s = self.state(wind_speed)?;
        if !(a0 > 0.0 && a1 > 0.0) {
            return None;
        }
        let sat = self.cfg.saturation;
        let (x0, x1) = ((a0 / sat) * (a0 / sat), (a1 / sat) * (a1 / sat));
        let beta = 2.0 * self.cfg.structural_damping * self.omega0;
        let alpha = s.aero_damping - beta;
        let t = if beta == 0.0 {
            if alpha == 0.0 {
                return None;
            }
            ((x1 / x0).ln() + x1 - x0) / alpha
        } else if alpha == 0.0 {
            // dx/dt = −β·x²/(1 + x): t = (1/x₁ − 1/x₀ − ln(x₁/x₀))/β.
            (1.0 / x1 - 1.0 / x0 - (x1 / x0).ln()) / beta
        } else {
            let ratio = (alpha - beta * x1) / (alpha - beta * x0);
            if ratio <= 0.0 {
                return None;
            }
            (x1 / x0).ln() / alpha - (alpha + beta) / (alpha * beta) * ratio.ln()
        };
        (t.is_finite() && t >= 0.0).then_some(t)
    }

    /// A time window \[s\] that shows how the twist from `theta0` \[rad\] evolves at wind speed
    /// `U`: 1.25 × the time to come within 5 % of the limit cycle when the twist grows and
    /// is bounded; the time for 20-fold growth when nothing bounds it; the time to decay to
    /// 10 % when it decays; 60 periods when neither. Kept within 20 periods and 2 hours.
    pub fn window(&self, wind_speed: f64, theta0: f64) -> f64 {
        let period = TAU / self.omega0;
        let (lo, hi) = (20.0 * period, 7200.0_f64.max(20.0 * period));
        let Some(s) = self.state(wind_speed) else {
            return lo;
        };
        let a0 = theta0.abs();
        let sigma = s.growth_rate();
        let t = match self.limit_cycle(wind_speed) {
            Some(lc) if a0 > 0.0 => {
                let target = if a0 < lc { 0.95 * lc } else { 1.05 * lc };
                self.time_between(wind_speed, a0, target)
                    .map(|t| 1.25 * t)
                    .unwrap_or(lo)
            }
            _ if sigma > 0.0 => 20.0_f64.ln() / sigma,
            _ if sigma < 0.0 => 10.0_f64.ln() / -sigma,
            _ => 60.0 * period,
        };
        if t.is_finite() {
            t.clamp(lo, hi)
        } else {
            hi
        }
    }

    /// The twist released from `theta0` \[rad\] at rest, at wind speed `U`, over
    /// `[0, t_end]` \[s\], integrated by RK4 with the amplitude-dependent damping (module
    /// doc) at `steps_per_period` steps per oscillation (at most 60 000 steps: longer runs
    /// take longer steps). `None` when there is no oscillating mode at `U` or the
    /// arguments are out of range.
    pub fn simulate(
        &self,
        wind_speed: f64,
        theta0: f64,
        t_end: f64,
        steps_per_period: usize,
    ) -> Option<TwistHistory> {
        let s = self.state(wind_speed)?;
        if !(t_end.is_finite() && t_end > 0.0 && theta0.is_finite()) || steps_per_period == 0 {
            return None;
        }
        let sys = Twist {
            c_s: 2.0 * self.cfg.structural_damping * self.omega0,
            c_a: s.aero_damping,
            k: s.stiffness,
            omega: s.omega,
            inv_sat2: 1.0 / (self.cfg.saturation * self.cfg.saturation),
        };
        let h_wanted = TAU / s.omega / steps_per_period as f64;
        let steps = ((t_end / h_wanted).ceil() as usize).clamp(1, MAX_STEPS);
        let h = t_end / steps as f64;
        let mut out = vec![[0.0; 2]; steps + 1];
        Rk4.solve_into(&sys, [theta0, 0.0], 0.0, h, &mut out).ok()?;
        Some(TwistHistory {
            t: (0..=steps).map(|i| h * i as f64).collect(),
            theta: out.iter().map(|y| y[0]).collect(),
            amplitude: out.iter().map(|y| sys.amplitude2(y).sqrt()).collect(),
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn config_is_validated() {
        let ok = ScanlanConfig::tacoma_1940();
        assert!(ScanlanModel::new(ok).is_ok());
        for bad in [
            ScanlanConfig { width: 0.0, ..ok },
            ScanlanConfig {
                inertia: -1.0,
                ..ok
            },
            ScanlanConfig {
                frequency: f64::NAN,
                ..ok
            },
            ScanlanConfig {
                structural_damping: -0.1,
                ..ok
            },
            ScanlanConfig {
                saturation: 0.0,
                ..ok
            },
            ScanlanConfig {
                aerodynamics: Aerodynamics::SimplestPicture {
                    slope: f64::INFINITY,
                },
                ..ok
            },
        ] {
            assert!(ScanlanModel::new(bad).is_err(), "{bad:?}");
        }
    }

    #[test]
    fn still_air_is_the_structure_alone() {
        let m = ScanlanModel::new(ScanlanConfig::tacoma_1940()).unwrap();
        let s = m.state(0.0).unwrap();
        assert!((s.damping_ratio() - 0.005).abs() < 1e-15);
        assert!(s.reduced_frequency.is_infinite());
        assert!(m.state(-1.0).is_none() && m.state(f64::NAN).is_none());
        assert!(m.simulate(10.0, 0.01, 0.0, 20).is_none());
    }
}
