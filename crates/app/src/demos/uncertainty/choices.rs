//! The tolerance demo's choice parameters as typed enums: the system analysed, the
//! distribution of the parts and the quantity of the second histogram.

use crate::declare::Choice;
use crate::t;
use zeta_solver::design::monte_carlo::{Distribution, McSamples};

/// Which parameter group is analysed.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum System {
    /// The quarter car under a mass tolerance.
    #[default]
    Suspension,
    /// The series RLC loop under part tolerances.
    Rlc,
}

impl Choice for System {
    const OPTIONS: &'static [(Self, &'static str, &'static str)] = &[
        (System::Suspension, "suspension", "quarter-car suspension"),
        (System::Rlc, "rlc", "series RLC"),
    ];
}

/// How the parts are distributed within their tolerance.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Dist {
    /// Uniform within ±tolerance.
    #[default]
    Uniform,
    /// Normal with the tolerance as 3σ.
    Normal,
}

impl Choice for Dist {
    const OPTIONS: &'static [(Self, &'static str, &'static str)] = &[
        (Dist::Uniform, "uniform", "uniform within ±tolerance"),
        (Dist::Normal, "normal", "normal, tolerance = 3σ"),
    ];
}

impl Dist {
    /// The solver's distribution.
    pub(super) fn distribution(self) -> Distribution {
        match self {
            Dist::Uniform => Distribution::Uniform,
            Dist::Normal => Distribution::Normal,
        }
    }
}

/// The quantity shown in the second histogram.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum HistOf {
    /// Damping ratio ζ.
    Zeta,
    /// Natural frequency f0 \[Hz\].
    F0,
    /// Quality factor Q.
    #[default]
    Q,
    /// Half-power bandwidth \[rad/s\].
    Bandwidth,
    /// Settling time of a release from rest \[s\].
    SettlingTime,
}

impl Choice for HistOf {
    const OPTIONS: &'static [(Self, &'static str, &'static str)] = &[
        (HistOf::Zeta, "zeta", "damping ratio ζ"),
        (HistOf::F0, "f0", "natural frequency f0"),
        (HistOf::Q, "q", "quality factor Q"),
        (HistOf::Bandwidth, "bandwidth", "bandwidth"),
        (HistOf::SettlingTime, "settling_time", "settling time"),
    ];
}

impl HistOf {
    /// Axis label (in the interface language) and unit.
    pub(super) fn label(self) -> (String, &'static str) {
        match self {
            HistOf::Zeta => (t!("uncertainty-quantity-zeta"), ""),
            HistOf::F0 => (t!("uncertainty-quantity-f0"), "Hz"),
            HistOf::Q => (t!("uncertainty-quantity-q"), ""),
            HistOf::Bandwidth => (t!("uncertainty-quantity-bandwidth"), "rad/s"),
            HistOf::SettlingTime => (t!("uncertainty-quantity-settling-time"), "s"),
        }
    }

    /// This quantity's draws.
    pub(super) fn data(self, s: &McSamples) -> &[f64] {
        match self {
            HistOf::Zeta => &s.zeta,
            HistOf::F0 => &s.f0,
            HistOf::Q => &s.q,
            HistOf::Bandwidth => &s.bandwidth,
            HistOf::SettlingTime => &s.settling_time,
        }
    }
}
