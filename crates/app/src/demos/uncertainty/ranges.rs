//! Exact ranges over the tolerance box, and the three designs of the response band with
//! their settling times: solver calls only.

use super::{System, P};
use zeta_solver::design::sensitivity::{spread, tolerance_box, Components, Quantity, Varied};
use zeta_solver::metrics::{free::FreeMetrics, SettlingBand};
use zeta_solver::SecondOrder;

/// Initial displacement of the suspension's free responses \[m\].
pub(super) const X0_CAR: f64 = 0.06;
/// Initial capacitor voltage of the RLC's free responses \[V\].
pub(super) const V0_RLC: f64 = 1.0;

/// Which design of the response band a member is.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) enum BandName {
    /// The car at its heaviest: mass raised by this many percent.
    MassUp(f64),
    /// The car at nominal mass.
    NominalMass,
    /// The car at its lightest: mass lowered by this many percent.
    MassDown(f64),
    /// The RLC corner of the tolerance box with the lowest ζ.
    LowestCorner,
    /// The RLC at nominal values.
    Nominal,
    /// The RLC corner of the tolerance box with the highest ζ.
    HighestCorner,
}

/// One design drawn in the response band.
pub(super) struct Member {
    /// The system, where the design is valid.
    pub(super) sys: Option<SecondOrder>,
    /// Which design it is (the legend names it, with its ζ).
    pub(super) name: BandName,
    /// Damping ratio, where defined.
    pub(super) zeta: Option<f64>,
    /// Settling time of a release from rest into the 5 % band \[s\].
    pub(super) settling_time: Option<f64>,
}

/// Exact ranges and the designs at the ends of the ζ range.
pub(super) struct Ranges {
    pub(super) zeta: Option<(f64, f64)>,
    pub(super) wn: Option<(f64, f64)>,
    pub(super) q: Option<(f64, f64)>,
    /// Lowest-ζ end, nominal, highest-ζ end.
    pub(super) band: [Member; 3],
    /// Initial value of the band's responses (m or V).
    pub(super) x0: f64,
}

impl Ranges {
    pub(super) fn new(p: &P) -> Self {
        let (d, tol) = p.design();
        let x0 = match p.system {
            System::Suspension => X0_CAR,
            System::Rlc => V0_RLC,
        };
        let member = |design: Components, name: BandName| {
            let sys = design.system().ok();
            let zeta = sys.and_then(|s| s.damping_ratio());
            Member {
                sys,
                name,
                zeta,
                settling_time: sys
                    .and_then(|s| FreeMetrics::exact(&s, x0, 0.0, SettlingBand::FREE_DEFAULT))
                    .and_then(|m| m.settling_time),
            }
        };
        match p.system {
            System::Suspension => {
                let dm = tol[0];
                let sp = |q| spread(&d, q, Varied::One(0), dm).map(|s| (s.min, s.max));
                let [m, c, k] = d.values();
                let pct = 100.0 * dm;
                // ζ ∝ m^−½: the heavy end has the lowest ζ.
                Ranges {
                    zeta: sp(Quantity::DampingRatio),
                    wn: sp(Quantity::NaturalFrequency),
                    q: sp(Quantity::QualityFactor),
                    band: [
                        member(d.with_values([m * (1.0 + dm), c, k]), BandName::MassUp(pct)),
                        member(d, BandName::NominalMass),
                        member(
                            d.with_values([m * (1.0 - dm), c, k]),
                            BandName::MassDown(pct),
                        ),
                    ],
                    x0,
                }
            }
            System::Rlc => {
                let range = |q| tolerance_box(&d, q, tol).map(|(lo, hi)| (lo.value, hi.value));
                let z = tolerance_box(&d, Quantity::DampingRatio, tol);
                Ranges {
                    zeta: z.map(|(lo, hi)| (lo.value, hi.value)),
                    wn: range(Quantity::NaturalFrequency),
                    q: range(Quantity::QualityFactor),
                    band: [
                        member(z.map_or(d, |(lo, _)| lo.design), BandName::LowestCorner),
                        member(d, BandName::Nominal),
                        member(z.map_or(d, |(_, hi)| hi.design), BandName::HighestCorner),
                    ],
                    x0,
                }
            }
        }
    }
}
