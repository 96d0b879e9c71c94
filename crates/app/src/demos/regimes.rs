//! `regimes`: free response of `x'' + 2ζωₙ·x' + ωₙ²·x = 0` in every damping regime, with
//! the two poles in the s-plane.

use super::{Demo, Frame, Readout};
use crate::figure::{
    finite_extent, padded, Axis, Dash, Figure, LineStyle, Marker, MarkerShape, Series,
};
use crate::params::Params;
use crate::spec::{DemoSpec, ParamSpec, PlotSpec, ReadoutSpec};
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
        }
    }

    fn update(&mut self, params: &Params) -> Frame {
        let (wn, zeta, x0, v0) = (
            params.get("wn"),
            params.get("zeta"),
            params.get("x0"),
            params.get("v0"),
        );
        match SecondOrder::from_natural(wn, zeta) {
            Ok(sys) => frame(&sys, x0, v0),
            // Unreachable with validated parameters; still, never panic: show the message.
            Err(e) => Frame {
                readouts: vec![
                    Readout::text("regime", e.to_string()),
                    Readout::number("wn", None, "rad/s", 4),
                    Readout::number("zeta", None, "", 3),
                    Readout::number("wd", None, "rad/s", 4),
                    Readout::number("pole_re", None, "1/s", 4),
                    Readout::number("pole_im", None, "rad/s", 4),
                ],
                figures: Vec::new(),
            },
        }
    }
}

fn frame(sys: &SecondOrder, x0: f64, v0: f64) -> Frame {
    let wn = sys.natural_frequency().unwrap_or(0.0);
    let zeta = sys.damping_ratio();
    let regime = sys.regime();
    let poles = sys.poles();
    let readouts = vec![
        Readout::text("regime", regime.key()),
        Readout::number("wn", sys.natural_frequency(), "rad/s", 4),
        Readout::number("zeta", zeta, "", 3),
        Readout::number("wd", sys.damped_frequency(), "rad/s", 4),
        Readout::number("pole_re", Some(poles[0].re), "1/s", 4),
        Readout::number("pole_im", Some(poles[0].im), "rad/s", 4),
    ];
    Frame {
        readouts,
        figures: vec![response_figure(sys, regime, x0, v0), pole_figure(sys, wn)],
    }
}

fn response_figure(sys: &SecondOrder, regime: Regime, x0: f64, v0: f64) -> Figure {
    let wn = sys.natural_frequency().unwrap_or(1.0);
    let t_end = PERIODS * std::f64::consts::TAU / wn;
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
        for (sign, label) in [(1.0, "envelope ±A·e^(−ζωₙ t)"), (-1.0, "")] {
            let env: Vec<(f64, f64)> = points
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
    let scale_floor = x0.abs().max(v0.abs() / wn).max(1e-6);
    let envelope_values = series.iter().flat_map(|s| s.points.iter().map(|p| p.1));
    let (lo, hi) = finite_extent(points.iter().map(|p| p.1).chain(envelope_values))
        .unwrap_or((-scale_floor, scale_floor));
    let y = padded(
        (lo.min(-0.2 * scale_floor), hi.max(0.2 * scale_floor)),
        0.08,
    );
    series.push(Series {
        label: format!("x(t), {}", regime.key()),
        points,
        style: LineStyle::solid(0, 2.5),
    });
    Figure {
        title: "Free response x(t)".into(),
        x: Axis::linear("time t", "s", (0.0, t_end)),
        y: Axis::linear("displacement x", "m", y),
        series,
        markers: Vec::new(),
        origin_lines: true,
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
    Figure {
        title: "Poles in the s-plane".into(),
        // Wider than tall, like the canvas, so the circle |s| = ωₙ looks round.
        x: Axis::linear("real part Re s", "1/s", (-1.35 * r, 1.35 * r)),
        y: Axis::linear("imaginary part Im s", "rad/s", (-r, r)),
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
        }
        assert_eq!(
            value(&run("zeta=2"), "wd"),
            "",
            "no damped frequency when overdamped"
        );
    }
}
