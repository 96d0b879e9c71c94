//! The tolerance demo's choice parameters as typed enums: the system analysed, the
//! distribution of the parts and the quantity of the second histogram.

use crate::declare::choice_enum;
use crate::t;
use zeta_solver::design::monte_carlo::{Distribution, McSamples};

choice_enum! {
    /// Which parameter group is analysed.
    pub enum System {
        /// The quarter car under a mass tolerance.
        #[default]
        Suspension => ("suspension", "quarter-car suspension"),
        /// The series RLC loop under part tolerances.
        Rlc => ("rlc", "series RLC"),
    }
}

choice_enum! {
    /// How the parts are distributed within their tolerance: the solver's distribution
    /// (uniform within ±tolerance by default; normal with the tolerance as 3σ).
    pub struct Dist(pub(super) Distribution) {
        default Distribution::Uniform;
        Distribution::Uniform => ("uniform", "uniform within ±tolerance"),
        Distribution::Normal => ("normal", "normal, tolerance = 3σ"),
    }
}

choice_enum! {
    /// The quantity shown in the second histogram.
    pub enum HistOf {
        /// Damping ratio ζ.
        Zeta => ("zeta", "damping ratio ζ"),
        /// Natural frequency f0 \[Hz\].
        F0 => ("f0", "natural frequency f0"),
        /// Quality factor Q.
        #[default]
        Q => ("q", "quality factor Q"),
        /// Half-power bandwidth \[rad/s\].
        Bandwidth => ("bandwidth", "bandwidth"),
        /// Settling time of a release from rest \[s\].
        SettlingTime => ("settling_time", "settling time"),
    }
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
