//! Base excitation: the road moves the wheel, the spring and damper carry it to the body.
//!
//! `m·x'' + c·(x' − u') + k·(x − u) = 0` for road input `u(t)` \[m\] and body displacement
//! `x(t)` \[m\] (with a [`SecondOrder`] read as `a = m`, `b = c`, `c = k`).
//!
//! For harmonic road input at frequency ratio `r = ω/ω_n` the body moves with the
//! displacement transmissibility `T(r) = |X/U|`; every curve passes through `T = 1` at
//! `r = 0` and at the crossover `r = √2`, beyond which damping *increases* what reaches the
//! body. For a single "1 − cos" bump the response is in closed form (forced during the bump,
//! free after it).
//!
//! ```
//! use zeta_solver::base::{self, Bump, BumpResponse};
//! use zeta_solver::SecondOrder;
//! assert!((base::transmissibility(base::CROSSOVER_RATIO, 0.3) - 1.0).abs() < 1e-15);
//! // Quarter car over a 5 cm, 2 m long bump at 10 m/s.
//! let car = SecondOrder::mechanical(300.0, 1610.0, 24_000.0).unwrap();
//! let bump = Bump::new(0.05, 2.0, 10.0).unwrap();
//! let ride = BumpResponse::new(car, bump).unwrap();
//! assert_eq!(ride.displacement(-1.0), 0.0); // at rest before the bump
//! assert!(ride.displacement(0.2).abs() < 0.1);
//! ```

use crate::error::{finite, positive, ModelError};
use crate::forced::{HarmonicForce, HarmonicResponse, StepResponse};
use crate::free::FreeResponse;
use crate::frf::{damped, Peak};
use crate::model::SecondOrder;
use std::f64::consts::{PI, SQRT_2, TAU};

/// The frequency ratio `r = √2` \[-\] where `T = 1` for every ζ: below it the suspension
/// amplifies road motion, above it isolates the body from it.
pub const CROSSOVER_RATIO: f64 = SQRT_2;

/// `1 − r²` as `(1 − r)(1 + r)`: accurate near `r = 1`.
fn one_minus_r2(r: f64) -> f64 {
    (1.0 - r) * (1.0 + r)
}

/// Displacement transmissibility `|X/U| = √((1 + (2ζr)²) / ((1 − r²)² + (2ζr)²))` \[-\] at
/// frequency ratio `r = ω/ω_n` and damping ratio `ζ`. Equals 1 at `r = 0` and at
/// `r = √2` for every ζ. It is also the ratio of body to road acceleration amplitudes.
pub fn transmissibility(r: f64, zeta: f64) -> f64 {
    let two_zr = 2.0 * zeta * r;
    let num = 1.0f64.hypot(two_zr);
    num / one_minus_r2(r).hypot(two_zr)
}

/// Phase of `X/U = (1 + 2iζr)/(1 − r² + 2iζr)` \[rad\]:
/// `atan2(−2ζr³, 1 − r² + 4ζ²r²)`, in (−π, 0\] for `ζ ≥ 0`, `r ≥ 0`, continuous in `r` for
/// `ζ > 0`; −π/2 is crossed where `1 − r² + 4ζ²r² = 0`.
pub fn transmissibility_phase(r: f64, zeta: f64) -> f64 {
    let two_zr = 2.0 * zeta * r;
    (-two_zr * r * r).atan2(one_minus_r2(r) + two_zr * two_zr)
}

/// Acceleration transmissibility `|x''|/(ω_n²·|u|) = r²·T(r, ζ)` \[-\]: body acceleration per
/// unit road displacement, normalised by `ω_n²`. At high `r` it grows like `2ζr`, which is
/// why a stiffer damper hurts comfort on short, sharp road texture.
pub fn acceleration_transmissibility(r: f64, zeta: f64) -> f64 {
    r * r * transmissibility(r, zeta)
}

/// Fills `out[i] = T(r[i], ζ)` (pairs beyond the shorter slice are left alone). No allocation.
pub fn transmissibility_into(r: &[f64], zeta: f64, out: &mut [f64]) {
    for (o, &ri) in out.iter_mut().zip(r) {
        *o = transmissibility(ri, zeta);
    }
}

/// The peak of `T(r, ζ)` over `r ≥ 0`: ratio `r_p = √((√(1 + 8ζ²) − 1)/(4ζ²))` \[-\] (< 1)
/// (computed as `r_p² = 2/(√(1 + 8ζ²) + 1)`, the same value without cancellation at small
/// ζ) and gain `T(r_p, ζ)` \[-\]. `None` for `ζ ≤ 0` (infinite peak at `ζ = 0`, no steady
/// state for `ζ < 0`) or NaN.
pub fn peak_transmissibility(zeta: f64) -> Option<Peak> {
    let zeta = damped(zeta)?;
    let s = 2.0 / ((1.0 + 8.0 * zeta * zeta).sqrt() + 1.0);
    let ratio = s.sqrt();
    Some(Peak {
        ratio,
        gain: transmissibility(ratio, zeta),
    })
}

/// A single "1 − cos" bump: `u(t) = h/2·(1 − cos(2πVt/L))` for `0 ≤ t ≤ L/V`, 0 otherwise.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Bump {
    height: f64,
    length: f64,
    speed: f64,
}

impl Bump {
    /// Bump of height `height` \[m\] (negative for a dip), length `length` \[m\] > 0, crossed
    /// at speed `speed` \[m/s\] > 0.
    pub fn new(height: f64, length: f64, speed: f64) -> Result<Self, ModelError> {
        let height = finite("bump height h", "m", height)?;
        let length = positive("bump length L", "m", length)?;
        let speed = positive("vehicle speed V", "m/s", speed)?;
        if !(TAU * speed / length).is_finite() || !(length / speed).is_finite() {
            return Err(ModelError::OutOfRange {
                name: "bump length / speed",
                reason: "crossing time L/V does not fit in double precision",
            });
        }
        Ok(Self {
            height,
            length,
            speed,
        })
    }

    /// Height `h` \[m\].
    pub fn height(&self) -> f64 {
        self.height
    }

    /// Length `L` \[m\].
    pub fn length(&self) -> f64 {
        self.length
    }

    /// Speed `V` \[m/s\].
    pub fn speed(&self) -> f64 {
        self.speed
    }

    /// Crossing time `L/V` \[s\].
    pub fn duration(&self) -> f64 {
        self.length / self.speed
    }

    /// Angular frequency of the profile `Ω = 2πV/L` \[rad/s\].
    pub fn omega(&self) -> f64 {
        TAU * self.speed / self.length
    }

    /// Road height `u(t)` \[m\].
    pub fn profile(&self, t: f64) -> f64 {
        if (0.0..=self.duration()).contains(&t) {
            0.5 * self.height * (1.0 - (self.omega() * t).cos())
        } else {
            0.0
        }
    }

    /// Road vertical velocity `u'(t) = h/2·Ω·sin(Ωt)` \[m/s\] (0 outside the bump).
    pub fn profile_velocity(&self, t: f64) -> f64 {
        if (0.0..=self.duration()).contains(&t) {
            0.5 * self.height * self.omega() * (self.omega() * t).sin()
        } else {
            0.0
        }
    }

    /// Time at which the wheel is on the crest, `L/(2V) = π/Ω` \[s\].
    pub fn crest_time(&self) -> f64 {
        PI / self.omega()
    }

    /// `∫u dt = h·L/(2V)` \[m·s\]: the "area" of the bump, which sets the size of the
    /// response to a short bump.
    pub fn area(&self) -> f64 {
        0.5 * self.height * self.duration()
    }
}

/// Body response to a [`Bump`], from rest at `x = 0`.
///
/// During the bump the road acts through spring and damper as the force
/// `k·u + c·u' = k·h/2 + Re[F·e^{iΩt}]` with `F = −k·h/2 − i·c·h·Ω/2`: a step plus a harmonic
/// force, both exact ([`StepResponse`], [`HarmonicResponse`]). After `t_end = L/V` the body
/// moves freely from the state reached, so `x` and `x'` are continuous there.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BumpResponse {
    sys: SecondOrder,
    bump: Bump,
    step: StepResponse,
    harmonic: HarmonicResponse,
    after: FreeResponse,
    t_end: f64,
}

impl BumpResponse {
    /// Response of `sys` (`a = m` \[kg\], `b = c` \[N·s/m\], `c = k` \[N/m\]) to `bump`.
    /// Errors only when the forcing overflows (e.g. `k·h` beyond 1e308).
    pub fn new(sys: SecondOrder, bump: Bump) -> Result<Self, ModelError> {
        let (damper, spring) = (sys.damping(), sys.stiffness());
        let h = bump.height;
        let w = bump.omega();
        let fr = -0.5 * spring * h;
        let fi = -0.5 * damper * h * w;
        let force = HarmonicForce::with_phase(fr.hypot(fi), w, fi.atan2(fr))?;
        let step = StepResponse::new(sys, finite("spring force k·h/2", "N", -fr)?, 0.0, 0.0);
        let harmonic = HarmonicResponse::new(sys, force, 0.0, 0.0);
        let t_end = bump.duration();
        let [x1, v1] = add(step.state(t_end), harmonic.state(t_end));
        Ok(Self {
            sys,
            bump,
            step,
            harmonic,
            after: FreeResponse::new(sys, x1, v1),
            t_end,
        })
    }

    /// The bump.
    pub fn bump(&self) -> Bump {
        self.bump
    }

    /// State `[x(t), x'(t)]` \[m, m/s\]; `[0, 0]` before the bump.
    pub fn state(&self, t: f64) -> [f64; 2] {
        if t < 0.0 {
            [0.0, 0.0]
        } else if t < self.t_end {
            add(self.step.state(t), self.harmonic.state(t))
        } else {
            self.after.state(t - self.t_end)
        }
    }

    /// Body displacement `x(t)` \[m\].
    pub fn displacement(&self, t: f64) -> f64 {
        self.state(t)[0]
    }

    /// Body velocity `x'(t)` \[m/s\].
    pub fn velocity(&self, t: f64) -> f64 {
        self.state(t)[1]
    }

    /// Body acceleration `x'' = (c·(u' − x') + k·(u − x))/m` \[m/s²\]: the suspension force
    /// over the mass, what a seat accelerometer would read.
    pub fn acceleration(&self, t: f64) -> f64 {
        let [x, v] = self.state(t);
        let u = self.bump.profile(t);
        let du = self.bump.profile_velocity(t);
        (self.sys.damping() * (du - v) + self.sys.stiffness() * (u - x)) / self.sys.inertia()
    }

    /// Fills `out[i] = x(t[i])` (pairs beyond the shorter slice are left alone). No allocation.
    pub fn sample_into(&self, t: &[f64], out: &mut [f64]) {
        for (o, &ti) in out.iter_mut().zip(t) {
            *o = self.displacement(ti);
        }
    }

    /// Fills `out[i] = x'(t[i])`. No allocation.
    pub fn velocity_into(&self, t: &[f64], out: &mut [f64]) {
        for (o, &ti) in out.iter_mut().zip(t) {
            *o = self.velocity(ti);
        }
    }

    /// Fills `out[i] = x''(t[i])` (body acceleration). No allocation.
    pub fn acceleration_into(&self, t: &[f64], out: &mut [f64]) {
        for (o, &ti) in out.iter_mut().zip(t) {
            *o = self.acceleration(ti);
        }
    }

    /// Fills `out[i] = u(t[i])` (the road profile, for drawing under the body). No allocation.
    pub fn profile_into(&self, t: &[f64], out: &mut [f64]) {
        for (o, &ti) in out.iter_mut().zip(t) {
            *o = self.bump.profile(ti);
        }
    }
}

fn add(p: [f64; 2], q: [f64; 2]) -> [f64; 2] {
    [p[0] + q[0], p[1] + q[1]]
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::testing::variants;

    #[test]
    fn crossover_and_static_limit() {
        for &z in &[0.0, 0.1, 0.5, 2.0] {
            assert_eq!(transmissibility(0.0, z), 1.0);
            assert!((transmissibility(CROSSOVER_RATIO, z) - 1.0).abs() < 1e-15);
        }
    }

    #[test]
    fn bump_validation() {
        let bad = [
            Bump::new(0.05, 0.0, 10.0),
            Bump::new(f64::NAN, 1.0, 10.0),
            Bump::new(0.05, 1e-300, 1e300),
        ];
        assert_eq!(variants(bad), ["NotPositive", "NotFinite", "OutOfRange"]);
        let b = Bump::new(-0.05, 2.0, 10.0).unwrap();
        assert!((b.profile(b.crest_time()) + 0.05).abs() < 1e-17);
        assert_eq!(b.profile(0.3), 0.0);
    }
}
