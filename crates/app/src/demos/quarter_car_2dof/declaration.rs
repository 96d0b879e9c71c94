//! The two-DOF quarter car's declaration: parameters and plots as tables (the readouts are
//! the table of `readouts.rs`).

use super::{readouts, text, Results, P};
use crate::declare::{Declaration, Param};
use crate::demos::rows::{self, sliders, Plot};

/// The demo's declaration.
pub(super) fn declaration() -> Declaration<P, Results> {
    let d = P::default();
    let car = sliders! { P;
        linear "ms", "body (sprung) mass", "m_s", "kg", (100.0, 800.0, 1.0), d.ms => ms;
        linear "mu", "wheel (unsprung) mass", "m_u", "kg", (10.0, 150.0, 1.0), d.mu => mu;
        linear "ks", "suspension stiffness", "k_s", "N/m", (5_000.0, 80_000.0, 100.0), d.ks => ks;
        linear "kt", "tyre stiffness", "k_t", "N/m", (50_000.0, 500_000.0, 1_000.0), d.kt => kt;
        linear "cs", "suspension damping", "c_s", "N·s/m", (0.0, 8_000.0, 10.0), d.cs => cs;
    };
    let presets = text::presets(&rows::defaults(&car));
    Declaration {
        equation_mathml: text::EQUATION,
        params: with_road(car),
        readouts: readouts::table(),
        plots: rows::plots(&PLOTS),
        presets,
        schematic: true,
        ..Declaration::new(
            "quarter-car-2dof",
            "Quarter car with body and wheel",
            text::SUMMARY,
        )
    }
}

/// The parameter table: the `car`'s sliders, then the road's.
fn with_road(car: Vec<Param<P>>) -> Vec<Param<P>> {
    let d = P::default();
    let mut params = car;
    params.push(Param::choice("road", "road input", d.road, |p, v| {
        p.road = v
    }));
    params.extend(sliders! { P;
        linear "h", "bump or step height, sine amplitude", "h", "m", (0.005, 0.2, 0.001), d.h => h;
        linear "L", "bump length", "L", "m", (0.1, 5.0, 0.05), d.l => l;
        linear "V", "speed", "V", "m/s", (2.0, 40.0, 0.5), d.v => v;
        log "f_road", "sine road frequency", "f", "Hz", (0.2, 30.0, 0.01), d.f_road => f_road;
    });
    params.push(Param::choice(
        "class",
        "random road class",
        d.class,
        |p, v| p.class = v,
    ));
    params.extend(sliders! { P;
        linear "seed", "random road seed", "seed", "", (1.0, 999.0, 1.0), d.seed => seed;
    });
    params
}

/// The plots, in order: key, title and width / height.
const PLOTS: [Plot; 4] = [
    ("motion", "Body, wheel and road", 2.0),
    ("accel", "Body acceleration", 1.25),
    ("frf", "Frequency response per unit road height", 2.0),
    ("tyre", "Tyre deflection", 1.25),
];
