//! The universality demo's declaration: both slots' parameters (the table of `params.rs`)
//! and "match", the readouts of both machines, the plots and the presets.

use super::params::{self, pick, Kind, P};
use super::{figures, machine, text, Results};
use crate::declare::{Choice, Declaration, Param, ReadoutDef};
use crate::demos::rows::{self, readouts, Drawn};
use crate::spec::Preset;

/// The demo's declaration.
pub(super) fn declaration() -> Declaration<P, Results> {
    let mut params = params::slot::<0>();
    params.extend(params::slot::<1>());
    params.push(Param::toggle(
        "match",
        "match: tune B to behave like A (same ωₙ and ζ)",
        false,
        |p, on| p.matched = on,
    ));
    let mut readouts = slot_readouts::<0>();
    readouts.extend(slot_readouts::<1>());
    readouts.extend(readouts! { Results, |r|;
        number "wn_ratio", "time-scale ratio ωₙ(B)/ωₙ(A)", "", 4
            => Some(r.m[1].wn() / r.m[0].wn());
        text "match", "match" => text::matching(&r.matching);
    });
    Declaration {
        equation_mathml: text::EQUATION,
        params,
        readouts,
        plots: rows::drawn_plots(&PLOTS),
        presets: presets(),
        table: Some(text::table()),
        schematic: true,
        ..Declaration::new("universality", "One equation, many machines", text::SUMMARY)
    }
}

/// `(value, text)` of coefficient `i` (0: a, 1: b, 2: c) of machine `slot`, in its units.
fn coefficient(r: &Results, slot: usize, i: usize) -> Option<(f64, String)> {
    let one = &r.m[slot];
    let v = [one.sys.inertia(), one.sys.damping(), one.sys.stiffness()][i];
    Some((v, text::amount(v, machine::units(one.kind)[i])))
}

/// Slot `S`'s coefficients, natural frequency, damping ratio and regime.
fn slot_readouts<const S: usize>() -> Vec<ReadoutDef<Results>> {
    let name = |a, b| pick(S, a, b);
    readouts! { Results, |r|;
        formatted name("a_A", "a_B"),
            name("inertia coefficient a of A", "inertia coefficient a of B"), ""
            => coefficient(r, S, 0);
        formatted name("b_A", "b_B"),
            name("damping coefficient b of A", "damping coefficient b of B"), ""
            => coefficient(r, S, 1);
        formatted name("c_A", "c_B"),
            name("stiffness coefficient c of A", "stiffness coefficient c of B"), ""
            => coefficient(r, S, 2);
        number name("wn_A", "wn_B"),
            name("natural frequency ωₙ of A", "natural frequency ωₙ of B"), "rad/s", 4
            => r.m[S].sys.natural_frequency();
        number name("zeta_A", "zeta_B"),
            name("damping ratio ζ of A", "damping ratio ζ of B"), "", 4
            => r.m[S].sys.damping_ratio();
        text name("regime_A", "regime_B"), name("regime of A", "regime of B")
            => crate::format::regime(r.m[S].sys.regime());
    }
}

/// The presets: pairs of machines, mostly matched.
fn presets() -> Vec<Preset> {
    let kinds = |a: Kind, b: Kind, on: bool| {
        vec![
            ("A", a.index() as f64),
            ("B", b.index() as f64),
            ("match", if on { 1.0 } else { 0.0 }),
        ]
    };
    let mut fast_thermometer = kinds(Kind::Thermal, Kind::MassSpring, true);
    fast_thermometer.extend([("A_C1", 5.0), ("A_R1", 0.5), ("A_C2", 1.0), ("A_R2", 2.0)]);
    vec![
        Preset {
            label: "Mass–spring and RLC circuit, matched",
            values: kinds(Kind::MassSpring, Kind::Rlc, true),
        },
        Preset {
            label: "U-tube manometer and mass–spring, matched",
            values: kinds(Kind::UTube, Kind::MassSpring, true),
        },
        Preset {
            label: "Building storey tuned like a servo",
            values: kinds(Kind::Servo, Kind::Storey, true),
        },
        Preset {
            label: "Thermometer (two capacities) and mass–spring, matched",
            values: fast_thermometer,
        },
        Preset {
            label: "A thermal system cannot match an oscillator",
            values: kinds(Kind::MassSpring, Kind::Thermal, true),
        },
    ]
}

/// The plots, in order: key, title and width / height, and the figure each shows.
pub(super) const PLOTS: [Drawn<Results>; 2] = [
    (
        ("normalised", "Normalised responses y/y₀ against ωₙt", 1.9),
        figures::normalised,
    ),
    (
        ("realtime", "Responses in real time", 1.9),
        figures::realtime,
    ),
];
