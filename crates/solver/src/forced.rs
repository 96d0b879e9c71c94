//! Forced responses of `a·x'' + b·x' + c·x = f(t)`: step, impulse and harmonic forcing, each
//! the full solution (transient plus particular) from given initial conditions `x(0) = x0`,
//! `x'(0) = v0`, for every validated [`SecondOrder`] (`c ≤ 0` and `b < 0` included).
//!
//! Units: `t` in s, `x` in the unit of `x0`, force in the unit of `a·x''` (N for the quarter
//! car, V for the RLC loop in the charge), angular frequency in rad/s, phase in rad.
//!
//! * Step `f = F0` for `t ≥ 0`: `x = F0/c + x_free` when `c ≠ 0`; when `c = 0` there is no
//!   equilibrium and the exact particular solution is the drift `(F0/a)·t²·φ₂(−2αt)` with
//!   `φ₂(z) = (eᶻ − 1 − z)/z²` — a ramp `F0·t/b` after the transient, a parabola
//!   `F0·t²/(2a)` when `b = 0` too.
//! * Impulse `I` at `t = 0`: a velocity jump `I/a`, then the free response.
//! * Harmonic `f = F0·cos(ωt + φ)`: for the undamped system the forced part is written with
//!   `cos ωt − cos ω_n t = −2·sin((ω−ω_n)t/2)·sin((ω+ω_n)t/2)`, which stays exact through
//!   beating and at resonance (`F0/(2aω_n)·t·sin(ω_n t)`); for light damping
//!   (`ζ² < 1/2`) it is the Duhamel integral in closed form with `(eᶻ − 1)/z` evaluated
//!   without cancellation; otherwise the periodic particular solution plus the free response.
//!
//! ```
//! use zeta_solver::forced::{HarmonicForce, HarmonicResponse, StepResponse};
//! use zeta_solver::SecondOrder;
//! // Undamped, driven exactly at ω_n = 2 rad/s from rest: x = F0/(2aω_n)·t·sin(ω_n t).
//! let sys = SecondOrder::from_natural(2.0, 0.0).unwrap();
//! let drive = HarmonicForce::new(1.0, 2.0).unwrap();
//! let x = HarmonicResponse::new(sys, drive, 0.0, 0.0);
//! let t = 3.0_f64;
//! assert!((x.displacement(t) - t * (2.0 * t).sin() / 4.0).abs() < 1e-14);
//! assert!(x.steady_state().is_none()); // no periodic solution at undamped resonance
//! // A unit step on k = 4: settles towards F0/c = 0.25.
//! let step = StepResponse::new(SecondOrder::from_natural(2.0, 0.5).unwrap(), 1.0, 0.0, 0.0);
//! assert_eq!(step.equilibrium(), Some(0.25));
//! ```

use crate::complex::Complex;
use crate::error::{finite, non_negative, ModelError};
use crate::free::FreeResponse;
use crate::model::SecondOrder;
use std::f64::consts::TAU;

/// Below this `|z|` the real `φ₂` uses its Taylor series (9 terms: truncation < 1e-17).
const PHI2_SERIES_LIMIT: f64 = 0.1;

/// Below this `|δ·t|` the beat factor `sin(δt)/δ` is replaced by `t` (error < 2e-17).
const SINC_LIMIT: f64 = 1e-8;

/// `φ₁(z) = (eᶻ − 1)/z`, `φ₁(0) = 1`, relative accuracy ~1 ulp for every real `z`.
fn phi1(z: f64) -> f64 {
    if z == 0.0 {
        1.0
    } else {
        z.exp_m1() / z
    }
}

/// `φ₂(z) = (eᶻ − 1 − z)/z²`, `φ₂(0) = 1/2`.
fn phi2(z: f64) -> f64 {
    if z.abs() < PHI2_SERIES_LIMIT {
        // Σ z^k/(k+2)!, k = 0..8, Horner form.
        let mut acc = 0.0;
        let mut fact = 3_628_800.0; // 10!
        for k in (0..9).rev() {
            acc = acc * z + 1.0 / fact;
            fact /= (k + 2) as f64;
        }
        acc
    } else {
        ((z.exp_m1() - z) / z) / z
    }
}

/// `e^z` for complex `z`.
fn cexp(z: Complex) -> Complex {
    let m = z.re.exp();
    let (s, c) = z.im.sin_cos();
    Complex::new(m * c, m * s)
}

/// Complex `φ₁(z) = (eᶻ − 1)/z` with `eᶻ − 1 = (expm1(x)·cos y − 2 sin²(y/2)) + i·eˣ sin y`,
/// which has no cancellation, so the quotient is accurate even for tiny `|z|`.
fn cphi1(z: Complex) -> Complex {
    if z.re == 0.0 && z.im == 0.0 {
        return Complex::real(1.0);
    }
    let (s, c) = z.im.sin_cos();
    let h = (0.5 * z.im).sin();
    let em1 = z.re.exp_m1();
    Complex::new(em1 * c - 2.0 * h * h, (em1 + 1.0) * s) / z
}

/// `J(q, t) = ∫₀ᵗ e^{q(t−τ)}·e^{iωτ} dτ`: `e^{qt}·t·φ₁((iω − q)t)` while that argument is
/// small (no cancellation near resonance), `(e^{iωt} − e^{qt})/(iω − q)` otherwise (no
/// `0·∞` for long times).
fn duhamel(q: Complex, omega: f64, t: f64) -> Complex {
    let z = Complex::new(-q.re, omega - q.im);
    let w = z * t;
    if w.abs() <= 1.0 {
        cexp(q * t) * cphi1(w) * t
    } else {
        (cexp(Complex::new(0.0, omega * t)) - cexp(q * t)) / z
    }
}

/// Sample `f` at every `t[i]` into `out[i]` (pairs beyond the shorter slice are skipped).
fn fill(t: &[f64], out: &mut [f64], f: impl Fn(f64) -> f64) {
    for (o, &ti) in out.iter_mut().zip(t) {
        *o = f(ti);
    }
}

/// Particular part of a step response.
#[derive(Debug, Clone, Copy, PartialEq)]
enum StepParticular {
    /// `c ≠ 0`: the constant `F0/c` (stable or not) minus the free response from
    /// `(F0/c, 0)`, i.e. the response from rest, so `x(0) = x0` holds exactly.
    Equilibrium { xe: f64, rest: FreeResponse },
    /// `c = 0`: the drift `accel·t²·φ₂(−2αt)` with `accel = F0/a` \[unit/s²\].
    Drift { alpha: f64, accel: f64 },
}

/// Response to a step force `f(t) = F0` for `t ≥ 0` from `x(0) = x0`, `x'(0) = v0`.
///
/// Formulas hold for `t ≥ 0`; for `t < 0` they extrapolate the same expression.
/// Non-finite inputs give non-finite samples (the app validates them first).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StepResponse {
    free: FreeResponse,
    particular: StepParticular,
}

impl StepResponse {
    /// Step of height `force` (`F0`, in the unit of `a·x''`) applied to `sys` from `(x0, v0)`.
    pub fn new(sys: SecondOrder, force: f64, x0: f64, v0: f64) -> Self {
        let particular = if sys.stiffness() == 0.0 {
            StepParticular::Drift {
                alpha: sys.alpha(),
                accel: force / sys.inertia(),
            }
        } else {
            let xe = force / sys.stiffness();
            StepParticular::Equilibrium {
                xe,
                rest: FreeResponse::new(sys, xe, 0.0),
            }
        };
        Self {
            free: FreeResponse::new(sys, x0, v0),
            particular,
        }
    }

    /// Static equilibrium `F0/c` (reached only when the system is stable); `None` when
    /// `c = 0`, where a constant force makes the body drift (ramp or parabola).
    pub fn equilibrium(&self) -> Option<f64> {
        match self.particular {
            StepParticular::Equilibrium { xe, .. } => Some(xe),
            StepParticular::Drift { .. } => None,
        }
    }

    /// Displacement `x(t)`.
    pub fn displacement(&self, t: f64) -> f64 {
        match self.particular {
            StepParticular::Equilibrium { xe, rest } => {
                self.free.displacement(t) + (xe - rest.displacement(t))
            }
            StepParticular::Drift { alpha, accel } => {
                self.free.displacement(t) + accel * t * t * phi2(-2.0 * alpha * t)
            }
        }
    }

    /// Velocity `x'(t)`; for `c = 0` the drift contributes `(F0/a)·(1 − e^{−2αt})/(2α)`.
    pub fn velocity(&self, t: f64) -> f64 {
        match self.particular {
            StepParticular::Equilibrium { rest, .. } => self.free.velocity(t) - rest.velocity(t),
            StepParticular::Drift { alpha, accel } => {
                self.free.velocity(t) + accel * t * phi1(-2.0 * alpha * t)
            }
        }
    }

    /// Acceleration `x''(t)`, differentiated analytically (not taken from the ODE); for
    /// `c = 0` the drift contributes `(F0/a)·e^{−2αt}`.
    pub fn acceleration(&self, t: f64) -> f64 {
        match self.particular {
            StepParticular::Equilibrium { rest, .. } => {
                self.free.acceleration(t) - rest.acceleration(t)
            }
            StepParticular::Drift { alpha, accel } => {
                self.free.acceleration(t) + accel * (-2.0 * alpha * t).exp()
            }
        }
    }

    /// State `[x(t), x'(t)]`.
    pub fn state(&self, t: f64) -> [f64; 2] {
        [self.displacement(t), self.velocity(t)]
    }

    /// Fills `out[i] = x(t[i])` (pairs beyond the shorter slice are left alone). No allocation.
    pub fn sample_into(&self, t: &[f64], out: &mut [f64]) {
        fill(t, out, |ti| self.displacement(ti));
    }

    /// Fills `out[i] = x'(t[i])` (pairs beyond the shorter slice are left alone). No allocation.
    pub fn velocity_into(&self, t: &[f64], out: &mut [f64]) {
        fill(t, out, |ti| self.velocity(ti));
    }
}

/// Response to an impulse `I` (a force `I·δ(t)`, in the unit of `a·x'` times s, e.g. N·s)
/// at `t = 0⁺`: the velocity jumps by `I/a`, then the system moves freely.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ImpulseResponse {
    free: FreeResponse,
    jump: f64,
}

impl ImpulseResponse {
    /// Impulse `impulse` applied to `sys` in state `(x0, v0)` just before `t = 0`.
    pub fn new(sys: SecondOrder, impulse: f64, x0: f64, v0: f64) -> Self {
        let jump = impulse / sys.inertia();
        Self {
            free: FreeResponse::new(sys, x0, v0 + jump),
            jump,
        }
    }

    /// Velocity jump `I/a` caused by the impulse.
    pub fn velocity_jump(&self) -> f64 {
        self.jump
    }

    /// Displacement `x(t)` for `t ≥ 0`.
    pub fn displacement(&self, t: f64) -> f64 {
        self.free.displacement(t)
    }

    /// Velocity `x'(t)` for `t > 0` (`v0 + I/a` at `t = 0⁺`).
    pub fn velocity(&self, t: f64) -> f64 {
        self.free.velocity(t)
    }

    /// Acceleration `x''(t)` for `t > 0`.
    pub fn acceleration(&self, t: f64) -> f64 {
        self.free.acceleration(t)
    }

    /// State `[x(t), x'(t)]`.
    pub fn state(&self, t: f64) -> [f64; 2] {
        self.free.state(t)
    }

    /// Fills `out[i] = x(t[i])` (pairs beyond the shorter slice are left alone). No allocation.
    pub fn sample_into(&self, t: &[f64], out: &mut [f64]) {
        self.free.sample_into(t, out);
    }

    /// Fills `out[i] = x'(t[i])` (pairs beyond the shorter slice are left alone). No allocation.
    pub fn velocity_into(&self, t: &[f64], out: &mut [f64]) {
        fill(t, out, |ti| self.free.velocity(ti));
    }
}

/// A harmonic force `f(t) = F0·cos(ωt + φ)`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HarmonicForce {
    amplitude: f64,
    omega: f64,
    phase: f64,
}

impl HarmonicForce {
    /// `F0·cos(ωt)`: amplitude `F0` (any finite real, in the unit of `a·x''`) and angular
    /// frequency `ω ≥ 0` \[rad/s\].
    pub fn new(amplitude: f64, omega: f64) -> Result<Self, ModelError> {
        Self::with_phase(amplitude, omega, 0.0)
    }

    /// `F0·cos(ωt + φ)` with a finite phase `φ` \[rad\].
    pub fn with_phase(amplitude: f64, omega: f64, phase: f64) -> Result<Self, ModelError> {
        Ok(Self {
            amplitude: finite("force amplitude F0", "N", amplitude)?,
            omega: non_negative("forcing frequency ω", "rad/s", omega)?,
            phase: finite("force phase φ", "rad", phase)?,
        })
    }

    /// Amplitude `F0`.
    pub fn amplitude(&self) -> f64 {
        self.amplitude
    }

    /// Angular frequency `ω` \[rad/s\].
    pub fn omega(&self) -> f64 {
        self.omega
    }

    /// Phase `φ` \[rad\].
    pub fn phase(&self) -> f64 {
        self.phase
    }

    /// Complex amplitude `F = F0·e^{iφ}`, so that `f(t) = Re[F·e^{iωt}]`.
    pub fn phasor(&self) -> Complex {
        let (s, c) = self.phase.sin_cos();
        Complex::new(self.amplitude * c, self.amplitude * s)
    }

    /// The force `F0·cos(ωt + φ)` at time `t` \[s\].
    pub fn at(&self, t: f64) -> f64 {
        self.amplitude * (self.omega * t + self.phase).cos()
    }
}

/// The periodic particular solution `x_p(t) = amplitude·cos(ωt + φ + phase)` for the force
/// `F0·cos(ωt + φ)`. It is the steady state only when the system is stable.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SteadyState {
    /// `|F0| / |c − aω² + i·bω|`, in the unit of `x`.
    pub amplitude: f64,
    /// Phase of the displacement relative to the force \[rad\], in (−π, π]: for `F0 > 0`,
    /// `−atan2(bω, c − aω²)` (a lag, in \[−π, 0\] when `b ≥ 0`).
    pub phase: f64,
}

/// Which closed form a harmonic response uses (see the module doc).
#[derive(Debug, Clone, Copy, PartialEq)]
enum Harmonic {
    /// `b = 0`, `c > 0`: beat (product) form; exact at resonance.
    Undamped { wn: f64 },
    /// `b ≠ 0`, `c > 0`, `ζ² < 1/2`: Duhamel integral with poles `p`, `p̄`, `ω_d = Im p`.
    LightlyDamped { p: Complex },
    /// Periodic particular `Re[P·e^{iωt}]`, `P = F/(c − aω² + ibω)`, plus free response.
    Particular { p: Complex },
    /// `ω = 0` and `c = 0`: a constant force, handled as a step.
    Constant(StepResponse),
}

/// Whether a harmonic response shows beats (see [`HarmonicResponse::beats`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Beats {
    /// Beats are visible, with this period `2π/|ω − ω_d|` \[s\].
    Visible {
        /// Beat period \[s\].
        period: f64,
    },
    /// The system has no free oscillation (`ζ ≥ 1`, or no stiffness): nothing to beat with.
    NoFreeOscillation,
    /// The force is constant (`ω = 0`).
    NoDrive,
    /// The drive is at `ω_d` exactly: one frequency, no beat.
    SameFrequency,
    /// The modulation is not slow against the oscillations (period at most four periods
    /// of the slower one): the sum reads as an irregular oscillation, not as beats.
    TooFast {
        /// What the beat period would be \[s\].
        period: f64,
    },
    /// The transient decays before half a beat period has passed (`τ ≤ T_b/2`).
    DiesOut {
        /// What the beat period would be \[s\].
        period: f64,
        /// Time constant of the transient `1/α` \[s\].
        time_constant: f64,
    },
}

impl Beats {
    /// The beat period \[s\] when beats are visible.
    pub fn period(self) -> Option<f64> {
        match self {
            Beats::Visible { period } => Some(period),
            _ => None,
        }
    }
}

/// Full response (transient + forced) to `F0·cos(ωt + φ)` applied from `t = 0` in state
/// `(x0, v0)`. Continuous in `ω` and in `b`, including `ω → ω_n` with `b = 0`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HarmonicResponse {
    sys: SecondOrder,
    force: HarmonicForce,
    x0: f64,
    v0: f64,
    free: FreeResponse,
    method: Harmonic,
}

impl HarmonicResponse {
    /// Response of `sys` to `force` from `x(0) = x0`, `x'(0) = v0`.
    pub fn new(sys: SecondOrder, force: HarmonicForce, x0: f64, v0: f64) -> Self {
        let (a, b, c) = (sys.inertia(), sys.damping(), sys.stiffness());
        let w = force.omega;
        let alpha = sys.alpha();
        let wn2 = sys.omega_n_squared();
        let method = if c > 0.0 && b == 0.0 {
            Harmonic::Undamped { wn: wn2.sqrt() }
        } else if c > 0.0 && 2.0 * alpha * alpha < wn2 {
            Harmonic::LightlyDamped {
                p: Complex::new(-alpha, (wn2 - alpha * alpha).sqrt()),
            }
        } else if c == 0.0 && w == 0.0 {
            let f = force.phasor().re;
            Harmonic::Constant(StepResponse::new(sys, f, x0, v0))
        } else {
            let d = Complex::new(c - a * w * w, b * w);
            Harmonic::Particular {
                p: force.phasor() / d,
            }
        };
        let free = match method {
            Harmonic::Particular { p } => {
                let xp0 = p.re;
                let vp0 = -w * p.im;
                FreeResponse::new(sys, x0 - xp0, v0 - vp0)
            }
            _ => FreeResponse::new(sys, x0, v0),
        };
        Self {
            sys,
            force,
            x0,
            v0,
            free,
            method,
        }
    }

    /// The force being applied.
    pub fn force(&self) -> HarmonicForce {
        self.force
    }

    /// `(x, x')` of the forced part: from rest for the undamped and lightly damped forms,
    /// the periodic particular solution otherwise. `None` for the constant-force case.
    fn forced_part(&self, t: f64) -> Option<(f64, f64)> {
        let f = self.force.phasor();
        let w = self.force.omega;
        let a = self.sys.inertia();
        match self.method {
            Harmonic::Undamped { wn } => {
                // Responses from rest to cos ωt (y_r) and sin ωt (y_i), in product form.
                let k = 1.0 / (a * (w + wn));
                let delta = 0.5 * (w - wn);
                let sigma = 0.5 * (w + wn);
                let (sd, cd) = (delta * t).sin_cos();
                let g = if (delta * t).abs() < SINC_LIMIT {
                    t
                } else {
                    sd / delta
                };
                let (ss, cs) = (sigma * t).sin_cos();
                let yr = k * g * ss;
                let yi = k * ((wn * t).sin() / wn - g * cs);
                let dyr = k * (cd * ss + g * sigma * cs);
                let dyi = k * ss * (sd + g * sigma);
                Some((f.re * yr - f.im * yi, f.re * dyr - f.im * dyi))
            }
            Harmonic::LightlyDamped { p } => {
                // h(s) = (e^{ps} − e^{p̄s})/(2iω_d·a); Y = ∫h(t−τ)e^{iωτ}dτ; x = Re[F·Y].
                let jp = duhamel(p, w, t);
                let jq = duhamel(p.conj(), w, t);
                let den = Complex::new(0.0, 2.0 * p.im * a);
                let y = (jp - jq) / den;
                let dy = (p * jp - p.conj() * jq) / den;
                Some(((f * y).re, (f * dy).re))
            }
            Harmonic::Particular { p } => {
                let e = cexp(Complex::new(0.0, w * t));
                let z = p * e;
                Some((z.re, -w * z.im))
            }
            Harmonic::Constant(_) => None,
        }
    }

    /// Displacement `x(t)`.
    pub fn displacement(&self, t: f64) -> f64 {
        self.state(t)[0]
    }

    /// Velocity `x'(t)`.
    pub fn velocity(&self, t: f64) -> f64 {
        self.state(t)[1]
    }

    /// State `[x(t), x'(t)]`.
    pub fn state(&self, t: f64) -> [f64; 2] {
        if let Harmonic::Constant(step) = self.method {
            return step.state(t);
        }
        let [x, v] = self.free.state(t);
        match self.forced_part(t) {
            Some((xf, vf)) => [x + xf, v + vf],
            None => [x, v],
        }
    }

    /// Acceleration `x''(t) = (f(t) − b·x' − c·x)/a`, taken from the ODE.
    pub fn acceleration(&self, t: f64) -> f64 {
        let [x, v] = self.state(t);
        (self.force.at(t) - self.sys.damping() * v - self.sys.stiffness() * x) / self.sys.inertia()
    }

    /// Fills `out[i] = x(t[i])` (pairs beyond the shorter slice are left alone). No allocation.
    pub fn sample_into(&self, t: &[f64], out: &mut [f64]) {
        fill(t, out, |ti| self.displacement(ti));
    }

    /// Fills `out[i] = x'(t[i])` (pairs beyond the shorter slice are left alone). No allocation.
    pub fn velocity_into(&self, t: &[f64], out: &mut [f64]) {
        fill(t, out, |ti| self.velocity(ti));
    }

    /// Complex steady-state gain `1/(c − aω² + i·bω)`; `None` when it does not exist
    /// (undamped exact resonance, or `ω = 0` with `c = 0`).
    fn receptance(&self) -> Option<Complex> {
        let w = self.force.omega;
        let d = Complex::new(
            self.sys.stiffness() - self.sys.inertia() * w * w,
            self.sys.damping() * w,
        );
        (d.re != 0.0 || d.im != 0.0).then(|| d.recip())
    }

    /// The periodic particular solution (amplitude and phase, see [`SteadyState`]); `None`
    /// at exact undamped resonance (`b = 0`, `ω = ω_n`: the amplitude grows like `t`) and
    /// for a constant force on a system without stiffness. The transient dies out and this
    /// is the steady state only when [`SecondOrder::regime`] is stable.
    pub fn steady_state(&self) -> Option<SteadyState> {
        let r = self.receptance()?;
        let f0 = self.force.amplitude;
        let signed = if f0 >= 0.0 { r } else { -r };
        Some(SteadyState {
            amplitude: f0.abs() * r.abs(),
            phase: signed.arg(),
        })
    }

    /// Beat period `2π/|ω − ω_d|` \[s\] of the slow amplitude modulation seen while the
    /// transient at `ω_d` and the forced motion at `ω` coexist (`ω_d = ω_n` when `b = 0`).
    /// `None` for systems that do not oscillate, for `ω = 0` and for `ω = ω_d` exactly.
    pub fn beat_period(&self) -> Option<f64> {
        let wd = self.sys.damped_frequency()?;
        let w = self.force.omega;
        (w > 0.0 && w != wd).then(|| TAU / (w - wd).abs())
    }

    /// Whether beats can be seen in this response, and their period when they can.
    ///
    /// The transient at `ω_d` and the forced motion at `ω` add to a slow modulation of
    /// period `T_b = 2π/|ω − ω_d|` ([`Self::beat_period`]), but it shows as beats only when
    /// (a) it is slow against both oscillations, `T_b > 4·2π/min(ω, ω_n)`, and (b) the
    /// transient survives half a beat, i.e. its time constant `τ = 1/α = 1/(ζω_n)` exceeds
    /// `T_b/2` (so its amplitude falls by less than a factor e before the first beat
    /// minimum). At resonance (`ω = ω_n`, `ζ > 0`) `T_b = 2π/(ω_n(1 − √(1 − ζ²))) ≈
    /// 4π/(ω_nζ²)` while `τ = 1/(ζω_n)`, so (b) fails for every `ζ < 1`: the amplitude builds
    /// up without beating. Undamped and negatively damped systems (`α ≤ 0`) meet (b).
    pub fn beats(&self) -> Beats {
        let Some(wd) = self.sys.damped_frequency() else {
            return Beats::NoFreeOscillation;
        };
        let w = self.force.omega;
        if w.is_nan() || w <= 0.0 {
            return Beats::NoDrive;
        }
        if w == wd {
            return Beats::SameFrequency;
        }
        let period = TAU / (w - wd).abs();
        let wn = self.sys.omega_n_squared().sqrt();
        if period.is_nan() || period <= 4.0 * TAU / wn.min(w) {
            return Beats::TooFast { period };
        }
        let alpha = self.sys.alpha();
        if alpha > 0.0 && 1.0 / alpha <= 0.5 * period {
            return Beats::DiesOut {
                period,
                time_constant: 1.0 / alpha,
            };
        }
        Beats::Visible { period }
    }

    /// Slowly varying envelope `E(t) ≥ |x(t)|` for plots, `None` for systems that do not
    /// oscillate. Writing `x = Re[Z(t)·e^{iΩt}]` with a carrier `Ω`, `E = |Z(t)|`:
    /// for `b = 0` (carrier `ω_n`) `Z = x0 − i·v0/ω_n + K·(i·F_i/ω_n − i·F·e^{iδt}·sin(δt)/δ)`,
    /// `K = 1/(a(ω + ω_n))`, `δ = (ω − ω_n)/2`, exact through resonance; otherwise (carrier
    /// `ω`) `Z = P + B·e^{(p − iω)t}` with `P` the particular phasor and `B` the free-response
    /// phasor at the pole `p = −α + iω_d` (absolute rounding ~1e-16·|P|).
    pub fn envelope(&self, t: f64) -> Option<f64> {
        let f = self.force.phasor();
        let w = self.force.omega;
        if let Harmonic::Undamped { wn } = self.method {
            let k = 1.0 / (self.sys.inertia() * (w + wn));
            let delta = 0.5 * (w - wn);
            let g = if (delta * t).abs() < SINC_LIMIT {
                t
            } else {
                (delta * t).sin() / delta
            };
            let rot = cexp(Complex::new(0.0, delta * t));
            let i = Complex::new(0.0, 1.0);
            let z = Complex::new(self.x0, -self.v0 / wn) + (i * (f.im / wn) - i * f * rot * g) * k;
            return Some(z.abs());
        }
        let wd = self.sys.damped_frequency()?;
        let p = self.receptance()? * f;
        let alpha = self.sys.alpha();
        let y0 = self.x0 - p.re;
        let w0 = self.v0 + w * p.im;
        let b = Complex::new(y0, -(w0 + alpha * y0) / wd);
        let z = p + b * cexp(Complex::new(-alpha * t, (wd - w) * t));
        Some(z.abs())
    }

    /// Fills `out[i] = E(t[i])` (see [`HarmonicResponse::envelope`]) and returns `true`;
    /// returns `false` and leaves `out` untouched when there is no envelope. No allocation.
    pub fn envelope_into(&self, t: &[f64], out: &mut [f64]) -> bool {
        if self.envelope(0.0).is_none() {
            return false;
        }
        fill(t, out, |ti| self.envelope(ti).unwrap_or(f64::NAN));
        true
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn phi_functions_match_their_definitions() {
        for &z in &[-3.0, -0.5, -0.09, -1e-3, 1e-3, 0.09, 0.5, 2.0] {
            let p2 = (f64::exp(z) - 1.0 - z) / (z * z);
            // Direct formula loses ~1e-16/z² relative; at |z| ≥ 1e-3 that is ≤ 1e-10.
            assert!((phi2(z) - p2).abs() < 2e-10 * p2.abs(), "z={z}");
            assert!((phi1(z) - (f64::exp(z) - 1.0) / z).abs() < 1e-12, "z={z}");
        }
        assert_eq!(phi2(0.0), 0.5);
        // Just inside the series range, the series agrees with the direct formula (whose
        // own rounding there is ~2e-16/z ≈ 2e-15).
        let z: f64 = 0.1 - 1e-12;
        assert!((phi2(z) - (z.exp_m1() - z) / z / z).abs() < 3e-15);
    }

    #[test]
    fn complex_phi1_is_accurate_for_tiny_arguments() {
        // (e^z − 1)/z = 1 + z/2 + z²/6 + …
        let z = Complex::new(1e-9, -2e-9);
        let v = cphi1(z);
        let series = Complex::real(1.0) + z * 0.5 + z * z * (1.0 / 6.0);
        assert!((v - series).abs() < 4e-16);
        let big = Complex::new(0.3, 0.8);
        let direct = (cexp(big) - Complex::real(1.0)) / big;
        assert!((cphi1(big) - direct).abs() < 1e-15);
    }

    #[test]
    fn harmonic_force_validates() {
        assert!(matches!(
            HarmonicForce::new(1.0, -2.0),
            Err(ModelError::Negative { .. })
        ));
        assert!(matches!(
            HarmonicForce::new(f64::NAN, 2.0),
            Err(ModelError::NotFinite { .. })
        ));
        assert!(HarmonicForce::with_phase(1.0, 2.0, f64::INFINITY).is_err());
    }

    #[test]
    fn constant_force_without_stiffness_is_a_parabola() {
        let sys = SecondOrder::new(2.0, 0.0, 0.0).unwrap();
        let h = HarmonicResponse::new(sys, HarmonicForce::new(4.0, 0.0).unwrap(), 0.0, 0.0);
        // x = F0 t²/(2a) = t².
        assert!((h.displacement(3.0) - 9.0).abs() < 1e-12);
        assert!(h.steady_state().is_none());
    }
}
