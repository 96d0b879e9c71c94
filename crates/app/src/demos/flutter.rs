//! `flutter`: the Tacoma Narrows bridge as single-degree-of-freedom torsional flutter.
//!
//! One torsional mode `θ'' + 2ζ_eff(U)·ω·θ' + ω²·θ = 0` with `ζ_eff(U) = ζ_s − g·U`
//! (all maths in [`zeta_solver::flutter`]). Plots: the effective damping against wind
//! speed with the critical speed, the root locus as the wind rises, and the twist `θ(t)`;
//! a table contrasts self-excited flutter with forced resonance; the schematic is the deck
//! cross-section twisting in the wind.
//!
//! Units: `U` in m/s, `omega` in rad/s, `slope` in s/m (damping ratio lost per m/s of
//! wind), `theta0` in **degrees** (the only non-SI parameter, for readability; readouts
//! stay SI).

// Not yet reshaped: still does maths the solver should do (issue "one shape").
#![allow(clippy::disallowed_methods)]

use super::{Demo, Frame, Readout};
use crate::figure::{
    finite_extent, padded, Axis, Dash, Figure, FigureKind, LineStyle, Marker, MarkerShape, Series,
};
use crate::format::si;
use crate::params::Params;
use crate::plot::Ink;
use crate::spec::{DemoSpec, ParamSpec, PlotSpec, Preset, ReadoutSpec, Table};
use zeta_solver::flutter::{
    FlutterConfig, FlutterModel, LocusPoint, TACOMA_FAILURE_WIND, TACOMA_STRUCTURAL_DAMPING,
};
use zeta_solver::{FreeResponse, Regime};

/// Samples of the time response (≈ 16 per period over [`PERIODS`] periods).
const SAMPLES: usize = 1000;
/// Torsional periods shown in the time response and the animation.
const PERIODS: f64 = 60.0;
/// Samples of the damping line and the root locus.
const LOCUS_SAMPLES: usize = 201;
/// Highest wind speed on the slider and the plots \[m/s\].
const U_MAX: f64 = 40.0;
/// Largest drawn twist of the deck in the schematic \[deg\].
const DRAWN_MAX_DEG: f64 = 30.0;
/// Metres per second in one mile per hour.
const MPH: f64 = 0.447_04;

const EQUATION: &str = "<math display=\"block\"><mtable>\
<mtr><mtd><mover><mi>θ</mi><mo>¨</mo></mover><mo>+</mo><mn>2</mn>\
<msub><mi>ζ</mi><mtext>eff</mtext></msub><mo>(</mo><mi>U</mi><mo>)</mo><mi>ω</mi>\
<mover><mi>θ</mi><mo>˙</mo></mover><mo>+</mo><msup><mi>ω</mi><mn>2</mn></msup><mi>θ</mi>\
<mo>=</mo><mn>0</mn></mtd></mtr>\
<mtr><mtd><msub><mi>ζ</mi><mtext>eff</mtext></msub><mo>(</mo><mi>U</mi><mo>)</mo><mo>=</mo>\
<msub><mi>ζ</mi><mi>s</mi></msub><mo>−</mo><mi>g</mi><mi>U</mi></mtd></mtr></mtable></math>";

/// The Tacoma Narrows flutter demo. Keeps its root-locus buffer between updates.
#[derive(Debug, Clone, Default)]
pub struct Flutter {
    locus: Vec<LocusPoint>,
}

/// The model, wind speed \[m/s\] and initial twist \[rad\] the parameters describe.
struct Setup {
    model: FlutterModel,
    u: f64,
    theta0: f64,
}

fn setup(params: &Params) -> Option<Setup> {
    let model = FlutterModel::new(FlutterConfig {
        omega: params.get("omega"),
        structural_damping: params.get("zeta_s"),
        aero_slope: params.get("slope"),
    })
    .ok()?;
    Some(Setup {
        model,
        u: params.get("U"),
        theta0: params.get("theta0").to_radians(),
    })
}

/// Length of the time window \[s\]: [`PERIODS`] undamped torsional periods.
fn window(model: &FlutterModel) -> f64 {
    PERIODS * std::f64::consts::TAU / model.config().omega
}

/// Amplitude `A` \[rad\] of the oscillation `θ = A·e^{σt}·cos(ω_d t − φ)` from `θ(0) = θ0`,
/// `θ'(0) = 0` (the envelope drawn around the response).
fn amplitude(model: &FlutterModel, u: f64, theta0: f64) -> f64 {
    let sigma = model.growth_rate(u);
    match model.damped_frequency(u) {
        Some(wd) if wd > 0.0 => (theta0 * theta0 + (sigma * theta0 / wd).powi(2)).sqrt(),
        _ => theta0.abs(),
    }
}

fn tacoma_preset(label: &'static str, u: f64) -> Preset {
    let c = FlutterConfig::tacoma_1940();
    Preset {
        label,
        values: vec![
            ("U", u),
            ("zeta_s", c.structural_damping),
            ("omega", c.omega),
            ("slope", c.aero_slope),
            ("theta0", 2.0),
        ],
    }
}

impl Demo for Flutter {
    fn spec(&self) -> DemoSpec {
        let tacoma = FlutterConfig::tacoma_1940();
        DemoSpec {
            id: "flutter",
            title: "Flutter: the Tacoma Narrows bridge",
            summary: "A steady wind can feed a twisting bridge deck energy through its own \
                      motion: the aerodynamic moment follows the twist rate, acting as negative \
                      damping. The structure's damping ratio ζ_s is eaten away as the wind \
                      speed U rises, ζ_eff = ζ_s − g·U, until at the critical speed U_crit = \
                      ζ_s/g it reaches zero: the poles cross the imaginary axis and any small \
                      twist grows like e^(σt) at the deck's own torsional frequency. This is not \
                      resonance. Forced resonance needs a force that oscillates near the natural \
                      frequency, and its amplitude stays bounded (by the damping); a steady wind \
                      has no frequency to match, and flutter needs none — the motion makes its \
                      own forcing, so above U_crit there is no bounded steady state at all, and \
                      more damping only raises U_crit. Teaching model: Scanlan's A2* term alone, \
                      linear in U; preset values are approximate (≈ 0.2 Hz torsion, ζ_s = 0.5 % \
                      assumed, U_crit set to the ≈ 42 mph of 7 November 1940).",
            equation_mathml: EQUATION,
            params: vec![
                ParamSpec::linear("U", "wind speed", "U", "m/s", (0.0, U_MAX, 0.1), 10.0),
                ParamSpec::linear(
                    "zeta_s",
                    "structural damping ratio",
                    "ζ_s",
                    "",
                    (0.0, 0.05, 0.0005),
                    TACOMA_STRUCTURAL_DAMPING,
                ),
                ParamSpec::linear(
                    "omega",
                    "torsional natural frequency",
                    "ω",
                    "rad/s",
                    (0.2, 6.0, 0.001),
                    tacoma.omega,
                ),
                ParamSpec::linear(
                    "slope",
                    "aerodynamic slope (damping lost per m/s)",
                    "g",
                    "s/m",
                    (0.0, 0.001, 0.000_001),
                    tacoma.aero_slope,
                ),
                ParamSpec::linear("theta0", "initial twist", "θ₀", "°", (0.1, 10.0, 0.1), 2.0),
            ],
            readouts: vec![
                ReadoutSpec {
                    key: "zeta_eff",
                    label: "effective damping ratio ζ_eff",
                    unit: "",
                },
                ReadoutSpec {
                    key: "U_crit",
                    label: "critical (flutter) speed U_crit",
                    unit: "m/s",
                },
                ReadoutSpec {
                    key: "growth_rate",
                    label: "growth rate σ (< 0 decays)",
                    unit: "1/s",
                },
                ReadoutSpec {
                    key: "regime",
                    label: "regime",
                    unit: "",
                },
                ReadoutSpec {
                    key: "doubling_time",
                    label: "amplitude doubles every",
                    unit: "s",
                },
                ReadoutSpec {
                    key: "amplitude_end",
                    label: "twist amplitude at the end of the plot",
                    unit: "rad",
                },
            ],
            plots: vec![
                PlotSpec {
                    key: "damping",
                    title: "Effective damping against wind speed",
                    aspect: 2.0,
                },
                PlotSpec {
                    key: "locus",
                    title: "Root locus as the wind rises",
                    aspect: 1.25,
                },
                PlotSpec {
                    key: "response",
                    title: "Deck twist θ(t)",
                    aspect: 2.2,
                },
            ],
            primary_plot: "",
            presets: vec![
                tacoma_preset("Tacoma 1940, 10 m/s (stable)", 10.0),
                tacoma_preset("Tacoma 1940 at U_crit", TACOMA_FAILURE_WIND),
                tacoma_preset("Tacoma 1940, 19 m/s (failure day, ≈ 42 mph)", 19.0),
                tacoma_preset("Tacoma 1940, 30 m/s gale", 30.0),
            ],
            table: Some(Table {
                caption: "Flutter is not resonance",
                columns: vec![
                    "case",
                    "what drives it",
                    "frequency",
                    "damping",
                    "amplitude",
                    "cure",
                ],
                rows: vec![
                    (
                        "resonance",
                        vec![
                            "Forced resonance (for contrast)",
                            "an outside force oscillating near ωₙ (marching feet, an engine)",
                            "set by the force; must match ωₙ",
                            "positive: limits the peak to about 1/(2ζ) × static",
                            "bounded steady state",
                            "detune, or add damping",
                        ],
                    ),
                    (
                        "underdamped",
                        vec![
                            "Wind below U_crit",
                            "steady wind; moment ∝ twist rate",
                            "the deck's own ω_d",
                            "ζ_eff = ζ_s − gU > 0",
                            "a twist dies away",
                            "—",
                        ],
                    ),
                    (
                        "undamped",
                        vec![
                            "At U_crit",
                            "steady wind; moment ∝ twist rate",
                            "the deck's own ω",
                            "ζ_eff = 0: poles on the imaginary axis",
                            "a twist persists unchanged",
                            "—",
                        ],
                    ),
                    (
                        "negatively damped",
                        vec![
                            "Flutter, wind above U_crit",
                            "steady wind; the motion makes its own forcing",
                            "the deck's own ω_d, no matching needed",
                            "ζ_eff < 0: energy flows in every cycle",
                            "grows like e^(σt) until something breaks",
                            "raise U_crit: stiffer, streamlined, open deck",
                        ],
                    ),
                ],
                highlight_readout: "regime",
            }),
            schematic: true,
        }
    }

    fn update(&mut self, params: &Params) -> Frame {
        match setup(params) {
            Some(s) => self.frame(&s),
            // Unreachable with validated parameters; still, never panic.
            None => Frame {
                readouts: vec![
                    Readout::number("zeta_eff", None, "", 3),
                    Readout::number("U_crit", None, "m/s", 4),
                    Readout::number("growth_rate", None, "1/s", 3),
                    Readout::text("regime", "invalid parameters"),
                    Readout::number("doubling_time", None, "s", 3),
                    Readout::number("amplitude_end", None, "rad", 3),
                ],
                figures: Vec::new(),
                time_span: None,
            },
        }
    }

    fn schematic(&self, params: &Params, t: f64) -> Option<Figure> {
        let s = setup(params)?;
        let resp = s.model.response(s.u, s.theta0, 0.0).ok()?;
        let t_end = window(&s.model);
        let theta = resp.displacement(t);
        // Largest |θ| on the window: the envelope at its larger end.
        let sigma = s.model.growth_rate(s.u);
        let peak = amplitude(&s.model, s.u, s.theta0) * (sigma * t_end).exp().max(1.0);
        let gain = if peak > 0.0 && peak.is_finite() {
            DRAWN_MAX_DEG.to_radians() / peak
        } else {
            1.0
        };
        Some(deck_figure(theta, gain, s.u, t))
    }
}

impl Flutter {
    fn frame(&mut self, s: &Setup) -> Frame {
        let m = &s.model;
        let zeta = m.effective_damping(s.u);
        let sigma = m.growth_rate(s.u);
        let regime = m.regime(s.u).ok();
        let doubling = (regime == Some(Regime::NegativelyDamped) && sigma > 0.0)
            .then(|| std::f64::consts::LN_2 / sigma);
        let readouts = vec![
            Readout::number("zeta_eff", Some(zeta), "", 3),
            Readout::number("U_crit", m.critical_speed(), "m/s", 4),
            Readout::number("growth_rate", Some(sigma), "1/s", 3),
            Readout::text(
                "regime",
                regime.map_or("invalid parameters", |r: Regime| r.key()),
            ),
            Readout::number("doubling_time", doubling, "s", 3),
            Readout::number(
                "amplitude_end",
                Some(amplitude(m, s.u, s.theta0) * (sigma * window(m)).exp()),
                "rad",
                3,
            ),
        ];
        self.locus.resize(LOCUS_SAMPLES, LocusPoint::default());
        let locus_ok = m.root_locus_into(0.0, U_MAX, &mut self.locus).is_ok();
        let locus: &[LocusPoint] = if locus_ok { &self.locus } else { &[] };
        Frame {
            readouts,
            figures: vec![
                damping_figure(m, s.u),
                locus_figure(m, s.u, locus),
                response_figure(m, s.u, s.theta0),
            ],
            time_span: Some((0.0, window(m))),
        }
    }
}

fn speed_text(u: f64) -> String {
    format!("{} ({} mph)", si(u, "m/s", 3), si(u / MPH, "", 3))
}

fn damping_figure(m: &FlutterModel, u: f64) -> Figure {
    let line: Vec<(f64, f64)> = (0..LOCUS_SAMPLES)
        .map(|i| {
            let ui = U_MAX * i as f64 / (LOCUS_SAMPLES - 1) as f64;
            (ui, m.effective_damping(ui))
        })
        .collect();
    let zeta = m.effective_damping(u);
    let (lo, hi) = finite_extent(line.iter().map(|p| p.1).chain([0.0])).unwrap_or((-0.01, 0.01));
    let y = padded((lo, hi.max(lo + 1e-4)), 0.1);
    let mut series = vec![Series {
        label: "ζ_eff(U) = ζ_s − g·U".into(),
        points: line,
        style: LineStyle::solid(Ink::Blue, 2.5),
    }];
    let mut markers = vec![Marker {
        label: format!("U = {}", si(u, "m/s", 3)),
        at: (u, zeta),
        shape: MarkerShape::Dot,
        ink: Ink::Vermillion,
    }];
    let crit = m.critical_speed();
    let crit_text = match crit {
        Some(uc) if uc <= U_MAX => {
            series.push(Series {
                label: format!("U_crit = {}", si(uc, "m/s", 3)),
                points: vec![(uc, y.0), (uc, y.1)],
                style: LineStyle {
                    ink: Ink::Purple,
                    dash: Dash::Dashed,
                    width: 1.5,
                },
            });
            markers.push(Marker {
                label: String::new(),
                at: (uc, 0.0),
                shape: MarkerShape::Cross,
                ink: Ink::Purple,
            });
            format!("crosses zero at the critical speed {}", speed_text(uc))
        }
        Some(uc) => format!(
            "would cross zero only at {}, beyond the plotted {}",
            si(uc, "m/s", 3),
            si(U_MAX, "m/s", 3)
        ),
        None => "never crosses zero: the wind does not remove damping (g = 0)".to_string(),
    };
    let side = if zeta > 0.0 {
        "positive (stable)"
    } else if zeta < 0.0 {
        "negative (flutter)"
    } else {
        "zero"
    };
    let description = format!(
        "Effective damping ratio falls in a straight line from ζ_s = {} at no wind; it {}. \
         At U = {} it is {}, {}.",
        si(m.config().structural_damping, "", 3),
        crit_text,
        si(u, "m/s", 3),
        si(zeta, "", 3),
        side
    );
    Figure {
        description,
        series,
        markers,
        origin_lines: true,
        ..Figure::plot(
            "Effective damping against wind speed",
            Axis::linear("wind speed U", "m/s", (0.0, U_MAX)),
            Axis::linear("effective damping ratio ζ_eff", "", y),
        )
    }
}

fn locus_figure(m: &FlutterModel, u: f64, locus: &[LocusPoint]) -> Figure {
    let upper: Vec<(f64, f64)> = locus
        .iter()
        .map(|p| {
            let s = if p.poles[0].im >= p.poles[1].im {
                p.poles[0]
            } else {
                p.poles[1]
            };
            (s.re, s.im)
        })
        .collect();
    let lower: Vec<(f64, f64)> = upper.iter().map(|&(re, im)| (re, -im)).collect();
    let w = m.config().omega;
    let (re_lo, re_hi) =
        finite_extent(upper.iter().map(|p| p.0).chain([0.0])).unwrap_or((-0.01 * w, 0.01 * w));
    let x = padded((re_lo, re_hi.max(re_lo + 1e-6 * w)), 0.15);
    // Taller above than below, so the legend in the upper right clears the upper branch.
    let y = (-1.5 * w, 2.2 * w);
    let mut markers = Vec::new();
    if let Some(&start) = upper.first() {
        markers.push(Marker {
            label: "U = 0".into(),
            at: start,
            shape: MarkerShape::Dot,
            ink: Ink::Green,
        });
    }
    let poles = m.poles(u).ok();
    if let Some(p) = poles {
        for (i, s) in p.iter().enumerate() {
            markers.push(Marker {
                label: if i == 0 {
                    format!("U = {}", si(u, "m/s", 3))
                } else {
                    String::new()
                },
                at: (s.re, s.im),
                shape: MarkerShape::Cross,
                ink: Ink::Vermillion,
            });
        }
    }
    let crossing = m
        .critical_speed()
        .filter(|&uc| uc <= U_MAX)
        .and_then(|uc| m.damped_frequency(uc));
    if let Some(wd) = crossing {
        markers.push(Marker {
            label: "U_crit".into(),
            at: (0.0, -wd),
            shape: MarkerShape::Dot,
            ink: Ink::Purple,
        });
    }
    let where_now = match poles {
        Some(p) => {
            let s = if p[0].im >= p[1].im { p[0] } else { p[1] };
            format!(
                "At U = {} the poles are {} ± {}i 1/s, in the {} half-plane.",
                si(u, "m/s", 3),
                si(s.re, "", 3),
                si(s.im.abs(), "", 4),
                if s.re > 0.0 {
                    "right (unstable)"
                } else {
                    "left (stable)"
                }
            )
        }
        None => String::new(),
    };
    let description = format!(
        "As the wind rises from 0 to {} the complex pole pair moves horizontally, at almost \
         constant frequency ±{} rad/s, from real part {} 1/s{}. {}",
        si(U_MAX, "m/s", 3),
        si(w, "", 4),
        si(upper.first().map_or(f64::NAN, |p| p.0), "", 3),
        match crossing {
            Some(_) => " across the imaginary axis at U_crit",
            None => ", never crossing the imaginary axis",
        },
        where_now
    );
    let style = |dash| LineStyle {
        ink: Ink::Blue,
        dash,
        width: 2.5,
    };
    Figure {
        description,
        series: vec![
            Series {
                label: "upper pole".into(),
                points: upper,
                style: style(Dash::Solid),
            },
            Series {
                label: "lower pole".into(),
                points: lower,
                style: style(Dash::Dashed),
            },
        ],
        markers,
        origin_lines: true,
        ..Figure::plot(
            "Root locus as the wind rises",
            Axis::linear("real part Re s", "1/s", x),
            Axis::linear("imaginary part Im s", "rad/s", y),
        )
    }
}

fn response_figure(m: &FlutterModel, u: f64, theta0: f64) -> Figure {
    let t_end = window(m);
    let title = "Deck twist θ(t)";
    let x = Axis::linear("time t", "s", (0.0, t_end));
    let Ok(resp) = m.response(u, theta0, 0.0) else {
        return Figure {
            description: "No response: invalid parameters.".into(),
            ..Figure::plot(title, x, Axis::linear("twist θ", "°", (-1.0, 1.0)))
        };
    };
    let sigma = m.growth_rate(u);
    let amp = amplitude(m, u, theta0);
    let mut theta = Vec::with_capacity(SAMPLES);
    sample_degrees(&resp, t_end, &mut theta);
    let mut series = Vec::with_capacity(3);
    for (sign, label) in [(1.0, "envelope ±A·e^(σt)"), (-1.0, "")] {
        let env = (0..=100)
            .map(|i| {
                let t = t_end * f64::from(i) / 100.0;
                (t, (sign * amp * (sigma * t).exp()).to_degrees())
            })
            .collect();
        series.push(Series {
            label: label.to_string(),
            points: env,
            style: LineStyle {
                ink: Ink::Vermillion,
                dash: Dash::Dashed,
                width: 1.5,
            },
        });
    }
    let end_factor = (sigma * t_end).exp();
    let (lo, hi) = finite_extent(
        theta
            .iter()
            .map(|p| p.1)
            .chain([amp.to_degrees() * end_factor.max(1.0)]),
    )
    .unwrap_or((-1.0, 1.0));
    let reach = lo.abs().max(hi.abs()).max(1e-9);
    // Head room for the legend above the curve.
    let y = (-1.15 * reach, 1.5 * reach);
    let regime = m.regime(u).map_or("invalid", |r: Regime| r.key());
    let change = if end_factor > 1.0 + 1e-9 {
        format!(
            "grows by a factor {} in {}",
            si(end_factor, "", 3),
            si(t_end, "s", 3)
        )
    } else if end_factor < 1.0 - 1e-9 {
        format!(
            "decays to {} of its start in {}",
            si(100.0 * end_factor, "%", 3),
            si(t_end, "s", 3)
        )
    } else {
        format!("keeps its amplitude over {}", si(t_end, "s", 3))
    };
    let description = format!(
        "{regime}: from an initial twist of {}, the oscillation at {} Hz {}.",
        si(theta0.to_degrees(), "°", 3),
        si(
            m.damped_frequency(u).unwrap_or(f64::NAN) / std::f64::consts::TAU,
            "",
            3
        ),
        change
    );
    series.push(Series {
        label: format!("θ(t), U = {}", si(u, "m/s", 3)),
        points: theta,
        style: LineStyle::solid(Ink::Blue, 2.0),
    });
    Figure {
        description,
        series,
        origin_lines: true,
        ..Figure::plot(title, x, Axis::linear("twist θ", "°", y))
    }
}

/// Fills `out` with `(t, θ(t) in degrees)` at [`SAMPLES`] points over `[0, t_end]`.
fn sample_degrees(resp: &FreeResponse, t_end: f64, out: &mut Vec<(f64, f64)>) {
    out.clear();
    out.extend((0..SAMPLES).map(|i| {
        let t = t_end * i as f64 / (SAMPLES - 1) as f64;
        (t, resp.displacement(t).to_degrees())
    }));
}

/// Rotates `p` by `angle` \[rad\] about the origin.
fn rotate((x, y): (f64, f64), angle: f64) -> (f64, f64) {
    let (s, c) = angle.sin_cos();
    (c * x - s * y, s * x + c * y)
}

fn ink(points: Vec<(f64, f64)>, color: Ink, dash: Dash, width: f64) -> Series {
    Series {
        label: String::new(),
        points,
        style: LineStyle {
            ink: color,
            dash,
            width,
        },
    }
}

fn text(label: String, at: (f64, f64)) -> Marker {
    Marker {
        label,
        at,
        shape: MarkerShape::Label,
        ink: Ink::Black,
    }
}

/// The deck cross-section (an H: the deck plate between two plate girders, like the 1940
/// deck, 12 units wide and 2.4 deep) twisted by `theta·gain` \[rad\], with wind arrows.
fn deck_figure(theta: f64, gain: f64, u: f64, t: f64) -> Figure {
    let drawn = if (theta * gain).is_finite() {
        (theta * gain).clamp(-1.2, 1.2)
    } else {
        0.0
    };
    let shape = |pts: &[(f64, f64)]| pts.iter().map(|&p| rotate(p, drawn)).collect::<Vec<_>>();
    let mut series = vec![
        // Rest position of the deck, for reference.
        ink(vec![(-7.0, 0.0), (7.0, 0.0)], Ink::Black, Dash::Dotted, 1.0),
        // Deck plate with a little thickness.
        ink(
            shape(&[
                (-6.0, -0.15),
                (6.0, -0.15),
                (6.0, 0.15),
                (-6.0, 0.15),
                (-6.0, -0.15),
            ]),
            Ink::Blue,
            Dash::Solid,
            3.0,
        ),
        // The two plate girders (the bluff H-section that made Tacoma prone to flutter).
        ink(
            shape(&[(-6.0, -1.2), (-6.0, 1.2)]),
            Ink::Blue,
            Dash::Solid,
            5.0,
        ),
        ink(
            shape(&[(6.0, -1.2), (6.0, 1.2)]),
            Ink::Blue,
            Dash::Solid,
            5.0,
        ),
    ];
    // Wind arrows from the left, their length following U.
    let len = 0.5 + 3.0 * (u / U_MAX).clamp(0.0, 1.0);
    for y in [-2.0, 0.0, 2.0] {
        let tip = (-8.0, y);
        series.push(ink(vec![(tip.0 - len, y), tip], Ink::Sky, Dash::Solid, 2.5));
        series.push(ink(
            vec![(tip.0 - 0.4, y + 0.3), tip, (tip.0 - 0.4, y - 0.3)],
            Ink::Sky,
            Dash::Solid,
            2.5,
        ));
    }
    // Arc showing the drawn twist angle at the right end.
    let arc: Vec<(f64, f64)> = (0..=20)
        .map(|i| rotate((7.5, 0.0), drawn * f64::from(i) / 20.0))
        .collect();
    series.push(ink(arc, Ink::Vermillion, Dash::Solid, 2.0));
    let shown_gain = if drawn.abs() > 0.0 && theta != 0.0 {
        drawn / theta
    } else {
        gain
    };
    let markers = vec![
        text(format!("wind U = {}", si(u, "m/s", 3)), (-11.5, 3.6)),
        text(
            format!("θ = {}", si(theta.to_degrees(), "°", 3)),
            (3.5, -2.9),
        ),
        text(format!("(drawn × {})", si(shown_gain, "", 2)), (3.5, -3.7)),
        Marker {
            label: String::new(),
            at: (0.0, 0.0),
            shape: MarkerShape::Dot,
            ink: Ink::Black,
        },
    ];
    let description = format!(
        "Bridge deck cross-section at t = {}: twisted {} (drawn {} times larger), wind {} \
         from the left.",
        si(t, "s", 3),
        si(theta.to_degrees(), "°", 3),
        si(shown_gain, "", 2),
        si(u, "m/s", 3)
    );
    Figure {
        kind: FigureKind::Schematic,
        description,
        series,
        markers,
        ..Figure::plot(
            "Deck cross-section",
            Axis::linear("", "", (-12.0, 9.0)),
            Axis::linear("", "", (-4.5, 4.5)),
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn preset_slope() -> f64 {
        FlutterConfig::tacoma_1940().aero_slope
    }

    fn run(query: &str) -> Frame {
        let mut d = Flutter::default();
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

    #[test]
    fn defaults_are_the_1940_bridge_in_a_moderate_wind() {
        let f = run("");
        let uc = num(&f, "U_crit");
        assert!((uc - 18.775_68).abs() < 1e-9, "{uc}");
        let z = num(&f, "zeta_eff");
        assert!((z - (0.005 - preset_slope() * 10.0)).abs() < 1e-15);
        assert!(num(&f, "growth_rate") < 0.0);
        assert_eq!(value(&f, "regime"), "underdamped");
        assert_eq!(value(&f, "doubling_time"), "");
    }

    #[test]
    fn the_poles_cross_at_the_critical_speed() {
        let at = run(&format!("U={TACOMA_FAILURE_WIND}"));
        assert_eq!(value(&at, "regime"), "undamped");
        assert!(num(&at, "zeta_eff").abs() < 1e-12);
        let above = run("U=19");
        assert_eq!(value(&above, "regime"), "negatively damped");
        let sigma = num(&above, "growth_rate");
        let omega = std::f64::consts::TAU * 0.2;
        assert!((sigma - (preset_slope() * 19.0 - 0.005) * omega).abs() < 1e-15);
        assert!((num(&above, "doubling_time") - std::f64::consts::LN_2 / sigma).abs() < 1e-6);
        assert!(above.figures[2].description.contains("grows by a factor"));
        assert!(run("U=10").figures[2].description.contains("decays to"));
    }

    #[test]
    fn no_wind_effect_means_no_critical_speed() {
        let f = run("slope=0&U=40");
        assert_eq!(value(&f, "U_crit"), "");
        assert_eq!(value(&f, "regime"), "underdamped");
        assert!(f.figures[0].description.contains("never crosses zero"));
        assert!(f.figures.iter().all(|fig| fig.has_visible_data()));
    }

    #[test]
    fn the_schematic_twists_with_the_deck() {
        let d = Flutter::default();
        let spec = d.spec();
        let p = Params::defaults(&spec);
        let a = d.schematic(&p, 0.0).unwrap();
        let b = d.schematic(&p, 2.5).unwrap(); // about half a period later
        assert_ne!(a.series[1].points, b.series[1].points);
        assert!(a.description.contains("2.00 °"), "{}", a.description);
        for t in [0.0, 100.0, 1e9] {
            let f = d.schematic(&p, t).unwrap();
            assert!(f
                .series
                .iter()
                .all(|s| s.points.iter().all(|q| q.0.is_finite() && q.1.is_finite())));
        }
    }

    #[test]
    fn the_table_has_a_row_for_every_reachable_regime() {
        let spec = Flutter::default().spec();
        let table = spec.table.unwrap();
        for u in [5.0, TACOMA_FAILURE_WIND, 30.0] {
            let r = value(&run(&format!("U={u}")), "regime");
            assert!(table.rows.iter().any(|(k, _)| *k == r), "{r}");
        }
        assert!(table
            .rows
            .iter()
            .all(|(_, c)| c.len() == table.columns.len()));
    }
}
