//! One equation, many machines: physical systems whose small motions obey
//! `a·y'' + b·y' + c·y = f(t)`, each described by its own parameters in its own units.
//!
//! Every machine here is a type with a checked constructor, its mapping to the
//! coefficients `(a, b, c)` of a [`SecondOrder`] ([`Machine::system`], formula and units in
//! each type's docs), and the inverse used to make it behave exactly like another machine
//! ([`Machine::matched`]): given a [`Target`] `(ωₙ, ζ)`, two *tuning* parameters are solved
//! for and the others kept. Two machines with equal `ωₙ` and `ζ` have the same normalised
//! free response `y(t)/y₀` at every time `t`, whatever their units.
//!
//! | machine | coordinate `y` | `a` | `b` | `c` | tuned by "match" |
//! | --- | --- | --- | --- | --- | --- |
//! | [`MassSpringDamper`] | displacement x \[m\] | m \[kg\] | c \[N·s/m\] | k \[N/m\] | k, c |
//! | [`SeriesRlc`] | charge q \[C\] | L \[H\] | R \[Ω\] | 1/C \[1/F\] | C, R |
//! | [`UTube`] | level change h \[m\] | ρAL \[kg\] | 8πμL \[N·s/m\] | 2ρgA \[N/m\] | L, μ |
//! | [`DcServo`] | angle error θ \[rad\] | J \[kg·m²\] | K_t(K_t + K_d)/R \[N·m·s/rad\] | K_t·K_p/R \[N·m/rad\] | K_p, K_d |
//! | [`Storey`] | storey drift u \[m\] | m \[kg\] | c \[N·s/m\] | 12nEI/h³ \[N/m\] | EI, c |
//! | [`TwoCapacityThermal`] | temperature excess T₂ \[K\] | R₁C₁R₂C₂ \[s²\] | R₁C₁ + R₂C₂ + R₁C₂ \[s\] | 1 \[-\] | R₁, R₂ |
//!
//! ```
//! use zeta_solver::machines::{Machine, MassSpringDamper, SeriesRlc, Target};
//! let spring = MassSpringDamper::new(1.0, 2.0, 100.0).unwrap();
//! let circuit = SeriesRlc::new(0.1, 10.0, 1e-3).unwrap();
//! let target = Target::of(&spring.system()).unwrap();
//! let tuned = circuit.matched(target).unwrap();
//! assert!((tuned.system().natural_frequency().unwrap() - 10.0).abs() < 1e-12);
//! assert!((tuned.system().damping_ratio().unwrap() - 0.1).abs() < 1e-12);
//! ```

use crate::error::{non_negative, positive, ModelError};
use crate::model::SecondOrder;
use std::f64::consts::PI;
use std::fmt;

/// Standard acceleration of gravity g_n = 9.806 65 m/s² (exact by definition, 3rd CGPM 1901).
pub const STANDARD_GRAVITY: f64 = 9.806_65;

/// A behaviour to match: natural frequency `ωₙ` \[rad/s\] > 0 and damping ratio `ζ` ≥ 0.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Target {
    wn: f64,
    zeta: f64,
}

impl Target {
    /// `ωₙ` \[rad/s\] > 0 and `ζ` \[-\] ≥ 0.
    pub fn new(wn: f64, zeta: f64) -> Result<Self, ModelError> {
        Ok(Self {
            wn: positive("natural frequency ωₙ", "rad/s", wn)?,
            zeta: non_negative("damping ratio ζ", "", zeta)?,
        })
    }

    /// The behaviour of `sys`: `ωₙ = √(c/a)`, `ζ = b/(2√(ac))`; `None` when `c ≤ 0` or
    /// `b < 0`, which no passive machine here realises.
    pub fn of(sys: &SecondOrder) -> Option<Self> {
        Self::new(sys.natural_frequency()?, sys.damping_ratio()?).ok()
    }

    /// Natural frequency `ωₙ` \[rad/s\].
    pub fn wn(&self) -> f64 {
        self.wn
    }

    /// Damping ratio `ζ` \[-\].
    pub fn zeta(&self) -> f64 {
        self.zeta
    }

    /// The linear damping `b = 2ζ·a·ωₙ` that gives this `ζ` with the leading coefficient
    /// `a` (and this `ωₙ`), in `a`'s unit per second.
    fn damping_for(&self, a: f64) -> f64 {
        2.0 * self.zeta * a * self.wn
    }

    /// The stiffness `c = a·ωₙ²` that gives this `ωₙ` with the leading coefficient `a`, in
    /// `a`'s unit per second squared.
    fn stiffness_for(&self, a: f64) -> f64 {
        a * self.wn * self.wn
    }
}

/// Why a machine could not be tuned to a target.
#[derive(Debug, Clone, PartialEq)]
pub enum MatchError {
    /// With its kept parameters the machine cannot be damped this lightly: it needs
    /// `ζ ≥ zeta_min` and the target asks for `zeta`.
    DampingTooLow {
        /// The smallest damping ratio reachable \[-\].
        zeta_min: f64,
        /// The target's damping ratio \[-\].
        zeta: f64,
    },
    /// The tuned parameters do not make a valid machine (e.g. beyond double precision).
    Model(ModelError),
}

impl fmt::Display for MatchError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            MatchError::DampingTooLow { zeta_min, zeta } => write!(
                f,
                "this machine needs a damping ratio of at least {zeta_min}, the target has {zeta}"
            ),
            MatchError::Model(e) => write!(f, "{e}"),
        }
    }
}

impl std::error::Error for MatchError {}

impl From<ModelError> for MatchError {
    fn from(e: ModelError) -> Self {
        MatchError::Model(e)
    }
}

/// A physical system governed by `a·y'' + b·y' + c·y = f(t)`.
pub trait Machine: Sized {
    /// Its coefficients `(a, b, c)`, in the machine's own units (see each type).
    fn system(&self) -> SecondOrder;

    /// The same machine with its two tuning parameters solved so that `ωₙ` and `ζ` equal
    /// `target`'s, every other parameter kept.
    fn matched(&self, target: Target) -> Result<Self, MatchError>;
}

/// A mass on a spring and a viscous damper: `m·x'' + c·x' + k·x = F(t)`.
///
/// `a = m` \[kg\], `b = c` \[N·s/m\], `c = k` \[N/m\]; `y = x` \[m\]. Match keeps `m`:
/// `k = m·ωₙ²`, `c = 2ζ·m·ωₙ`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MassSpringDamper {
    m: f64,
    c: f64,
    k: f64,
    sys: SecondOrder,
}

impl MassSpringDamper {
    /// Mass `m` \[kg\] > 0, damper rate `c` \[N·s/m\] ≥ 0, spring rate `k` \[N/m\] > 0.
    pub fn new(m: f64, c: f64, k: f64) -> Result<Self, ModelError> {
        let m = positive("mass m", "kg", m)?;
        let c = non_negative("damping c", "N·s/m", c)?;
        let k = positive("stiffness k", "N/m", k)?;
        Ok(Self {
            m,
            c,
            k,
            sys: SecondOrder::mechanical(m, c, k)?,
        })
    }

    /// `(m [kg], c [N·s/m], k [N/m])`.
    pub fn params(&self) -> (f64, f64, f64) {
        (self.m, self.c, self.k)
    }
}

impl Machine for MassSpringDamper {
    fn system(&self) -> SecondOrder {
        self.sys
    }

    fn matched(&self, t: Target) -> Result<Self, MatchError> {
        Ok(Self::new(
            self.m,
            t.damping_for(self.m),
            t.stiffness_for(self.m),
        )?)
    }
}

/// A series inductor–resistor–capacitor loop, in the charge `q`: `L·q'' + R·q' + q/C = E(t)`.
///
/// `a = L` \[H\], `b = R` \[Ω\], `c = 1/C` \[1/F\]; `y = q` \[C\] (the capacitor's voltage is
/// `q/C`). Match keeps `L`: `C = 1/(L·ωₙ²)`, `R = 2ζ·L·ωₙ`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SeriesRlc {
    l: f64,
    r: f64,
    cap: f64,
    sys: SecondOrder,
}

impl SeriesRlc {
    /// Inductance `l` \[H\] > 0, resistance `r` \[Ω\] ≥ 0, capacitance `cap` \[F\] > 0.
    pub fn new(l: f64, r: f64, cap: f64) -> Result<Self, ModelError> {
        let sys = SecondOrder::electrical(l, r, cap)?;
        Ok(Self { l, r, cap, sys })
    }

    /// `(L [H], R [Ω], C [F])`.
    pub fn params(&self) -> (f64, f64, f64) {
        (self.l, self.r, self.cap)
    }
}

impl Machine for SeriesRlc {
    fn system(&self) -> SecondOrder {
        self.sys
    }

    fn matched(&self, t: Target) -> Result<Self, MatchError> {
        let inverse_cap = t.stiffness_for(self.l);
        Ok(Self::new(self.l, t.damping_for(self.l), 1.0 / inverse_cap)?)
    }
}

/// A U-tube manometer: a liquid column of length `L` in a tube of bore `d`, with laminar
/// (Poiseuille) wall friction.
///
/// When one level rises by `h` the other falls by `h`; the column of mass `ρAL`
/// (`A = πd²/4`) feels the weight of the `2h` difference, `2ρgA·h`, and the quasi-steady
/// Poiseuille friction `(32μL/d²)·A·h' = 8πμL·h'`:
/// `ρAL·h'' + 8πμL·h' + 2ρgA·h = A·Δp(t)`.
/// So `a = ρAL` \[kg\], `b = 8πμL` \[N·s/m\], `c = 2ρgA` \[N/m\]; `y = h` \[m\];
/// `ωₙ = √(2g/L)` and `ζ = 16μ/(ρd²ωₙ)`. (A teaching model: the friction of an
/// oscillating flow is larger than Poiseuille's at high frequency.)
/// Match keeps the bore and the density: `L = 2g/ωₙ²`, `μ = ζρd²ωₙ/16`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct UTube {
    length: f64,
    bore: f64,
    density: f64,
    viscosity: f64,
    sys: SecondOrder,
}

impl UTube {
    /// Column length `length` \[m\] > 0, bore `bore` \[m\] > 0, density `density` \[kg/m³\]
    /// > 0, dynamic viscosity `viscosity` \[Pa·s\] ≥ 0.
    pub fn new(length: f64, bore: f64, density: f64, viscosity: f64) -> Result<Self, ModelError> {
        let length = positive("column length L", "m", length)?;
        let bore = positive("bore d", "m", bore)?;
        let density = positive("density ρ", "kg/m³", density)?;
        let viscosity = non_negative("viscosity μ", "Pa·s", viscosity)?;
        let area = PI * bore * bore / 4.0;
        let sys = SecondOrder::new(
            density * area * length,
            8.0 * PI * viscosity * length,
            2.0 * density * STANDARD_GRAVITY * area,
        )?;
        Ok(Self {
            length,
            bore,
            density,
            viscosity,
            sys,
        })
    }

    /// `(L [m], d [m], ρ [kg/m³], μ [Pa·s])`.
    pub fn params(&self) -> (f64, f64, f64, f64) {
        (self.length, self.bore, self.density, self.viscosity)
    }
}

impl Machine for UTube {
    fn system(&self) -> SecondOrder {
        self.sys
    }

    fn matched(&self, t: Target) -> Result<Self, MatchError> {
        let length = 2.0 * STANDARD_GRAVITY / (t.wn * t.wn);
        let viscosity = t.zeta * self.density * self.bore * self.bore * t.wn / 16.0;
        Ok(Self::new(length, self.bore, self.density, viscosity)?)
    }
}

/// A DC-motor position servo under proportional-derivative control, driven by voltage.
///
/// The controller applies `V = K_p·e − K_d·θ'` to the armature (resistance `R`, inductance
/// neglected: its time constant is far shorter than the mechanical one), with `e` the angle
/// error. Torque `K_t·i` with `i = (V − K_t·θ')/R` (back-EMF constant = torque constant in
/// SI units) turns the load of inertia `J`:
/// `J·θ'' + (K_t(K_t + K_d)/R)·θ' + (K_t·K_p/R)·θ = (K_t·K_p/R)·θ_ref`.
/// So `a = J` \[kg·m²\], `b = K_t(K_t + K_d)/R` \[N·m·s/rad\], `c = K_t·K_p/R`
/// \[N·m/rad\]; `y` = the angle error \[rad\]. The back-EMF alone damps the motor:
/// `b ≥ K_t²/R`. Match keeps the motor (`J`, `K_t`, `R`) and tunes the controller:
/// `K_p = R·J·ωₙ²/K_t`, `K_d = 2ζωₙ·R·J/K_t − K_t`, which needs `K_d ≥ 0`, i.e.
/// `ζ ≥ K_t²/(2ωₙ·R·J)`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DcServo {
    inertia: f64,
    torque_constant: f64,
    resistance: f64,
    kp: f64,
    kd: f64,
    sys: SecondOrder,
}

impl DcServo {
    /// Inertia `inertia` \[kg·m²\] > 0, torque constant `torque_constant` \[N·m/A\] > 0,
    /// armature resistance `resistance` \[Ω\] > 0, proportional gain `kp` \[V/rad\] > 0,
    /// derivative gain `kd` \[V·s/rad\] ≥ 0.
    pub fn new(
        inertia: f64,
        torque_constant: f64,
        resistance: f64,
        kp: f64,
        kd: f64,
    ) -> Result<Self, ModelError> {
        let inertia = positive("inertia J", "kg·m²", inertia)?;
        let kt = positive("torque constant K_t", "N·m/A", torque_constant)?;
        let r = positive("armature resistance R", "Ω", resistance)?;
        let kp = positive("proportional gain K_p", "V/rad", kp)?;
        let kd = non_negative("derivative gain K_d", "V·s/rad", kd)?;
        let sys = SecondOrder::new(inertia, kt * (kt + kd) / r, kt * kp / r)?;
        Ok(Self {
            inertia,
            torque_constant: kt,
            resistance: r,
            kp,
            kd,
            sys,
        })
    }

    /// `(J [kg·m²], K_t [N·m/A], R [Ω], K_p [V/rad], K_d [V·s/rad])`.
    pub fn params(&self) -> (f64, f64, f64, f64, f64) {
        (
            self.inertia,
            self.torque_constant,
            self.resistance,
            self.kp,
            self.kd,
        )
    }
}

impl Machine for DcServo {
    fn system(&self) -> SecondOrder {
        self.sys
    }

    fn matched(&self, t: Target) -> Result<Self, MatchError> {
        let (j, kt, r) = (self.inertia, self.torque_constant, self.resistance);
        let kp = r * j * t.wn * t.wn / kt;
        let kd = 2.0 * t.zeta * t.wn * r * j / kt - kt;
        if kd < 0.0 {
            return Err(MatchError::DampingTooLow {
                zeta_min: kt * kt / (2.0 * t.wn * r * j),
                zeta: t.zeta,
            });
        }
        Ok(Self::new(j, kt, r, kp, kd)?)
    }
}

/// One storey of a building under ground motion: a rigid floor of mass `m` on `n` columns
/// of height `h` and bending stiffness `EI`, clamped at both ends, with viscous damping `c`.
///
/// A clamped–clamped column whose top slides sideways by `u` without turning resists with
/// `12EI/h³·u`, so the storey's lateral stiffness is `k = 12nEI/h³`. In the drift
/// `u = x − x_g` relative to the ground, `m·u'' + c·u' + k·u = −m·x_g''(t)`.
/// So `a = m` \[kg\], `b = c` \[N·s/m\], `c = 12nEI/h³` \[N/m\]; `y = u` \[m\].
/// Match keeps the floor and the geometry: `EI = m·ωₙ²·h³/(12n)`, `c = 2ζ·m·ωₙ`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Storey {
    mass: f64,
    height: f64,
    rigidity: f64,
    columns: f64,
    damping: f64,
    sys: SecondOrder,
}

impl Storey {
    /// Floor mass `mass` \[kg\] > 0, storey height `height` \[m\] > 0, bending stiffness of
    /// each column `rigidity` = EI \[N·m²\] > 0, number of columns `columns` > 0, damping
    /// coefficient `damping` \[N·s/m\] ≥ 0.
    pub fn new(
        mass: f64,
        height: f64,
        rigidity: f64,
        columns: f64,
        damping: f64,
    ) -> Result<Self, ModelError> {
        let mass = positive("floor mass m", "kg", mass)?;
        let height = positive("storey height h", "m", height)?;
        let rigidity = positive("column bending stiffness EI", "N·m²", rigidity)?;
        let columns = positive("number of columns n", "", columns)?;
        let damping = non_negative("damping c", "N·s/m", damping)?;
        let k = 12.0 * columns * rigidity / (height * height * height);
        Ok(Self {
            mass,
            height,
            rigidity,
            columns,
            damping,
            sys: SecondOrder::mechanical(mass, damping, k)?,
        })
    }

    /// `(m [kg], h [m], EI [N·m²], n, c [N·s/m])`.
    pub fn params(&self) -> (f64, f64, f64, f64, f64) {
        (
            self.mass,
            self.height,
            self.rigidity,
            self.columns,
            self.damping,
        )
    }
}

impl Machine for Storey {
    fn system(&self) -> SecondOrder {
        self.sys
    }

    fn matched(&self, t: Target) -> Result<Self, MatchError> {
        let h3 = self.height * self.height * self.height;
        let rigidity = t.stiffness_for(self.mass) * h3 / (12.0 * self.columns);
        let damping = t.damping_for(self.mass);
        Ok(Self::new(
            self.mass,
            self.height,
            rigidity,
            self.columns,
            damping,
        )?)
    }
}

/// Two thermal capacities in a chain: body 1 (heat capacity `C₁`) exchanges heat with the
/// surroundings through the thermal resistance `R₁`, and body 2 (`C₂`) with body 1 through
/// `R₂`. In temperatures above the surroundings,
/// `C₁·T₁' = −T₁/R₁ − (T₁ − T₂)/R₂` and `C₂·T₂' = (T₁ − T₂)/R₂`.
/// Eliminating `T₁ = T₂ + R₂C₂·T₂'`:
/// `R₁C₁R₂C₂·T₂'' + (R₁C₁ + R₂C₂ + R₁C₂)·T₂' + T₂ = T_s(t)` (the surroundings' temperature).
/// So `a = τ₁τ₂` \[s²\], `b = τ₁ + τ₂ + R₁C₂` \[s\], `c = 1` \[-\] with `τ₁ = R₁C₁`,
/// `τ₂ = R₂C₂`; `y = T₂` \[K\].
///
/// **It can never oscillate.** `b² − 4ac = (τ₁ − τ₂)² + R₁C₂(2τ₁ + 2τ₂ + R₁C₂) > 0`
/// ([`TwoCapacityThermal::discriminant`]), so `ζ = (τ₁ + τ₂ + R₁C₂)/(2√(τ₁τ₂)) > 1` for
/// every positive `C₁, R₁, C₂, R₂`: heat has no inertia, nothing carries it past equilibrium.
/// Match keeps the capacities and tunes the resistances; the least reachable damping is
/// then `ζ = √(1 + C₂/C₁)` ([`TwoCapacityThermal::min_damping_ratio`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TwoCapacityThermal {
    c1: f64,
    r1: f64,
    c2: f64,
    r2: f64,
    sys: SecondOrder,
}

impl TwoCapacityThermal {
    /// Heat capacities `c1`, `c2` \[J/K\] > 0 and thermal resistances `r1`, `r2` \[K/W\] > 0.
    pub fn new(c1: f64, r1: f64, c2: f64, r2: f64) -> Result<Self, ModelError> {
        let c1 = positive("heat capacity C₁", "J/K", c1)?;
        let r1 = positive("thermal resistance R₁", "K/W", r1)?;
        let c2 = positive("heat capacity C₂", "J/K", c2)?;
        let r2 = positive("thermal resistance R₂", "K/W", r2)?;
        let (tau1, tau2) = (r1 * c1, r2 * c2);
        let sys = SecondOrder::new(tau1 * tau2, tau1 + tau2 + r1 * c2, 1.0)?;
        Ok(Self {
            c1,
            r1,
            c2,
            r2,
            sys,
        })
    }

    /// `(C₁ [J/K], R₁ [K/W], C₂ [J/K], R₂ [K/W])`.
    pub fn params(&self) -> (f64, f64, f64, f64) {
        (self.c1, self.r1, self.c2, self.r2)
    }

    /// `b² − 4ac` \[s²\], computed as the sum of positive terms
    /// `(τ₁ − τ₂)² + R₁C₂(2τ₁ + 2τ₂ + R₁C₂)`: always > 0, so the poles are real and distinct.
    pub fn discriminant(&self) -> f64 {
        let (tau1, tau2, x) = (self.r1 * self.c1, self.r2 * self.c2, self.r1 * self.c2);
        (tau1 - tau2) * (tau1 - tau2) + x * (2.0 * tau1 + 2.0 * tau2 + x)
    }

    /// The least damping ratio reachable by tuning `R₁` and `R₂` with these capacities:
    /// `√(1 + C₂/C₁)` \[-\].
    pub fn min_damping_ratio(&self) -> f64 {
        (1.0 + self.c2 / self.c1).sqrt()
    }
}

impl Machine for TwoCapacityThermal {
    fn system(&self) -> SecondOrder {
        self.sys
    }

    /// With `u = R₁(C₁ + C₂)` and `v = R₂C₂`: `u + v = b = 2ζ/ωₙ` and
    /// `u·v = a·(C₁ + C₂)/C₁ = (C₁ + C₂)/(C₁ωₙ²)`, so `u`, `v` are the roots of
    /// `s² − b·s + u·v = 0`, real when `ζ² ≥ 1 + C₂/C₁`. Of the two solutions the one
    /// nearer the present `R₁` (in ratio) is taken, so tuning moves the sliders least.
    fn matched(&self, t: Target) -> Result<Self, MatchError> {
        let (c1, c2) = (self.c1, self.c2);
        let zeta_min = self.min_damping_ratio();
        let sum = 2.0 * t.zeta / t.wn;
        let product = (c1 + c2) / (c1 * t.wn * t.wn);
        let disc = sum * sum - 4.0 * product;
        if t.zeta < zeta_min || disc < 0.0 {
            return Err(MatchError::DampingTooLow {
                zeta_min,
                zeta: t.zeta,
            });
        }
        let big = 0.5 * (sum + disc.sqrt());
        let small = product / big;
        let now = self.r1 * (c1 + c2);
        let distance = |u: f64| (u / now).ln().abs();
        let u = if distance(small) < distance(big) {
            small
        } else {
            big
        };
        let v = product / u;
        Ok(Self::new(c1, u / (c1 + c2), c2, v / c2)?)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn errors_name_the_parameter_and_unit() {
        let e = UTube::new(0.5, 0.01, -1.0, 1e-3).unwrap_err();
        assert_eq!(e.to_string(), "density ρ must be positive, got -1 kg/m³");
        assert!(matches!(
            TwoCapacityThermal::new(1.0, f64::NAN, 1.0, 1.0),
            Err(ModelError::NotFinite { .. })
        ));
        assert!(matches!(
            DcServo::new(1e-3, 0.1, 2.0, 20.0, -1.0),
            Err(ModelError::Negative { .. })
        ));
        assert!(Target::new(0.0, 0.5).is_err());
    }

    #[test]
    fn the_servo_reports_the_least_damping_its_back_emf_allows() {
        let servo = DcServo::new(1e-3, 0.1, 2.0, 20.0, 0.1).unwrap();
        let e = servo.matched(Target::new(10.0, 0.1).unwrap()).unwrap_err();
        // K_t²/(2ωₙRJ) = 0.01/(2·10·2·1e-3) = 0.25.
        match e {
            MatchError::DampingTooLow { zeta_min, zeta } => {
                assert!((zeta_min - 0.25).abs() < 1e-15);
                assert_eq!(zeta, 0.1);
            }
            other => panic!("{other:?}"),
        }
    }
}
