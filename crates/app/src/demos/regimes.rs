//! `regimes`: free response of `x'' + 2ζωₙ·x' + ωₙ²·x = 0` in every damping regime, with
//! the two poles in the s-plane, a table of the regimes and an animated mass on a spring.

use super::{Demo, Frame, Readout};
use crate::figure::{
    finite_extent, padded, Axis, Dash, Figure, LineStyle, Marker, MarkerShape, Series,
};
use crate::format::si;
use crate::params::Params;
use crate::schematic::{mass_spring_damper, MassLabels};
use crate::spec::{DemoSpec, ParamSpec, PlotSpec, Preset, ReadoutSpec, Table};
use zeta_solver::metrics::{free::FreeMetrics, SettlingBand};
use zeta_solver::{FreeResponse, Regime, SecondOrder};

/// Samples per curve: smooth at any canvas width up to ~1200 CSS px.
const SAMPLES: usize = 600;
/// Periods of the undamped oscillation shown.
const PERIODS: f64 = 4.0;

/// The damping-regimes demo. Stateless: everything follows from the parameters.
#[derive(Debug, Default, Clone, Copy)]
pub struct Regimes;

const EQUATION: &str = "<math display=\"block\"><mrow>\
<mover><mi>x</mi><mo>¨</mo></mover><mo>+</mo><mn>2</mn><mi>ζ</mi><msub><mi>ω</mi><mi>n</mi></msub>\
<mover><mi>x</mi><mo>˙</mo></mover><mo>+</mo><msubsup><mi>ω</mi><mi>n</mi><mn>2</mn></msubsup><mi>x</mi>\
<mo>=</mo><mn>0</mn></mrow></math>";

/// The system and initial state the parameters describe.
fn model(params: &Params) -> Option<(SecondOrder, f64, f64)> {
    let sys = SecondOrder::from_natural(params.get("wn"), params.get("zeta")).ok()?;
    Some((sys, params.get("x0"), params.get("v0")))
}

fn time_window(sys: &SecondOrder) -> f64 {
    PERIODS * std::f64::consts::TAU / sys.natural_frequency().unwrap_or(1.0)
}

impl Demo for Regimes {
    fn spec(&self) -> DemoSpec {
        DemoSpec {
            id: "regimes",
            title: "Damping regimes",
            summary: "Free response from x(0) = x₀, x′(0) = v₀. The damping ratio ζ decides the \
                      regime: ζ = 0 undamped, 0 < ζ < 1 underdamped, ζ = 1 critically damped, \
                      ζ > 1 overdamped, ζ < 0 negatively damped (the response grows). The poles \
                      s = −ζωₙ ± ωₙ√(ζ² − 1) move around a circle of radius ωₙ, onto the real \
                      axis at ζ = 1 and across the imaginary axis at ζ = 0.",
            equation_mathml: EQUATION,
            params: vec![
                ParamSpec::linear(
                    "wn",
                    "natural frequency",
                    "ωₙ",
                    "rad/s",
                    (0.5, 20.0, 0.01),
                    6.0,
                ),
                ParamSpec::linear("zeta", "damping ratio", "ζ", "", (-0.5, 3.0, 0.01), 0.3),
                ParamSpec::linear(
                    "x0",
                    "initial displacement",
                    "x₀",
                    "m",
                    (-0.1, 0.1, 0.001),
                    0.06,
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
                ReadoutSpec {
                    key: "regime",
                    label: "regime",
                    unit: "",
                },
                ReadoutSpec {
                    key: "wn",
                    label: "natural frequency ωₙ",
                    unit: "rad/s",
                },
                ReadoutSpec {
                    key: "zeta",
                    label: "damping ratio ζ",
                    unit: "",
                },
                ReadoutSpec {
                    key: "wd",
                    label: "damped frequency ω_d",
                    unit: "rad/s",
                },
                ReadoutSpec {
                    key: "pole_re",
                    label: "pole real part",
                    unit: "1/s",
                },
                ReadoutSpec {
                    key: "pole_im",
                    label: "pole imaginary part",
                    unit: "rad/s",
                },
            ],
            plots: vec![
                PlotSpec {
                    key: "response",
                    title: "Free response x(t)",
                    aspect: 1.9,
                },
                PlotSpec {
                    key: "poles",
                    title: "Poles in the s-plane",
                    aspect: 1.25,
                },
            ],
            presets: [
                ("Undamped ζ = 0", 0.0),
                ("Underdamped ζ = 0.2", 0.2),
                ("Critically damped ζ = 1", 1.0),
                ("Overdamped ζ = 2", 2.0),
                ("Negative damping ζ = −0.1", -0.1),
            ]
            .into_iter()
            .map(|(label, z)| Preset {
                label,
                values: vec![("zeta", z), ("x0", 0.06), ("v0", 0.0)],
            })
            .collect(),
            table: Some(Table {
                caption: "The damping regimes",
                columns: vec![
                    "regime",
                    "condition",
                    "roots s₁, s₂",
                    "behaviour",
                    "engineering examples",
                ],
                rows: vec![
                    (
                        "undamped",
                        vec![
                            "Undamped",
                            "ζ = 0",
                            "±iωₙ, on the imaginary axis",
                            "oscillates forever at ωₙ",
                            "ideal pendulum, LC tank circuit",
                        ],
                    ),
                    (
                        "underdamped",
                        vec![
                            "Underdamped",
                            "0 < ζ < 1",
                            "−ζωₙ ± iω_d, complex pair",
                            "decaying oscillation at ω_d",
                            "car suspension (ζ ≈ 0.2–0.7), guitar string",
                        ],
                    ),
                    (
                        "critically damped",
                        vec![
                            "Critically damped",
                            "ζ = 1",
                            "−ωₙ, double real root",
                            "fastest return without oscillating",
                            "door closer, analogue meter needle",
                        ],
                    ),
                    (
                        "overdamped",
                        vec![
                            "Overdamped",
                            "ζ > 1",
                            "two negative real roots",
                            "slow return, no oscillation",
                            "heavy hydraulic damper, thermometer",
                        ],
                    ),
                    (
                        "negatively damped",
                        vec![
                            "Negatively damped",
                            "ζ < 0",
                            "right half-plane",
                            "growing oscillation",
                            "flutter (Tacoma Narrows), squealing brakes",
                        ],
                    ),
                ],
                highlight_readout: "regime",
            }),
            schematic: true,
        }
    }

    fn update(&mut self, params: &Params) -> Frame {
        match model(params) {
            Some((sys, x0, v0)) => frame(&sys, x0, v0),
            // Unreachable with validated parameters; still, never panic.
            None => Frame {
                readouts: vec![
                    Readout::text("regime", "invalid parameters"),
                    Readout::number("wn", None, "rad/s", 4),
                    Readout::number("zeta", None, "", 3),
                    Readout::number("wd", None, "rad/s", 4),
                    Readout::number("pole_re", None, "1/s", 4),
                    Readout::number("pole_im", None, "rad/s", 4),
                ],
                figures: Vec::new(),
                time_span: None,
            },
        }
    }

    fn sonify(&self, params: &Params, t: f64) -> Option<f64> {
        let (sys, x0, v0) = model(params)?;
        let reach = x0.abs().max(v0.abs() / sys.natural_frequency()?).max(1e-9);
        Some(FreeResponse::new(sys, x0, v0).displacement(t) / reach)
    }

    fn schematic(&self, params: &Params, t: f64) -> Option<Figure> {
        let (sys, x0, v0) = model(params)?;
        let resp = FreeResponse::new(sys, x0, v0);
        let wn = sys.natural_frequency().unwrap_or(1.0);
        let reach = x0.abs().max(v0.abs() / wn).max(1e-9);
        let x = resp.displacement(t);
        let labels = MassLabels {
            mass: "m",
            spring: "k",
            damper: "c",
            base: "",
        };
        let description = format!(
            "Mass on a spring and damper at t = {}: displaced {} from rest.",
            si(t, "s", 3),
            si(x, "m", 3)
        );
        Some(mass_spring_damper(x / reach, 0.0, &labels, description))
    }
}

fn frame(sys: &SecondOrder, x0: f64, v0: f64) -> Frame {
    let wn = sys.natural_frequency().unwrap_or(0.0);
    let regime = sys.regime();
    let poles = sys.poles();
    let readouts = vec![
        Readout::text("regime", regime.key()),
        Readout::number("wn", sys.natural_frequency(), "rad/s", 4),
        Readout::number("zeta", sys.damping_ratio(), "", 3),
        Readout::number("wd", sys.damped_frequency(), "rad/s", 4),
        Readout::number("pole_re", Some(poles[0].re), "1/s", 4),
        Readout::number("pole_im", Some(poles[0].im), "rad/s", 4),
    ];
    Frame {
        readouts,
        figures: vec![response_figure(sys, regime, x0, v0), pole_figure(sys, wn)],
        time_span: Some((0.0, time_window(sys))),
    }
}

/// The response described in words, for screen readers and the plot's text alternative.
fn describe(sys: &SecondOrder, regime: Regime, x0: f64, v0: f64) -> String {
    let band = SettlingBand::FREE_DEFAULT;
    match FreeMetrics::exact(sys, x0, v0, band) {
        Some(m) => {
            let settle = m
                .settling_time
                .map(|t| format!("stays within 5 % of rest after {}", si(t, "s", 3)))
                .unwrap_or_else(|| "does not settle".to_string());
            // The solver counts crossings before the response settles into the band.
            let swings = match m.zero_crossings {
                0 => "no swing past equilibrium before settling".to_string(),
                1 => "swings past equilibrium once before settling".to_string(),
                n => format!("swings past equilibrium {n} times before settling"),
            };
            format!(
                "{}: {}, {}, peak rebound {}.",
                regime.key(),
                swings,
                settle,
                si(100.0 * m.peak_rebound, "%", 3)
            )
        }
        None => match regime {
            Regime::Undamped => format!(
                "undamped: oscillates forever with amplitude {} at {}.",
                si(
                    (x0 * x0 + (v0 / sys.natural_frequency().unwrap_or(1.0)).powi(2)).sqrt(),
                    "m",
                    3
                ),
                si(sys.natural_frequency().unwrap_or(0.0), "rad/s", 3)
            ),
            Regime::NegativelyDamped => format!(
                "negatively damped: the response grows without bound, by a factor e every {}.",
                si(1.0 / (-sys.alpha()).max(1e-300), "s", 3)
            ),
            _ => format!("{}: starts at rest at equilibrium.", regime.key()),
        },
    }
}

fn response_figure(sys: &SecondOrder, regime: Regime, x0: f64, v0: f64) -> Figure {
    let wn = sys.natural_frequency().unwrap_or(1.0);
    let t_end = time_window(sys);
    let resp = FreeResponse::new(*sys, x0, v0);
    let points: Vec<(f64, f64)> = (0..SAMPLES)
        .map(|i| {
            let t = t_end * i as f64 / (SAMPLES - 1) as f64;
            (t, resp.displacement(t))
        })
        .collect();
    let mut series = Vec::with_capacity(3);
    // The decay envelope ±A·e^{−αt} of an oscillating response.
    if let Some(wd) = sys.damped_frequency() {
        let alpha = sys.alpha();
        let amp = (x0 * x0 + ((v0 + alpha * x0) / wd).powi(2)).sqrt();
        for (sign, label) in [(1.0, "envelope ±A·e^(−ζωₙt)"), (-1.0, "")] {
            let env = points
                .iter()
                .map(|&(t, _)| (t, sign * amp * (-alpha * t).exp()))
                .collect();
            series.push(Series {
                label: label.to_string(),
                points: env,
                style: LineStyle {
                    color: 1,
                    dash: Dash::Dashed,
                    width: 1.5,
                },
            });
        }
    }
    let floor = x0.abs().max(v0.abs() / wn).max(1e-6);
    let envelope_values = series.iter().flat_map(|s| s.points.iter().map(|p| p.1));
    let (lo, hi) =
        finite_extent(points.iter().map(|p| p.1).chain(envelope_values)).unwrap_or((-floor, floor));
    let y = padded((lo.min(-0.2 * floor), hi.max(0.2 * floor)), 0.08);
    series.push(Series {
        label: format!("x(t), {}", regime.key()),
        points,
        style: LineStyle::solid(0, 2.5),
    });
    Figure {
        description: describe(sys, regime, x0, v0),
        series,
        origin_lines: true,
        ..Figure::plot(
            "Free response x(t)",
            Axis::linear("time t", "s", (0.0, t_end)),
            Axis::linear("displacement x", "m", y),
        )
    }
}

fn pole_figure(sys: &SecondOrder, wn: f64) -> Figure {
    let poles = sys.poles();
    let r = poles.iter().map(|p| p.abs()).fold(wn, f64::max).max(1e-6) * 1.25;
    // The circle |s| = ωₙ on which underdamped poles move as ζ varies.
    let circle: Vec<(f64, f64)> = (0..=180)
        .map(|i| {
            let th = std::f64::consts::TAU * i as f64 / 180.0;
            (wn * th.cos(), wn * th.sin())
        })
        .collect();
    let markers = poles
        .iter()
        .enumerate()
        .map(|(i, p)| Marker {
            label: if i == 0 { "s₁".into() } else { "s₂".into() },
            at: (p.re, p.im),
            shape: MarkerShape::Cross,
            color: 1,
        })
        .collect();
    let side = if poles[0].re > 0.0 {
        "right (unstable)"
    } else {
        "left (stable)"
    };
    let description = format!(
        "Poles at {} {} {}i and {} {} {}i 1/s, in the {} half-plane.",
        si(poles[0].re, "", 4),
        if poles[0].im < 0.0 { "−" } else { "+" },
        si(poles[0].im.abs(), "", 4),
        si(poles[1].re, "", 4),
        if poles[1].im < 0.0 { "−" } else { "+" },
        si(poles[1].im.abs(), "", 4),
        side
    );
    Figure {
        description,
        series: vec![Series {
            label: "|s| = ωₙ".into(),
            points: circle,
            style: LineStyle {
                color: 2,
                dash: Dash::Dotted,
                width: 1.5,
            },
        }],
        markers,
        origin_lines: true,
        ..Figure::plot(
            "Poles in the s-plane",
            // Wider than tall, like the canvas, so the circle |s| = ωₙ looks round.
            Axis::linear("real part Re s", "1/s", (-1.35 * r, 1.35 * r)),
            Axis::linear("imaginary part Im s", "rad/s", (-r, r)),
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn run(query: &str) -> Frame {
        let mut d = Regimes;
        let spec = d.spec();
        let (p, _) = crate::params::resolve_query(&spec, query);
        d.update(&p)
    }

    fn value(f: &Frame, key: &str) -> String {
        f.readouts
            .iter()
            .find(|r| r.key == key)
            .map(|r| r.data_value.clone())
            .unwrap()
    }

    #[test]
    fn readouts_come_from_the_solver() {
        const WN: f64 = 8.944_271_909_999_16; // √80 rad/s: m = 300 kg, k = 24 000 N/m
        let f = run(&format!("wn={WN}&zeta=0.2"));
        assert_eq!(value(&f, "wn").parse::<f64>().unwrap(), WN);
        assert_eq!(value(&f, "regime"), "underdamped");
        let wd: f64 = value(&f, "wd").parse().unwrap();
        assert!((wd - WN * (1.0f64 - 0.04).sqrt()).abs() < 1e-12);
        let re: f64 = value(&f, "pole_re").parse().unwrap();
        assert!((re + 0.2 * WN).abs() < 1e-12);
    }

    #[test]
    fn every_regime_is_reachable_from_the_sliders() {
        for (z, name) in [
            (0.0, "undamped"),
            (0.5, "underdamped"),
            (1.0, "critically damped"),
            (2.0, "overdamped"),
            (-0.3, "negatively damped"),
        ] {
            let f = run(&format!("zeta={z}"));
            assert_eq!(value(&f, "regime"), name);
            assert!(f.figures.iter().all(|fig| fig.has_visible_data()));
            assert!(
                f.figures[0].description.starts_with(name),
                "{}",
                f.figures[0].description
            );
        }
        assert_eq!(
            value(&run("zeta=2"), "wd"),
            "",
            "no damped frequency when overdamped"
        );
    }

    #[test]
    fn the_text_alternative_follows_the_response() {
        let light = run("zeta=0.1").figures[0].description.clone();
        let heavy = run("zeta=0.6").figures[0].description.clone();
        assert_ne!(light, heavy);
        assert!(
            light.contains("swings past equilibrium 9 times") && light.contains("within 5 %"),
            "{light}"
        );
        // ζ = 0.6 from rest: rebound e^{−πζ/√(1−ζ²)} = 9.48 %.
        assert!(heavy.contains("9.48 %"), "{heavy}");
    }

    #[test]
    fn every_table_row_matches_a_regime_key() {
        let spec = Regimes.spec();
        let keys: Vec<&str> = Regime::ALL.iter().map(|r| r.key()).collect();
        for (key, cells) in &spec.table.unwrap().rows {
            assert!(keys.contains(key));
            assert_eq!(cells.len(), 5);
        }
    }
}
