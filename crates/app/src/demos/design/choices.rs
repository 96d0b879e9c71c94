//! The design demo's choice parameters as typed enums: the map's metric and the road class.

use crate::declare::Choice;
use zeta_solver::design::sweep::KcMaps;
use zeta_solver::two_dof::IsoClass;

/// The metric shown on the map.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Metric {
    /// Settling time of a release from rest.
    #[default]
    SettlingTime,
    /// Peak rebound of a release from rest.
    PeakRebound,
    /// Ride comfort: `a_w`, the `W_k`-weighted RMS body acceleration of the two-DOF car,
    /// stationary on the road.
    AccelRms,
    /// Peak displacement transmissibility.
    PeakTransmissibility,
}

impl Choice for Metric {
    const OPTIONS: &'static [(Self, &'static str, &'static str)] = &[
        (
            Metric::SettlingTime,
            "settling_time",
            "settling time (free response)",
        ),
        (
            Metric::PeakRebound,
            "peak_rebound",
            "peak rebound (free response)",
        ),
        (
            Metric::AccelRms,
            "accel_rms",
            "comfort a_w (W_k-weighted RMS body acceleration)",
        ),
        (
            Metric::PeakTransmissibility,
            "peak_transmissibility",
            "peak transmissibility |X/U|",
        ),
    ];
}

impl Metric {
    /// The map of this metric.
    pub(super) fn values(self, maps: &KcMaps) -> &[f64] {
        match self {
            Metric::SettlingTime => &maps.settling_time,
            Metric::PeakRebound => &maps.peak_rebound,
            Metric::AccelRms => &maps.accel_rms,
            Metric::PeakTransmissibility => &maps.peak_transmissibility,
        }
    }
}

/// The road under the comfort metric: ISO 8608 classes A–D.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Road {
    /// Class A.
    A,
    /// Class B.
    B,
    /// Class C (the quarter-car-2dof demo's default).
    #[default]
    C,
    /// Class D.
    D,
}

impl Choice for Road {
    const OPTIONS: &'static [(Self, &'static str, &'static str)] = &[
        (Road::A, "a", "class A (very good)"),
        (Road::B, "b", "class B (good)"),
        (Road::C, "c", "class C (average)"),
        (Road::D, "d", "class D (poor)"),
    ];
}

impl Road {
    /// The class's letter, as ISO 8608 writes it.
    pub(super) fn letter(self) -> &'static str {
        match self {
            Road::A => "A",
            Road::B => "B",
            Road::C => "C",
            Road::D => "D",
        }
    }

    /// The solver's ISO 8608 class.
    pub(super) fn class(self) -> IsoClass {
        match self {
            Road::A => IsoClass::A,
            Road::B => IsoClass::B,
            Road::C => IsoClass::C,
            Road::D => IsoClass::D,
        }
    }
}
