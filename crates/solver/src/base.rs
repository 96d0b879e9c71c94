//! Base excitation: the road moves the wheel, the spring and damper carry it to the body.
//!
//! `m·x'' + c·(x' − u') + k·(x − u) = 0` for road input `u(t)`.

/// Displacement transmissibility `|X/U| = √((1 + (2ζr)²) / ((1 − r²)² + (2ζr)²))` \[-\] at
/// frequency ratio `r = ω/ω_n` and damping ratio `ζ`. Equals 1 at `r = 0` and at
/// `r = √2` for every ζ.
pub fn transmissibility(r: f64, zeta: f64) -> f64 {
    let two_zr = 2.0 * zeta * r;
    let num = 1.0 + two_zr * two_zr;
    let one_minus = 1.0 - r * r;
    (num / (one_minus * one_minus + two_zr * two_zr)).sqrt()
}
