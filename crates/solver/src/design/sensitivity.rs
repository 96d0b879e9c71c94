//! How ζ, ω_n, f0, Q and bandwidth move when the components vary by ±x %: exact ranges and
//! the linearised (logarithmic) sensitivities.
//!
//! Every quantity is a product of powers of the three components,
//!
//! | quantity | mechanical `(m, c, k)` | electrical `(L, R, C)` |
//! |---|---|---|
//! | `ζ = b/(2√(ac))` | `m^−½ c^1 k^−½` | `L^−½ R^1 C^½` |
//! | `ω_n = √(c/a)`, `f0 = ω_n/2π` | `m^−½ c^0 k^½` | `L^−½ R^0 C^−½` |
//! | `Q = √(ac)/b` | `m^½ c^−1 k^½` | `L^½ R^−1 C^−½` |
//! | bandwidth `b/a` | `m^−1 c^1 k^0` | `L^−1 R^1 C^0` |
//!
//! so each is monotone in each component (constant where the exponent is 0), and the
//! extremes over a box of component values are at its corners. [`spread`] evaluates the
//! exact quantity at the two ends (one component varied) or all eight corners (all varied);
//! the exponents are the exact logarithmic sensitivities `d ln q / d ln p` used by the
//! linearised estimate `q·(1 ± Σ|S_p|·x)`.
//!
//! ```
//! use zeta_solver::design::sensitivity::{spread, Components, Quantity, Varied};
//! // ±10 % sprung mass on a ζ = 1 design: ζ ∝ m^−½ spans [1/√1.1, 1/√0.9].
//! let car = Components::mechanical_for_zeta(300.0, 24_000.0, 1.0);
//! let s = spread(&car, Quantity::DampingRatio, Varied::One(0), 0.10).unwrap();
//! assert!((s.min - 1.0 / 1.1f64.sqrt()).abs() < 1e-12);
//! assert!((s.max - 1.0 / 0.9f64.sqrt()).abs() < 1e-12);
//! ```

use crate::model::SecondOrder;

/// The three component values of a design, in SI units.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Components {
    /// Quarter car: mass `m` \[kg\], damper `c` \[N·s/m\], spring `k` \[N/m\].
    Mechanical {
        /// Mass \[kg\].
        m: f64,
        /// Damper rate \[N·s/m\].
        c: f64,
        /// Spring rate \[N/m\].
        k: f64,
    },
    /// Series RLC: inductance `l` \[H\], resistance `r` \[Ω\], capacitance `cap` \[F\].
    Electrical {
        /// Inductance \[H\].
        l: f64,
        /// Resistance \[Ω\].
        r: f64,
        /// Capacitance \[F\].
        cap: f64,
    },
}

impl Components {
    /// Quarter car of mass `m` and spring `k` with the damper for damping ratio `zeta`,
    /// `c = 2ζ√(km)`.
    pub fn mechanical_for_zeta(m: f64, k: f64, zeta: f64) -> Self {
        Components::Mechanical {
            m,
            c: 2.0 * zeta * (k * m).sqrt(),
            k,
        }
    }

    /// The values `[m, c, k]` or `[L, R, C]`.
    pub fn values(&self) -> [f64; 3] {
        match *self {
            Components::Mechanical { m, c, k } => [m, c, k],
            Components::Electrical { l, r, cap } => [l, r, cap],
        }
    }

    /// Names of the components, in the order of [`Self::values`].
    pub fn names(&self) -> [&'static str; 3] {
        match self {
            Components::Mechanical { .. } => ["mass m", "damping c", "stiffness k"],
            Components::Electrical { .. } => ["inductance L", "resistance R", "capacitance C"],
        }
    }

    /// The same kind of design with new values `[m, c, k]` or `[L, R, C]`.
    pub fn with_values(&self, v: [f64; 3]) -> Self {
        let [a, b, c] = v;
        match self {
            Components::Mechanical { .. } => Components::Mechanical { m: a, c: b, k: c },
            Components::Electrical { .. } => Components::Electrical { l: a, r: b, cap: c },
        }
    }

    /// The model; errors as [`SecondOrder::mechanical`] / [`SecondOrder::electrical`].
    pub fn system(&self) -> Result<SecondOrder, crate::ModelError> {
        match *self {
            Components::Mechanical { m, c, k } => SecondOrder::mechanical(m, c, k),
            Components::Electrical { l, r, cap } => SecondOrder::electrical(l, r, cap),
        }
    }
}

/// A derived quantity of the design.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Quantity {
    /// `ζ` \[-\].
    DampingRatio,
    /// `ω_n` \[rad/s\].
    NaturalFrequency,
    /// `f0 = ω_n/2π` \[Hz\].
    NaturalFrequencyHz,
    /// `Q = 1/(2ζ)` \[-\].
    QualityFactor,
    /// Half-power bandwidth `b/a` \[rad/s\].
    Bandwidth,
}

impl Quantity {
    /// All quantities.
    pub const ALL: [Quantity; 5] = [
        Quantity::DampingRatio,
        Quantity::NaturalFrequency,
        Quantity::NaturalFrequencyHz,
        Quantity::QualityFactor,
        Quantity::Bandwidth,
    ];

    /// Its value for `sys`; `None` where undefined (e.g. `Q` without damping).
    pub fn of(self, sys: &SecondOrder) -> Option<f64> {
        match self {
            Quantity::DampingRatio => sys.damping_ratio(),
            Quantity::NaturalFrequency => sys.natural_frequency(),
            Quantity::NaturalFrequencyHz => sys.natural_frequency_hz(),
            Quantity::QualityFactor => sys.quality_factor(),
            Quantity::Bandwidth => sys.velocity_half_power_bandwidth(),
        }
    }

    /// Exact logarithmic sensitivity `d ln q / d ln p` to component `p` (0, 1, 2 in the
    /// order of [`Components::values`]) — the exponents of the module table. `None` for an
    /// index above 2.
    pub fn log_sensitivity(self, design: &Components, p: usize) -> Option<f64> {
        // Exponents of (a, b, c) = (inertia, damping, stiffness coefficient).
        let abc: [f64; 3] = match self {
            Quantity::DampingRatio => [-0.5, 1.0, -0.5],
            Quantity::NaturalFrequency | Quantity::NaturalFrequencyHz => [-0.5, 0.0, 0.5],
            Quantity::QualityFactor => [0.5, -1.0, 0.5],
            Quantity::Bandwidth => [-1.0, 1.0, 0.0],
        };
        let e = abc.get(p).copied()?;
        // The electrical stiffness coefficient is 1/C: the exponent in C changes sign.
        let flip = p == 2 && matches!(design, Components::Electrical { .. });
        Some(if flip { -e } else { e })
    }
}

/// Which components vary.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Varied {
    /// Only component `p` (0, 1, 2 in the order of [`Components::values`]).
    One(usize),
    /// All three together.
    All,
}

/// Exact and linearised range of a quantity.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Spread {
    /// Value at the nominal design.
    pub nominal: f64,
    /// Exact minimum over the tolerance box (at a corner).
    pub min: f64,
    /// Exact maximum over the tolerance box (at a corner).
    pub max: f64,
    /// Linearised minimum `nominal·(1 − Σ|S_p|·x)`.
    pub linear_min: f64,
    /// Linearised maximum `nominal·(1 + Σ|S_p|·x)`.
    pub linear_max: f64,
}

/// Range of `quantity` when the `varied` components each take any value in
/// `[p·(1 − x), p·(1 + x)]`, `x = tolerance` (a fraction, `0 ≤ x < 1`).
///
/// `None` for an invalid tolerance or component index, or when the quantity is undefined
/// at the nominal design or a corner.
pub fn spread(
    design: &Components,
    quantity: Quantity,
    varied: Varied,
    tolerance: f64,
) -> Option<Spread> {
    if !(0.0..1.0).contains(&tolerance) {
        return None;
    }
    let nominal = quantity.of(&design.system().ok()?)?;
    let mask = match varied {
        Varied::One(p) if p < 3 => [p == 0, p == 1, p == 2],
        Varied::One(_) => return None,
        Varied::All => [true; 3],
    };
    let tolerances = mask.map(|on| if on { tolerance } else { 0.0 });
    let (lo, hi) = tolerance_box(design, quantity, tolerances)?;
    let (min, max) = (nominal.min(lo.value), nominal.max(hi.value));
    let mut sum = 0.0;
    for (p, &on) in mask.iter().enumerate() {
        if on {
            sum += quantity.log_sensitivity(design, p)?.abs();
        }
    }
    Some(Spread {
        nominal,
        min,
        max,
        linear_min: nominal * (1.0 - sum * tolerance),
        linear_max: nominal * (1.0 + sum * tolerance),
    })
}

/// One extreme of a quantity over a tolerance box: its value and the corner reaching it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Extreme {
    /// The quantity's value at the corner.
    pub value: f64,
    /// The design at that corner.
    pub design: Components,
}

/// Exact `(min, max)` of `quantity` when each component `p_i` (in the order of
/// [`Components::values`]) takes any value in `[p_i·(1 − x_i), p_i·(1 + x_i)]`, with its own
/// tolerance `x_i = tolerances[i]` (a fraction, `0 ≤ x_i < 1`; 0 holds a component fixed).
///
/// Each quantity is a product of powers of the components (module docs), so monotone in
/// each, and its extremes over the box lie at corners: all `2³` corners
/// `p_i·(1 ± x_i)` are evaluated exactly and the lowest and highest returned with the
/// corner designs. With equal tolerances this is [`spread`]'s exact range.
///
/// `None` for a tolerance outside `[0, 1)` (or NaN), or when the quantity is undefined at
/// a corner (e.g. Q with no damping).
///
/// ```
/// use zeta_solver::design::sensitivity::{tolerance_box, Components, Quantity};
/// // ζ = (R/2)·√(C/L) is lowest at R(1 − dR), C(1 − dC), L(1 + dL).
/// let rlc = Components::Electrical { l: 0.5, r: 7.0, cap: 0.02 };
/// let (lo, _) = tolerance_box(&rlc, Quantity::DampingRatio, [0.05, 0.2, 0.1]).unwrap();
/// assert!((lo.value - 2.8 * (0.018f64 / 0.525).sqrt()).abs() < 1e-12);
/// ```
pub fn tolerance_box(
    design: &Components,
    quantity: Quantity,
    tolerances: [f64; 3],
) -> Option<(Extreme, Extreme)> {
    if !tolerances.iter().all(|x| (0.0..1.0).contains(x)) {
        return None;
    }
    let base = design.values();
    let mut lo: Option<Extreme> = None;
    let mut hi: Option<Extreme> = None;
    for corner in 0..8u32 {
        let mut v = base;
        for (i, (vi, x)) in v.iter_mut().zip(tolerances).enumerate() {
            let sign = if corner >> i & 1 == 1 { 1.0 } else { -1.0 };
            *vi *= 1.0 + sign * x;
        }
        let d = design.with_values(v);
        let value = quantity.of(&d.system().ok()?)?;
        let e = Extreme { value, design: d };
        if lo.is_none_or(|l| value < l.value) {
            lo = Some(e);
        }
        if hi.is_none_or(|h| value > h.value) {
            hi = Some(e);
        }
    }
    lo.zip(hi)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn invalid_requests_are_none() {
        let d = Components::mechanical_for_zeta(300.0, 24_000.0, 0.7);
        assert!(spread(&d, Quantity::DampingRatio, Varied::One(3), 0.1).is_none());
        assert!(spread(&d, Quantity::DampingRatio, Varied::All, 1.0).is_none());
        assert!(spread(&d, Quantity::DampingRatio, Varied::All, f64::NAN).is_none());
        let undamped = Components::Mechanical {
            m: 1.0,
            c: 0.0,
            k: 1.0,
        };
        assert!(spread(&undamped, Quantity::QualityFactor, Varied::All, 0.1).is_none());
    }
}
