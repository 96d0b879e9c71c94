//! Typed errors for every fallible entry point of the solver.
//!
//! Each variant's `Display` is a sentence a student can read, with the offending value and
//! its unit, so the app can show it as it is.

use std::fmt;

/// Why a model could not be built from the given parameters.
#[derive(Debug, Clone, PartialEq)]
pub enum ModelError {
    /// A parameter was NaN or infinite.
    NotFinite {
        /// Name of the parameter, e.g. `"mass"`.
        name: &'static str,
        /// Its unit, e.g. `"kg"`.
        unit: &'static str,
    },
    /// A parameter that must be strictly positive was zero or negative.
    NotPositive {
        /// Name of the parameter.
        name: &'static str,
        /// Its unit.
        unit: &'static str,
        /// The value given.
        value: f64,
    },
    /// A parameter that must not be negative was negative.
    Negative {
        /// Name of the parameter.
        name: &'static str,
        /// Its unit.
        unit: &'static str,
        /// The value given.
        value: f64,
    },
    /// The ratio of coefficients is too extreme to compute with in double precision.
    OutOfRange {
        /// Name of the parameter or derived quantity.
        name: &'static str,
        /// Why it is out of range.
        reason: &'static str,
    },
}

impl fmt::Display for ModelError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ModelError::NotFinite { name, unit } => {
                write!(f, "{name} must be a finite number (in {unit})")
            }
            ModelError::NotPositive { name, unit, value } => {
                write!(f, "{name} must be positive, got {value} {unit}")
            }
            ModelError::Negative { name, unit, value } => {
                write!(f, "{name} must not be negative, got {value} {unit}")
            }
            ModelError::OutOfRange { name, reason } => {
                write!(f, "{name} is out of range: {reason}")
            }
        }
    }
}

impl std::error::Error for ModelError {}

/// A parameter value that passed its check, or why it did not.
pub(crate) type Checked = Result<f64, ModelError>;

/// Checks that `value` is finite; returns it.
pub(crate) fn finite(name: &'static str, unit: &'static str, value: f64) -> Checked {
    if value.is_finite() {
        Ok(value)
    } else {
        Err(ModelError::NotFinite { name, unit })
    }
}

/// Checks that `value` is finite and `ok(value)` holds; returns it, else the error
/// `reject(name, unit, value)`.
fn bounded(
    name: &'static str,
    unit: &'static str,
    value: f64,
    ok: fn(f64) -> bool,
    reject: fn(&'static str, &'static str, f64) -> ModelError,
) -> Checked {
    let v = finite(name, unit, value)?;
    if ok(v) {
        Ok(v)
    } else {
        Err(reject(name, unit, v))
    }
}

/// Checks that `value` is finite and strictly positive; returns it.
pub(crate) fn positive(name: &'static str, unit: &'static str, value: f64) -> Checked {
    let not_positive = |name, unit, value| ModelError::NotPositive { name, unit, value };
    bounded(name, unit, value, |v| v > 0.0, not_positive)
}

/// Checks that `value` is finite and not negative; returns it.
pub(crate) fn non_negative(name: &'static str, unit: &'static str, value: f64) -> Checked {
    let negative = |name, unit, value| ModelError::Negative { name, unit, value };
    bounded(name, unit, value, |v| v >= 0.0, negative)
}
