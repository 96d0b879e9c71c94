//! The design demo's declaration as data: parameters, readouts, plots and presets.

use super::{figures, text, Metric, Results, Road, P};
use crate::declare::{Declaration, Param, ReadoutDef};
use crate::spec::{PlotSpec, Preset};

pub(super) fn declaration() -> Declaration<P, Results> {
    let linear = Param::linear;
    Declaration {
        equation_mathml: text::EQUATION,
        params: vec![
            sprung_mass("sprung mass", |p, v| p.m = v),
            // Wheel and tyre of the two-DOF car behind the comfort metric: the ranges
            // and defaults of the quarter-car-2dof demo.
            linear(
                "mu",
                "comfort: wheel (unsprung) mass",
                "m_u",
                "kg",
                (10.0, 150.0, 1.0),
                40.0,
                |p, v| p.mu = v,
            ),
            linear(
                "kt",
                "comfort: tyre stiffness",
                "k_t",
                "N/m",
                (50_000.0, 500_000.0, 1_000.0),
                200_000.0,
                |p, v| p.kt = v,
            ),
            Param::choice("metric", "map metric", Metric::SettlingTime, |p, v| {
                p.metric = v
            }),
            linear(
                "band",
                "settling band, ± % of x₀ (free response)",
                "",
                "%",
                (1.0, 20.0, 0.5),
                5.0,
                |p, v| p.band = v,
            ),
            Param::choice("road", "road (ISO 8608)", Road::C, |p, v| p.road = v),
            linear(
                "V",
                "comfort: speed",
                "V",
                "m/s",
                (2.0, 40.0, 0.5),
                10.0,
                |p, v| p.v = v,
            ),
            linear(
                "k_min",
                "map: lowest spring rate",
                "k_min",
                "N/m",
                (2_000.0, 30_000.0, 500.0),
                10_000.0,
                |p, v| p.k_min = v,
            ),
            linear(
                "k_max",
                "map: highest spring rate",
                "k_max",
                "N/m",
                (35_000.0, 150_000.0, 500.0),
                60_000.0,
                |p, v| p.k_max = v,
            ),
            linear(
                "c_min",
                "map: lowest damper rate",
                "c_min",
                "N·s/m",
                (100.0, 2_000.0, 50.0),
                500.0,
                |p, v| p.c_min = v,
            ),
            linear(
                "c_max",
                "map: highest damper rate",
                "c_max",
                "N·s/m",
                (2_500.0, 15_000.0, 100.0),
                8_000.0,
                |p, v| p.c_max = v,
            ),
            linear(
                "k",
                "selected spring rate",
                "k",
                "N/m",
                (2_000.0, 150_000.0, 100.0),
                24_000.0,
                |p, v| p.k = v,
            ),
            linear(
                "c",
                "selected damper rate",
                "c",
                "N·s/m",
                (100.0, 15_000.0, 10.0),
                2_000.0,
                |p, v| p.c = v,
            ),
            linear(
                "n",
                "grid cells per axis",
                "n",
                "",
                (20.0, 160.0, 1.0),
                100.0,
                |p, v| p.n = v.round().clamp(2.0, 400.0) as usize,
            ),
        ],
        readouts: vec![
            ReadoutDef::number("k", "selected spring rate k", "N/m", 4, |r| Some(r.k)),
            ReadoutDef::number("c", "selected damper rate c", "N·s/m", 4, |r| Some(r.c)),
            ReadoutDef::number("zeta", "damping ratio ζ", "", 3, |r| r.sel.zeta),
            ReadoutDef::number(
                "settling_time",
                "settling time into the ± band of x₀ (free response)",
                "s",
                4,
                |r| r.sel.settling_time,
            ),
            ReadoutDef::number(
                "overshoot",
                "peak rebound, % of x₀ (free response)",
                "%",
                3,
                |r| r.sel.overshoot,
            ),
            // Plain: accelerations stay in m/s² (no "mm/s²").
            // The road and speed written beside the value, as the label cannot vary.
            ReadoutDef::formatted(
                "accel_rms",
                "a_w: RMS body acceleration weighted by ISO 2631-1 W_k (two-DOF car, \
                 stationary on the ISO 8608 road at speed V)",
                "m/s²",
                |r| {
                    let a = r.sel.accel_rms?;
                    Some((a, text::with_road(a, &r.key)))
                },
            ),
            ReadoutDef::formatted(
                "accel_unweighted",
                "RMS body acceleration, unweighted (same car and road)",
                "m/s²",
                |r| {
                    let a = r.sel.ride?.rms_body_acceleration;
                    Some((a, text::with_road(a, &r.key)))
                },
            ),
            ReadoutDef::formatted("grid_size", "grid size (cells)", "", |r| {
                Some(((r.grid * r.grid) as f64, text::grid_size(r)))
            }),
            // Plain: the value is already in ms (an SI prefix would give "µms").
            ReadoutDef::plain("compute_time", "sweep compute time", "ms", 3, |r| {
                Some(r.sweep_ms)
            }),
        ],
        plots: vec![
            PlotSpec {
                key: "map",
                title: figures::MAP_TITLE,
                aspect: 1.35,
            },
            PlotSpec {
                key: "pareto",
                title: figures::PARETO_TITLE,
                aspect: 1.35,
            },
            PlotSpec {
                key: "response",
                title: figures::RESPONSE_TITLE,
                aspect: 1.35,
            },
        ],
        presets: presets(),
        ..Declaration::new("design", "Design space (k, c)", text::SUMMARY)
    }
}

/// The quarter car's sprung-mass slider `m` \[kg\] (100–800 kg, 300 kg), with its label;
/// the `uncertainty` demo's suspension declares the same.
pub(in crate::demos) fn sprung_mass<Q: 'static>(
    label: &'static str,
    set: fn(&mut Q, f64),
) -> Param<Q> {
    Param::linear("m", label, "m", "kg", (100.0, 800.0, 1.0), 300.0, set)
}

/// The preset buttons.
fn presets() -> Vec<Preset> {
    vec![
        Preset {
            label: "Settling-time map, 300 kg, ζ ≈ 0.37",
            values: vec![
                ("m", 300.0),
                ("metric", 0.0),
                ("k", 24_000.0),
                ("c", 2_000.0),
            ],
        },
        Preset {
            label: "Laden car 500 kg, same parts",
            values: vec![
                ("m", 500.0),
                ("metric", 0.0),
                ("k", 24_000.0),
                ("c", 2_000.0),
            ],
        },
        Preset {
            label: "Comfort map on a class C road",
            values: vec![("metric", 2.0), ("road", 2.0), ("m", 300.0)],
        },
        Preset {
            label: "Peak-rebound map, ζ = 0.7 design",
            values: vec![
                ("metric", 1.0),
                ("m", 300.0),
                ("k", 24_000.0),
                ("c", 3_760.0),
            ],
        },
        Preset {
            label: "Fine grid 160 × 160",
            values: vec![("n", 160.0), ("metric", 0.0)],
        },
    ]
}
