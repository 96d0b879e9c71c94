//! The design demo's declaration as data: parameters, readouts, plots and presets.

use super::{figures, text, Metric, Results, Road, P};
use crate::declare::{Declaration, Param};
use crate::demos::rows::{self, readouts, sliders, Plot};
use crate::spec::Preset;

pub(super) fn declaration() -> Declaration<P, Results> {
    Declaration {
        equation_mathml: text::EQUATION,
        params: params(),
        // What the design point does leads (a phone's strip shows the first two while a slider
        // is held); the point itself follows, which its own sliders show too.
        readouts: readouts! { Results, |r|;
            number "zeta", "damping ratio ζ", "", 3 => r.sel.zeta;
            number "settling_time", "settling time into the ± band of x₀ (free response)", "s", 4
                => r.sel.settling_time;
            number "overshoot", "peak rebound, % of x₀ (free response)", "%", 3 => r.sel.overshoot;
            // Plain: accelerations stay in m/s² (no "mm/s²").
            // The road and speed written beside the value, as the label cannot vary.
            formatted "accel_rms",
                "a_w: RMS body acceleration weighted by ISO 2631-1 W_k (two-DOF car, \
                 stationary on the ISO 8608 road at speed V)",
                "m/s²"
                => r.sel.accel_rms.map(|a| (a, text::with_road(a, &r.key)));
            formatted "accel_unweighted", "RMS body acceleration, unweighted (same car and road)",
                "m/s²"
                => r.sel.ride.map(|ride| {
                    let a = ride.rms_body_acceleration;
                    (a, text::with_road(a, &r.key))
                });
            number "k", "selected spring rate k", "N/m", 4 => Some(r.k);
            number "c", "selected damper rate c", "N·s/m", 4 => Some(r.c);
            formatted "grid_size", "grid size (cells)", ""
                => Some(((r.grid * r.grid) as f64, text::grid_size(r)));
            // Plain: the value is already in ms (an SI prefix would give "µms").
            plain "compute_time", "sweep compute time", "ms", 3 => Some(r.sweep_ms);
        },
        plots: rows::plots(&PLOTS),
        presets: PRESETS
            .iter()
            .map(|&(label, values)| Preset {
                label,
                values: values.to_vec(),
            })
            .collect(),
        ..Declaration::new("design", "Design space (k, c)", text::SUMMARY)
    }
}

/// The parameters, in order.
fn params() -> Vec<Param<P>> {
    [
        vec![sprung_mass::<P>("sprung mass", |p, v| p.m = v)],
        // Wheel and tyre of the two-DOF car behind the comfort metric: the ranges and
        // defaults of the quarter-car-2dof demo.
        sliders! { P;
            linear "mu", "comfort: wheel (unsprung) mass", "m_u", "kg", (10.0, 150.0, 1.0), 40.0 => mu;
            linear "kt", "comfort: tyre stiffness", "k_t", "N/m", (50_000.0, 500_000.0, 1_000.0), 200_000.0 => kt;
        },
        vec![Param::choice("metric", "map metric", Metric::default(), |p, v| p.metric = v)],
        sliders! { P;
            linear "band", "settling band, ± % of x₀ (free response)", "", "%", (1.0, 20.0, 0.5), 5.0 => band;
        },
        vec![Param::choice("road", "road (ISO 8608)", Road::default(), |p, v| p.road = v)],
        sliders! { P;
            linear "V", "comfort: speed", "V", "m/s", (2.0, 40.0, 0.5), 10.0 => v;
            linear "k_min", "map: lowest spring rate", "k_min", "N/m", (2_000.0, 30_000.0, 500.0), 10_000.0 => k_min;
            linear "k_max", "map: highest spring rate", "k_max", "N/m", (35_000.0, 150_000.0, 500.0), 60_000.0 => k_max;
            linear "c_min", "map: lowest damper rate", "c_min", "N·s/m", (100.0, 2_000.0, 50.0), 500.0 => c_min;
            linear "c_max", "map: highest damper rate", "c_max", "N·s/m", (2_500.0, 15_000.0, 100.0), 8_000.0 => c_max;
            linear "k", "selected spring rate", "k", "N/m", (2_000.0, 150_000.0, 100.0), 24_000.0 => k;
            linear "c", "selected damper rate", "c", "N·s/m", (100.0, 15_000.0, 10.0), 2_000.0 => c;
            linear "n", "grid cells per axis", "n", "", (20.0, 160.0, 1.0), 100.0 => n;
        },
    ]
    .into_iter()
    .flatten()
    .collect()
}

/// The quarter car's sprung-mass slider `m` \[kg\] (100–800 kg, 300 kg), with its label;
/// the `uncertainty` demo's suspension declares the same.
pub(in crate::demos) fn sprung_mass<Q: 'static>(
    label: &'static str,
    set: fn(&mut Q, f64),
) -> Param<Q> {
    Param::linear("m", label, "m", "kg", (100.0, 800.0, 1.0), 300.0, set)
}

/// The plots, in order: key, title and width / height.
const PLOTS: [Plot; 3] = [
    ("map", figures::MAP_TITLE, 1.35),
    ("pareto", figures::PARETO_TITLE, 1.35),
    ("response", figures::RESPONSE_TITLE, 1.35),
];

/// The preset buttons: label and the values they set (the others stay as they are).
const PRESETS: [(&str, &[(&str, f64)]); 5] = [
    (
        "Settling-time map, 300 kg, ζ ≈ 0.37",
        &[
            ("m", 300.0),
            ("metric", 0.0),
            ("k", 24_000.0),
            ("c", 2_000.0),
        ],
    ),
    (
        "Laden car 500 kg, same parts",
        &[
            ("m", 500.0),
            ("metric", 0.0),
            ("k", 24_000.0),
            ("c", 2_000.0),
        ],
    ),
    (
        "Comfort map on a class C road",
        &[("metric", 2.0), ("road", 2.0), ("m", 300.0)],
    ),
    (
        "Peak-rebound map, ζ = 0.7 design",
        &[
            ("metric", 1.0),
            ("m", 300.0),
            ("k", 24_000.0),
            ("c", 3_760.0),
        ],
    ),
    ("Fine grid 160 × 160", &[("n", 160.0), ("metric", 0.0)]),
];
