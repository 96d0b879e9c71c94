//! The design demo's choice parameters as typed enums: the map's metric and the road class.

use super::DesignSpace;
use crate::declare::{choice_enum, Choice};
use zeta_solver::two_dof::IsoClass;

choice_enum! {
    /// The metric shown on the map.
    pub enum Metric {
        /// Settling time of a release from rest.
        #[default]
        SettlingTime => ("settling_time", "settling time (free response)"),
        /// Peak rebound of a release from rest.
        PeakRebound => ("peak_rebound", "peak rebound (free response)"),
        /// Ride comfort: `a_w`, the `W_k`-weighted RMS body acceleration of the two-DOF
        /// car, stationary on the road.
        AccelRms => ("accel_rms", "comfort a_w (W_k-weighted RMS body acceleration)"),
        /// Peak displacement transmissibility.
        PeakTransmissibility => ("peak_transmissibility", "peak transmissibility |X/U|"),
    }
}

impl Metric {
    /// The map of this metric (comfort computed if not yet: [`DesignSpace::comfort`]).
    pub(super) fn values(self, d: &DesignSpace) -> &[f64] {
        match self {
            Metric::SettlingTime => &d.maps.settling_time,
            Metric::PeakRebound => &d.maps.peak_rebound,
            Metric::AccelRms => &d.comfort().accel_rms,
            Metric::PeakTransmissibility => &d.maps.peak_transmissibility,
        }
    }
}

choice_enum! {
    /// The road under the comfort metric: the solver's ISO 8608 class, A–D (class C, the
    /// quarter-car-2dof demo's default, by default).
    pub struct Road(pub(super) IsoClass) {
        default IsoClass::C;
        IsoClass::A => ("a", "class A (very good)"),
        IsoClass::B => ("b", "class B (good)"),
        IsoClass::C => ("c", "class C (average)"),
        IsoClass::D => ("d", "class D (poor)"),
    }
}

impl Road {
    /// The class's letter, as ISO 8608 writes it: the URL key in capitals.
    pub(super) fn letter(self) -> String {
        self.key().to_ascii_uppercase()
    }
}
