//! Which of the two damper sliders, `c` or `zeta`, the user moved (see the module docs of
//! the demo): the damper rate in use and the values the page is asked to show.

use super::{QuarterCar, C_DEFAULT, C_RANGE, P, ZETA_DEFAULT, ZETA_RANGE};
use zeta_solver::SecondOrder;

/// The `c`/`zeta` values seen at the previous update and published for the sliders.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct Coupling {
    /// `c` parameter at the previous update \[N·s/m\].
    pub(super) seen_c: f64,
    /// `zeta` parameter at the previous update.
    pub(super) seen_zeta: f64,
    /// `c` the page was asked to show \[N·s/m\].
    pub(super) shown_c: f64,
    /// `zeta` the page was asked to show (clamped to its slider).
    pub(super) shown_zeta: f64,
}

impl QuarterCar {
    /// A fresh demo (no update seen yet).
    pub fn new() -> Self {
        Self::default()
    }

    /// Resolves the damper rate from the `c` and `zeta` parameters (module docs), stores it
    /// and what to publish; returns it.
    pub(super) fn resolve_c(&mut self, p: &P) -> f64 {
        let (pc, pz) = (p.c, p.zeta);
        // c = ζ·2√(km), the solver's critical damping of this car.
        let crit = SecondOrder::mechanical(p.m, 0.0, p.k)
            .ok()
            .and_then(|s| s.critical_damping());
        let from_zeta = |z: f64| crit.map_or(f64::NAN, |crit| z * crit);
        let c = match self.coupling {
            None if pc == C_DEFAULT && pz != ZETA_DEFAULT => from_zeta(pz),
            None => pc,
            Some(cp) => {
                let moved = |v: f64, seen: f64, shown: f64| v != seen && v != shown;
                if moved(pc, cp.seen_c, cp.shown_c) {
                    pc
                } else if moved(pz, cp.seen_zeta, cp.shown_zeta) {
                    from_zeta(pz)
                } else {
                    self.c
                }
            }
        };
        let c = if c.is_finite() {
            c.clamp(C_RANGE.0, C_RANGE.1)
        } else {
            C_DEFAULT
        };
        let zeta = SecondOrder::mechanical(p.m, c, p.k)
            .ok()
            .and_then(|s| s.damping_ratio())
            .unwrap_or(pz);
        self.c = c;
        self.coupling = Some(Coupling {
            seen_c: pc,
            seen_zeta: pz,
            shown_c: c,
            shown_zeta: zeta.clamp(ZETA_RANGE.0, ZETA_RANGE.1),
        });
        c
    }
}
