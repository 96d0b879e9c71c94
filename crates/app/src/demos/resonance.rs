//! `resonance`: a mass on a spring and damper driven by a harmonic force
//! `F(t) = F₀·cos(ωt)`. The frequency response `|H(r)|` and phase for a family of damping
//! ratios (the current one highlighted, peak and half-power points marked), and the full
//! time response from rest at the chosen frequency ratio `r = ω/ωₙ`: build-up at resonance,
//! beating off resonance, with the steady-state amplitude and the slow envelope drawn.
//!
//! The mass is fixed at 1 kg, so `k = ωₙ²` \[N/m\], `c = 2ζωₙ` \[N·s/m\] and the static
//! deflection is `F₀/k`.

// Not yet reshaped: still does maths the solver should do (issue "one shape").
#![allow(clippy::disallowed_methods)]

use super::{Demo, Frame, Readout};
use crate::figure::{Axis, AxisScale, Dash, Figure, LineStyle, Marker, MarkerShape, Series};
use crate::format::si;
use crate::params::Params;
use crate::plot::Ink;
use crate::schematic::{mass_spring_damper, MassLabels};
use crate::spec::{DemoSpec, ParamSpec, PlotSpec, Preset, ReadoutSpec};
use std::f64::consts::{FRAC_1_SQRT_2, TAU};
use zeta_solver::forced::{HarmonicForce, HarmonicResponse};
use zeta_solver::{frf, SecondOrder};

/// The mass \[kg\]: fixed, so that `k = ωₙ²·m` and `c = 2ζωₙ·m` follow from ωₙ and ζ.
const MASS: f64 = 1.0;
/// Points per frequency-response curve (on a grid dense near `r = 1`).
const FRF_SAMPLES: usize = 801;
/// Points of the time response.
const TIME_SAMPLES: usize = 1000;
/// Shown range of the frequency ratio (also the range of the `r` slider).
const R_RANGE: (f64, f64) = (0.1, 10.0);
/// How strongly the frequency grid crowds towards `r = 1` (see [`ratio_grid`]).
const GRID_STRETCH: f64 = 5.0;
/// The family of damping ratios drawn thin behind the current one.
const FAMILY: [f64; 8] = [0.01, 0.05, 0.1, 0.2, 0.3, 0.5, 0.707, 1.0];
/// Members of the family labelled on the magnitude plot.
const LABELLED: [f64; 4] = [0.01, 0.05, 0.2, 0.707];
/// Fixed dB range: holds every curve of the family (and of the ζ slider) for r in R_RANGE.
const DB_RANGE: (f64, f64) = (-45.0, 40.0);
/// At most this many cycles (of the faster of drive and natural motion) in the time window.
const MAX_CYCLES: f64 = 40.0;
/// Magnitude views.
const VIEWS: [(&str, &str); 2] = [("linear", "linear |H|"), ("db", "decibels 20·log₁₀|H|")];

const EQUATION: &str = "<math display=\"block\"><mrow>\
<mi>m</mi><mover><mi>x</mi><mo>¨</mo></mover><mo>+</mo><mi>c</mi><mover><mi>x</mi><mo>˙</mo></mover>\
<mo>+</mo><mi>k</mi><mi>x</mi><mo>=</mo><msub><mi>F</mi><mn>0</mn></msub><mi>cos</mi><mo>⁡</mo>\
<mo>(</mo><mi>ω</mi><mi>t</mi><mo>)</mo></mrow></math>\
<math display=\"block\"><mrow><mi>H</mi><mo>(</mo><mi>r</mi><mo>)</mo><mo>=</mo><mfrac><mn>1</mn><mrow><mn>1</mn><mo>−</mo>\
<msup><mi>r</mi><mn>2</mn></msup><mo>+</mo><mn>2</mn><mi>i</mi><mi>ζ</mi><mi>r</mi></mrow></mfrac>\
</mrow></math>";

/// The forced-response demo. Holds its frequency grid so updates do not rebuild it.
#[derive(Debug, Clone)]
pub struct Resonance {
    grid: Vec<f64>,
}

impl Default for Resonance {
    fn default() -> Self {
        Self {
            grid: ratio_grid(FRF_SAMPLES),
        }
    }
}

/// `n` frequency ratios from `R_RANGE.0` to `R_RANGE.1`, symmetric in `log r` about
/// `r = 1` and crowded there (`ln r ∝ sinh(B·u)`, `u` evenly spaced in −1…1), so that even
/// the ζ = 0.01 peak (half-power width ≈ 0.02) gets dozens of points. Presentation only.
fn ratio_grid(n: usize) -> Vec<f64> {
    let half = (R_RANGE.1 / R_RANGE.0).ln() / 2.0;
    let centre = (R_RANGE.0 * R_RANGE.1).sqrt().ln();
    let n = n.max(2);
    (0..n)
        .map(|i| {
            let u = -1.0 + 2.0 * i as f64 / (n - 1) as f64;
            (centre + half * (GRID_STRETCH * u).sinh() / GRID_STRETCH.sinh()).exp()
        })
        .map(|r| r.clamp(R_RANGE.0, R_RANGE.1))
        .collect()
}

/// Validated inputs.
struct Inputs {
    sys: SecondOrder,
    zeta: f64,
    r: f64,
    wn: f64,
    f0: f64,
    db: bool,
}

fn inputs(params: &Params) -> Option<Inputs> {
    let (zeta, r, wn, f0) = (
        params.get("zeta"),
        params.get("r"),
        params.get("wn"),
        params.get("F0"),
    );
    let sys = SecondOrder::mechanical(MASS, 2.0 * zeta * wn * MASS, wn * wn * MASS).ok()?;
    (r.is_finite() && r > 0.0 && f0.is_finite()).then_some(Inputs {
        sys,
        zeta,
        r,
        wn,
        f0,
        db: params.get("view") >= 0.5,
    })
}

impl Inputs {
    fn response(&self) -> Option<HarmonicResponse> {
        let force = HarmonicForce::new(self.f0, self.r * self.wn).ok()?;
        Some(HarmonicResponse::new(self.sys, force, 0.0, 0.0))
    }

    /// Time window: long enough to see the build-up (five time constants `1/(ζωₙ)`) or a
    /// few slow beats, at least two drive and three natural periods, at most
    /// [`MAX_CYCLES`] cycles of the faster motion so every cycle keeps ~25 samples.
    fn window(&self, resp: &HarmonicResponse) -> f64 {
        let tn = TAU / self.wn;
        let tf = TAU / (self.r * self.wn);
        let mut want = if self.zeta > 0.0 {
            5.0 / (self.zeta * self.wn)
        } else {
            f64::INFINITY
        };
        if let Some(tb) = resp.beat_period() {
            if tb > 4.0 * tn.max(tf) {
                want = want.min(3.5 * tb);
            }
        }
        want.max(2.0 * tf)
            .max(3.0 * tn)
            .min(MAX_CYCLES * tn.min(tf))
    }
}

fn ratio_axis() -> Axis {
    Axis {
        label: "frequency ratio r = ω/ωₙ".to_string(),
        unit: "",
        range: R_RANGE,
        scale: AxisScale::Log,
    }
}

fn line(label: impl Into<String>, points: Vec<(f64, f64)>, style: LineStyle) -> Series {
    Series {
        label: label.into(),
        points,
        style,
    }
}

fn styled(color: Ink, dash: Dash, width: f64) -> LineStyle {
    LineStyle {
        ink: color,
        dash,
        width,
    }
}

/// Replaces points above `top` by gaps, keeping the crossing points pinned to `top` so a
/// clipped peak still reaches the frame (the renderer would otherwise flatten it along the
/// edge). Presentation only.
fn clip_above(points: &mut [(f64, f64)], top: f64) {
    let above: Vec<bool> = points.iter().map(|p| p.1.is_nan() || p.1 > top).collect();
    for (i, p) in points.iter_mut().enumerate() {
        if !above[i] {
            continue;
        }
        let prev_in = i > 0 && !above[i - 1];
        let next_in = i + 1 < above.len() && !above[i + 1];
        p.1 = if (prev_in || next_in) && !p.1.is_nan() {
            top
        } else {
            f64::NAN
        };
    }
}

/// A dimensionless number with 3 significant digits and no trailing zeros (`0.05`, `1.05`).
fn fmt_ratio(r: f64) -> String {
    let s = si(r, "", 3);
    if s.contains('.') && !s.contains('e') {
        s.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        s
    }
}

fn degrees(rad: f64) -> f64 {
    rad.to_degrees()
}

impl Demo for Resonance {
    fn spec(&self) -> DemoSpec {
        DemoSpec {
            id: "resonance",
            title: "Forced resonance",
            summary: "A 1 kg mass on a spring (k = ωₙ²·m) and damper (c = 2ζωₙ·m), at rest, is \
                      driven from t = 0 by F(t) = F₀·cos(ωt). In the steady state it moves at the \
                      drive frequency with amplitude |H(r)|·F₀/k, lagging the force by the phase \
                      of H, where r = ω/ωₙ. Light damping gives a tall, narrow peak near r = 1 \
                      (height ≈ Q = 1/(2ζ), half-power width ≈ 2ζ); above ζ = 1/√2 there is no \
                      peak at all. Driven exactly at resonance, the amplitude builds up over a \
                      few time constants 1/(ζωₙ); driven near it, the free and forced motions \
                      beat against each other until the free part dies away.",
            equation_mathml: EQUATION,
            params: vec![
                ParamSpec::log("zeta", "damping ratio", "ζ", "", (0.01, 2.0, 0.001), 0.1),
                ParamSpec::log(
                    "r",
                    "forcing ratio ω/ωₙ",
                    "r",
                    "",
                    (R_RANGE.0, R_RANGE.1, 0.001),
                    1.0,
                ),
                ParamSpec::linear(
                    "wn",
                    "natural frequency",
                    "ωₙ",
                    "rad/s",
                    (0.5, 20.0, 0.01),
                    6.0,
                ),
                ParamSpec::linear("F0", "force amplitude", "F₀", "N", (0.1, 100.0, 0.1), 10.0),
                ParamSpec::choice("view", "magnitude view", &VIEWS, 0),
            ],
            readouts: vec![
                ReadoutSpec {
                    key: "peak_gain",
                    label: "resonant peak |H|max",
                    unit: "",
                },
                ReadoutSpec {
                    key: "peak_ratio",
                    label: "peak at r = ω/ωₙ",
                    unit: "",
                },
                ReadoutSpec {
                    key: "Q",
                    label: "quality factor Q = 1/(2ζ)",
                    unit: "",
                },
                ReadoutSpec {
                    key: "bandwidth",
                    label: "half-power bandwidth Δr",
                    unit: "",
                },
                ReadoutSpec {
                    key: "gain_at_r",
                    label: "gain |H(r)| at the drive",
                    unit: "",
                },
                ReadoutSpec {
                    key: "phase_at_r",
                    label: "phase ∠H(r) at the drive",
                    unit: "rad",
                },
                ReadoutSpec {
                    key: "amplitude",
                    label: "steady amplitude X = |H|·F₀/k",
                    unit: "m",
                },
                ReadoutSpec {
                    key: "beat_period",
                    label: "beat period 2π/|ω − ω_d|",
                    unit: "s",
                },
            ],
            plots: vec![
                PlotSpec {
                    key: "magnitude",
                    title: "Amplification |H(r)|",
                    aspect: 1.4,
                },
                PlotSpec {
                    key: "phase",
                    title: "Phase ∠H(r)",
                    aspect: 1.4,
                },
                PlotSpec {
                    key: "time",
                    title: "Response from rest x(t)",
                    aspect: 1.9,
                },
            ],
            primary_plot: "",
            presets: vec![
                Preset {
                    label: "At resonance, ζ = 0.05",
                    values: vec![("zeta", 0.05), ("r", 1.0)],
                },
                Preset {
                    label: "Beating near resonance, r = 0.9",
                    values: vec![("zeta", 0.01), ("r", 0.9)],
                },
                Preset {
                    label: "No peak, ζ ≈ 1/√2",
                    values: vec![("zeta", 0.7072), ("r", 1.0)],
                },
                Preset {
                    label: "Quasi-static, r = 0.2",
                    values: vec![("zeta", 0.1), ("r", 0.2)],
                },
                Preset {
                    label: "Isolation, r = 3",
                    values: vec![("zeta", 0.1), ("r", 3.0)],
                },
            ],
            table: None,
            schematic: true,
        }
    }

    fn update(&mut self, params: &Params) -> Frame {
        match inputs(params).and_then(|i| i.response().map(|resp| (i, resp))) {
            Some((inp, resp)) => frame(&inp, &resp, &self.grid),
            // Unreachable with validated parameters; still, never panic.
            None => Frame {
                readouts: [
                    ("peak_gain", ""),
                    ("peak_ratio", ""),
                    ("Q", ""),
                    ("bandwidth", ""),
                    ("gain_at_r", ""),
                    ("phase_at_r", "rad"),
                    ("amplitude", "m"),
                    ("beat_period", "s"),
                ]
                .into_iter()
                .map(|(k, u)| Readout::number(k, None, u, 4))
                .collect(),
                figures: Vec::new(),
                time_span: None,
            },
        }
    }

    fn schematic(&self, params: &Params, t: f64) -> Option<Figure> {
        let inp = inputs(params)?;
        let resp = inp.response()?;
        let t_end = inp.window(&resp);
        // Normalise by the largest excursion in the window, so the mass stays in the frame.
        let reach = (0..=200)
            .map(|i| resp.displacement(t_end * i as f64 / 200.0).abs())
            .filter(|v| v.is_finite())
            .fold(1e-12, f64::max);
        let x = resp.displacement(t);
        let force = resp.force().at(t);
        let labels = MassLabels {
            mass: "m",
            spring: "k",
            damper: "c",
            base: "fixed base",
        };
        let description = format!(
            "Mass on a spring and damper over a fixed base, pushed by the force F(t) = {} \
             (arrow above the mass) at t = {}: displaced {} from rest.",
            si(force, "N", 3),
            si(t, "s", 3),
            si(x, "m", 3)
        );
        let mut fig = mass_spring_damper(x / reach, 0.0, &labels, description);
        // The force arrow, drawn from the top of the mass in the direction of F(t).
        // Geometry of `mass_spring_damper`: centre 2.4 + 0.55·x, height 0.8.
        let top = 2.4 + 0.55 * (x / reach).clamp(-1.2, 1.2) + 0.4;
        let f = if inp.f0 != 0.0 { force / inp.f0 } else { 0.0 };
        let f = if f.is_finite() {
            f.clamp(-1.0, 1.0)
        } else {
            0.0
        };
        let base = top + 0.1 + if f < 0.0 { 0.75 } else { 0.0 };
        let tip = base + 0.75 * f;
        let ink = styled(Ink::Orange, Dash::Solid, 3.0);
        if (tip - base).abs() > 0.03 {
            let head = if f > 0.0 { -0.15 } else { 0.15 };
            fig.series
                .push(line("", vec![(0.0, base), (0.0, tip)], ink));
            fig.series.push(line(
                "",
                vec![(-0.12, tip + head), (0.0, tip), (0.12, tip + head)],
                ink,
            ));
        }
        fig.markers.push(Marker {
            label: "F(t)".to_string(),
            at: (0.25, top + 0.6),
            shape: MarkerShape::Label,
            ink: Ink::Black,
        });
        fig.y.range = (fig.y.range.0, fig.y.range.1.max(top + 1.0).max(4.4));
        Some(fig)
    }
}

fn frame(inp: &Inputs, resp: &HarmonicResponse, grid: &[f64]) -> Frame {
    let z = inp.zeta;
    let peak = frf::peak(z).filter(|p| p.ratio > 0.0);
    let steady = resp.steady_state();
    let readouts = vec![
        Readout::number("peak_gain", peak.map(|p| p.gain), "", 4),
        Readout::number("peak_ratio", peak.map(|p| p.ratio), "", 4),
        Readout::number("Q", frf::quality_factor(z), "", 4),
        Readout::number("bandwidth", frf::bandwidth(z), "", 4),
        Readout::number("gain_at_r", Some(frf::magnitude(inp.r, z)), "", 4),
        Readout::number("phase_at_r", Some(frf::phase(inp.r, z)), "rad", 4),
        Readout::number("amplitude", steady.map(|s| s.amplitude), "m", 4),
        Readout::number("beat_period", resp.beat_period(), "s", 4),
    ];
    let t_end = inp.window(resp);
    Frame {
        readouts,
        figures: vec![
            magnitude_figure(inp, grid),
            phase_figure(inp, grid),
            time_figure(inp, resp, t_end),
        ],
        time_span: Some((0.0, t_end)),
    }
}

/// `|H|` in the current view (plain ratio or dB).
fn gain(r: f64, zeta: f64, db: bool) -> f64 {
    if db {
        frf::magnitude_db(r, zeta)
    } else {
        frf::magnitude(r, zeta)
    }
}

/// A ratio as it is plotted in the current view.
fn level(g: f64, db: bool) -> f64 {
    if db {
        (20.0 * g.log10()).clamp(frf::DB_FLOOR, frf::DB_CEILING)
    } else {
        g
    }
}

fn magnitude_figure(inp: &Inputs, grid: &[f64]) -> Figure {
    let (z, db) = (inp.zeta, inp.db);
    let peak = frf::peak(z).filter(|p| p.ratio > 0.0);
    let top_gain = peak.map_or(1.0, |p| p.gain);
    let (y_range, top) = if db {
        (DB_RANGE, DB_RANGE.1)
    } else {
        let top = (1.2 * top_gain).max(2.5);
        ((0.0, top), top)
    };
    let mut series = Vec::with_capacity(FAMILY.len() + 4);
    let mut markers = Vec::new();
    for (i, &zf) in FAMILY.iter().enumerate() {
        let mut pts: Vec<(f64, f64)> = grid.iter().map(|&r| (r, gain(r, zf, db))).collect();
        clip_above(&mut pts, top);
        let label = if i == 0 { "family ζ = 0.01 … 1" } else { "" };
        series.push(line(label, pts, styled(Ink::Black, Dash::Dotted, 1.2)));
        if LABELLED.contains(&zf) {
            // Beside the peaks, level with |H(1)| = 1/(2ζ); in the linear view only where
            // the curves are far enough apart to tell which label is which.
            let at = (1.3, gain(1.0, zf, db));
            let floor = if db { y_range.0 } else { 0.12 * top };
            if at.1 < 0.93 * top && at.1 > floor {
                markers.push(Marker {
                    label: format!("ζ = {zf}"),
                    at,
                    shape: MarkerShape::Label,
                    ink: Ink::Black,
                });
            }
        }
    }
    // Half-power band: the level peak/√2 between the two points (from r_min if no lower one).
    let hp = frf::half_power_points(z);
    let mut band_text = String::new();
    if let Some(h) = hp {
        let lvl = level(top_gain * FRAC_1_SQRT_2, db);
        let lo = h.lower.unwrap_or(R_RANGE.0).max(R_RANGE.0);
        let hi = h.upper.min(R_RANGE.1);
        let bw = frf::bandwidth(z).unwrap_or(f64::NAN);
        series.push(line(
            format!("half-power band Δr = {}", fmt_ratio(bw)),
            vec![(lo, lvl), (hi, lvl)],
            styled(Ink::Purple, Dash::Dashed, 2.0),
        ));
        for r in h.lower.into_iter().chain([h.upper]) {
            markers.push(Marker {
                label: String::new(),
                at: (r, lvl),
                shape: MarkerShape::Cross,
                ink: Ink::Purple,
            });
        }
        band_text = match h.lower {
            Some(l) => format!(
                "half-power points at r = {} and {} (bandwidth {})",
                fmt_ratio(l),
                fmt_ratio(h.upper),
                fmt_ratio(bw)
            ),
            None => format!(
                "|H| stays above the half-power level from r = 0 up to r = {}",
                fmt_ratio(h.upper)
            ),
        };
    }
    let mut cur: Vec<(f64, f64)> = grid.iter().map(|&r| (r, gain(r, z, db))).collect();
    clip_above(&mut cur, top);
    series.push(line(
        format!("current ζ = {}", fmt_ratio(z)),
        cur,
        LineStyle::solid(Ink::Blue, 3.0),
    ));
    let at_r = gain(inp.r, z, db);
    series.push(line(
        format!("drive r = {}", fmt_ratio(inp.r)),
        vec![(inp.r, y_range.0), (inp.r, y_range.1)],
        styled(Ink::Vermillion, Dash::Dashed, 1.5),
    ));
    markers.push(Marker {
        label: String::new(),
        at: (inp.r, at_r.min(top)),
        shape: MarkerShape::Dot,
        ink: Ink::Vermillion,
    });
    if let Some(p) = peak {
        markers.push(Marker {
            label: "peak".to_string(),
            at: (p.ratio.max(R_RANGE.0), level(p.gain, db).min(top)),
            shape: MarkerShape::Cross,
            ink: Ink::Green,
        });
    }
    let unit_text = |g: f64| {
        if db {
            si(20.0 * g.log10(), "dB", 3)
        } else {
            si(g, "", 3)
        }
    };
    let peak_text = match peak {
        Some(p) => format!(
            "resonant peak {} at r = {}",
            unit_text(p.gain),
            si(p.ratio, "", 4)
        ),
        None => "no resonant peak (ζ ≥ 1/√2): |H| only falls from 1 at r = 0".to_string(),
    };
    let description = format!(
        "Magnitude{} for ζ = {}: {}; {}. At the drive r = {} the amplification is {}.",
        if db { " in dB" } else { "" },
        fmt_ratio(z),
        peak_text,
        band_text,
        fmt_ratio(inp.r),
        unit_text(frf::magnitude(inp.r, z)),
    );
    let y = if db {
        Axis::linear("magnitude 20·log₁₀|H|", "dB", y_range)
    } else {
        Axis::linear("amplification |H| = X/(F₀/k)", "", y_range)
    };
    Figure {
        description,
        series,
        markers,
        ..Figure::plot(
            if db {
                "Amplification |H(r)| in dB"
            } else {
                "Amplification |H(r)|"
            },
            ratio_axis(),
            y,
        )
    }
}

fn phase_figure(inp: &Inputs, grid: &[f64]) -> Figure {
    let z = inp.zeta;
    let mut series = Vec::with_capacity(FAMILY.len() + 2);
    for (i, &zf) in FAMILY.iter().enumerate() {
        let pts = grid
            .iter()
            .map(|&r| (r, degrees(frf::phase(r, zf))))
            .collect();
        let label = if i == 0 { "family ζ = 0.01 … 1" } else { "" };
        series.push(line(label, pts, styled(Ink::Black, Dash::Dotted, 1.2)));
    }
    series.push(line(
        format!("current ζ = {}", fmt_ratio(z)),
        grid.iter()
            .map(|&r| (r, degrees(frf::phase(r, z))))
            .collect(),
        LineStyle::solid(Ink::Blue, 3.0),
    ));
    let ph = frf::phase(inp.r, z);
    series.push(line(
        format!("drive r = {}", fmt_ratio(inp.r)),
        vec![(inp.r, -190.0), (inp.r, 10.0)],
        styled(Ink::Vermillion, Dash::Dashed, 1.5),
    ));
    let markers = vec![
        Marker {
            label: String::new(),
            at: (inp.r, degrees(ph)),
            shape: MarkerShape::Dot,
            ink: Ink::Vermillion,
        },
        Marker {
            label: "−90° at r = 1".to_string(),
            at: (1.0, -90.0),
            shape: MarkerShape::Cross,
            ink: Ink::Green,
        },
    ];
    let description = format!(
        "Phase of the displacement behind the force for ζ = {}: 0° at low frequency, −90° at \
         r = 1 for every damping ratio, towards −180° above resonance; the smaller ζ, the \
         sharper the switch. At the drive r = {} the lag is {} ({} rad).",
        fmt_ratio(z),
        fmt_ratio(inp.r),
        si(degrees(ph), "°", 3),
        si(ph, "", 4),
    );
    Figure {
        description,
        series,
        markers,
        ..Figure::plot(
            "Phase ∠H(r)",
            ratio_axis(),
            Axis::linear("phase ∠H (lag of x behind F)", "°", (-190.0, 10.0)),
        )
    }
}

fn time_figure(inp: &Inputs, resp: &HarmonicResponse, t_end: f64) -> Figure {
    let n = TIME_SAMPLES;
    let times = (0..n).map(|i| t_end * i as f64 / (n - 1) as f64);
    let points: Vec<(f64, f64)> = times.clone().map(|t| (t, resp.displacement(t))).collect();
    let steady = resp.steady_state();
    let mut reach = points
        .iter()
        .map(|p| p.1.abs())
        .filter(|v| v.is_finite())
        .fold(0.0, f64::max);
    let mut series = Vec::with_capacity(5);
    // The envelope is informative only while it varies slowly against the oscillation
    // (near resonance: slow beats or a build-up) and the free motion rings for a while.
    let slowest = TAU / inp.wn.min(inp.r * inp.wn);
    let slow = resp.beat_period().is_none_or(|tb| tb > 3.0 * slowest);
    let has_envelope = inp.zeta < 0.5 && slow && resp.envelope(0.0).is_some();
    if has_envelope {
        let env: Vec<(f64, f64)> = times
            .clone()
            .map(|t| (t, resp.envelope(t).unwrap_or(f64::NAN)))
            .collect();
        reach = env
            .iter()
            .map(|p| p.1)
            .filter(|v| v.is_finite())
            .fold(reach, f64::max);
        let lower = env.iter().map(|&(t, e)| (t, -e)).collect();
        series.push(line(
            "envelope ±E(t)",
            env,
            styled(Ink::Green, Dash::Dotted, 2.0),
        ));
        series.push(line("", lower, styled(Ink::Green, Dash::Dotted, 2.0)));
    }
    if let Some(s) = steady {
        reach = reach.max(s.amplitude);
        for (sign, label) in [(1.0, "steady amplitude ±X"), (-1.0, "")] {
            series.push(line(
                label,
                vec![(0.0, sign * s.amplitude), (t_end, sign * s.amplitude)],
                styled(Ink::Vermillion, Dash::Dashed, 1.5),
            ));
        }
    }
    let max_x = points
        .iter()
        .map(|p| p.1.abs())
        .filter(|v| v.is_finite())
        .fold(0.0, f64::max);
    series.push(line("x(t)", points, LineStyle::solid(Ink::Blue, 2.0)));
    let m = reach.max(1e-12);
    let y = (-1.12 * m, 1.9 * m);
    Figure {
        description: describe_time(inp, resp, t_end, max_x),
        series,
        origin_lines: true,
        ..Figure::plot(
            "Response from rest x(t)",
            Axis::linear("time t", "s", (0.0, t_end)),
            Axis::linear("displacement x", "m", y),
        )
    }
}

fn describe_time(inp: &Inputs, resp: &HarmonicResponse, t_end: f64, max_x: f64) -> String {
    let head = format!(
        "Driven from rest at r = {} (ω = {}) for {}",
        fmt_ratio(inp.r),
        si(inp.r * inp.wn, "rad/s", 3),
        si(t_end, "s", 3)
    );
    let tau = 1.0 / (inp.zeta * inp.wn);
    let Some(s) = resp.steady_state() else {
        return format!(
            "{head}: no steady state; the amplitude grows, reaching {}.",
            si(max_x, "m", 3)
        );
    };
    let amp = si(s.amplitude, "m", 3);
    let tn = TAU / inp.wn;
    let tf = TAU / (inp.r * inp.wn);
    let beats = resp
        .beat_period()
        .filter(|&tb| tb > 4.0 * tn.max(tf) && tau > 0.5 * tb);
    let body = if let Some(tb) = beats {
        format!(
            "the free and forced motions beat with period {} (time constant of the decay {}), \
             towards the steady amplitude {}",
            si(tb, "s", 3),
            si(tau, "s", 3),
            amp
        )
    } else if (inp.r - 1.0).abs() < inp.zeta.max(0.02) && inp.zeta < 0.5 {
        format!(
            "at resonance the amplitude builds up towards the steady amplitude {} with time \
             constant 1/(ζωₙ) = {}",
            amp,
            si(tau, "s", 3)
        )
    } else {
        format!(
            "after a transient (time constant {}) it settles to the steady amplitude {}",
            si(tau, "s", 3),
            amp
        )
    };
    format!(
        "{head}: {body}, lagging the force by {}. Largest excursion shown {}.",
        si(s.phase.to_degrees().abs(), "°", 3),
        si(max_x, "m", 3)
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    fn run(query: &str) -> Frame {
        let mut d = Resonance::default();
        let spec = d.spec();
        let (p, _) = crate::params::resolve_query(&spec, query);
        d.update(&p)
    }

    fn value(f: &Frame, key: &str) -> Option<f64> {
        f.readouts
            .iter()
            .find(|r| r.key == key)
            .and_then(|r| r.data_value.parse().ok())
    }

    fn close(a: f64, b: f64, tol: f64) -> bool {
        (a - b).abs() <= tol * b.abs().max(1e-300)
    }

    #[test]
    fn readouts_match_the_closed_forms() {
        let z = 0.05;
        let f = run("zeta=0.05&r=1&wn=6&F0=10");
        assert!(close(value(&f, "Q").unwrap(), 10.0, 1e-12));
        let g = 1.0 / (2.0 * z * (1.0f64 - z * z).sqrt());
        assert!(close(value(&f, "peak_gain").unwrap(), g, 1e-12));
        assert!(close(
            value(&f, "peak_ratio").unwrap(),
            (1.0f64 - 2.0 * z * z).sqrt(),
            1e-12
        ));
        assert!(close(value(&f, "gain_at_r").unwrap(), 10.0, 1e-12));
        assert!(close(
            value(&f, "phase_at_r").unwrap(),
            -std::f64::consts::FRAC_PI_2,
            1e-12
        ));
        // X = |H|·F0/k = 10 · 10/36 m.
        assert!(close(value(&f, "amplitude").unwrap(), 100.0 / 36.0, 1e-9));
        let s = (1.0f64 - z * z).sqrt();
        let bw =
            (1.0 - 2.0 * z * z + 2.0 * z * s).sqrt() - (1.0 - 2.0 * z * z - 2.0 * z * s).sqrt();
        assert!(close(value(&f, "bandwidth").unwrap(), bw, 1e-9));
    }

    #[test]
    fn no_peak_above_one_over_root_two() {
        let f = run("zeta=0.8&r=2");
        assert_eq!(value(&f, "peak_gain"), None);
        assert_eq!(value(&f, "peak_ratio"), None);
        assert!(value(&f, "bandwidth").is_some());
        assert!(f.figures[0].description.contains("no resonant peak"));
        let shown: Vec<&str> = f
            .readouts
            .iter()
            .filter(|r| r.key == "peak_gain")
            .map(|r| r.text.as_str())
            .collect();
        assert_eq!(shown, vec!["—"]);
    }

    #[test]
    fn grid_is_crowded_at_resonance_and_ends_exactly() {
        let g = ratio_grid(FRF_SAMPLES);
        assert_eq!(g.len(), FRF_SAMPLES);
        assert!(close(g[0], R_RANGE.0, 1e-12) && close(g[g.len() - 1], R_RANGE.1, 1e-12));
        assert!(g.windows(2).all(|w| w[1] > w[0]));
        let near = g.iter().filter(|r| (**r - 1.0).abs() < 0.01).count();
        assert!(near >= 30, "{near} points within ±0.01 of r = 1");
    }

    #[test]
    fn the_views_change_the_magnitude_axis_and_every_figure_is_drawable() {
        let lin = run("view=linear&zeta=0.01");
        let db = run("view=db&zeta=0.01");
        assert_eq!(lin.figures[0].y.unit, "");
        assert_eq!(db.figures[0].y.unit, "dB");
        for f in lin.figures.iter().chain(&db.figures) {
            assert!(f.has_visible_data());
            assert!(f.x.range.0 > 0.0 || f.x.scale == AxisScale::Linear);
        }
        // The ζ = 0.01 peak (50) is resolved by the grid: the drawn maximum is within 0.1 %.
        let drawn = lin.figures[0]
            .series
            .iter()
            .find(|s| s.label.starts_with("current"))
            .unwrap()
            .points
            .iter()
            .map(|p| p.1)
            .filter(|v| v.is_finite())
            .fold(0.0, f64::max);
        assert!(
            close(drawn, 1.0 / (0.02 * (1.0f64 - 1e-4).sqrt()), 1e-3),
            "{drawn}"
        );
    }

    #[test]
    fn build_up_at_resonance_and_beats_off_it() {
        let res = run("zeta=0.05&r=1");
        let d = &res.figures[2].description;
        assert!(d.contains("builds up"), "{d}");
        let x = &res.figures[2].series.last().unwrap().points;
        let early = x[..100].iter().map(|p| p.1.abs()).fold(0.0, f64::max);
        let late = x[900..].iter().map(|p| p.1.abs()).fold(0.0, f64::max);
        assert!(late > 3.0 * early);
        let beat = run("zeta=0.01&r=0.9");
        let d = &beat.figures[2].description;
        assert!(d.contains("beat"), "{d}");
        assert!(value(&beat, "beat_period").is_some());
        let labels = |f: &Frame| -> Vec<String> {
            f.figures[2]
                .series
                .iter()
                .map(|s| s.label.clone())
                .collect()
        };
        assert!(labels(&beat).iter().any(|l| l.starts_with("envelope")));
        // Far from resonance the "envelope" would wobble faster than the motion: not drawn.
        assert!(!labels(&run("zeta=0.1&r=0.2"))
            .iter()
            .any(|l| l.starts_with("envelope")));
    }

    #[test]
    fn clipping_pins_crossings_and_gaps_the_rest() {
        let mut p = vec![(1.0, 1.0), (2.0, 5.0), (3.0, 9.0), (4.0, 6.0), (5.0, 1.0)];
        clip_above(&mut p, 4.0);
        assert_eq!(p[1].1, 4.0);
        assert!(p[2].1.is_nan());
        assert_eq!(p[3].1, 4.0);
        assert_eq!(p[4].1, 1.0);
        let mut inf = vec![(1.0, 1.0), (2.0, f64::INFINITY), (3.0, 1.0)];
        clip_above(&mut inf, 4.0);
        assert_eq!(inf[1].1, 4.0);
    }

    #[test]
    fn schematic_draws_the_force_and_stays_finite() {
        let d = Resonance::default();
        let spec = d.spec();
        for q in ["zeta=0.01&r=0.1", "zeta=2&r=10", "zeta=0.05&r=1&F0=0.1"] {
            let (p, _) = crate::params::resolve_query(&spec, q);
            for t in [0.0, 0.3, 7.0] {
                let fig = d.schematic(&p, t).unwrap();
                assert!(fig.has_visible_data());
                assert!(fig
                    .series
                    .iter()
                    .all(|s| s.points.iter().all(|p| p.0.is_finite() && p.1.is_finite())));
                assert!(fig.description.contains("force"));
            }
        }
    }
}
