//! `nonlinear`: the quarter car beyond the linear model — a Duffing spring, an asymmetric
//! damper, Coulomb friction and bump stops, integrated with RK4 and drawn against the
//! linear model from the same initial state (all maths in [`zeta_solver::nonlinear`]).
//!
//! Cost per update is bounded: `STEPS` RK4 steps into buffers kept between updates.
//! Coulomb friction is the solver's smooth `F_c·tanh(x'/v_ε)`; this demo picks
//! `v_ε = max(1 mm/s, F_c·h/m)` so that one step `h` never exceeds the friction layer's time
//! constant `m·v_ε/F_c` (RK4 stays stable and the "stuck" mass creeps by at most a few mm).

// Not yet reshaped: still does maths the solver should do (issue "one shape").
#![allow(clippy::disallowed_methods)]

use super::{Demo, Frame, Readout};
use crate::figure::{
    finite_extent, padded, Axis, Dash, Figure, LineStyle, Marker, MarkerShape, Series,
};
use crate::format::si;
use crate::params::Params;
use crate::plot::Ink;
use crate::schematic::{mass_spring_damper, MassLabels};
use crate::spec::{DemoSpec, ParamSpec, PlotSpec, Preset, ReadoutSpec, Table};
use zeta_solver::integrate::{IntegrationError, Solution, Stats};
use zeta_solver::nonlinear::{Comparison, NonlinearConfig, NonlinearModel, Sticking};
use zeta_solver::FreeResponse;

/// RK4 steps per update (the brief's budget is ≤ 4000).
const STEPS: usize = 3600;
/// Every `STRIDE`-th state is plotted (≤ ~1000 points per curve).
const STRIDE: usize = 4;
/// Undamped linear periods shown.
const PERIODS: f64 = 5.0;
/// Travel beyond which a trajectory counts as escaped (a softening spring that gave way) \[m\].
const ESCAPE: f64 = 1.0;
/// Points of the force curves.
const CURVE: usize = 241;
/// Smallest friction regularisation velocity \[m/s\].
const V_EPS_MIN: f64 = 1e-3;

const EQUATION: &str = "<math display=\"block\"><mrow>\
<mi>m</mi><mover><mi>x</mi><mo>¨</mo></mover><mo>+</mo>\
<msub><mi>F</mi><mi>d</mi></msub><mo>(</mo><mover><mi>x</mi><mo>˙</mo></mover><mo>)</mo><mo>+</mo>\
<msub><mi>F</mi><mi>c</mi></msub><mi>sgn</mi><mo>(</mo><mover><mi>x</mi><mo>˙</mo></mover><mo>)</mo>\
<mo>+</mo><mi>k</mi><mi>x</mi><mo>+</mo><msub><mi>k</mi><mn>3</mn></msub><msup><mi>x</mi><mn>3</mn></msup>\
<mo>+</mo><msub><mi>F</mi><mtext>stop</mtext></msub><mo>(</mo><mi>x</mi><mo>)</mo><mo>=</mo><mn>0</mn>\
</mrow></math>";

/// The nonlinear quarter-car demo. Keeps its trajectory buffers between updates.
#[derive(Debug, Clone)]
pub struct Nonlinear {
    cmp: Comparison,
    /// Whether the last run escaped (or became non-finite) and was cut short.
    escaped: bool,
    sticking: Option<Sticking>,
}

impl Default for Nonlinear {
    fn default() -> Self {
        Self {
            cmp: Comparison {
                t: Vec::with_capacity(STEPS + 1),
                nonlinear: Vec::with_capacity(STEPS + 1),
                linear: Vec::with_capacity(STEPS + 1),
            },
            escaped: false,
            sticking: None,
        }
    }
}

/// The model, step and initial state the parameters describe.
struct Setup {
    model: NonlinearModel,
    h: f64,
    x0: f64,
    v0: f64,
}

fn setup(params: &Params) -> Option<Setup> {
    let (m, k) = (params.get("m"), params.get("k"));
    let friction = params.get("friction");
    let t_lin = std::f64::consts::TAU * (m / k).sqrt();
    let h = PERIODS * t_lin / STEPS as f64;
    if !(h.is_finite() && h > 0.0) {
        return None;
    }
    let model = NonlinearModel::new(NonlinearConfig {
        mass: m,
        k,
        k3: params.get("k3"),
        c_compression: params.get("c_comp"),
        c_rebound: params.get("c_reb"),
        friction,
        friction_velocity: V_EPS_MIN.max(friction * h / m),
        stop_gap: params.get("gap"),
        stop_stiffness: params.get("k_stop"),
    })
    .ok()?;
    Some(Setup {
        model,
        h,
        x0: params.get("x0"),
        v0: params.get("v0"),
    })
}

/// Which departure from the linear model dominates (the table's row key).
fn effect(cfg: &NonlinearConfig, max_travel: f64, escaped: bool) -> &'static str {
    if escaped {
        return "escaped";
    }
    let mut found = Vec::with_capacity(5);
    if cfg.k3 > 0.0 {
        found.push("hardening spring");
    }
    if cfg.k3 < 0.0 {
        found.push("softening spring");
    }
    if cfg.friction > 0.0 {
        found.push("stick-slip");
    }
    if cfg.stop_stiffness > 0.0 && max_travel > cfg.stop_gap {
        found.push("bump-stop impact");
    }
    if cfg.c_compression != cfg.c_rebound {
        found.push("asymmetric damper");
    }
    match found.as_slice() {
        [] => "linear",
        [one] => one,
        _ => "several at once",
    }
}

fn preset(label: &'static str, changes: &[(&'static str, f64)]) -> Preset {
    let mut values = vec![
        ("m", 300.0),
        ("k", 24_000.0),
        ("k3", 0.0),
        ("c_comp", 500.0),
        ("c_reb", 500.0),
        ("friction", 0.0),
        ("gap", 0.06),
        ("k_stop", 0.0),
        ("x0", 0.08),
        ("v0", 0.0),
    ];
    for &(key, v) in changes {
        if let Some(slot) = values.iter_mut().find(|(k, _)| *k == key) {
            slot.1 = v;
        }
    }
    Preset { label, values }
}

fn readout_spec(key: &'static str, label: &'static str, unit: &'static str) -> ReadoutSpec {
    ReadoutSpec { key, label, unit }
}

impl Demo for Nonlinear {
    fn spec(&self) -> DemoSpec {
        DemoSpec {
            id: "nonlinear",
            title: "Beyond the linear model",
            summary: "A real suspension is only linear for small motions. Here the quarter car \
                      gets a cubic spring (k₃ > 0 hardening, k₃ < 0 softening), a damper that is \
                      stiffer in rebound (x′ > 0) than in compression, Coulomb friction in the \
                      joints and rubber bump stops beyond ±gap. The motion is integrated with RK4 \
                      and drawn against the linear model m·x″ + c̄·x′ + k·x = 0 (c̄ the mean damper \
                      rate) from the same start. Watch where the prediction fails: the period \
                      depends on the amplitude (hardening shortens it, softening lengthens it), \
                      friction makes the amplitude fall in a straight line and then holds the \
                      mass off-centre (stick–slip), a bump stop turns a smooth swing into an \
                      impact, and an asymmetric damper shifts the mean position. x is the \
                      suspension extension from static equilibrium (positive = body up).",
            equation_mathml: EQUATION,
            params: vec![
                ParamSpec::linear("m", "sprung mass", "m", "kg", (100.0, 600.0, 1.0), 300.0),
                ParamSpec::linear(
                    "k",
                    "linear spring rate",
                    "k",
                    "N/m",
                    (5_000.0, 60_000.0, 100.0),
                    24_000.0,
                ),
                ParamSpec::linear(
                    "k3",
                    "cubic spring coefficient (+ hardening, − softening)",
                    "k₃",
                    "N/m³",
                    (-4.0e6, 4.0e6, 10_000.0),
                    3.0e6,
                ),
                ParamSpec::linear(
                    "c_comp",
                    "damper rate in compression",
                    "c_c",
                    "N·s/m",
                    (0.0, 6_000.0, 10.0),
                    150.0,
                ),
                ParamSpec::linear(
                    "c_reb",
                    "damper rate in rebound",
                    "c_r",
                    "N·s/m",
                    (0.0, 6_000.0, 10.0),
                    150.0,
                ),
                ParamSpec::linear(
                    "friction",
                    "Coulomb friction force",
                    "F_c",
                    "N",
                    (0.0, 1_500.0, 10.0),
                    0.0,
                ),
                ParamSpec::linear(
                    "gap",
                    "bump-stop clearance",
                    "gap",
                    "m",
                    (0.01, 0.2, 0.001),
                    0.06,
                ),
                ParamSpec::linear(
                    "k_stop",
                    "bump-stop rate (0 = no stops)",
                    "k_stop",
                    "N/m",
                    (0.0, 500_000.0, 1_000.0),
                    0.0,
                ),
                ParamSpec::linear(
                    "x0",
                    "initial extension",
                    "x₀",
                    "m",
                    (-0.15, 0.15, 0.001),
                    0.08,
                ),
                ParamSpec::linear(
                    "v0",
                    "initial velocity",
                    "v₀",
                    "m/s",
                    (-2.0, 2.0, 0.01),
                    0.0,
                ),
            ],
            readouts: vec![
                readout_spec("effect", "dominant nonlinearity", ""),
                readout_spec("period_ratio", "period ratio T_nonlinear / T_linear", ""),
                readout_spec("max_deviation", "largest |x_nonlinear − x_linear|", "m"),
                readout_spec("period_nonlinear", "nonlinear period", "s"),
                readout_spec("period_linear", "linear period", "s"),
                readout_spec("max_travel", "largest |x| (nonlinear)", "m"),
                readout_spec("stick_position", "friction holds the mass at", "m"),
            ],
            plots: vec![
                PlotSpec {
                    key: "response",
                    title: "Nonlinear and linear response x(t)",
                    aspect: 2.0,
                },
                PlotSpec {
                    key: "phase",
                    title: "Phase plane (x, v)",
                    aspect: 1.25,
                },
                PlotSpec {
                    key: "spring",
                    title: "Spring and bump-stop force",
                    aspect: 2.0,
                },
                PlotSpec {
                    key: "damper",
                    title: "Damper and friction force",
                    aspect: 1.25,
                },
            ],
            primary_plot: "",
            presets: vec![
                preset("Linear (all off)", &[]),
                preset(
                    "Hardening spring",
                    &[("k3", 3.0e6), ("c_comp", 150.0), ("c_reb", 150.0)],
                ),
                preset(
                    "Softening spring",
                    &[("k3", -2.0e6), ("c_comp", 150.0), ("c_reb", 150.0)],
                ),
                preset(
                    "Friction stick–slip",
                    &[("friction", 300.0), ("c_comp", 50.0), ("c_reb", 50.0)],
                ),
                preset(
                    "Bump-stop impact",
                    &[
                        ("k_stop", 300_000.0),
                        ("gap", 0.05),
                        ("x0", 0.0),
                        ("v0", 1.5),
                    ],
                ),
                preset(
                    "Asymmetric damper",
                    &[("c_comp", 300.0), ("c_reb", 1_500.0)],
                ),
            ],
            table: Some(Table {
                caption: "Where the linear model fails",
                columns: vec![
                    "nonlinearity",
                    "force law",
                    "what the linear model misses",
                    "signature in the plots",
                ],
                rows: vec![
                    (
                        "linear",
                        vec![
                            "None (linear)",
                            "k·x + c·x′",
                            "nothing: the model is exact",
                            "the two curves coincide",
                        ],
                    ),
                    (
                        "hardening spring",
                        vec![
                            "Hardening spring",
                            "k·x + k₃·x³, k₃ > 0",
                            "frequency rises with amplitude",
                            "shorter period while the swing is large; the curves drift apart",
                        ],
                    ),
                    (
                        "softening spring",
                        vec![
                            "Softening spring",
                            "k·x + k₃·x³, k₃ < 0",
                            "frequency falls with amplitude; past √(−k/k₃) the spring gives way",
                            "longer period; a large start can escape",
                        ],
                    ),
                    (
                        "stick-slip",
                        vec![
                            "Coulomb friction",
                            "F_c·sgn(x′)",
                            "amplitude falls by about 4F_c/k per cycle, in a straight line, then \
                             the mass sticks where |k·x| ≤ F_c",
                            "straight-line envelope; a flat end off zero",
                        ],
                    ),
                    (
                        "bump-stop impact",
                        vec![
                            "Bump stops",
                            "k_stop·(|x| − gap) beyond ±gap",
                            "a sudden stiff contact: large force, fast reversal",
                            "clipped peaks at ±gap; kinks in the phase loop",
                        ],
                    ),
                    (
                        "asymmetric damper",
                        vec![
                            "Asymmetric damper",
                            "c_r·x′ in rebound, c_c·x′ in compression",
                            "a mean shift (jacking) and unequal half-cycles",
                            "lopsided decay; the phase spiral is off-centre",
                        ],
                    ),
                    (
                        "several at once",
                        vec![
                            "Several at once",
                            "sum of the above",
                            "their effects add and interact",
                            "see each row",
                        ],
                    ),
                    (
                        "escaped",
                        vec![
                            "Softening spring past its limit",
                            "k·x + k₃·x³ < 0 for |x| > √(−k/k₃)",
                            "the model stops describing a suspension",
                            "the run is cut where |x| exceeds 1 m",
                        ],
                    ),
                ],
                highlight_readout: "effect",
            }),
            schematic: true,
        }
    }

    fn update(&mut self, params: &Params) -> Frame {
        let Some(s) = setup(params) else {
            // Unreachable with validated parameters; still, never panic.
            self.cmp.t.clear();
            self.cmp.nonlinear.clear();
            self.cmp.linear.clear();
            return Frame {
                readouts: vec![
                    Readout::text("effect", "invalid parameters"),
                    Readout::number("period_ratio", None, "", 4),
                    Readout::number("max_deviation", None, "m", 3),
                    Readout::number("period_nonlinear", None, "s", 4),
                    Readout::number("period_linear", None, "s", 4),
                    Readout::number("max_travel", None, "m", 3),
                    Readout::number("stick_position", None, "m", 3),
                ],
                figures: Vec::new(),
                time_span: None,
            };
        };
        self.run(&s);
        self.frame(&s)
    }

    fn schematic(&self, params: &Params, t: f64) -> Option<Figure> {
        let s = setup(params)?;
        let x = self.x_at(t)?;
        let reach = self
            .cmp
            .nonlinear
            .iter()
            .map(|p| p[0].abs())
            .fold(s.x0.abs(), f64::max)
            .max(1e-6);
        let cfg = s.model.config();
        let labels = MassLabels {
            mass: "m",
            spring: "k, k₃",
            damper: "c_c/c_r",
            base: "",
        };
        let stops = if cfg.stop_stiffness > 0.0 {
            if x.abs() > cfg.stop_gap {
                ", pressing on a bump stop"
            } else {
                ", clear of the bump stops"
            }
        } else {
            ""
        };
        let description = format!(
            "Quarter car at t = {}: suspension extended {}{}.",
            si(t, "s", 3),
            si(x, "m", 3),
            stops
        );
        Some(mass_spring_damper(x / reach, 0.0, &labels, description))
    }
}

impl Nonlinear {
    /// Runs the nonlinear model and fills the linear one on the same grid, cutting the run
    /// where it escapes; no allocation after the first update.
    fn run(&mut self, s: &Setup) {
        let n = STEPS + 1;
        let cmp = &mut self.cmp;
        cmp.nonlinear.clear();
        cmp.nonlinear.resize(n, [0.0; 2]);
        let mut valid = match s.model.simulate_into(s.x0, s.v0, s.h, &mut cmp.nonlinear) {
            Ok(()) => n,
            // Slot i holds the state at i·h; the failing step was the one to `t`.
            Err(IntegrationError::NonFinite { t }) => ((t / s.h).round() as usize).min(n),
            Err(_) => 0,
        };
        self.escaped = valid < n;
        if let Some(i) = cmp.nonlinear[..valid]
            .iter()
            .position(|p| p[0].is_nan() || p[0].abs() > ESCAPE)
        {
            valid = i;
            self.escaped = true;
        }
        cmp.nonlinear.truncate(valid);
        cmp.t.clear();
        cmp.t.extend((0..valid).map(|i| i as f64 * s.h));
        cmp.linear.clear();
        match s.model.linear_model() {
            Ok(sys) => {
                let lin = FreeResponse::new(sys, s.x0, s.v0);
                cmp.linear.extend(cmp.t.iter().map(|&t| lin.state(t)));
            }
            Err(_) => cmp.linear.resize(valid, [f64::NAN; 2]),
        }
        // `sticking` reads a `Solution`: lend it the buffers and take them back.
        let sol = Solution {
            t: std::mem::take(&mut cmp.t),
            y: std::mem::take(&mut cmp.nonlinear),
            stats: Stats::default(),
        };
        self.sticking = s.model.sticking(&sol);
        cmp.t = sol.t;
        cmp.nonlinear = sol.y;
    }

    /// Nonlinear displacement at `t` \[s\], linearly interpolated on the last run's grid.
    fn x_at(&self, t: f64) -> Option<f64> {
        let (ts, xs) = (&self.cmp.t, &self.cmp.nonlinear);
        let last = ts.len().checked_sub(1)?;
        let h = if last > 0 { ts[1] - ts[0] } else { 1.0 };
        let f = (t / h).clamp(0.0, last as f64);
        let i = (f.floor() as usize).min(last);
        let j = (i + 1).min(last);
        let w = f - i as f64;
        Some(xs[i][0] * (1.0 - w) + xs[j][0] * w)
    }

    fn frame(&self, s: &Setup) -> Frame {
        let cmp = &self.cmp;
        let cfg = s.model.config();
        let max_travel = finite_extent(cmp.nonlinear.iter().map(|p| p[0].abs())).map(|e| e.1);
        let effect = effect(&cfg, max_travel.unwrap_or(0.0), self.escaped);
        let deviation = (!cmp.t.is_empty()).then(|| cmp.max_deviation());
        let readouts = vec![
            Readout::text("effect", effect),
            Readout::number("period_ratio", cmp.period_ratio(), "", 4),
            Readout::number("max_deviation", deviation, "m", 3),
            Readout::number("period_nonlinear", cmp.period_nonlinear(), "s", 4),
            Readout::number("period_linear", cmp.period_linear(), "s", 4),
            Readout::number("max_travel", max_travel, "m", 3),
            Readout::number("stick_position", self.sticking.map(|st| st.x), "m", 3),
        ];
        let t_end = STEPS as f64 * s.h;
        Frame {
            readouts,
            figures: vec![
                self.response_figure(&cfg, effect, t_end),
                self.phase_figure(),
                spring_figure(&s.model, max_travel.unwrap_or(0.0)),
                damper_figure(&s.model, cmp),
            ],
            time_span: Some((0.0, t_end)),
        }
    }

    fn response_figure(&self, cfg: &NonlinearConfig, effect: &str, t_end: f64) -> Figure {
        let cmp = &self.cmp;
        let nl: Vec<(f64, f64)> = decimate(&cmp.t, &cmp.nonlinear, 0);
        let lin: Vec<(f64, f64)> = decimate(&cmp.t, &cmp.linear, 0);
        let (lo, hi) =
            finite_extent(nl.iter().chain(&lin).map(|p| p.1).chain([0.0])).unwrap_or((-0.1, 0.1));
        let mut y = padded((lo, hi.max(lo + 1e-6)), 0.1);
        y.1 += 0.25 * (y.1 - y.0); // room for the legend
        let mut series = Vec::with_capacity(4);
        let mut markers = Vec::new();
        if cfg.stop_stiffness > 0.0 {
            for (sign, label) in [
                (1.0, format!("bump stops ±{}", si(cfg.stop_gap, "m", 3))),
                (-1.0, String::new()),
            ] {
                series.push(Series {
                    label,
                    points: vec![(0.0, sign * cfg.stop_gap), (t_end, sign * cfg.stop_gap)],
                    style: LineStyle {
                        ink: Ink::Purple,
                        dash: Dash::Dotted,
                        width: 1.5,
                    },
                });
            }
        }
        series.push(Series {
            label: "linear model".into(),
            points: lin,
            style: LineStyle {
                ink: Ink::Vermillion,
                dash: Dash::Dashed,
                width: 2.0,
            },
        });
        series.push(Series {
            label: "nonlinear (RK4)".into(),
            points: nl,
            style: LineStyle::solid(Ink::Blue, 2.5),
        });
        if let Some(st) = self.sticking {
            markers.push(Marker {
                label: "sticks".into(),
                at: (st.t, st.x),
                shape: MarkerShape::Dot,
                ink: Ink::Green,
            });
        }
        let worst = cmp
            .nonlinear
            .iter()
            .zip(&cmp.linear)
            .zip(&cmp.t)
            .map(|((a, b), &t)| ((a[0] - b[0]).abs(), t))
            .filter(|d| d.0.is_finite())
            .fold((0.0, 0.0), |acc, d| if d.0 > acc.0 { d } else { acc });
        let periods = match (cmp.period_nonlinear(), cmp.period_linear()) {
            (Some(a), Some(b)) => format!(
                "; period {} against the linear {} (ratio {})",
                si(a, "s", 3),
                si(b, "s", 3),
                si(a / b, "", 3)
            ),
            _ => String::new(),
        };
        let stick = self.sticking.map_or(String::new(), |st| {
            format!(
                "; friction holds the mass at {} from {}",
                si(st.x, "m", 3),
                si(st.t, "s", 3)
            )
        });
        let escape = if self.escaped {
            format!(
                "; the nonlinear run leaves the plot (|x| > {}) at {}",
                si(ESCAPE, "m", 2),
                si(cmp.t.last().copied().unwrap_or(0.0), "s", 3)
            )
        } else {
            String::new()
        };
        let description = format!(
            "{effect}: both start together; they differ by up to {} at t = {}{periods}{stick}{escape}.",
            si(worst.0, "m", 3),
            si(worst.1, "s", 3),
        );
        Figure {
            description,
            series,
            markers,
            origin_lines: true,
            ..Figure::plot(
                "Nonlinear and linear response x(t)",
                Axis::linear("time t", "s", (0.0, t_end)),
                Axis::linear("extension x", "m", y),
            )
        }
    }

    fn phase_figure(&self) -> Figure {
        let cmp = &self.cmp;
        let nl: Vec<(f64, f64)> = phase_points(&cmp.nonlinear);
        let lin: Vec<(f64, f64)> = phase_points(&cmp.linear);
        let xs =
            finite_extent(nl.iter().chain(&lin).map(|p| p.0).chain([0.0])).unwrap_or((-0.1, 0.1));
        let vs =
            finite_extent(nl.iter().chain(&lin).map(|p| p.1).chain([0.0])).unwrap_or((-1.0, 1.0));
        let x = padded((xs.0, xs.1.max(xs.0 + 1e-6)), 0.08);
        let mut y = padded((vs.0, vs.1.max(vs.0 + 1e-6)), 0.08);
        y.1 += 0.3 * (y.1 - y.0); // room for the legend
        let end = |pts: &[(f64, f64)]| pts.last().copied().unwrap_or((0.0, 0.0));
        let (ne, le) = (end(&nl), end(&lin));
        let description = format!(
            "Phase plane: both trajectories start at x = {}, v = {}. The linear one spirals in \
             towards ({}, {}); the nonlinear one ends at x = {}, v = {}, its largest speed {} \
             against the linear {}.",
            si(nl.first().map_or(0.0, |p| p.0), "m", 3),
            si(nl.first().map_or(0.0, |p| p.1), "m/s", 3),
            si(le.0, "m", 2),
            si(le.1, "m/s", 2),
            si(ne.0, "m", 3),
            si(ne.1, "m/s", 3),
            si(nl.iter().map(|p| p.1.abs()).fold(0.0, f64::max), "m/s", 3),
            si(lin.iter().map(|p| p.1.abs()).fold(0.0, f64::max), "m/s", 3),
        );
        let start = nl.first().copied();
        Figure {
            description,
            series: vec![
                Series {
                    label: "linear model".into(),
                    points: lin,
                    style: LineStyle {
                        ink: Ink::Vermillion,
                        dash: Dash::Dashed,
                        width: 2.0,
                    },
                },
                Series {
                    label: "nonlinear (RK4)".into(),
                    points: nl,
                    style: LineStyle::solid(Ink::Blue, 2.0),
                },
            ],
            markers: start
                .map(|p| Marker {
                    label: "start".into(),
                    at: p,
                    shape: MarkerShape::Dot,
                    ink: Ink::Black,
                })
                .into_iter()
                .collect(),
            origin_lines: true,
            ..Figure::plot(
                "Phase plane (x, v)",
                Axis::linear("extension x", "m", x),
                Axis::linear("velocity v", "m/s", y),
            )
        }
    }
}

/// Every [`STRIDE`]-th `(t, state[component])`, always including the last point.
fn decimate(t: &[f64], states: &[[f64; 2]], component: usize) -> Vec<(f64, f64)> {
    let n = t.len().min(states.len());
    let mut out: Vec<(f64, f64)> = (0..n)
        .step_by(STRIDE)
        .map(|i| (t[i], states[i][component]))
        .collect();
    if n > 0 && !(n - 1).is_multiple_of(STRIDE) {
        out.push((t[n - 1], states[n - 1][component]));
    }
    out
}

/// Every [`STRIDE`]-th `(x, v)`, always including the last point.
fn phase_points(states: &[[f64; 2]]) -> Vec<(f64, f64)> {
    let n = states.len();
    let mut out: Vec<(f64, f64)> = states
        .iter()
        .step_by(STRIDE)
        .map(|s| (s[0], s[1]))
        .collect();
    if n > 0 && !(n - 1).is_multiple_of(STRIDE) {
        out.push((states[n - 1][0], states[n - 1][1]));
    }
    out
}

fn spring_figure(model: &NonlinearModel, max_travel: f64) -> Figure {
    let cfg = model.config();
    let mut reach = max_travel.max(0.02);
    if cfg.stop_stiffness > 0.0 {
        reach = reach.max(1.3 * cfg.stop_gap);
    }
    let reach = reach.min(ESCAPE) * 1.15;
    let sample = |f: &dyn Fn(f64) -> f64| -> Vec<(f64, f64)> {
        (0..CURVE)
            .map(|i| {
                let x = -reach + 2.0 * reach * i as f64 / (CURVE - 1) as f64;
                (x, f(x))
            })
            .collect()
    };
    let nl = sample(&|x| model.elastic_force(x));
    let lin = sample(&|x| cfg.k * x);
    let (lo, hi) = finite_extent(nl.iter().chain(&lin).map(|p| p.1)).unwrap_or((-1.0, 1.0));
    let mut y = padded((lo, hi.max(lo + 1e-6)), 0.08);
    y.1 += 0.3 * (y.1 - y.0);
    let at = max_travel.max(1e-6);
    let description = format!(
        "Restoring force against extension over ±{}: the linear spring is the straight line \
         k·x; at the largest travel {} the nonlinear force is {} against the linear {}{}.",
        si(reach, "m", 3),
        si(at, "m", 3),
        si(model.elastic_force(at), "N", 3),
        si(cfg.k * at, "N", 3),
        if cfg.stop_stiffness > 0.0 {
            format!(
                ", the bump stops adding {} beyond ±{}",
                si(cfg.stop_stiffness, "N/m", 3),
                si(cfg.stop_gap, "m", 3)
            )
        } else {
            String::new()
        }
    );
    Figure {
        description,
        series: vec![
            Series {
                label: "linear k·x".into(),
                points: lin,
                style: LineStyle {
                    ink: Ink::Vermillion,
                    dash: Dash::Dashed,
                    width: 2.0,
                },
            },
            Series {
                label: "k·x + k₃·x³ + stops".into(),
                points: nl,
                style: LineStyle::solid(Ink::Blue, 2.5),
            },
        ],
        origin_lines: true,
        ..Figure::plot(
            "Spring and bump-stop force",
            Axis::linear("extension x", "m", (-reach, reach)),
            Axis::linear("force F", "N", y),
        )
    }
}

fn damper_figure(model: &NonlinearModel, cmp: &Comparison) -> Figure {
    let cfg = model.config();
    let vmax = finite_extent(cmp.nonlinear.iter().chain(&cmp.linear).map(|p| p[1].abs()))
        .map_or(0.5, |e| e.1)
        .clamp(0.05, 10.0)
        * 1.15;
    let c_mean = 0.5 * (cfg.c_compression + cfg.c_rebound);
    let sample = |f: &dyn Fn(f64) -> f64| -> Vec<(f64, f64)> {
        (0..CURVE)
            .map(|i| {
                let v = -vmax + 2.0 * vmax * i as f64 / (CURVE - 1) as f64;
                (v, f(v))
            })
            .collect()
    };
    let nl = sample(&|v| model.dissipative_force(v));
    let lin = sample(&|v| c_mean * v);
    let (lo, hi) =
        finite_extent(nl.iter().chain(&lin).map(|p| p.1).chain([0.0])).unwrap_or((-1.0, 1.0));
    let mut y = padded((lo, hi.max(lo + 1e-6)), 0.08);
    y.1 += 0.3 * (y.1 - y.0);
    let description = format!(
        "Damper plus friction force against velocity over ±{}: at +{} (rebound) it is {}, at \
         −{} (compression) {}; the linear model's mean damper gives ±{}{}.",
        si(vmax, "m/s", 3),
        si(vmax, "m/s", 3),
        si(model.dissipative_force(vmax), "N", 3),
        si(vmax, "m/s", 3),
        si(model.dissipative_force(-vmax), "N", 3),
        si(c_mean * vmax, "N", 3),
        if cfg.friction > 0.0 {
            format!(
                "; friction adds a jump of ±{} at v = 0 (smoothed over {})",
                si(cfg.friction, "N", 3),
                si(cfg.friction_velocity, "m/s", 2)
            )
        } else {
            String::new()
        }
    );
    Figure {
        description,
        series: vec![
            Series {
                label: "linear c̄·v".into(),
                points: lin,
                style: LineStyle {
                    ink: Ink::Vermillion,
                    dash: Dash::Dashed,
                    width: 2.0,
                },
            },
            Series {
                label: "damper + friction".into(),
                points: nl,
                style: LineStyle::solid(Ink::Blue, 2.5),
            },
        ],
        origin_lines: true,
        ..Figure::plot(
            "Damper and friction force",
            Axis::linear("velocity v (+ rebound)", "m/s", (-vmax, vmax)),
            Axis::linear("force F", "N", y),
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn run(query: &str) -> Frame {
        let mut d = Nonlinear::default();
        let spec = d.spec();
        let (p, notices) = crate::params::resolve_query(&spec, query);
        assert!(notices.is_empty(), "{notices:?}");
        d.update(&p)
    }

    fn value(f: &Frame, key: &str) -> String {
        f.readouts
            .iter()
            .find(|r| r.key == key)
            .map(|r| r.data_value.clone())
            .unwrap()
    }

    fn num(f: &Frame, key: &str) -> f64 {
        value(f, key).parse().unwrap()
    }

    fn preset_query(label: &str) -> String {
        let spec = Nonlinear::default().spec();
        let p = spec.presets.iter().find(|p| p.label == label).unwrap();
        p.values
            .iter()
            .map(|(k, v)| format!("{k}={v}"))
            .collect::<Vec<_>>()
            .join("&")
    }

    #[test]
    fn linear_settings_reproduce_the_linear_model() {
        let f = run(&preset_query("Linear (all off)"));
        assert_eq!(value(&f, "effect"), "linear");
        assert!((num(&f, "period_ratio") - 1.0).abs() < 1e-6);
        // RK4 with ~720 steps per period against the closed form.
        assert!(
            num(&f, "max_deviation") < 1e-8,
            "{}",
            num(&f, "max_deviation")
        );
        let wn = (24_000.0f64 / 300.0).sqrt();
        let c = 500.0 / (2.0 * (300.0f64 * 24_000.0).sqrt());
        let td = std::f64::consts::TAU / (wn * (1.0 - c * c).sqrt());
        assert!((num(&f, "period_linear") - td).abs() < 1e-4 * td);
    }

    #[test]
    fn each_preset_shows_its_effect() {
        let hard = run(&preset_query("Hardening spring"));
        assert_eq!(value(&hard, "effect"), "hardening spring");
        assert!(num(&hard, "period_ratio") < 0.95);
        let soft = run(&preset_query("Softening spring"));
        assert_eq!(value(&soft, "effect"), "softening spring");
        assert!(num(&soft, "period_ratio") > 1.03);
        let fric = run(&preset_query("Friction stick–slip"));
        assert_eq!(value(&fric, "effect"), "stick-slip");
        let x = num(&fric, "stick_position");
        assert!(x.abs() <= 300.0 / 24_000.0 + 1e-9, "{x}");
        assert!(x.abs() > 1e-4, "{x}");
        let stop = run(&preset_query("Bump-stop impact"));
        assert_eq!(value(&stop, "effect"), "bump-stop impact");
        let travel = num(&stop, "max_travel");
        let linear_reach = 1.5 / (24_000.0f64 / 300.0).sqrt();
        assert!(travel > 0.05 && travel < linear_reach, "{travel}");
        let asym = run(&preset_query("Asymmetric damper"));
        assert_eq!(value(&asym, "effect"), "asymmetric damper");
        assert!(num(&asym, "max_deviation") > 1e-3);
        for f in [&hard, &soft, &fric, &stop, &asym] {
            assert!(f.figures.iter().all(|g| g.has_visible_data()));
        }
    }

    #[test]
    fn a_softening_spring_past_its_limit_escapes_without_panicking() {
        let f = run("k3=-4000000&x0=0.15&v0=2&c_comp=0&c_reb=0&k=5000");
        assert_eq!(value(&f, "effect"), "escaped");
        assert!(f.figures[0].description.contains("leaves the plot"));
        assert!(f.readouts.iter().all(|r| !r.data_value.contains("NaN")));
    }

    #[test]
    fn the_schematic_follows_the_run() {
        let mut d = Nonlinear::default();
        let spec = d.spec();
        let p = Params::defaults(&spec);
        d.update(&p);
        let a = d.schematic(&p, 0.0).unwrap();
        let b = d.schematic(&p, 0.3).unwrap();
        assert_ne!(a.description, b.description);
        assert!(a.description.contains("80.0 mm"), "{}", a.description);
    }

    #[test]
    fn every_table_row_is_a_possible_effect() {
        let spec = Nonlinear::default().spec();
        let table = spec.table.unwrap();
        for label in [
            "Linear (all off)",
            "Hardening spring",
            "Softening spring",
            "Friction stick–slip",
            "Bump-stop impact",
            "Asymmetric damper",
        ] {
            let e = value(&run(&preset_query(label)), "effect");
            assert!(table.rows.iter().any(|(k, _)| *k == e), "{e}");
        }
        assert!(table
            .rows
            .iter()
            .all(|(_, c)| c.len() == table.columns.len()));
    }
}
