//! Why an integration could not be carried out.

use std::fmt;

/// Why an integration could not be carried out, with the time at which it stopped.
#[derive(Debug, Clone, PartialEq)]
pub enum IntegrationError {
    /// The step size `h` (s) was zero, negative, NaN or infinite.
    InvalidStep {
        /// The step size given (s).
        h: f64,
    },
    /// The time span was not finite or ended before it started (`T = t_end − t0 < 0`).
    InvalidSpan {
        /// Start time (s).
        t0: f64,
        /// End time (s).
        t_end: f64,
    },
    /// A tolerance or controller setting was out of its allowed range.
    InvalidSetting {
        /// Name of the setting, e.g. `"rtol"`.
        name: &'static str,
        /// The value given.
        value: f64,
        /// What it must satisfy, e.g. `"must be positive"`.
        rule: &'static str,
    },
    /// The run needs more steps than the memory budget allows.
    TooManySteps {
        /// Steps the run would need (`⌈T/h⌉`, possibly huge or infinite).
        needed: f64,
        /// The cap, [`super::MAX_STEPS`].
        limit: usize,
    },
    /// Symplectic Euler splits the state into position and velocity halves; an odd
    /// dimension has no such split.
    OddDimension {
        /// The dimension given.
        n: usize,
    },
    /// The adaptive step size fell below what double precision can resolve at `t`.
    StepSizeUnderflow {
        /// Time reached (s).
        t: f64,
    },
    /// The adaptive integrator used up its step budget at `t`.
    MaxSteps {
        /// Time reached (s).
        t: f64,
        /// Steps attempted (accepted and rejected).
        n: usize,
    },
    /// The state (or the initial state) became NaN or infinite at `t`: the solution
    /// overflowed, usually because the method is unstable at this step size.
    NonFinite {
        /// Time at which the state stopped being finite (s).
        t: f64,
    },
    /// The implicit (trapezoidal) step's Newton iteration did not converge or met a
    /// singular matrix at `t`.
    ImplicitSolveFailed {
        /// Start time of the failing step (s).
        t: f64,
    },
}

impl fmt::Display for IntegrationError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            IntegrationError::InvalidStep { h } => {
                write!(f, "step size must be a positive number, got {h} s")
            }
            IntegrationError::InvalidSpan { t0, t_end } => write!(
                f,
                "the time span must be finite and end after it starts, got {t0} s to {t_end} s"
            ),
            IntegrationError::InvalidSetting { name, value, rule } => {
                write!(f, "{name} {rule}, got {value}")
            }
            IntegrationError::TooManySteps { needed, limit } => write!(
                f,
                "this run needs {needed:.0} steps, more than the limit of {limit}; use a larger step or a shorter span"
            ),
            IntegrationError::OddDimension { n } => write!(
                f,
                "symplectic Euler needs a state of positions and velocities (even size), got size {n}"
            ),
            IntegrationError::StepSizeUnderflow { t } => write!(
                f,
                "the step size became too small to make progress at t = {t} s (the problem may be too stiff or singular)"
            ),
            IntegrationError::MaxSteps { t, n } => {
                write!(f, "gave up at t = {t} s after {n} steps")
            }
            IntegrationError::NonFinite { t } => write!(
                f,
                "the solution became infinite or undefined at t = {t} s (try a smaller step)"
            ),
            IntegrationError::ImplicitSolveFailed { t } => write!(
                f,
                "the implicit step starting at t = {t} s could not be solved"
            ),
        }
    }
}

impl std::error::Error for IntegrationError {}
