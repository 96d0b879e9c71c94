//! `quarter-car-2dof`: sprung (body) and unsprung (wheel) mass on a suspension and a tyre,
//! driven by a bump, a step, a sinusoid or a random ISO 8608 road (all maths in
//! [`zeta_solver::two_dof`]). Plots: body, wheel and road motion; body acceleration; tyre
//! deflection; and the frequency responses with the two modes, body bounce and wheel hop.
//!
//! Cost per update is bounded: at most `MAX_STEPS` RK4 steps into buffers kept between
//! updates, a random road of `ROAD_COMPONENTS` sinusoids rebuilt only when its class, speed
//! or seed changes, and a `FRF_POINTS`-point frequency sweep into a reused buffer.

// Not yet reshaped: still does maths the solver should do (issue "one shape").
#![allow(clippy::disallowed_methods)]

use super::{Demo, Frame, Readout};
use crate::figure::{
    finite_extent, padded, Axis, AxisScale, Dash, Figure, FigureKind, LineStyle, Marker,
    MarkerShape, Series,
};
use crate::format::si;
use crate::params::Params;
use crate::plot::Ink;
use crate::schematic::{damper, rect, spring};
use crate::spec::{DemoSpec, ParamSpec, PlotSpec, Preset, ReadoutSpec};
use std::f64::consts::TAU;
use zeta_solver::integrate::{FixedStep, Rk4, Solution, Stats};
use zeta_solver::two_dof::{
    Frf, IsoClass, RandomRoad, RandomRoadConfig, Road, RunMetrics, TwoDof, TwoDofConfig,
};

/// Most RK4 steps per update.
const MAX_STEPS: usize = 4000;
/// RK4 steps per wheel-hop period (accuracy; stability needs far fewer).
const STEPS_PER_HOP: f64 = 30.0;
/// Every `STRIDE`-th state is plotted once a run exceeds [`PLOT_POINTS`] points.
const PLOT_POINTS: usize = 1000;
/// Most RK4 steps per update on a random road.
const MAX_STEPS_RANDOM: usize = 1500;
/// Sinusoids in the random road.
const ROAD_COMPONENTS: usize = 64;
/// Samples per second of the tabulated random road \[Hz\].
const TABLE_RATE: f64 = 150.0;
/// Temporal frequency band of the random road \[Hz\] (both modes, up to wheel hop).
const ROAD_BAND: (f64, f64) = (0.5, 20.0);
/// Frequencies of the response sweep.
const FRF_POINTS: usize = 320;
/// Sweep range \[Hz\].
const FRF_RANGE: (f64, f64) = (0.1, 60.0);
/// Standard gravity \[m/s²\], for the static tyre deflection.
const G: f64 = 9.806_65;

const ROADS: &[(&str, &str)] = &[
    ("bump", "single bump (1 − cos)"),
    ("step", "step (kerb)"),
    ("sine", "sinusoid"),
    ("random", "random road (ISO 8608)"),
];
const CLASSES: &[(&str, &str)] = &[
    ("A", "A (very good)"),
    ("B", "B (good)"),
    ("C", "C (average)"),
    ("D", "D (poor)"),
    ("E", "E (very poor)"),
    ("F", "F"),
    ("G", "G"),
    ("H", "H"),
];

const EQUATION: &str = "<math display=\"block\"><mtable>\
<mtr><mtd><msub><mi>m</mi><mi>s</mi></msub><msub><mover><mi>z</mi><mo>¨</mo></mover><mi>s</mi></msub>\
<mo>=</mo><mo>−</mo><msub><mi>k</mi><mi>s</mi></msub><mo>(</mo><msub><mi>z</mi><mi>s</mi></msub><mo>−</mo>\
<msub><mi>z</mi><mi>u</mi></msub><mo>)</mo><mo>−</mo><msub><mi>c</mi><mi>s</mi></msub><mo>(</mo>\
<msub><mover><mi>z</mi><mo>˙</mo></mover><mi>s</mi></msub><mo>−</mo>\
<msub><mover><mi>z</mi><mo>˙</mo></mover><mi>u</mi></msub><mo>)</mo></mtd></mtr>\
<mtr><mtd><msub><mi>m</mi><mi>u</mi></msub><msub><mover><mi>z</mi><mo>¨</mo></mover><mi>u</mi></msub>\
<mo>=</mo><msub><mi>k</mi><mi>s</mi></msub><mo>(</mo><msub><mi>z</mi><mi>s</mi></msub><mo>−</mo>\
<msub><mi>z</mi><mi>u</mi></msub><mo>)</mo><mo>+</mo><msub><mi>c</mi><mi>s</mi></msub><mo>(</mo>\
<msub><mover><mi>z</mi><mo>˙</mo></mover><mi>s</mi></msub><mo>−</mo>\
<msub><mover><mi>z</mi><mo>˙</mo></mover><mi>u</mi></msub><mo>)</mo><mo>−</mo><msub><mi>k</mi><mi>t</mi></msub>\
<mo>(</mo><msub><mi>z</mi><mi>u</mi></msub><mo>−</mo><mi>u</mi><mo>(</mo><mi>t</mi><mo>)</mo><mo>)</mo>\
</mtd></mtr></mtable></math>";

/// Key of the cached random road: class index, speed bits, seed.
type RoadKey = (usize, u64, u64);

/// The two-degree-of-freedom quarter-car demo; keeps its buffers between updates.
#[derive(Debug, Clone)]
pub struct QuarterCar2Dof {
    /// States `[z_s, z_u, z_s', z_u']` of the last run, `t = i·h`.
    states: Vec<[f64; 4]>,
    times: Vec<f64>,
    h: f64,
    /// Road height at each grid point.
    road_u: Vec<f64>,
    /// The random road sampled at [`TABLE_RATE`].
    table: Vec<f64>,
    /// States measured from the road surface (random road metrics).
    shifted: Vec<[f64; 4]>,
    road: Road,
    random: Option<(RoadKey, RandomRoad)>,
    omegas: Vec<f64>,
    frf: Vec<Frf>,
}

impl Default for QuarterCar2Dof {
    fn default() -> Self {
        Self {
            states: Vec::with_capacity(MAX_STEPS + 1),
            times: Vec::with_capacity(MAX_STEPS + 1),
            h: 1e-3,
            road_u: Vec::with_capacity(MAX_STEPS + 1),
            table: Vec::new(),
            shifted: Vec::new(),
            road: Road::Flat,
            random: None,
            omegas: Vec::with_capacity(FRF_POINTS),
            frf: Vec::with_capacity(FRF_POINTS),
        }
    }
}

/// Which road the choice selects.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum RoadKind {
    Bump,
    Step,
    Sine,
    Random,
}

impl RoadKind {
    fn from_index(i: f64) -> Self {
        match i.round() as i64 {
            1 => RoadKind::Step,
            2 => RoadKind::Sine,
            3 => RoadKind::Random,
            _ => RoadKind::Bump,
        }
    }
}

fn car(params: &Params) -> Option<TwoDof> {
    TwoDof::new(TwoDofConfig {
        sprung_mass: params.get("ms"),
        unsprung_mass: params.get("mu"),
        k_s: params.get("ks"),
        c_s: params.get("cs"),
        k_t: params.get("kt"),
        c_t: 0.0,
    })
    .ok()
}

fn class(params: &Params) -> (usize, IsoClass) {
    let i = (params.get("class").round().max(0.0) as usize).min(IsoClass::ALL.len() - 1);
    (i, IsoClass::ALL[i])
}

/// Length of the run \[s\]: long enough for the body to settle after a bump or step, a few
/// road periods for a sinusoid.
fn duration(kind: RoadKind, params: &Params) -> f64 {
    match kind {
        RoadKind::Bump => params.get("L") / params.get("V") + 2.5,
        RoadKind::Step => 2.5,
        RoadKind::Sine => (6.0 / params.get("f_road")).clamp(2.5, 6.0),
        RoadKind::Random => 3.0,
    }
}

fn readout_spec(key: &'static str, label: &'static str, unit: &'static str) -> ReadoutSpec {
    ReadoutSpec { key, label, unit }
}

fn preset(label: &'static str, changes: &[(&'static str, f64)]) -> Preset {
    let mut values = vec![
        ("ms", 300.0),
        ("mu", 40.0),
        ("ks", 24_000.0),
        ("kt", 200_000.0),
        ("cs", 1_500.0),
    ];
    values.extend_from_slice(changes);
    Preset { label, values }
}

impl Demo for QuarterCar2Dof {
    fn spec(&self) -> DemoSpec {
        DemoSpec {
            id: "quarter-car-2dof",
            title: "Quarter car with body and wheel",
            summary: "Two masses, two modes. The body (sprung mass m_s) sits on the suspension \
                      spring k_s and damper c_s; the wheel (unsprung mass m_u) sits on the tyre \
                      spring k_t, which follows the road u(t). Body bounce, around 1–1.5 Hz, is \
                      the body moving on the soft suspension; wheel hop, around 10–15 Hz, is the \
                      light wheel bouncing between the stiff tyre and the suspension. The \
                      frequency responses show both: the body follows slow road waves, rides \
                      over fast ones, and shakes most near body bounce; the tyre deflection, \
                      which decides grip, peaks at wheel hop — if it exceeds the static tyre \
                      deflection the tyre leaves the road. Comfort is judged by the RMS body \
                      acceleration, road holding by the RMS tyre deflection (both over the run, \
                      starting from rest). Displacements are from static equilibrium, upward \
                      positive; the random road sums 64 sinusoids with the ISO 8608 spectrum over 0.5–20 Hz.",
            equation_mathml: EQUATION,
            params: vec![
                ParamSpec::linear(
                    "ms",
                    "body (sprung) mass",
                    "m_s",
                    "kg",
                    (100.0, 800.0, 1.0),
                    300.0,
                ),
                ParamSpec::linear(
                    "mu",
                    "wheel (unsprung) mass",
                    "m_u",
                    "kg",
                    (10.0, 150.0, 1.0),
                    40.0,
                ),
                ParamSpec::linear(
                    "ks",
                    "suspension stiffness",
                    "k_s",
                    "N/m",
                    (5_000.0, 80_000.0, 100.0),
                    24_000.0,
                ),
                ParamSpec::linear(
                    "kt",
                    "tyre stiffness",
                    "k_t",
                    "N/m",
                    (50_000.0, 500_000.0, 1_000.0),
                    200_000.0,
                ),
                ParamSpec::linear(
                    "cs",
                    "suspension damping",
                    "c_s",
                    "N·s/m",
                    (0.0, 8_000.0, 10.0),
                    1_500.0,
                ),
                ParamSpec::choice("road", "road input", ROADS, 0),
                ParamSpec::linear(
                    "h",
                    "bump or step height, sine amplitude",
                    "h",
                    "m",
                    (0.005, 0.2, 0.001),
                    0.05,
                ),
                ParamSpec::linear("L", "bump length", "L", "m", (0.1, 5.0, 0.05), 0.5),
                ParamSpec::linear("V", "speed", "V", "m/s", (2.0, 40.0, 0.5), 10.0),
                ParamSpec::log(
                    "f_road",
                    "sine road frequency",
                    "f",
                    "Hz",
                    (0.2, 30.0, 0.01),
                    1.2,
                ),
                ParamSpec::choice("class", "random road class", CLASSES, 2),
                ParamSpec::linear(
                    "seed",
                    "random road seed",
                    "seed",
                    "",
                    (1.0, 999.0, 1.0),
                    1.0,
                ),
            ],
            readouts: vec![
                readout_spec("f_body", "body bounce frequency [Hz]", "Hz"),
                readout_spec("f_wheel", "wheel hop frequency [Hz]", "Hz"),
                readout_spec("rms_body_accel", "RMS body acceleration (comfort)", "m/s²"),
                readout_spec(
                    "rms_tyre_deflection",
                    "RMS tyre deflection (road holding)",
                    "m",
                ),
                readout_spec("max_travel", "largest suspension travel", "m"),
                readout_spec("static_tyre_deflection", "static tyre deflection", "m"),
                readout_spec("rms_road", "RMS road height (random road)", "m"),
                readout_spec("body_gain", "body / road amplitude at the sine frequency", ""),
                readout_spec(
                    "tyre_gain",
                    "tyre deflection / road amplitude at the sine frequency",
                    "",
                ),
            ],
            plots: vec![
                PlotSpec {
                    key: "motion",
                    title: "Body, wheel and road",
                    aspect: 2.0,
                },
                PlotSpec {
                    key: "accel",
                    title: "Body acceleration",
                    aspect: 1.25,
                },
                PlotSpec {
                    key: "frf",
                    title: "Frequency response per unit road height",
                    aspect: 2.0,
                },
                PlotSpec {
                    key: "tyre",
                    title: "Tyre deflection",
                    aspect: 1.25,
                },
            ],
            primary_plot: "",
            presets: vec![
                preset(
                    "Speed bump 5 cm at 10 m/s",
                    &[("road", 0.0), ("h", 0.05), ("L", 0.5), ("V", 10.0)],
                ),
                preset("Kerb step 5 cm", &[("road", 1.0), ("h", 0.05)]),
                preset(
                    "Road wave at body bounce",
                    &[("road", 2.0), ("h", 0.02), ("f_road", 1.25)],
                ),
                preset(
                    "Road wave at wheel hop",
                    &[("road", 2.0), ("h", 0.005), ("f_road", 11.5)],
                ),
                preset(
                    "Random road, class C, 20 m/s",
                    &[("road", 3.0), ("class", 2.0), ("V", 20.0), ("seed", 1.0)],
                ),
                preset(
                    "Soft damper on a poor road",
                    &[
                        ("road", 3.0),
                        ("class", 3.0),
                        ("V", 20.0),
                        ("cs", 500.0),
                        ("seed", 1.0),
                    ],
                ),
            ],
            table: None,
            schematic: true,
        }
    }

    fn update(&mut self, params: &Params) -> Frame {
        let Some(car) = car(params) else {
            // Unreachable with validated parameters; still, never panic.
            self.states.clear();
            self.times.clear();
            return Frame {
                readouts: [
                    ("f_body", "Hz"),
                    ("f_wheel", "Hz"),
                    ("rms_body_accel", "m/s²"),
                    ("rms_tyre_deflection", "m"),
                    ("max_travel", "m"),
                    ("static_tyre_deflection", "m"),
                    ("rms_road", "m"),
                    ("body_gain", ""),
                    ("tyre_gain", ""),
                ]
                .into_iter()
                .map(|(k, u)| Readout::number(k, None, u, 4))
                .collect(),
                figures: Vec::new(),
                time_span: None,
            };
        };
        let kind = RoadKind::from_index(params.get("road"));
        self.set_road(kind, params);
        let [f_body, f_wheel] = car.natural_frequencies_hz();
        let metrics = self.run(&car, duration(kind, params), f_wheel, params);
        self.sweep(&car);
        let cfg = car.config();
        let static_tyre = (cfg.sprung_mass + cfg.unsprung_mass) * G / cfg.k_t;
        let rms_road = match (&self.road, kind) {
            (Road::Random(r), RoadKind::Random) => Some(r.variance().sqrt()),
            _ => None,
        };
        let sine_frf = (kind == RoadKind::Sine).then(|| car.frf(TAU * params.get("f_road")));
        let readouts = vec![
            Readout::number("f_body", Some(f_body), "Hz", 4),
            Readout::number("f_wheel", Some(f_wheel), "Hz", 4),
            Readout::number(
                "rms_body_accel",
                metrics.map(|m| m.rms_body_acceleration),
                "m/s²",
                3,
            ),
            Readout::number(
                "rms_tyre_deflection",
                metrics.map(|m| m.rms_tyre_deflection),
                "m",
                3,
            ),
            Readout::number(
                "max_travel",
                metrics.map(|m| m.max_suspension_travel),
                "m",
                3,
            ),
            Readout::number("static_tyre_deflection", Some(static_tyre), "m", 3),
            Readout::number("rms_road", rms_road, "m", 3),
            Readout::number("body_gain", sine_frf.map(|r| r.body.abs()), "", 4),
            Readout::number(
                "tyre_gain",
                sine_frf.map(|r| r.tyre_deflection.abs()),
                "",
                4,
            ),
        ];
        let t_end = self.times.last().copied().unwrap_or(1.0).max(1e-3);
        let sine = (kind == RoadKind::Sine).then(|| params.get("f_road"));
        Frame {
            readouts,
            figures: vec![
                self.motion_figure(t_end, kind),
                self.accel_figure(&car, t_end, metrics),
                self.frf_figure(f_body, f_wheel, sine),
                self.tyre_figure(t_end, static_tyre, metrics),
            ],
            time_span: Some((0.0, t_end)),
        }
    }

    fn schematic(&self, params: &Params, t: f64) -> Option<Figure> {
        car(params)?;
        let s = self.state_at(t)?;
        let (u, _) = self.road.at(t);
        let reach = self
            .states
            .iter()
            .flat_map(|y| [y[0].abs(), y[1].abs()])
            .fold(u.abs(), f64::max)
            .max(1e-6);
        Some(car_figure(
            s,
            u,
            reach,
            |dt| self.road.at(t + dt).0,
            params.get("V"),
            t,
        ))
    }
}

impl QuarterCar2Dof {
    /// Builds the road; the random road is rebuilt only when its class, speed or seed change.
    fn set_road(&mut self, kind: RoadKind, params: &Params) {
        let h = params.get("h");
        let v = params.get("V");
        self.road = match kind {
            RoadKind::Bump => Road::Bump {
                height: h,
                length: params.get("L"),
                speed: v,
            },
            RoadKind::Step => Road::Step { height: h },
            RoadKind::Sine => Road::Sine {
                amplitude: h,
                frequency_hz: params.get("f_road"),
            },
            RoadKind::Random => {
                let (ci, class) = class(params);
                let seed = params.get("seed").round().max(0.0) as u64;
                let key = (ci, v.to_bits(), seed);
                let cached = match &self.random {
                    Some((k, r)) if *k == key => Some(r.clone()),
                    _ => None,
                };
                let built = cached.or_else(|| {
                    // The spatial frequencies that reach ROAD_BAND at this speed, within
                    // ISO 8608's 0.011–2.83 cycles/m.
                    let n_min = (ROAD_BAND.0 / v).clamp(0.011, 1.0);
                    let n_max = (ROAD_BAND.1 / v).clamp(n_min * 2.0, 2.83);
                    RandomRoad::new(RandomRoadConfig {
                        class,
                        speed: v,
                        n_min,
                        n_max,
                        components: ROAD_COMPONENTS,
                        seed,
                    })
                    .ok()
                });
                match built {
                    Some(r) => {
                        self.random = Some((key, r.clone()));
                        Road::Random(r)
                    }
                    None => Road::Flat,
                }
            }
        };
    }

    /// RK4 from rest over `[0, t_end]` into the reused buffers (step ≤ a thirtieth of the
    /// fastest period, at most `MAX_STEPS` steps); fills the road height at every grid
    /// point and returns the run's metrics.
    ///
    /// A random road costs one sine per component per evaluation, and RK4 evaluates it four
    /// times a step; so it is sampled once on a [`TABLE_RATE`] grid and interpolated (see
    /// [`tabulated`]), and the metrics use the same table.
    fn run(
        &mut self,
        car: &TwoDof,
        t_end: f64,
        f_wheel: f64,
        params: &Params,
    ) -> Option<RunMetrics> {
        let random = matches!(self.road, Road::Random(_));
        let f_fast = if random {
            f_wheel
        } else {
            f_wheel.max(params.get("f_road"))
        };
        let cap = if random { MAX_STEPS_RANDOM } else { MAX_STEPS };
        let h = 1.0 / (STEPS_PER_HOP * f_fast.max(1e-3));
        let n = ((t_end / h).ceil().max(1.0) as usize).min(cap);
        let h = t_end / n as f64;
        self.h = h;
        self.states.clear();
        self.states.resize(n + 1, [0.0; 4]);
        let ok = if random {
            tabulated::fill(&self.road, t_end, &mut self.table);
            let sys = tabulated::Driven::new(car, &self.table, t_end);
            Rk4.solve_into(&sys, [0.0; 4], 0.0, h, &mut self.states)
                .is_ok()
        } else {
            Rk4.solve_into(&car.driven(&self.road), [0.0; 4], 0.0, h, &mut self.states)
                .is_ok()
        };
        if !ok {
            self.states.clear();
        }
        self.times.clear();
        self.times
            .extend((0..self.states.len()).map(|i| i as f64 * h));
        self.road_u.clear();
        if random {
            let table = &self.table;
            self.road_u.extend(
                self.times
                    .iter()
                    .map(|&t| tabulated::height(table, t_end, t)),
            );
        } else {
            let road = &self.road;
            self.road_u.extend(self.times.iter().map(|&t| road.at(t).0));
        }
        // `metrics` reads a `Solution`: lend it the buffers and take them back.
        let (sol, metrics_road) = if random {
            // Heights measured from the road surface under the tyre at each instant: every
            // metric depends only on relative displacements and velocities, so on a flat
            // road these states give the same numbers without re-evaluating the road.
            self.shifted.clear();
            self.shifted.extend(
                self.states
                    .iter()
                    .zip(&self.road_u)
                    .map(|(y, &u)| [y[0] - u, y[1] - u, y[2], y[3]]),
            );
            (
                Solution {
                    t: std::mem::take(&mut self.times),
                    y: std::mem::take(&mut self.shifted),
                    stats: Stats::default(),
                },
                Road::Flat,
            )
        } else {
            (
                Solution {
                    t: std::mem::take(&mut self.times),
                    y: std::mem::take(&mut self.states),
                    stats: Stats::default(),
                },
                self.road.clone(),
            )
        };
        let m = car.metrics(&metrics_road, &sol);
        self.times = sol.t;
        if random {
            self.shifted = sol.y;
        } else {
            self.states = sol.y;
        }
        m
    }

    /// The frequency responses over [`FRF_RANGE`] at log-spaced frequencies.
    fn sweep(&mut self, car: &TwoDof) {
        let (lo, hi) = FRF_RANGE;
        self.omegas.clear();
        self.omegas.extend(
            (0..FRF_POINTS).map(|i| TAU * lo * (hi / lo).powf(i as f64 / (FRF_POINTS - 1) as f64)),
        );
        self.frf.clear();
        self.frf.resize(FRF_POINTS, Frf::default());
        car.frf_into(&self.omegas, &mut self.frf);
    }

    /// The state at `t` \[s\], linearly interpolated on the last run's grid.
    fn state_at(&self, t: f64) -> Option<[f64; 4]> {
        let last = self.states.len().checked_sub(1)?;
        let f = (t / self.h).clamp(0.0, last as f64);
        let i = (f.floor() as usize).min(last);
        let j = (i + 1).min(last);
        let w = f - i as f64;
        let (a, b) = (self.states[i], self.states[j]);
        Some(std::array::from_fn(|k| a[k] * (1.0 - w) + b[k] * w))
    }

    fn stride(&self) -> usize {
        self.states.len().div_ceil(PLOT_POINTS).max(1)
    }

    /// `(t, f(t, state))` at every [`Self::stride`]-th grid point.
    fn sampled(&self, f: impl Fn(f64, &[f64; 4]) -> f64) -> Vec<(f64, f64)> {
        self.times
            .iter()
            .zip(&self.states)
            .step_by(self.stride())
            .map(|(&t, y)| (t, f(t, y)))
            .collect()
    }

    /// `(t, f(state, road height))` at every [`Self::stride`]-th grid point.
    fn sampled_road(&self, f: impl Fn(&[f64; 4], f64) -> f64) -> Vec<(f64, f64)> {
        self.times
            .iter()
            .zip(&self.states)
            .zip(&self.road_u)
            .step_by(self.stride())
            .map(|((&t, y), &u)| (t, f(y, u)))
            .collect()
    }

    fn motion_figure(&self, t_end: f64, kind: RoadKind) -> Figure {
        let road = self.sampled_road(|_, u| u);
        let body = self.sampled(|_, y| y[0]);
        let wheel = self.sampled(|_, y| y[1]);
        let all = road
            .iter()
            .chain(&body)
            .chain(&wheel)
            .map(|p| p.1)
            .chain([0.0]);
        let (lo, hi) = finite_extent(all).unwrap_or((-0.05, 0.05));
        let mut y = padded((lo, hi.max(lo + 1e-6)), 0.08);
        y.1 += 0.35 * (y.1 - y.0); // room for the legend
        let peak = |s: &[(f64, f64)]| {
            s.iter().fold((0.0, 0.0), |acc: (f64, f64), p| {
                if p.1.abs() > acc.1.abs() {
                    (p.0, p.1)
                } else {
                    acc
                }
            })
        };
        let (tb, zb) = peak(&body);
        let (tw, zw) = peak(&wheel);
        let (_, ur) = peak(&road);
        let road_name = match kind {
            RoadKind::Bump => "a bump",
            RoadKind::Step => "a step",
            RoadKind::Sine => "a sinusoidal road",
            RoadKind::Random => "a random road",
        };
        let description = format!(
            "Over {} (largest road height {}), the body moves at most {} (at {}) and the wheel \
             {} (at {}).",
            road_name,
            si(ur, "m", 3),
            si(zb, "m", 3),
            si(tb, "s", 3),
            si(zw, "m", 3),
            si(tw, "s", 3)
        );
        Figure {
            description,
            series: vec![
                Series {
                    label: "road u".into(),
                    points: road,
                    style: LineStyle {
                        ink: Ink::Black,
                        dash: Dash::Dotted,
                        width: 2.0,
                    },
                },
                Series {
                    label: "wheel z_u".into(),
                    points: wheel,
                    style: LineStyle {
                        ink: Ink::Vermillion,
                        dash: Dash::Dashed,
                        width: 1.8,
                    },
                },
                Series {
                    label: "body z_s".into(),
                    points: body,
                    style: LineStyle::solid(Ink::Blue, 2.5),
                },
            ],
            origin_lines: true,
            ..Figure::plot(
                "Body, wheel and road",
                Axis::linear("time t", "s", (0.0, t_end)),
                Axis::linear("height from equilibrium", "m", y),
            )
        }
    }

    fn accel_figure(&self, car: &TwoDof, t_end: f64, m: Option<RunMetrics>) -> Figure {
        let acc = self.sampled(|_, y| car.body_acceleration(y));
        let (lo, hi) = finite_extent(acc.iter().map(|p| p.1).chain([0.0])).unwrap_or((-1.0, 1.0));
        let mut y = padded((lo, hi.max(lo + 1e-6)), 0.08);
        y.1 += 0.2 * (y.1 - y.0);
        let peak = lo.abs().max(hi.abs());
        let rms = m.map(|m| m.rms_body_acceleration);
        let mut series = vec![Series {
            label: "body acceleration".into(),
            points: acc,
            style: LineStyle::solid(Ink::Blue, 2.0),
        }];
        if let Some(r) = rms {
            for (sign, label) in [(1.0, "± RMS".to_string()), (-1.0, String::new())] {
                series.push(Series {
                    label,
                    points: vec![(0.0, sign * r), (t_end, sign * r)],
                    style: LineStyle {
                        ink: Ink::Purple,
                        dash: Dash::Dashed,
                        width: 1.5,
                    },
                });
            }
        }
        let description = format!(
            "Body acceleration peaks at {} ({} g); its RMS over the run is {}.",
            si(peak, "m/s²", 3),
            si(peak / G, "", 2),
            si(rms.unwrap_or(f64::NAN), "m/s²", 3)
        );
        Figure {
            description,
            series,
            origin_lines: true,
            ..Figure::plot(
                "Body acceleration",
                Axis::linear("time t", "s", (0.0, t_end)),
                Axis::linear("acceleration z_s″", "m/s²", y),
            )
        }
    }

    fn tyre_figure(&self, t_end: f64, static_tyre: f64, m: Option<RunMetrics>) -> Figure {
        let defl = self.sampled_road(|y, u| y[1] - u);
        let (lo, hi) =
            finite_extent(defl.iter().map(|p| p.1).chain([0.0])).unwrap_or((-0.01, 0.01));
        let shows_limit = hi > 0.5 * static_tyre;
        let top = if shows_limit { hi.max(static_tyre) } else { hi };
        let mut y = padded((lo, top.max(lo + 1e-6)), 0.08);
        y.1 += 0.3 * (y.1 - y.0);
        let lifted = defl.iter().filter(|p| p.1 > static_tyre).count();
        let mut series = vec![Series {
            label: "z_u − u".into(),
            points: defl,
            style: LineStyle::solid(Ink::Blue, 2.0),
        }];
        if shows_limit {
            series.push(Series {
                label: "lift-off (static deflection)".into(),
                points: vec![(0.0, static_tyre), (t_end, static_tyre)],
                style: LineStyle {
                    ink: Ink::Vermillion,
                    dash: Dash::Dashed,
                    width: 1.5,
                },
            });
        }
        let lift = if lifted > 0 {
            "; it exceeds the static deflection, so the tyre force would be negative: the \
             wheel leaves the road"
                .to_string()
        } else {
            format!(
                "; it stays below the static deflection {}, so the tyre keeps contact",
                si(static_tyre, "m", 3)
            )
        };
        let description = format!(
            "Tyre deflection (wheel above road, positive = tyre unloading) ranges from {} to \
             {}, RMS {}{}.",
            si(lo, "m", 3),
            si(hi, "m", 3),
            si(m.map_or(f64::NAN, |m| m.rms_tyre_deflection), "m", 3),
            lift
        );
        Figure {
            description,
            series,
            origin_lines: true,
            ..Figure::plot(
                "Tyre deflection",
                Axis::linear("time t", "s", (0.0, t_end)),
                Axis::linear("tyre deflection z_u − u", "m", y),
            )
        }
    }

    fn frf_figure(&self, f_body: f64, f_wheel: f64, sine: Option<f64>) -> Figure {
        // Magnitudes clamped into a drawable positive band for the log axis.
        let clampm = |v: f64| {
            if v.is_finite() {
                v.clamp(1e-4, 1e4)
            } else {
                1e4
            }
        };
        let hz = |w: f64| w / TAU;
        let body: Vec<(f64, f64)> = self
            .frf
            .iter()
            .map(|r| (hz(r.omega), clampm(r.body.abs())))
            .collect();
        let tyre: Vec<(f64, f64)> = self
            .frf
            .iter()
            .map(|r| (hz(r.omega), clampm(r.tyre_deflection.abs())))
            .collect();
        let (lo, hi) = finite_extent(body.iter().chain(&tyre).map(|p| p.1)).unwrap_or((1e-3, 10.0));
        // Log axis: strictly positive, from just below the smallest value (the clamp keeps
        // it ≥ 1e-4) to well above the largest, leaving room for the legend.
        let y = ((lo / 1.5).max(1e-4), hi.max(1.5) * 20.0);
        let peak_near = |s: &[(f64, f64)], f: f64| {
            s.iter().filter(|p| p.0 > f / 1.6 && p.0 < f * 1.6).fold(
                (f, 0.0),
                |acc: (f64, f64), p| if p.1 > acc.1 { *p } else { acc },
            )
        };
        let (fb, gb) = peak_near(&body, f_body);
        let (fw, gw) = peak_near(&tyre, f_wheel);
        let at20 = self
            .frf
            .iter()
            .min_by(|a, b| {
                (hz(a.omega) - 20.0)
                    .abs()
                    .total_cmp(&(hz(b.omega) - 20.0).abs())
            })
            .map_or(f64::NAN, |r| r.body.abs());
        let mut series = vec![
            Series {
                label: "body/road".into(),
                points: body,
                style: LineStyle::solid(Ink::Blue, 2.5),
            },
            Series {
                label: "tyre defl./road".into(),
                points: tyre,
                style: LineStyle {
                    ink: Ink::Vermillion,
                    dash: Dash::Dashed,
                    width: 2.0,
                },
            },
        ];
        for (f, label, color) in [
            (
                f_body,
                format!("f_body {}", si(f_body, "Hz", 3)),
                Ink::Green,
            ),
            (
                f_wheel,
                format!("f_wheel {}", si(f_wheel, "Hz", 3)),
                Ink::Purple,
            ),
        ] {
            series.push(Series {
                label,
                points: vec![(f, y.0), (f, y.1)],
                style: LineStyle {
                    ink: color,
                    dash: Dash::Dotted,
                    width: 1.8,
                },
            });
        }
        let mut markers = Vec::new();
        if let Some(f) = sine {
            let g = self
                .frf
                .iter()
                .min_by(|a, b| (hz(a.omega) - f).abs().total_cmp(&(hz(b.omega) - f).abs()))
                .map_or(1.0, |r| clampm(r.body.abs()));
            markers.push(Marker {
                label: "road".into(),
                at: (f, g),
                shape: MarkerShape::Dot,
                ink: Ink::Black,
            });
        }
        let description = format!(
            "Frequency response per unit road height, on log axes. The body follows slow road \
             waves (ratio 1), peaks at {} near body bounce {}, and is isolated above: {} at \
             20 Hz. The tyre deflection peaks at {} near wheel hop {}.",
            si(gb, "", 3),
            si(fb, "Hz", 3),
            si(at20, "", 2),
            si(gw, "", 3),
            si(fw, "Hz", 3)
        );
        Figure {
            description,
            series,
            markers,
            ..Figure::plot(
                "Frequency response per unit road height",
                Axis {
                    scale: AxisScale::Log,
                    ..Axis::linear("frequency f", "Hz", FRF_RANGE)
                },
                Axis {
                    scale: AxisScale::Log,
                    ..Axis::linear("magnitude per unit road height", "", y)
                },
            )
        }
    }
}

/// A random road sampled once and interpolated, so RK4 does not re-sum its sinusoids at
/// every stage.
///
/// Presentation-level speed-up, candidate for the solver (a `Road::Sampled` variant, or a
/// cheaper `RandomRoad` evaluation on a uniform grid by rotating each term's phasor instead
/// of calling `sin_cos`): [`RandomRoad::at`] costs one `sin_cos` per component, and with 64
/// components evaluated at every RK4 stage an update took about 25 ms natively (measured);
/// sampled once at 150 Hz it takes about 0.4 ms.
mod tabulated {
    use super::TABLE_RATE;
    use zeta_solver::integrate::System;
    use zeta_solver::two_dof::{Road, TwoDof};

    /// Fills `out` with the road height at `i/TABLE_RATE` for `0 ≤ i/TABLE_RATE ≤ t_end`.
    pub fn fill(road: &Road, t_end: f64, out: &mut Vec<f64>) {
        let n = (t_end * TABLE_RATE).ceil().max(1.0) as usize;
        out.clear();
        out.extend((0..=n).map(|i| road.at(i as f64 / TABLE_RATE).0));
    }

    /// Road height at `t` \[s\], linear between samples, held beyond the ends.
    pub fn height(table: &[f64], t_end: f64, t: f64) -> f64 {
        let Some(last) = table.len().checked_sub(1) else {
            return 0.0;
        };
        let f = (t.min(t_end) * TABLE_RATE).clamp(0.0, last as f64);
        let i = (f.floor() as usize).min(last);
        let j = (i + 1).min(last);
        let w = f - i as f64;
        table[i] * (1.0 - w) + table[j] * w
    }

    /// The car on the tabulated road. The tyre has no damping in this demo (`c_t = 0`), so
    /// the road enters only through its height: each stage is the solver's own equations
    /// on a road held at the interpolated height (`Road::Step`), no maths repeated here.
    pub struct Driven<'a> {
        car: &'a TwoDof,
        table: &'a [f64],
        t_end: f64,
    }

    impl<'a> Driven<'a> {
        pub fn new(car: &'a TwoDof, table: &'a [f64], t_end: f64) -> Self {
            Self { car, table, t_end }
        }
    }

    impl System<4> for Driven<'_> {
        fn rhs(&self, t: f64, y: &[f64; 4], dy: &mut [f64; 4]) {
            let road = Road::Step {
                height: height(self.table, self.t_end, t),
            };
            self.car.driven(&road).rhs(t.max(0.0), y, dy);
        }
    }

    #[cfg(test)]
    mod tests {
        use super::*;
        use zeta_solver::two_dof::{RandomRoad, RandomRoadConfig, TwoDofConfig};

        #[test]
        fn interpolates_the_samples_and_matches_the_exact_road() {
            let road = Road::Random(
                RandomRoad::new(RandomRoadConfig {
                    components: 32,
                    n_min: 0.025,
                    n_max: 1.0,
                    ..Default::default()
                })
                .unwrap(),
            );
            let mut table = Vec::new();
            fill(&road, 2.0, &mut table);
            assert_eq!(table.len(), 301);
            assert_eq!(height(&table, 2.0, 0.5), road.at(0.5).0);
            // Between samples: within a few % of the road's RMS (content ≤ 20 Hz at 150 Hz).
            let Road::Random(r) = &road else {
                unreachable!()
            };
            let rms = r.variance().sqrt();
            for k in 0..200 {
                let t = 0.003 + 0.01 * f64::from(k);
                assert!((height(&table, 2.0, t) - road.at(t).0).abs() < 0.1 * rms);
            }
            // The tabulated system equals the solver's at a sample time.
            let car = TwoDof::new(TwoDofConfig::default()).unwrap();
            let y = [0.01, -0.02, 0.3, -0.1];
            let (mut a, mut b) = ([0.0; 4], [0.0; 4]);
            Driven::new(&car, &table, 2.0).rhs(0.5, &y, &mut a);
            car.driven(&road).rhs(0.5, &y, &mut b);
            assert_eq!(a, b);
        }
    }
}

fn ink(points: Vec<(f64, f64)>, color: Ink, width: f64) -> Series {
    Series {
        label: String::new(),
        points,
        style: LineStyle::solid(color, width),
    }
}

fn label(text: String, at: (f64, f64)) -> Marker {
    Marker {
        label: text,
        at,
        shape: MarkerShape::Label,
        ink: Ink::Black,
    }
}

/// The quarter car drawn at state `s` over road height `u` (all lengths divided by
/// `reach`, the largest excursion of the run), with the road profile around the tyre
/// (`road(dt)` is the road height `dt` seconds later, i.e. `V·dt` metres ahead).
fn car_figure(
    s: [f64; 4],
    u: f64,
    reach: f64,
    road: impl Fn(f64) -> f64,
    speed: f64,
    t: f64,
) -> Figure {
    let amp = 0.45;
    let norm = |v: f64| {
        if v.is_finite() {
            (v / reach).clamp(-1.3, 1.3) * amp
        } else {
            0.0
        }
    };
    let ground = 0.0;
    let road_y = ground + norm(u);
    let wheel_c = 1.2 + norm(s[1]);
    let body_c = 3.1 + norm(s[0]);
    let (wheel_h, body_h) = (0.5, 0.7);
    let mut series = Vec::with_capacity(16);
    // Road profile: 1 drawing unit per metre along the road, the car moving right.
    let profile: Vec<(f64, f64)> = (0..=60)
        .map(|i| {
            let x = -1.8 + 3.6 * f64::from(i) / 60.0;
            (x, ground + norm(road(x / speed.max(0.1))))
        })
        .collect();
    series.push(ink(profile, Ink::Black, 2.5));
    // Tyre spring from the road to the wheel.
    series.push(ink(
        spring(0.0, road_y, wheel_c - wheel_h / 2.0, 4, 0.15),
        Ink::Vermillion,
        2.5,
    ));
    series.push(ink(
        rect((0.0, wheel_c), 0.9, wheel_h),
        Ink::Vermillion,
        3.0,
    ));
    // Suspension spring (left) and damper (right) from the wheel to the body.
    let (top, bottom) = (body_c - body_h / 2.0, wheel_c + wheel_h / 2.0);
    series.push(ink(spring(-0.4, bottom, top, 5, 0.16), Ink::Blue, 2.5));
    for part in damper(0.4, bottom, top, 0.14) {
        series.push(ink(part, Ink::Green, 2.5));
    }
    series.push(ink(rect((0.0, body_c), 1.8, body_h), Ink::Blue, 3.0));
    // Rest positions, for reference.
    for rest in [1.2, 3.1] {
        series.push(Series {
            label: String::new(),
            points: vec![(1.1, rest), (1.5, rest)],
            style: LineStyle {
                ink: Ink::Black,
                dash: Dash::Dashed,
                width: 1.0,
            },
        });
    }
    let markers = vec![
        label("m_s".into(), (-0.2, body_c + 0.12)),
        label("m_u".into(), (-0.2, wheel_c + 0.1)),
        label("k_s".into(), (-1.15, (top + bottom) / 2.0 + 0.1)),
        label("c_s".into(), (0.62, (top + bottom) / 2.0 + 0.1)),
        label("k_t".into(), (0.25, (road_y + wheel_c) / 2.0 + 0.1)),
        label(format!("→ {}", si(speed, "m/s", 3)), (-1.7, 4.2)),
    ];
    let description = format!(
        "Quarter car at t = {}: body {}, wheel {}, road {} (drawn to a common scale).",
        si(t, "s", 3),
        si(s[0], "m", 3),
        si(s[1], "m", 3),
        si(u, "m", 3)
    );
    Figure {
        kind: FigureKind::Schematic,
        description,
        series,
        markers,
        ..Figure::plot(
            "Schematic",
            Axis::linear("", "", (-1.9, 1.9)),
            Axis::linear("", "", (-0.8, 4.4)),
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn run(query: &str) -> Frame {
        let mut d = QuarterCar2Dof::default();
        let spec = d.spec();
        let (p, notices) = crate::params::resolve_query(&spec, query);
        assert!(notices.is_empty(), "{notices:?}");
        d.update(&p)
    }

    fn num(f: &Frame, key: &str) -> Option<f64> {
        f.readouts
            .iter()
            .find(|r| r.key == key)
            .and_then(|r| r.data_value.parse().ok())
    }

    #[test]
    fn natural_frequencies_are_the_two_modes() {
        let f = run("");
        let fb = num(&f, "f_body").unwrap();
        let fw = num(&f, "f_wheel").unwrap();
        assert!(fb > 1.0 && fb < 1.5, "{fb}");
        assert!(fw > 10.0 && fw < 15.0, "{fw}");
        // det(K − ω²M) = 0: m_s·m_u·λ² − (k_s·m_u + (k_s + k_t)·m_s)·λ + k_s·k_t = 0.
        for f in [fb, fw] {
            let l = (TAU * f).powi(2);
            let det = 300.0 * 40.0 * l * l - (24_000.0 * 40.0 + 224_000.0 * 300.0) * l
                + 24_000.0 * 200_000.0;
            assert!(det.abs() < 1e-9 * 24_000.0 * 200_000.0, "{det}");
        }
    }

    #[test]
    fn every_road_runs_and_draws() {
        for road in ["bump", "step", "sine", "random"] {
            let f = run(&format!("road={road}"));
            assert!(num(&f, "rms_body_accel").unwrap() > 0.0, "{road}");
            assert!(num(&f, "rms_tyre_deflection").unwrap() > 0.0, "{road}");
            assert!(f.figures.iter().all(|g| g.has_visible_data()), "{road}");
            assert_eq!(num(&f, "rms_road").is_some(), road == "random");
        }
    }

    #[test]
    fn a_rougher_road_class_shakes_more() {
        let a = run("road=random&class=A&V=20");
        let e = run("road=random&class=E&V=20");
        // Each class quadruples the PSD: RMS road height and response double per class.
        let ratio = num(&e, "rms_road").unwrap() / num(&a, "rms_road").unwrap();
        assert!((ratio - 16.0).abs() < 1e-9, "{ratio}");
        let acc = num(&e, "rms_body_accel").unwrap() / num(&a, "rms_body_accel").unwrap();
        assert!((acc - 16.0).abs() < 1e-6, "{acc}");
    }

    #[test]
    fn the_step_count_is_capped() {
        let mut d = QuarterCar2Dof::default();
        let spec = d.spec();
        let (p, _) =
            crate::params::resolve_query(&spec, "road=sine&f_road=30&kt=500000&mu=10&h=0.005");
        d.update(&p);
        assert!(d.states.len() <= MAX_STEPS + 1);
        assert!(d.frf.len() == FRF_POINTS);
    }

    #[test]
    fn the_schematic_moves_with_the_run() {
        let mut d = QuarterCar2Dof::default();
        let spec = d.spec();
        let p = Params::defaults(&spec);
        d.update(&p);
        let a = d.schematic(&p, 0.0).unwrap();
        let b = d.schematic(&p, 0.1).unwrap();
        assert_ne!(a.series[0].points, b.series[0].points);
        assert_ne!(a.description, b.description);
    }
}
