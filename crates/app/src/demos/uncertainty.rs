//! `uncertainty`: tolerances and robustness. The exact range of ζ, ω_n and Q when the
//! components sit anywhere within their tolerances, the band of free responses at the ends
//! of the range, and a seeded Monte Carlo run: histograms, percentiles and the yield against
//! a specification.

// Not yet reshaped: still does maths the solver should do (issue "one shape").
#![allow(clippy::disallowed_methods)]

use super::design::Stopwatch;
use super::{Demo, Frame, Readout};
use crate::figure::{finite_extent, padded, Axis, Dash, Figure, LineStyle, Marker};
use crate::figure::{MarkerShape, Series};
use crate::format::{si, significant};
use crate::params::Params;
use crate::plot::Ink;
use crate::spec::{DemoSpec, ParamSpec, PlotSpec, Preset, ReadoutSpec};
use zeta_solver::design::monte_carlo::{
    histogram_into, percentiles_into, run_into, yield_percent, Distribution, McConfig, McSamples,
    Spec, Tolerance,
};
use zeta_solver::design::sensitivity::{spread, Components, Quantity, Varied};
use zeta_solver::metrics::{free::FreeMetrics, SettlingBand};
use zeta_solver::{FreeResponse, SecondOrder};

/// Initial displacement of the suspension's free responses \[m\].
const X0_CAR: f64 = 0.06;
/// Initial capacitor voltage of the RLC's free responses \[V\].
const V0_RLC: f64 = 1.0;
/// Samples per response curve.
const SAMPLES: usize = 500;
/// Histogram bins.
const BINS: usize = 40;

/// `v` to `sig` significant digits without trailing zeros ("10", "0.6").
fn short(v: f64, sig: usize) -> String {
    let t = significant(v, sig);
    if t.contains('.') && !t.contains('e') {
        t.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        t
    }
}

/// A count with thin-space thousands separators ("100 000").
fn count_text(n: usize) -> String {
    let digits = n.to_string();
    let mut out = String::with_capacity(digits.len() + 4);
    for (i, ch) in digits.chars().enumerate() {
        if i > 0 && (digits.len() - i).is_multiple_of(3) {
            out.push('\u{2009}');
        }
        out.push(ch);
    }
    out
}

/// Which parameter group is analysed.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum System {
    Suspension,
    Rlc,
}

/// The quantity shown in the second histogram.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum HistOf {
    Zeta,
    F0,
    Q,
    Bandwidth,
    SettlingTime,
}

impl HistOf {
    const OPTIONS: [(&'static str, &'static str); 5] = [
        ("zeta", "damping ratio ζ"),
        ("f0", "natural frequency f0"),
        ("q", "quality factor Q"),
        ("bandwidth", "bandwidth"),
        ("settling_time", "settling time"),
    ];

    fn from_index(v: f64) -> Self {
        match v.round() as i64 {
            0 => HistOf::Zeta,
            1 => HistOf::F0,
            3 => HistOf::Bandwidth,
            4 => HistOf::SettlingTime,
            _ => HistOf::Q,
        }
    }

    fn index(self) -> usize {
        match self {
            HistOf::Zeta => 0,
            HistOf::F0 => 1,
            HistOf::Q => 2,
            HistOf::Bandwidth => 3,
            HistOf::SettlingTime => 4,
        }
    }

    /// Axis label and unit.
    fn label(self) -> (&'static str, &'static str) {
        match self {
            HistOf::Zeta => ("damping ratio ζ", ""),
            HistOf::F0 => ("natural frequency f0", "Hz"),
            HistOf::Q => ("quality factor Q", ""),
            HistOf::Bandwidth => ("half-power bandwidth", "rad/s"),
            HistOf::SettlingTime => ("settling time (5 %)", "s"),
        }
    }

    fn data(self, s: &McSamples) -> &[f64] {
        match self {
            HistOf::Zeta => &s.zeta,
            HistOf::F0 => &s.f0,
            HistOf::Q => &s.q,
            HistOf::Bandwidth => &s.bandwidth,
            HistOf::SettlingTime => &s.settling_time,
        }
    }
}

/// Everything the Monte Carlo run depends on; it is repeated only when this changes.
#[derive(Debug, Clone, Copy, PartialEq)]
struct McKey {
    design: Components,
    tolerances: [f64; 3],
    normal: bool,
    draws: usize,
    seed: u64,
}

/// The tolerance demo. Keeps the Monte Carlo samples and scratch buffers between updates.
#[derive(Debug, Default)]
pub struct Uncertainty {
    samples: McSamples,
    key: Option<McKey>,
    mc_ms: f64,
    runs: u64,
    scratch: Vec<f64>,
    counts: Vec<u64>,
    /// 5th and 95th percentiles per [`HistOf`] index, filled lazily after each run.
    pct: [Option<[f64; 2]>; 5],
}

const EQUATION: &str = "<math display=\"block\"><mrow>\
<mi>ζ</mi><mo>=</mo><mfrac><mi>c</mi><mrow><mn>2</mn><msqrt><mi>k</mi><mi>m</mi></msqrt></mrow></mfrac>\
<mo>∝</mo><msup><mi>m</mi><mrow><mo>−</mo><mn>1/2</mn></mrow></msup><mo>,</mo><mspace width=\"1em\"/>\
<mi>ζ</mi><mo>=</mo><mfrac><mi>R</mi><mn>2</mn></mfrac><msqrt><mfrac><mi>C</mi><mi>L</mi></mfrac></msqrt>\
</mrow></math>";

/// Validated inputs of one update.
struct Inputs {
    system: System,
    key: McKey,
    spec: Spec,
    zeta_window: (f64, f64),
    ts_max: f64,
    hist: HistOf,
    normal: bool,
}

fn inputs(p: &Params) -> Inputs {
    let system = if p.get("system").round() == 1.0 {
        System::Rlc
    } else {
        System::Suspension
    };
    let (design, tolerances) = match system {
        System::Suspension => (
            Components::mechanical_for_zeta(p.get("m"), p.get("k"), p.get("zeta")),
            [p.get("dm") / 100.0, 0.0, 0.0],
        ),
        System::Rlc => (
            Components::Electrical {
                l: p.get("L"),
                r: p.get("R"),
                cap: p.get("C"),
            },
            [
                p.get("dL") / 100.0,
                p.get("dR") / 100.0,
                p.get("dC") / 100.0,
            ],
        ),
    };
    let normal = p.get("dist").round() == 1.0;
    let (lo, hi) = (p.get("zeta_lo"), p.get("zeta_hi"));
    let zeta_window = (lo.min(hi), lo.max(hi));
    let ts_max = p.get("ts_max");
    Inputs {
        system,
        key: McKey {
            design,
            tolerances,
            normal,
            draws: p.get("N").round().clamp(1.0, 100_000.0) as usize,
            seed: p.get("seed").round().max(0.0) as u64,
        },
        spec: Spec {
            zeta: Some(zeta_window),
            max_settling_time: Some(ts_max),
            ..Spec::default()
        },
        zeta_window,
        ts_max,
        hist: HistOf::from_index(p.get("hist")),
        normal,
    }
}

/// Exact extremes of a quantity over a box of component tolerances that may differ per
/// component.
///
/// **Solver gap:** `sensitivity::spread` takes one tolerance for every varied component;
/// the RLC analysis needs `±dL`, `±dR`, `±dC` separately. The maths is the same as
/// `spread`'s (each quantity is a product of powers of the components, so monotone in each,
/// and the extremes lie at the corners of the box); it belongs in the solver as e.g.
/// `spread_box(design, quantity, [x0, x1, x2])`.
mod tolerance_box {
    use zeta_solver::design::sensitivity::{Components, Quantity};

    /// One extreme: the value and the component values where it is reached.
    #[derive(Debug, Clone, Copy, PartialEq)]
    pub struct Extreme {
        /// The quantity's value.
        pub value: f64,
        /// The design at that corner.
        pub design: Components,
    }

    /// `(min, max)` of `quantity` over the corners `p_i·(1 ± tol_i)` (`0 ≤ tol_i < 1`),
    /// evaluated exactly with the solver. `None` for an invalid tolerance or when the
    /// quantity is undefined at a corner.
    pub fn extremes(
        design: &Components,
        quantity: Quantity,
        tol: [f64; 3],
    ) -> Option<(Extreme, Extreme)> {
        if !tol.iter().all(|t| (0.0..1.0).contains(t)) {
            return None;
        }
        let base = design.values();
        let mut lo: Option<Extreme> = None;
        let mut hi: Option<Extreme> = None;
        for corner in 0..8u32 {
            let mut v = base;
            for (i, (vi, t)) in v.iter_mut().zip(tol).enumerate() {
                let sign = if corner >> i & 1 == 1 { 1.0 } else { -1.0 };
                *vi *= 1.0 + sign * t;
            }
            let d = design.with_values(v);
            let value = quantity.of(&d.system().ok()?)?;
            let e = Extreme { value, design: d };
            if lo.is_none_or(|l| value < l.value) {
                lo = Some(e);
            }
            if hi.is_none_or(|h| value > h.value) {
                hi = Some(e);
            }
        }
        lo.zip(hi)
    }

    #[cfg(test)]
    mod tests {
        use super::*;
        use zeta_solver::design::sensitivity::{spread, Varied};

        #[test]
        fn equal_tolerances_agree_with_the_solver_spread() {
            let rlc = Components::Electrical {
                l: 0.5,
                r: 7.0,
                cap: 0.02,
            };
            for q in Quantity::ALL {
                let (lo, hi) = extremes(&rlc, q, [0.1; 3]).unwrap();
                let s = spread(&rlc, q, Varied::All, 0.1).unwrap();
                assert!((lo.value - s.min).abs() <= 1e-12 * s.min.abs(), "{q:?}");
                assert!((hi.value - s.max).abs() <= 1e-12 * s.max.abs(), "{q:?}");
            }
        }

        #[test]
        fn separate_tolerances_reach_the_analytic_corners() {
            // ζ = (R/2)√(C/L): lowest at R(1 − dR), C(1 − dC), L(1 + dL).
            let rlc = Components::Electrical {
                l: 0.5,
                r: 7.0,
                cap: 0.02,
            };
            let (lo, hi) = extremes(&rlc, Quantity::DampingRatio, [0.05, 0.2, 0.1]).unwrap();
            let z = |l: f64, r: f64, c: f64| r / 2.0 * (c / l).sqrt();
            assert!((lo.value - z(0.525, 5.6, 0.018)).abs() < 1e-12);
            assert!((hi.value - z(0.475, 8.4, 0.022)).abs() < 1e-12);
            let corner = [0.525, 5.6, 0.018];
            for (v, e) in lo.design.values().iter().zip(corner) {
                assert!((v - e).abs() < 1e-12 * e);
            }
            assert!(extremes(&rlc, Quantity::DampingRatio, [1.0, 0.0, 0.0]).is_none());
        }
    }
}

/// Exact ranges and the two extreme designs of the response band.
struct Ranges {
    zeta: Option<(f64, f64)>,
    wn: Option<(f64, f64)>,
    q: Option<(f64, f64)>,
    /// Designs of the band: lowest-ζ end, nominal, highest-ζ end, with their labels.
    band: [(Components, String); 3],
}

fn ranges(inp: &Inputs) -> Ranges {
    let d = inp.key.design;
    match inp.system {
        System::Suspension => {
            let dm = inp.key.tolerances[0];
            let sp = |q| spread(&d, q, Varied::One(0), dm).map(|s| (s.min, s.max));
            let [m, c, k] = d.values();
            let zeta_of = |mm: f64| {
                SecondOrder::mechanical(mm, c, k)
                    .ok()
                    .and_then(|s| s.damping_ratio())
                    .map_or_else(String::new, |z| format!(" (ζ = {})", significant(z, 3)))
            };
            let pct = short(100.0 * dm, 3);
            // ζ ∝ m^−½: the heavy end has the lowest ζ.
            let heavy = m * (1.0 + dm);
            let light = m * (1.0 - dm);
            Ranges {
                zeta: sp(Quantity::DampingRatio),
                wn: sp(Quantity::NaturalFrequency),
                q: sp(Quantity::QualityFactor),
                band: [
                    (
                        d.with_values([heavy, c, k]),
                        format!("m + {pct} %{}", zeta_of(heavy)),
                    ),
                    (d, format!("nominal m{}", zeta_of(m))),
                    (
                        d.with_values([light, c, k]),
                        format!("m − {pct} %{}", zeta_of(light)),
                    ),
                ],
            }
        }
        System::Rlc => {
            let tol = inp.key.tolerances;
            let ex = |q| tolerance_box::extremes(&d, q, tol);
            let range = |q| ex(q).map(|(lo, hi)| (lo.value, hi.value));
            let z = ex(Quantity::DampingRatio);
            let lab = |what: &str, v: Option<f64>| match v {
                Some(v) => format!("{what} (ζ = {})", significant(v, 3)),
                None => what.to_string(),
            };
            let nominal_zeta = d.system().ok().and_then(|s| s.damping_ratio());
            Ranges {
                zeta: z.map(|(lo, hi)| (lo.value, hi.value)),
                wn: range(Quantity::NaturalFrequency),
                q: range(Quantity::QualityFactor),
                band: [
                    (
                        z.map_or(d, |(lo, _)| lo.design),
                        lab("lowest-ζ corner", z.map(|(lo, _)| lo.value)),
                    ),
                    (d, lab("nominal", nominal_zeta)),
                    (
                        z.map_or(d, |(_, hi)| hi.design),
                        lab("highest-ζ corner", z.map(|(_, hi)| hi.value)),
                    ),
                ],
            }
        }
    }
}

impl Uncertainty {
    fn run_if_needed(&mut self, inp: &Inputs) {
        if self.key == Some(inp.key) {
            return;
        }
        let watch = Stopwatch::start();
        let distribution = if inp.key.normal {
            Distribution::Normal
        } else {
            Distribution::Uniform
        };
        let tol = |fraction: f64| Tolerance {
            fraction,
            distribution,
        };
        let cfg = McConfig {
            design: inp.key.design,
            tolerances: inp.key.tolerances.map(tol),
            draws: inp.key.draws,
            seed: inp.key.seed,
            band: SettlingBand::FREE_DEFAULT,
        };
        run_into(&cfg, &mut self.samples);
        self.pct = [None; 5];
        self.percentiles(HistOf::Zeta);
        self.percentiles(HistOf::Q);
        self.mc_ms = watch.elapsed_ms();
        self.runs += 1;
        self.key = Some(inp.key);
    }

    /// `[p5, p95]` of a quantity over the current draws (cached per run).
    fn percentiles(&mut self, h: HistOf) -> [f64; 2] {
        let i = h.index();
        if let Some(Some(p)) = self.pct.get(i) {
            return *p;
        }
        let mut out = [f64::NAN; 2];
        percentiles_into(
            h.data(&self.samples),
            &[0.05, 0.95],
            &mut self.scratch,
            &mut out,
        );
        if let Some(slot) = self.pct.get_mut(i) {
            *slot = Some(out);
        }
        out
    }

    /// A histogram of `h` with the spec window (for ζ and settling time) and the 5th/95th
    /// percentiles marked.
    fn histogram(&mut self, inp: &Inputs, h: HistOf, title: &str, yield_pct: f64) -> Figure {
        let [p5, p95] = self.percentiles(h);
        let (name, unit) = h.label();
        let range = histogram_into(h.data(&self.samples), BINS, None, &mut self.counts);
        let draws = self.samples.zeta.len();
        let mut series = Vec::with_capacity(5);
        let mut markers = Vec::new();
        let mut xs: Vec<f64> = Vec::with_capacity(6);
        let mut top = 1.0f64;
        if let Some((lo, hi)) = range {
            let w = (hi - lo) / BINS as f64;
            let mut pts = Vec::with_capacity(2 * BINS + 2);
            pts.push((lo, 0.0));
            for (i, &c) in self.counts.iter().enumerate() {
                let x = lo + w * i as f64;
                pts.push((x, c as f64));
                pts.push((x + w, c as f64));
            }
            pts.push((hi, 0.0));
            top = self.counts.iter().copied().max().unwrap_or(1).max(1) as f64;
            xs.extend([lo, hi]);
            series.push(Series {
                label: format!("draws per bin ({BINS} bins)"),
                points: pts,
                style: LineStyle::solid(Ink::Blue, 2.0),
            });
        } else {
            markers.push(Marker {
                label: "no finite values".into(),
                at: (0.5, 0.5),
                shape: MarkerShape::Label,
                ink: Ink::Black,
            });
        }
        // Headroom above the bars for the legend box.
        let ymax = top * 1.5;
        let vline = |x: f64| vec![(x, 0.0), (x, ymax)];
        let spec_lines: Vec<f64> = match h {
            HistOf::Zeta => vec![inp.zeta_window.0, inp.zeta_window.1],
            HistOf::SettlingTime => vec![inp.ts_max],
            _ => Vec::new(),
        };
        for (j, &x) in spec_lines.iter().enumerate() {
            xs.push(x);
            series.push(Series {
                label: if j == 0 {
                    "spec limit".into()
                } else {
                    String::new()
                },
                points: vline(x),
                style: LineStyle {
                    ink: Ink::Vermillion,
                    dash: Dash::Dashed,
                    width: 2.0,
                },
            });
        }
        for (j, &x) in [p5, p95].iter().enumerate() {
            if x.is_finite() {
                series.push(Series {
                    label: if j == 0 {
                        "5th / 95th percentile".into()
                    } else {
                        String::new()
                    },
                    points: vline(x),
                    style: LineStyle {
                        ink: Ink::Green,
                        dash: Dash::Dotted,
                        width: 2.0,
                    },
                });
            }
        }
        let xr = padded(
            finite_extent(xs.iter().copied()).unwrap_or((0.0, 1.0)),
            0.06,
        );
        let xr = if range.is_none() { (0.0, 1.0) } else { xr };
        let dist = if inp.normal {
            "normal (tolerance = 3σ)"
        } else {
            "uniform"
        };
        let spec_text = match h {
            HistOf::Zeta => format!(
                " The spec window ζ {}–{} is marked; {} of draws meet the whole spec.",
                short(inp.zeta_window.0, 3),
                short(inp.zeta_window.1, 3),
                si(yield_pct, "%", 3)
            ),
            HistOf::SettlingTime => {
                format!(" The spec limit {} is marked.", si(inp.ts_max, "s", 3))
            }
            _ => String::new(),
        };
        let description = match range {
            Some((lo, hi)) => format!(
                "Histogram of {name} over {} {dist} draws: from {} to {}, 5th percentile {}, \
                 95th percentile {}.{spec_text}",
                count_text(draws),
                si(lo, unit, 4),
                si(hi, unit, 4),
                si(p5, unit, 4),
                si(p95, unit, 4),
            ),
            None => format!("No draw has a finite {name}."),
        };
        Figure {
            description,
            series,
            markers,
            ..Figure::plot(
                title.to_string(),
                Axis::linear(name, unit, xr),
                Axis::linear("draws", "", (0.0, ymax)),
            )
        }
    }
}

fn band_figure(inp: &Inputs, r: &Ranges) -> Figure {
    let (x0, y_name, y_unit) = match inp.system {
        System::Suspension => (X0_CAR, "displacement x", "m"),
        System::Rlc => (V0_RLC, "capacitor voltage v_C", "V"),
    };
    let systems: Vec<Option<SecondOrder>> = r.band.iter().map(|(d, _)| d.system().ok()).collect();
    let settle = |s: &SecondOrder| {
        FreeMetrics::exact(s, x0, 0.0, SettlingBand::FREE_DEFAULT).and_then(|m| m.settling_time)
    };
    let times: Vec<Option<f64>> = systems
        .iter()
        .map(|s| s.as_ref().and_then(settle))
        .collect();
    let longest = times.iter().flatten().fold(0.0f64, |a, &b| a.max(b));
    let wn = systems
        .get(1)
        .copied()
        .flatten()
        .and_then(|s| s.natural_frequency())
        .unwrap_or(1.0);
    let t_end = if longest > 0.0 {
        (1.3 * longest).min(200.0 / wn)
    } else {
        4.0 * std::f64::consts::TAU / wn
    };
    let styles = [
        LineStyle {
            ink: Ink::Vermillion,
            dash: Dash::Dashed,
            width: 2.0,
        },
        LineStyle::solid(Ink::Blue, 2.5),
        LineStyle {
            ink: Ink::Green,
            dash: Dash::Dotted,
            width: 2.5,
        },
    ];
    let mut series = Vec::with_capacity(5);
    let h = SettlingBand::FREE_DEFAULT.fraction() * x0;
    for (sign, label) in [(1.0, "5 % settling band"), (-1.0, "")] {
        series.push(Series {
            label: label.into(),
            points: vec![(0.0, sign * h), (t_end, sign * h)],
            style: LineStyle {
                ink: Ink::Black,
                dash: Dash::Dotted,
                width: 1.2,
            },
        });
    }
    let mut markers = Vec::with_capacity(3);
    for (((sys, (_, label)), style), ts) in systems.iter().zip(&r.band).zip(styles).zip(&times) {
        let Some(sys) = sys else { continue };
        let resp = FreeResponse::new(*sys, x0, 0.0);
        if let Some(t) = ts.filter(|&t| t <= t_end) {
            // Where each curve enters the band for good (colours match the curves; the
            // times are in the caption).
            markers.push(Marker {
                label: String::new(),
                at: (t, resp.displacement(t)),
                shape: MarkerShape::Cross,
                ink: style.ink,
            });
        }
        let points = (0..SAMPLES)
            .map(|i| {
                let t = t_end * i as f64 / (SAMPLES - 1) as f64;
                (t, resp.displacement(t))
            })
            .collect();
        series.push(Series {
            label: label.clone(),
            points,
            style,
        });
    }
    let ys = series.iter().flat_map(|s| s.points.iter().map(|p| p.1));
    let (lo, hi) = padded(finite_extent(ys).unwrap_or((-x0, x0)), 0.08);
    // Headroom for the legend box.
    let y = (lo, hi + 0.3 * (hi - lo));
    let fmt_t = |t: Option<f64>| t.map_or("never".to_string(), |t| si(t, "s", 3));
    let (what, ignored) = match inp.system {
        System::Suspension => (
            format!(
                "Free response from {} with the sprung mass at +{} %, nominal and −{} %",
                si(X0_CAR, "m", 2),
                short(100.0 * inp.key.tolerances[0], 3),
                short(100.0 * inp.key.tolerances[0], 3)
            ),
            "The RLC sliders are ignored.",
        ),
        System::Rlc => (
            "Capacitor voltage from 1 V at the lowest-ζ corner, nominal and highest-ζ corner of \
             the tolerance box"
                .to_string(),
            "The suspension sliders are ignored.",
        ),
    };
    let zeta_text = r.zeta.map_or_else(
        || "ζ is undefined at an end of the range".to_string(),
        |(lo, hi)| format!("ζ spans {}–{}", significant(lo, 3), significant(hi, 3)),
    );
    let description = format!(
        "{what}: {zeta_text}; 5 % settling times (crosses) {}, {} and {}. {ignored}",
        fmt_t(times.first().copied().flatten()),
        fmt_t(times.get(1).copied().flatten()),
        fmt_t(times.get(2).copied().flatten()),
    );
    Figure {
        description,
        series,
        markers,
        origin_lines: true,
        ..Figure::plot(
            "Band of free responses over the tolerance",
            Axis::linear("time t", "s", (0.0, t_end)),
            Axis::linear(y_name, y_unit, y),
        )
    }
}

impl Demo for Uncertainty {
    fn spec(&self) -> DemoSpec {
        let pct =
            |key, label, default| ParamSpec::linear(key, label, "", "%", (0.0, 30.0, 0.5), default);
        DemoSpec {
            id: "uncertainty",
            title: "Tolerance analysis",
            summary: "Real parts are not their nominal values. Choose the system: the quarter \
                      car (sprung mass m, spring k and the damper set for ζ at nominal mass; \
                      the mass varies by ±dm as the car is loaded) or the series RLC loop \
                      (R, L and C each within ±dR, ±dL, ±dC). Only the chosen system's sliders \
                      are used; the other group is ignored. The exact ranges of ζ, ωₙ and Q come \
                      from the corners of the tolerance box. The Monte Carlo run draws N designs \
                      (seeded, so the same seed gives the same result): uniform within the \
                      tolerance, or normal with the tolerance as 3σ. The yield is the share of \
                      draws with ζ inside the spec window and a 5 % settling time (release \
                      from rest) no longer than the limit.",
            equation_mathml: EQUATION,
            params: vec![
                ParamSpec::choice(
                    "system",
                    "system",
                    &[
                        ("suspension", "quarter-car suspension"),
                        ("rlc", "series RLC"),
                    ],
                    0,
                ),
                ParamSpec::linear(
                    "m",
                    "suspension: sprung mass",
                    "m",
                    "kg",
                    (100.0, 800.0, 1.0),
                    300.0,
                ),
                ParamSpec::linear(
                    "k",
                    "suspension: spring rate",
                    "k",
                    "N/m",
                    (5_000.0, 100_000.0, 100.0),
                    24_000.0,
                ),
                ParamSpec::linear(
                    "zeta",
                    "suspension: design ζ at nominal mass",
                    "ζ",
                    "",
                    (0.05, 2.0, 0.01),
                    0.7,
                ),
                pct("dm", "suspension: mass tolerance ±", 10.0),
                ParamSpec::log("R", "RLC: resistance", "R", "Ω", (0.1, 1_000.0, 0.01), 7.0),
                ParamSpec::log("L", "RLC: inductance", "L", "H", (0.001, 10.0, 0.001), 0.5),
                ParamSpec::log("C", "RLC: capacitance", "C", "F", (1e-6, 1.0, 1e-6), 0.02),
                pct("dR", "RLC: resistor tolerance ±", 5.0),
                pct("dL", "RLC: inductor tolerance ±", 5.0),
                pct("dC", "RLC: capacitor tolerance ±", 5.0),
                ParamSpec::choice(
                    "dist",
                    "distribution of parts",
                    &[
                        ("uniform", "uniform within ±tolerance"),
                        ("normal", "normal, tolerance = 3σ"),
                    ],
                    0,
                ),
                ParamSpec::log(
                    "N",
                    "Monte Carlo draws",
                    "N",
                    "",
                    (100.0, 100_000.0, 1.0),
                    10_000.0,
                ),
                ParamSpec::linear("seed", "random seed", "", "", (0.0, 999.0, 1.0), 1.0),
                ParamSpec::linear(
                    "zeta_lo",
                    "spec: lowest ζ",
                    "ζ_lo",
                    "",
                    (0.0, 2.0, 0.01),
                    0.6,
                ),
                ParamSpec::linear(
                    "zeta_hi",
                    "spec: highest ζ",
                    "ζ_hi",
                    "",
                    (0.0, 3.0, 0.01),
                    1.0,
                ),
                ParamSpec::log(
                    "ts_max",
                    "spec: longest settling time",
                    "t_s,max",
                    "s",
                    (0.01, 10.0, 0.001),
                    0.5,
                ),
                ParamSpec::choice("hist", "second histogram", &HistOf::OPTIONS, 2),
            ],
            readouts: [
                ("zeta_min", "ζ, lowest (exact)", ""),
                ("zeta_max", "ζ, highest (exact)", ""),
                ("wn_min", "ωₙ, lowest (exact)", "rad/s"),
                ("wn_max", "ωₙ, highest (exact)", "rad/s"),
                ("Q_min", "Q, lowest (exact)", ""),
                ("Q_max", "Q, highest (exact)", ""),
                ("yield", "yield (meets spec)", "%"),
                ("zeta_p5", "ζ, 5th percentile", ""),
                ("zeta_p95", "ζ, 95th percentile", ""),
                ("Q_p5", "Q, 5th percentile", ""),
                ("Q_p95", "Q, 95th percentile", ""),
                ("draws", "draws", ""),
                ("compute_time", "Monte Carlo compute time", "ms"),
            ]
            .into_iter()
            .map(|(key, label, unit)| ReadoutSpec { key, label, unit })
            .collect(),
            plots: vec![
                PlotSpec {
                    key: "band",
                    title: "Band of free responses over the tolerance",
                    aspect: 2.0,
                },
                PlotSpec {
                    key: "zeta_hist",
                    title: "Monte Carlo: damping ratio ζ",
                    aspect: 1.5,
                },
                PlotSpec {
                    key: "hist",
                    title: "Monte Carlo: chosen quantity",
                    aspect: 1.5,
                },
            ],
            primary_plot: "",
            presets: vec![
                Preset {
                    label: "ζ = 1 design under ±10 % mass",
                    values: vec![
                        ("system", 0.0),
                        ("m", 300.0),
                        ("k", 24_000.0),
                        ("zeta", 1.0),
                        ("dm", 10.0),
                    ],
                },
                Preset {
                    label: "ζ = 0.7 design under ±10 % mass",
                    values: vec![
                        ("system", 0.0),
                        ("m", 300.0),
                        ("k", 24_000.0),
                        ("zeta", 0.7),
                        ("dm", 10.0),
                    ],
                },
                Preset {
                    label: "RLC 5 % parts",
                    values: vec![("system", 1.0), ("dR", 5.0), ("dL", 5.0), ("dC", 5.0)],
                },
                Preset {
                    label: "RLC 20 % parts",
                    values: vec![("system", 1.0), ("dR", 20.0), ("dL", 20.0), ("dC", 20.0)],
                },
            ],
            table: None,
            schematic: false,
        }
    }

    fn update(&mut self, params: &Params) -> Frame {
        let inp = inputs(params);
        self.run_if_needed(&inp);
        let r = ranges(&inp);
        let yield_pct = yield_percent(&self.samples, &inp.spec);
        let [zp5, zp95] = self.percentiles(HistOf::Zeta);
        let [qp5, qp95] = self.percentiles(HistOf::Q);
        let lo = |v: Option<(f64, f64)>| v.map(|v| v.0);
        let hi = |v: Option<(f64, f64)>| v.map(|v| v.1);
        let draws = self.samples.zeta.len();
        let readouts = vec![
            Readout::number("zeta_min", lo(r.zeta), "", 4),
            Readout::number("zeta_max", hi(r.zeta), "", 4),
            Readout::number("wn_min", lo(r.wn), "rad/s", 4),
            Readout::number("wn_max", hi(r.wn), "rad/s", 4),
            Readout::number("Q_min", lo(r.q), "", 4),
            Readout::number("Q_max", hi(r.q), "", 4),
            Readout::number("yield", Some(yield_pct), "%", 3),
            Readout::number("zeta_p5", Some(zp5), "", 4),
            Readout::number("zeta_p95", Some(zp95), "", 4),
            Readout::number("Q_p5", Some(qp5), "", 4),
            Readout::number("Q_p95", Some(qp95), "", 4),
            Readout {
                key: "draws",
                text: format!("{draws}"),
                data_value: format!("{draws}"),
            },
            Readout::plain("compute_time", Some(self.mc_ms), "ms", 3),
        ];
        let (name, _) = inp.hist.label();
        let second_title = format!("Monte Carlo: {name}");
        let figures = vec![
            band_figure(&inp, &r),
            self.histogram(
                &inp,
                HistOf::Zeta,
                "Monte Carlo: damping ratio ζ",
                yield_pct,
            ),
            self.histogram(&inp, inp.hist, &second_title, yield_pct),
        ];
        Frame {
            readouts,
            figures,
            time_span: None,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn run(d: &mut Uncertainty, query: &str) -> Frame {
        let spec = d.spec();
        let (p, notices) = crate::params::resolve_query(&spec, query);
        assert!(notices.is_empty(), "{notices:?}");
        d.update(&p)
    }

    fn value(f: &Frame, key: &str) -> f64 {
        f.readouts
            .iter()
            .find(|r| r.key == key)
            .map(|r| r.data_value.parse::<f64>().unwrap())
            .unwrap()
    }

    #[test]
    fn the_mass_range_of_zeta_is_exact() {
        let mut d = Uncertainty::default();
        let f = run(&mut d, "zeta=1&dm=10");
        // ζ ∝ m^−½ at fixed c, k.
        assert!((value(&f, "zeta_min") - 1.0 / 1.1f64.sqrt()).abs() < 1e-12);
        assert!((value(&f, "zeta_max") - 1.0 / 0.9f64.sqrt()).abs() < 1e-12);
        let wn = (24_000.0f64 / 300.0).sqrt();
        assert!((value(&f, "wn_min") - wn / 1.1f64.sqrt()).abs() < 1e-12);
        // Q = 1/(2ζ).
        assert!((value(&f, "Q_max") - 1.1f64.sqrt() / 2.0).abs() < 1e-12);
        assert_eq!(value(&f, "draws"), 10_000.0);
        let band = &f.figures[0];
        assert_eq!(
            band.series.len(),
            5,
            "three masses and the band's two edges"
        );
        assert_eq!(band.markers.len(), 3, "where each settles");
        assert!(
            band.description.contains("RLC sliders are ignored"),
            "{}",
            band.description
        );
    }

    #[test]
    fn the_same_seed_gives_the_same_draws_and_others_differ() {
        let mut d = Uncertainty::default();
        let a = run(&mut d, "system=rlc&seed=3");
        let b = run(&mut d, "system=rlc&seed=4");
        let c = run(&mut d, "system=rlc&seed=3");
        assert_eq!(value(&a, "Q_p5"), value(&c, "Q_p5"));
        assert_ne!(value(&a, "Q_p5"), value(&b, "Q_p5"));
        assert_eq!(d.runs, 3);
        // Changing only the spec or the histogram reuses the draws.
        run(&mut d, "system=rlc&seed=3&zeta_lo=0.65&hist=f0");
        assert_eq!(d.runs, 3);
    }

    #[test]
    fn percentiles_and_yield_follow_the_samples() {
        let mut d = Uncertainty::default();
        let f = run(&mut d, "system=rlc&dR=20&dL=20&dC=20&N=2000");
        let (zmin, zmax) = (value(&f, "zeta_min"), value(&f, "zeta_max"));
        let (p5, p95) = (value(&f, "zeta_p5"), value(&f, "zeta_p95"));
        assert!(zmin < p5 && p5 < 0.7 && 0.7 < p95 && p95 < zmax);
        // Uniform draws never leave the exact range.
        assert!(d
            .samples
            .zeta
            .iter()
            .all(|z| *z >= zmin - 1e-12 && *z <= zmax + 1e-12));
        let y = value(&f, "yield");
        assert!((0.0..=100.0).contains(&y));
        let pass = d
            .samples
            .zeta
            .iter()
            .zip(&d.samples.settling_time)
            .filter(|(z, t)| (0.6..=1.0).contains(*z) && **t <= 0.5)
            .count();
        assert!((y - 100.0 * pass as f64 / 2000.0).abs() < 1e-9);
        // The second histogram follows the choice.
        let f = run(
            &mut d,
            "system=rlc&dR=20&dL=20&dC=20&N=2000&hist=settling_time",
        );
        assert!(f.figures[2].description.contains("settling time"));
        assert_eq!(d.runs, 1);
    }

    #[test]
    fn a_hundred_thousand_draws_run() {
        let mut d = Uncertainty::default();
        let f = run(&mut d, "N=100000&dist=normal");
        assert_eq!(value(&f, "draws"), 100_000.0);
        assert!(f.figures.iter().all(|g| g.has_visible_data()));
    }
}
