//! Damping regimes of `a·y'' + b·y' + c·y = 0`.
//!
//! ```
//! use zeta_solver::{Regime, SecondOrder};
//! assert_eq!(SecondOrder::from_natural(2.0, 1.0).unwrap().regime(), Regime::CriticallyDamped);
//! assert_eq!(SecondOrder::from_natural(2.0, -0.1).unwrap().regime(), Regime::NegativelyDamped);
//! ```

use std::fmt;

/// `|ζ − 1|` at or below which a system counts as critically damped, and `|ζ|` at or
/// below which it counts as undamped. Values this close cannot be told apart in a plot,
/// and the closed forms are continuous across both boundaries.
pub const ZETA_TOLERANCE: f64 = 1e-9;

/// How the free response behaves.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Regime {
    /// `ζ = 0`: oscillates forever at `ω_n`, energy conserved.
    Undamped,
    /// `0 < ζ < 1`: decaying oscillation at `ω_d = ω_n√(1 − ζ²)`.
    Underdamped,
    /// `ζ = 1`: fastest return without overshooting more than once; double real pole.
    CriticallyDamped,
    /// `ζ > 1`: two real poles, slow non-oscillating return.
    Overdamped,
    /// `ζ < 0`: energy grows; the response grows without bound (flutter).
    NegativelyDamped,
    /// `c = 0`: no restoring force; the response drifts to a constant (or grows linearly if
    /// also undamped).
    Neutral,
    /// `c < 0`: a positive real pole; the response diverges exponentially.
    Divergent,
}

impl Regime {
    /// Classifies from the stiffness `c` and the damping ratio (defined when `c > 0`).
    pub(crate) fn classify(c: f64, zeta: Option<f64>) -> Regime {
        if c < 0.0 {
            return Regime::Divergent;
        }
        match zeta {
            None => Regime::Neutral,
            Some(z) if z.abs() <= ZETA_TOLERANCE => Regime::Undamped,
            Some(z) if z < 0.0 => Regime::NegativelyDamped,
            Some(z) if (z - 1.0).abs() <= ZETA_TOLERANCE => Regime::CriticallyDamped,
            Some(z) if z < 1.0 => Regime::Underdamped,
            Some(_) => Regime::Overdamped,
        }
    }

    /// A stable machine name, used in URLs and `data-value` attributes.
    pub fn key(self) -> &'static str {
        match self {
            Regime::Undamped => "undamped",
            Regime::Underdamped => "underdamped",
            Regime::CriticallyDamped => "critically damped",
            Regime::Overdamped => "overdamped",
            Regime::NegativelyDamped => "negatively damped",
            Regime::Neutral => "neutral",
            Regime::Divergent => "divergent",
        }
    }

    /// Whether the free response returns to rest.
    pub fn is_stable(self) -> bool {
        matches!(
            self,
            Regime::Underdamped | Regime::CriticallyDamped | Regime::Overdamped
        )
    }

    /// Whether the free response oscillates.
    pub fn oscillates(self) -> bool {
        matches!(
            self,
            Regime::Undamped | Regime::Underdamped | Regime::NegativelyDamped
        )
    }

    /// All regimes, in teaching order.
    pub const ALL: [Regime; 7] = [
        Regime::Undamped,
        Regime::Underdamped,
        Regime::CriticallyDamped,
        Regime::Overdamped,
        Regime::NegativelyDamped,
        Regime::Neutral,
        Regime::Divergent,
    ];
}

impl fmt::Display for Regime {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.key())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn boundaries_use_the_stated_tolerance() {
        let c = |z: f64| Regime::classify(1.0, Some(z));
        assert_eq!(c(1.0 + 0.5e-9), Regime::CriticallyDamped);
        assert_eq!(c(1.0 - 0.5e-9), Regime::CriticallyDamped);
        assert_eq!(c(1.0 - 2e-9), Regime::Underdamped);
        assert_eq!(c(1.0 + 2e-9), Regime::Overdamped);
        assert_eq!(c(0.0), Regime::Undamped);
        assert_eq!(c(-1e-3), Regime::NegativelyDamped);
        assert_eq!(c(-3.0), Regime::NegativelyDamped);
        assert_eq!(Regime::classify(0.0, None), Regime::Neutral);
        assert_eq!(Regime::classify(-1.0, None), Regime::Divergent);
    }
}
