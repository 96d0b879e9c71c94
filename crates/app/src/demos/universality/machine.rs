//! Each machine of a slot built through the solver (`zeta_solver::machines`), tuned to a
//! target by the solver's inverse, and what the page needs to say about it: the units of
//! its coefficients, its coordinate, the slider ranges and which sliders "match" moves.

use super::params::{self, pick, Kind, Values};
use crate::declare::Param;
use zeta_solver::machines::{
    DcServo, Machine, MassSpringDamper, MatchError, SeriesRlc, Storey, Target, TwoCapacityThermal,
    UTube,
};
use zeta_solver::SecondOrder;

// Slider ranges `(min, max, step)`, one per quantity, shared by both slots. The ranges of
// the parameters that "match" tunes are also where the tuned values must land.
pub(super) const M: (f64, f64, f64) = (0.1, 100.0, 0.001);
pub(super) const C: (f64, f64, f64) = (0.0, 100.0, 0.01);
pub(super) const K: (f64, f64, f64) = (0.1, 10_000.0, 0.01);
pub(super) const L: (f64, f64, f64) = (1e-3, 10.0, 1e-4);
pub(super) const R: (f64, f64, f64) = (0.0, 500.0, 0.01);
pub(super) const CAP: (f64, f64, f64) = (1e-6, 1.0, 1e-7);
pub(super) const LEN: (f64, f64, f64) = (0.05, 5.0, 0.001);
pub(super) const BORE: (f64, f64, f64) = (1e-3, 0.05, 1e-4);
pub(super) const RHO: (f64, f64, f64) = (500.0, 15_000.0, 1.0);
pub(super) const MU: (f64, f64, f64) = (1e-5, 10.0, 1e-6);
pub(super) const J: (f64, f64, f64) = (1e-5, 1.0, 1e-6);
pub(super) const KT: (f64, f64, f64) = (0.01, 2.0, 0.001);
pub(super) const RA: (f64, f64, f64) = (0.1, 100.0, 0.01);
pub(super) const KP: (f64, f64, f64) = (0.01, 10_000.0, 0.01);
pub(super) const KD: (f64, f64, f64) = (0.0, 50.0, 0.001);
pub(super) const MF: (f64, f64, f64) = (1_000.0, 1e6, 1.0);
pub(super) const H: (f64, f64, f64) = (2.5, 6.0, 0.01);
pub(super) const EI: (f64, f64, f64) = (1e4, 1e10, 1.0);
pub(super) const CF: (f64, f64, f64) = (0.0, 2e6, 100.0);
pub(super) const CTH: (f64, f64, f64) = (1e-3, 1e6, 1e-3);
pub(super) const RTH: (f64, f64, f64) = (1e-3, 1e3, 1e-4);

/// Columns under each storey (the storey's lateral stiffness is 12·n·EI/h³).
pub(super) const COLUMNS: f64 = 4.0;

/// The coefficients of machine `kind` with slider values `v`.
pub(super) fn system(kind: Kind, v: &Values) -> Result<SecondOrder, MatchError> {
    solve(kind, v, None).map(|(sys, _)| sys)
}

/// The slider values of machine `kind` tuned by the solver to `target`: the two tuning
/// parameters solved for, everything else kept.
pub(super) fn tune(kind: Kind, v: &Values, target: Target) -> Result<Values, MatchError> {
    solve(kind, v, Some(target)).map(|(_, tuned)| tuned)
}

/// Machine `kind` built by the solver from slider values `v` and, given a `target`, tuned
/// to it: its coefficients, and `v` with the two tuning parameters as the machine has them.
fn solve(
    kind: Kind,
    v: &Values,
    target: Option<Target>,
) -> Result<(SecondOrder, Values), MatchError> {
    let mut out = *v;
    let sys = match kind {
        Kind::MassSpring => {
            let m = tuned_to(MassSpringDamper::new(v.m, v.c, v.k)?, target)?;
            (_, out.c, out.k) = m.params();
            m.system()
        }
        Kind::Rlc => {
            let m = tuned_to(SeriesRlc::new(v.l, v.r, v.cap)?, target)?;
            (_, out.r, out.cap) = m.params();
            m.system()
        }
        Kind::UTube => {
            let m = tuned_to(UTube::new(v.len, v.bore, v.rho, v.mu)?, target)?;
            (out.len, _, _, out.mu) = m.params();
            m.system()
        }
        Kind::Servo => {
            let m = tuned_to(DcServo::new(v.j, v.kt, v.ra, v.kp, v.kd)?, target)?;
            (_, _, _, out.kp, out.kd) = m.params();
            m.system()
        }
        Kind::Storey => {
            let m = tuned_to(Storey::new(v.mf, v.h, v.ei, COLUMNS, v.cf)?, target)?;
            (_, _, out.ei, _, out.cf) = m.params();
            m.system()
        }
        Kind::Thermal => {
            let m = tuned_to(TwoCapacityThermal::new(v.c1, v.r1, v.c2, v.r2)?, target)?;
            (_, out.r1, _, out.r2) = m.params();
            m.system()
        }
    };
    Ok((sys, out))
}

/// `m` tuned to `target`, or as it is without one.
fn tuned_to<M: Machine>(m: M, target: Option<Target>) -> Result<M, MatchError> {
    match target {
        Some(t) => m.matched(t),
        None => Ok(m),
    }
}

/// One slider that "match" moves: URL key, symbol, unit, allowed range and tuned value.
pub(super) struct Tuned {
    pub key: &'static str,
    pub symbol: &'static str,
    pub unit: &'static str,
    pub range: (f64, f64),
    pub value: f64,
}

/// The two sliders of slot `slot` that "match" moves for machine `kind`, at values `v`;
/// symbol, unit and range as the slot's parameter table declares them.
pub(super) fn tuned(kind: Kind, slot: usize, v: &Values) -> Vec<Tuned> {
    let moved = match kind {
        Kind::MassSpring => [("A_k", "B_k", v.k), ("A_c", "B_c", v.c)],
        Kind::Rlc => [("A_C", "B_C", v.cap), ("A_R", "B_R", v.r)],
        Kind::UTube => [("A_len", "B_len", v.len), ("A_mu", "B_mu", v.mu)],
        Kind::Servo => [("A_Kp", "B_Kp", v.kp), ("A_Kd", "B_Kd", v.kd)],
        Kind::Storey => [("A_EI", "B_EI", v.ei), ("A_cf", "B_cf", v.cf)],
        Kind::Thermal => [("A_R1", "B_R1", v.r1), ("A_R2", "B_R2", v.r2)],
    };
    let declared = if slot == 0 {
        params::slot::<0>()
    } else {
        params::slot::<1>()
    };
    moved
        .into_iter()
        .filter_map(|(a, b, value)| {
            let key = pick(slot, a, b);
            let spec = declared.iter().map(Param::spec).find(|s| s.key == key)?;
            Some(Tuned {
                key,
                symbol: spec.symbol,
                unit: spec.unit,
                range: (spec.min, spec.max),
                value,
            })
        })
        .collect()
}

/// Units of the coefficients `(a, b, c)` of machine `kind`.
pub(super) fn units(kind: Kind) -> [&'static str; 3] {
    match kind {
        Kind::MassSpring | Kind::UTube | Kind::Storey => ["kg", "N·s/m", "N/m"],
        Kind::Rlc => ["H", "Ω", "1/F"],
        Kind::Servo => ["kg·m²", "N·m·s/rad", "N·m/rad"],
        Kind::Thermal => ["s²", "s", ""],
    }
}

/// The normalised coordinate `y/y₀` of machine `kind` in its own symbols.
pub(super) fn normalised_coordinate(kind: Kind) -> &'static str {
    match kind {
        Kind::MassSpring => "x/x₀",
        Kind::Rlc => "q/q₀",
        Kind::UTube => "h/h₀",
        Kind::Servo => "θ/θ₀",
        Kind::Storey => "u/u₀",
        Kind::Thermal => "T₂/T₂(0)",
    }
}
