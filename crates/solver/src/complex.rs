//! A minimal complex number, enough for poles and frequency responses.
//!
//! ```
//! use zeta_solver::Complex;
//! let z = Complex::new(3.0, 4.0);
//! assert_eq!(z.abs(), 5.0);
//! ```

use std::ops::{Add, Div, Mul, Neg, Sub};

/// A complex number `re + i·im`.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Complex {
    /// Real part.
    pub re: f64,
    /// Imaginary part.
    pub im: f64,
}

impl Complex {
    /// `re + i·im`.
    pub const fn new(re: f64, im: f64) -> Self {
        Self { re, im }
    }

    /// A real number as a complex one.
    pub const fn real(re: f64) -> Self {
        Self { re, im: 0.0 }
    }

    /// Modulus `|z| = √(re² + im²)`, computed without overflow.
    pub fn abs(self) -> f64 {
        self.re.hypot(self.im)
    }

    /// Argument `atan2(im, re)` in rad, in (−π, π].
    pub fn arg(self) -> f64 {
        self.im.atan2(self.re)
    }

    /// Complex conjugate.
    pub fn conj(self) -> Self {
        Self::new(self.re, -self.im)
    }

    /// `1 / z`, scaled to avoid overflow (Smith's algorithm).
    pub fn recip(self) -> Self {
        Complex::real(1.0) / self
    }
}

impl Add for Complex {
    type Output = Complex;
    fn add(self, o: Complex) -> Complex {
        Complex::new(self.re + o.re, self.im + o.im)
    }
}

impl Sub for Complex {
    type Output = Complex;
    fn sub(self, o: Complex) -> Complex {
        Complex::new(self.re - o.re, self.im - o.im)
    }
}

impl Mul for Complex {
    type Output = Complex;
    fn mul(self, o: Complex) -> Complex {
        Complex::new(
            self.re * o.re - self.im * o.im,
            self.re * o.im + self.im * o.re,
        )
    }
}

impl Mul<f64> for Complex {
    type Output = Complex;
    fn mul(self, k: f64) -> Complex {
        Complex::new(self.re * k, self.im * k)
    }
}

impl Div for Complex {
    type Output = Complex;
    /// Smith's algorithm: divides without forming `|o|²`, which could overflow.
    fn div(self, o: Complex) -> Complex {
        if o.re.abs() >= o.im.abs() {
            let r = o.im / o.re;
            let den = o.re + o.im * r;
            Complex::new((self.re + self.im * r) / den, (self.im - self.re * r) / den)
        } else {
            let r = o.re / o.im;
            let den = o.re * r + o.im;
            Complex::new((self.re * r + self.im) / den, (self.im * r - self.re) / den)
        }
    }
}

impl Neg for Complex {
    type Output = Complex;
    fn neg(self) -> Complex {
        Complex::new(-self.re, -self.im)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn division_inverts_multiplication() {
        let a = Complex::new(1.5, -2.0);
        let b = Complex::new(-0.25, 3.0);
        let q = (a * b) / b;
        assert!((q - a).abs() < 1e-15);
        let tiny = Complex::new(1e-300, 1e-300);
        assert!((tiny / tiny - Complex::real(1.0)).abs() < 1e-15);
    }

    #[test]
    fn modulus_and_argument() {
        let z = Complex::new(0.0, -2.0);
        assert_eq!(z.abs(), 2.0);
        assert!((z.arg() + std::f64::consts::FRAC_PI_2).abs() < 1e-15);
    }
}
