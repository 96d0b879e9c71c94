//! Flutter: a torsional mode whose effective damping falls with wind speed, until it goes
//! negative and the twisting grows (the 1940 Tacoma Narrows failure).
//!
//! Two models: [`scanlan::ScanlanModel`], the deck on Scanlan's flutter derivatives
//! `A₂*(K)`, `A₃*(K)` (tabulated in [`derivatives`]; the streamlined box's are the flat
//! plate's of [`theodorsen`]) with an amplitude-dependent bound on the motion, and, here, [`FlutterModel`], the *simplest picture*:
//!
//! Model: one torsional mode of the deck, angle `θ(t)` \[rad\],
//!
//! `θ'' + 2·ζ_eff(U)·ω·θ' + ω²·θ = 0`,  `ζ_eff(U) = ζ_s − g·U`,
//!
//! with torsional natural frequency `ω` \[rad/s\], structural damping ratio `ζ_s` \[-\] and an
//! aerodynamic slope `g` \[s/m\] by which each m/s of wind speed `U` removes damping.
//!
//! Assumptions (why this is a teaching simplification): it is a reduced form of Scanlan's
//! flutter-derivative model (Scanlan & Tomko, 1971), in which the self-excited moment on the
//! deck is written with measured flutter derivatives; here only the `A2*` term is kept —
//! the part of the moment proportional to the deck's angular velocity, i.e. aerodynamic
//! damping, which turns negative for bluff H-shaped decks like Tacoma's — and `A2*`'s
//! dependence on the reduced frequency `K = Bω/U` is replaced by a straight line in `U`.
//! Left out: the aerodynamic stiffness `A3*` (which would shift the frequency with `U`;
//! here `ω` is fixed and only the damped frequency `ω√(1 − ζ_eff²)` changes), coupling to
//! vertical bending (`A1*`, `A4*`, `H1*…H4*`), turbulence (buffeting), vortex shedding and
//! all structural non-linearity. It is single-degree-of-freedom torsional flutter: what it
//! captures is the sign change of the damping at the critical speed `U_crit = ζ_s/g`, not
//! forced resonance.
//!
//! ```
//! use zeta_solver::flutter::FlutterModel;
//! use zeta_solver::Regime;
//! let bridge = FlutterModel::tacoma_1940();
//! let u_crit = bridge.critical_speed().unwrap();
//! assert!((u_crit - 18.78).abs() < 0.01); // ≈ 42 mph
//! assert!(bridge.growth_rate(15.0) < 0.0 && bridge.growth_rate(25.0) > 0.0);
//! assert_eq!(bridge.regime(25.0).unwrap(), Regime::NegativelyDamped);
//! ```

pub mod derivatives;
pub mod scanlan;
pub mod theodorsen;

pub use derivatives::{DeckSection, DerivativeTable};
pub use scanlan::{FlutterState, ScanlanConfig, ScanlanModel, TwistHistory};

use crate::complex::Complex;
use crate::error::{finite, non_negative, positive, ModelError};
use crate::free::FreeResponse;
use crate::model::SecondOrder;
use crate::regime::Regime;
use std::f64::consts::TAU;

/// Torsional frequency of the 1940 Tacoma Narrows deck, ≈ 0.2 Hz \[Hz\]. Approximate
/// historical value as commonly quoted (e.g. T. Irvine, "Tacoma Narrows Bridge Failure",
/// vibrationdata.com; Billah & Scanlan, Am. J. Phys. 59 (1991) 118–124).
pub const TACOMA_TORSION_HZ: f64 = 0.2;

/// Wind speed on the morning of the failure, 7 Nov 1940: ≈ 42 mph = 18.78 m/s \[m/s\]
/// (approximate; 40–42 mph is quoted). Used as the preset's critical speed.
pub const TACOMA_FAILURE_WIND: f64 = 42.0 * 0.447_04;

/// Structural damping ratio of the preset, 0.5 % \[-\]: an assumed value typical of welded
/// and bolted steel suspension decks, not a measured 1940 value.
pub const TACOMA_STRUCTURAL_DAMPING: f64 = 0.005;

/// Parameters of the flutter model (validated by [`FlutterModel::new`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FlutterConfig {
    /// Torsional natural frequency `ω` \[rad/s\], > 0.
    pub omega: f64,
    /// Structural damping ratio `ζ_s` \[-\], ≥ 0.
    pub structural_damping: f64,
    /// Aerodynamic slope `g` \[s/m\]: damping ratio removed per m/s of wind. Any finite
    /// value; `g ≤ 0` means the wind never destabilises the mode.
    pub aero_slope: f64,
}

impl FlutterConfig {
    /// The 1940 Tacoma Narrows preset: `ω = 2π·0.2` rad/s, `ζ_s = 0.005`, and
    /// `g = ζ_s / 18.78 m/s` so that the critical speed is the failure wind speed.
    pub fn tacoma_1940() -> Self {
        Self {
            omega: TAU * TACOMA_TORSION_HZ,
            structural_damping: TACOMA_STRUCTURAL_DAMPING,
            aero_slope: TACOMA_STRUCTURAL_DAMPING / TACOMA_FAILURE_WIND,
        }
    }
}

/// One sample of the root locus: the two poles \[1/s\] at wind speed `speed` \[m/s\].
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct LocusPoint {
    /// Wind speed `U` \[m/s\].
    pub speed: f64,
    /// Poles of `s² + 2ζ_eff·ω·s + ω² = 0` (order as [`SecondOrder::poles`]).
    pub poles: [Complex; 2],
}

/// The validated flutter model (see the module doc).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FlutterModel {
    omega: f64,
    zeta_s: f64,
    slope: f64,
}

impl FlutterModel {
    /// Checks `config`: `ω` finite and > 0, `ζ_s` finite and ≥ 0, `g` finite.
    pub fn new(config: FlutterConfig) -> Result<Self, ModelError> {
        Ok(Self {
            omega: positive("torsional frequency ω", "rad/s", config.omega)?,
            zeta_s: non_negative(
                "structural damping ratio ζ_s",
                "",
                config.structural_damping,
            )?,
            slope: finite("aerodynamic slope g", "s/m", config.aero_slope)?,
        })
    }

    /// The 1940 Tacoma Narrows preset ([`FlutterConfig::tacoma_1940`]).
    pub fn tacoma_1940() -> Self {
        let c = FlutterConfig::tacoma_1940();
        Self {
            omega: c.omega,
            zeta_s: c.structural_damping,
            slope: c.aero_slope,
        }
    }

    /// The parameters.
    pub fn config(&self) -> FlutterConfig {
        FlutterConfig {
            omega: self.omega,
            structural_damping: self.zeta_s,
            aero_slope: self.slope,
        }
    }

    /// Effective damping ratio `ζ_eff(U) = ζ_s − g·U` \[-\] at wind speed `U` \[m/s\],
    /// evaluated with one rounding (fused multiply-add) so its zero is at `U_crit` to ~1 ulp.
    pub fn effective_damping(&self, wind_speed: f64) -> f64 {
        (-self.slope).mul_add(wind_speed, self.zeta_s)
    }

    /// Critical (flutter) speed `U_crit = ζ_s / g` \[m/s\], where `ζ_eff = 0`; `None` when
    /// `g ≤ 0` (the wind only adds damping) — `Some(0)` when `ζ_s = 0` and `g > 0`.
    pub fn critical_speed(&self) -> Option<f64> {
        (self.slope > 0.0).then(|| self.zeta_s / self.slope)
    }

    /// Growth rate `σ(U)` \[1/s\]: the largest real part of the two poles. While
    /// `|ζ_eff| < 1` (every realistic case) `σ = −ζ_eff·ω`: negative (oscillation decays with
    /// time constant `1/|σ|`) below `U_crit`, positive (grows like `e^{σt}`) above it. For
    /// `|ζ_eff| ≥ 1` the poles are real and `σ = ω·(−ζ_eff + √(ζ_eff² − 1))`.
    pub fn growth_rate(&self, wind_speed: f64) -> f64 {
        let z = self.effective_damping(wind_speed);
        let w = self.omega;
        if z.abs() < 1.0 {
            -z * w
        } else if z > 0.0 {
            // −ζ + √(ζ² − 1) = −1/(ζ + √(ζ² − 1)), without cancellation.
            -w / (z + (z - 1.0).sqrt() * (z + 1.0).sqrt())
        } else {
            w * (-z + (-z - 1.0).sqrt() * (1.0 - z).sqrt())
        }
    }

    /// Damped torsional frequency `ω·√(1 − ζ_eff²)` \[rad/s\]; `None` once `|ζ_eff| ≥ 1`.
    /// (The real deck's frequency also shifts through the aerodynamic stiffness `A3*`,
    /// which this model leaves out.)
    pub fn damped_frequency(&self, wind_speed: f64) -> Option<f64> {
        let z = self.effective_damping(wind_speed);
        (z.abs() < 1.0).then(|| self.omega * ((1.0 - z) * (1.0 + z)).sqrt())
    }

    /// The mode as a [`SecondOrder`] at wind speed `U` \[m/s\] (`a = 1`, `b = 2ζ_eff·ω`,
    /// `c = ω²`). Errors when `U` is negative or not finite, or `ζ_eff` is out of range.
    pub fn system(&self, wind_speed: f64) -> Result<SecondOrder, ModelError> {
        let u = non_negative("wind speed U", "m/s", wind_speed)?;
        SecondOrder::from_natural(self.omega, self.effective_damping(u))
    }

    /// The two poles \[1/s\] at wind speed `U`; they cross the imaginary axis at `U_crit`.
    pub fn poles(&self, wind_speed: f64) -> Result<[Complex; 2], ModelError> {
        Ok(self.system(wind_speed)?.poles())
    }

    /// The damping regime at wind speed `U` (underdamped below `U_crit`, undamped within
    /// [`crate::ZETA_TOLERANCE`] of it, negatively damped above).
    pub fn regime(&self, wind_speed: f64) -> Result<Regime, ModelError> {
        Ok(self.system(wind_speed)?.regime())
    }

    /// Free torsional motion at wind speed `U` from angle `theta0` \[rad\] and angular
    /// velocity `rate0` \[rad/s\] (closed form, see [`FreeResponse`]).
    pub fn response(
        &self,
        wind_speed: f64,
        theta0: f64,
        rate0: f64,
    ) -> Result<FreeResponse, ModelError> {
        Ok(FreeResponse::new(self.system(wind_speed)?, theta0, rate0))
    }

    /// Undamped torsional period `T = 2π/ω` \[s\].
    pub fn torsional_period(&self) -> f64 {
        TAU / self.omega
    }

    /// Amplitude `A` \[rad\] of the oscillation `θ = A·e^{σt}·cos(ω_d t − φ)` released from
    /// `θ(0) = theta0` \[rad\] at rest: `A = √(θ₀² + (σθ₀/ω_d)²)`, with `σ` the growth rate
    /// and `ω_d` the damped frequency; `|θ₀|` when the mode does not oscillate.
    pub fn envelope_amplitude(&self, wind_speed: f64, theta0: f64) -> f64 {
        let sigma = self.growth_rate(wind_speed);
        match self.damped_frequency(wind_speed) {
            Some(wd) if wd > 0.0 => (theta0 * theta0 + (sigma * theta0 / wd).powi(2)).sqrt(),
            _ => theta0.abs(),
        }
    }

    /// The envelope `A·e^{σt}` \[rad\] at time `t` \[s\] of the motion released from
    /// `theta0` \[rad\] at rest (see [`Self::envelope_amplitude`]): the twist touches `±` this
    /// curve once per half period.
    pub fn envelope(&self, wind_speed: f64, theta0: f64, t: f64) -> f64 {
        self.envelope_amplitude(wind_speed, theta0) * (self.growth_rate(wind_speed) * t).exp()
    }

    /// Factor `e^{σt}` \[-\] by which the amplitude changes over `t` \[s\] at wind speed `U`.
    pub fn growth_factor(&self, wind_speed: f64, t: f64) -> f64 {
        (self.growth_rate(wind_speed) * t).exp()
    }

    /// Time for the amplitude to double, `ln 2/σ` \[s\], while the twist grows (negatively
    /// damped, `σ > 0`); `None` otherwise.
    pub fn doubling_time(&self, wind_speed: f64) -> Option<f64> {
        let sigma = self.growth_rate(wind_speed);
        (self.regime(wind_speed).ok() == Some(Regime::NegativelyDamped) && sigma > 0.0)
            .then(|| std::f64::consts::LN_2 / sigma)
    }

    /// Root locus: fills `out` with the poles at `out.len()` wind speeds evenly spaced from
    /// `u_min` to `u_max` \[m/s\] (both included; a single point uses `u_min`). No
    /// allocation. Errors (leaving `out` untouched) when a bound is negative or not finite.
    pub fn root_locus_into(
        &self,
        u_min: f64,
        u_max: f64,
        out: &mut [LocusPoint],
    ) -> Result<(), ModelError> {
        let lo = non_negative("lowest wind speed", "m/s", u_min)?;
        let hi = non_negative("highest wind speed", "m/s", u_max)?;
        // Validate the far ends first so a failure leaves `out` untouched: ζ_eff is linear
        // in U, so if both ends are in range every point between them is.
        self.system(lo)?;
        self.system(hi)?;
        let n = out.len();
        let step = if n > 1 {
            (hi - lo) / (n - 1) as f64
        } else {
            0.0
        };
        for (i, p) in out.iter_mut().enumerate() {
            let u = if i + 1 == n && n > 1 {
                hi
            } else {
                lo + step * i as f64
            };
            let poles = self.poles(u)?;
            *p = LocusPoint { speed: u, poles };
        }
        Ok(())
    }
}

/// Angle in degrees from radians: `deg = rad·180/π`.
pub fn degrees(radians: f64) -> f64 {
    radians.to_degrees()
}

/// Angle in radians from degrees: `rad = deg·π/180`.
pub fn radians(degrees: f64) -> f64 {
    degrees.to_radians()
}

/// The point `p = (x, y)` of a rigid deck section after it twists by `angle` \[rad\]
/// about the origin: `(x·cos θ − y·sin θ, x·sin θ + y·cos θ)`, in the unit of `p`.
pub fn rotate(p: (f64, f64), angle: f64) -> (f64, f64) {
    let (s, c) = angle.sin_cos();
    (c * p.0 - s * p.1, s * p.0 + c * p.1)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn config_is_validated() {
        let mut c = FlutterConfig::tacoma_1940();
        c.omega = 0.0;
        assert!(matches!(
            FlutterModel::new(c),
            Err(ModelError::NotPositive { .. })
        ));
        let mut c = FlutterConfig::tacoma_1940();
        c.structural_damping = -0.01;
        assert!(matches!(
            FlutterModel::new(c),
            Err(ModelError::Negative { .. })
        ));
        let mut c = FlutterConfig::tacoma_1940();
        c.aero_slope = f64::NAN;
        assert!(matches!(
            FlutterModel::new(c),
            Err(ModelError::NotFinite { .. })
        ));
        assert_eq!(
            FlutterModel::new(FlutterConfig::tacoma_1940()).ok(),
            Some(FlutterModel::tacoma_1940())
        );
    }

    #[test]
    fn no_critical_speed_without_destabilising_wind() {
        let mut c = FlutterConfig::tacoma_1940();
        c.aero_slope = 0.0;
        let m = FlutterModel::new(c).unwrap();
        assert_eq!(m.critical_speed(), None);
        assert!(m.growth_rate(100.0) < 0.0);
        assert!(m.system(-1.0).is_err());
    }
}
