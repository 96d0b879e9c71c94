//! `quarter-car`: free response of a quarter-car suspension `m·x'' + c·x' + k·x = 0`
//! released from `x(0) = x₀`, `x'(0) = 0` (the body pushed down and let go, road fixed),
//! against the family of textbook damper settings; settling time against ζ with its
//! minimum; and how far ζ moves when the sprung mass changes by ±dm %.
//!
//! **`c` and `zeta` are two views of one quantity**, `c = 2ζ√(k·m)`. Both are sliders.
//! The damper rate `c` is the stored truth (it is the hardware: changing `m` or `k` keeps
//! the damper and moves ζ). In [`Demo::update`] the demo decides which of the two the user
//! moved, by comparing each with the value it saw at the previous update *and* with the
//! value it last asked the page to show ([`QuarterCar::derived_params`]):
//! - `c` moved → use it (this includes a preset, which gives both: `c` wins);
//! - else `zeta` moved → `c = 2ζ√(km)` (clamped to the `c` slider's range);
//! - else (`m`, `k` or nothing moved) → keep the previous `c`.
//!
//! On the first update (a fresh page or URL) nothing was seen before: `c` is used unless it
//! is at its default and `zeta` is not, i.e. **a URL giving both uses `c`**, a URL giving
//! only `zeta` uses `zeta`. The page should move the other slider after each update by
//! applying [`QuarterCar::derived_params`]; the rules above make that write-back a no-op
//! for the next update.

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
use crate::spec::{DemoSpec, ParamSpec, PlotSpec, Preset, ReadoutSpec};
use zeta_solver::design::sensitivity::{spread, Components, Quantity, Spread, Varied};
use zeta_solver::design::sweep::{
    fastest_settling_zeta, sweep_zeta_into, ZetaCurves, ZetaOptimum, ZetaSweepConfig,
};
use zeta_solver::metrics::{free::FreeMetrics, SettlingBand};
use zeta_solver::{FreeResponse, Regime, SecondOrder};

/// Samples per time curve.
const SAMPLES: usize = 500;
/// Points of the settling-time sweep over ζ.
const SWEEP_POINTS: usize = 400;
/// Grid of the search for the fastest-settling ζ (then refined by the solver).
const OPTIMUM_GRID: usize = 240;
/// ζ range searched for the fastest-settling ζ: the optimum is 0.46…0.83 for bands of 20…1 %.
const OPTIMUM_RANGE: (f64, f64) = (0.05, 2.5);
/// Samples of the mass-sensitivity curve.
const STRIP_POINTS: usize = 60;

const M_DEFAULT: f64 = 300.0;
const K_DEFAULT: f64 = 24_000.0;
const ZETA_DEFAULT: f64 = 0.3;
/// `2·0.3·√(24 000·300)` N·s/m, so the defaults of `c` and `zeta` agree (a test checks it).
const C_DEFAULT: f64 = 1_609.968_943_799_848_6;
const C_RANGE: (f64, f64, f64) = (0.0, 20_000.0, 10.0);
const ZETA_RANGE: (f64, f64, f64) = (0.0, 3.0, 0.01);
const X0_DEFAULT: f64 = 0.06;

/// The preset family, drawn on the current car: group, ζ.
const FAMILY: [(&str, f64); 6] = [
    ("comfort", 0.3),
    ("comfort", 0.4),
    ("performance", 0.65),
    ("performance", 0.7),
    ("critical", 1.0),
    ("overdamped", 2.0),
];

const EQUATION: &str = "<math display=\"block\"><mrow>\
<mi>m</mi><mover><mi>x</mi><mo>¨</mo></mover><mo>+</mo><mi>c</mi><mover><mi>x</mi><mo>˙</mo></mover>\
<mo>+</mo><mi>k</mi><mi>x</mi><mo>=</mo><mn>0</mn><mo>,</mo><mspace width=\"1em\"/>\
<mi>c</mi><mo>=</mo><mn>2</mn><mi>ζ</mi><msqrt><mi>k</mi><mi>m</mi></msqrt></mrow></math>";

/// The `c`/`zeta` values seen at the previous update and published for the sliders.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Coupling {
    /// `c` parameter at the previous update \[N·s/m\].
    seen_c: f64,
    /// `zeta` parameter at the previous update.
    seen_zeta: f64,
    /// `c` the page was asked to show \[N·s/m\].
    shown_c: f64,
    /// `zeta` the page was asked to show (clamped to its slider).
    shown_zeta: f64,
}

/// The settling-time sweep, kept while `ω_n`, the band and the ζ range stay the same
/// (moving `c` or `zeta` alone then costs no sweep).
#[derive(Debug, Clone, Default)]
struct SweepCache {
    key: Option<[f64; 4]>,
    zetas: Vec<f64>,
    curves: ZetaCurves,
    /// `(ζ, t_s)` with a NaN break at every jump of the settling time.
    points: Vec<(f64, f64)>,
    /// The fastest-settling ζ for `(ω_n, band)`.
    optimum: Option<([f64; 2], Option<ZetaOptimum>)>,
}

/// The quarter-car demo. Holds the damper rate (see the module docs) and a sweep cache.
#[derive(Debug, Clone, Default)]
pub struct QuarterCar {
    /// Damper rate in use \[N·s/m\].
    c: f64,
    coupling: Option<Coupling>,
    sweep: SweepCache,
}

impl QuarterCar {
    /// A fresh demo (no update seen yet).
    pub fn new() -> Self {
        Self::default()
    }

    /// Parameter values the page should show after the last update, because the demo
    /// derived them: `c` \[N·s/m\] and `zeta` (clamped to the ζ slider's range). Setting the
    /// parameters to these values is idempotent: the next update sees no move. Empty
    /// before the first update.
    pub fn derived_params(&self) -> Vec<(&'static str, f64)> {
        match self.coupling {
            Some(cp) => vec![("c", cp.shown_c), ("zeta", cp.shown_zeta)],
            None => Vec::new(),
        }
    }

    /// Resolves the damper rate from the `c` and `zeta` parameters (module docs), stores it
    /// and what to publish; returns it.
    fn resolve_c(&mut self, params: &Params, m: f64, k: f64) -> f64 {
        let (pc, pz) = (params.get("c"), params.get("zeta"));
        // c = ζ·2√(km), the solver's critical damping of this car.
        let from_zeta = |z: f64| {
            SecondOrder::mechanical(m, 0.0, k)
                .ok()
                .and_then(|s| s.critical_damping())
                .map_or(f64::NAN, |crit| z * crit)
        };
        let c = match self.coupling {
            None if pc == C_DEFAULT && pz != ZETA_DEFAULT => from_zeta(pz),
            None => pc,
            Some(cp) => {
                let moved = |v: f64, seen: f64, shown: f64| v != seen && v != shown;
                if moved(pc, cp.seen_c, cp.shown_c) {
                    pc
                } else if moved(pz, cp.seen_zeta, cp.shown_zeta) {
                    from_zeta(pz)
                } else {
                    self.c
                }
            }
        };
        let c = if c.is_finite() {
            c.clamp(C_RANGE.0, C_RANGE.1)
        } else {
            C_DEFAULT
        };
        let zeta = SecondOrder::mechanical(m, c, k)
            .ok()
            .and_then(|s| s.damping_ratio())
            .unwrap_or(pz);
        self.c = c;
        self.coupling = Some(Coupling {
            seen_c: pc,
            seen_zeta: pz,
            shown_c: c,
            shown_zeta: zeta.clamp(ZETA_RANGE.0, ZETA_RANGE.1),
        });
        c
    }
}

/// Everything one update works from.
#[derive(Debug, Clone, Copy)]
struct Car {
    sys: SecondOrder,
    m: f64,
    k: f64,
    c: f64,
    x0: f64,
    band: SettlingBand,
    band_pct: f64,
    dm_pct: f64,
}

impl Car {
    fn wn(&self) -> f64 {
        self.sys.natural_frequency().unwrap_or(1.0)
    }

    fn zeta(&self) -> f64 {
        self.sys.damping_ratio().unwrap_or(0.0)
    }

    /// The same car with damping ratio `zeta`.
    fn with_zeta(&self, zeta: f64) -> Option<SecondOrder> {
        let c = self.sys.critical_damping()? * zeta;
        SecondOrder::mechanical(self.m, c, self.k).ok()
    }

    fn metrics(&self, sys: &SecondOrder) -> Option<FreeMetrics> {
        FreeMetrics::exact(sys, self.x0, 0.0, self.band)
    }
}

fn car(params: &Params, c: f64) -> Option<Car> {
    let (m, k) = (params.get("m"), params.get("k"));
    let band_pct = params.get("band");
    Some(Car {
        sys: SecondOrder::mechanical(m, c, k).ok()?,
        m,
        k,
        c,
        x0: params.get("x0"),
        band: SettlingBand::new(band_pct / 100.0).ok()?,
        band_pct,
        dm_pct: params.get("dm"),
    })
}

fn readout_specs() -> Vec<ReadoutSpec> {
    [
        ("regime", "regime", ""),
        ("wn", "natural frequency ωₙ", "rad/s"),
        ("fn", "natural frequency fₙ", "Hz"),
        ("zeta", "damping ratio ζ", ""),
        ("c", "damper rate c in use", "N·s/m"),
        ("c_crit", "critical damping 2√(km)", "N·s/m"),
        ("wd", "damped frequency ω_d", "rad/s"),
        ("settling_time", "settling time t_s", "s"),
        ("overshoot", "peak rebound (of x₀)", "%"),
        ("peak_time", "time of peak rebound", "s"),
        ("zeta_argmin", "fastest-settling ζ", ""),
        ("settling_min", "its settling time", "s"),
        ("zeta_lo", "ζ at mass +dm %", ""),
        ("zeta_hi", "ζ at mass −dm %", ""),
    ]
    .into_iter()
    .map(|(key, label, unit)| ReadoutSpec { key, label, unit })
    .collect()
}

impl Demo for QuarterCar {
    fn derived_params(&self) -> Vec<(&'static str, f64)> {
        QuarterCar::derived_params(self)
    }

    fn spec(&self) -> DemoSpec {
        DemoSpec {
            id: "quarter-car",
            title: "Quarter-car suspension",
            summary: "One corner of a car: the body (sprung mass m) on a spring k and a damper \
                      c over a fixed road, pushed by x₀ and released from rest (x′(0) = 0). c and ζ are two \
                      views of one damper, c = 2ζ√(km): move either and the other follows; \
                      changing m or k keeps the damper, so ζ moves. The thin curves show the \
                      textbook settings on this car: comfort (ζ ≈ 0.3–0.4) rebounds, \
                      performance (ζ ≈ 0.65–0.7) settles fastest, critical (ζ = 1) and \
                      overdamped settings return without rebound but more slowly. Settling \
                      time jumps as ζ passes the values where a rebound drops inside the band: \
                      the fastest ζ sits just past such a jump, so a heavier load can push a \
                      well-tuned car over the edge (see the mass strip).",
            equation_mathml: EQUATION,
            params: vec![
                ParamSpec::linear(
                    "m",
                    "sprung mass",
                    "m",
                    "kg",
                    (100.0, 1000.0, 1.0),
                    M_DEFAULT,
                ),
                ParamSpec::linear(
                    "k",
                    "spring rate",
                    "k",
                    "N/m",
                    (5_000.0, 100_000.0, 100.0),
                    K_DEFAULT,
                ),
                ParamSpec::linear("c", "damper rate", "c", "N·s/m", C_RANGE, C_DEFAULT),
                ParamSpec::linear("zeta", "damping ratio", "ζ", "", ZETA_RANGE, ZETA_DEFAULT),
                ParamSpec::linear(
                    "x0",
                    "initial displacement",
                    "x₀",
                    "m",
                    (0.005, 0.15, 0.001),
                    X0_DEFAULT,
                ),
                ParamSpec::linear("band", "settling band", "±", "%", (1.0, 20.0, 0.5), 5.0),
                ParamSpec::linear(
                    "dm",
                    "sprung-mass variation",
                    "±Δm",
                    "%",
                    (0.0, 40.0, 1.0),
                    10.0,
                ),
            ],
            readouts: readout_specs(),
            plots: vec![
                PlotSpec {
                    key: "response",
                    title: "Body displacement x(t)",
                    aspect: 1.3,
                },
                PlotSpec {
                    key: "settling",
                    title: "Settling time against ζ",
                    aspect: 1.6,
                },
                PlotSpec {
                    key: "sensitivity",
                    title: "ζ when the sprung mass varies",
                    aspect: 2.0,
                },
            ],
            primary_plot: "",
            presets: presets(),
            table: None,
            schematic: true,
        }
    }

    fn update(&mut self, params: &Params) -> Frame {
        let (m, k) = (params.get("m"), params.get("k"));
        let c = self.resolve_c(params, m, k);
        match car(params, c) {
            Some(car) => self.frame(&car),
            // Unreachable with validated parameters; still, never panic.
            None => Frame {
                readouts: readout_specs()
                    .iter()
                    .map(|r| {
                        if r.key == "regime" {
                            Readout::text("regime", "invalid parameters")
                        } else {
                            Readout::number(r.key, None, r.unit, 4)
                        }
                    })
                    .collect(),
                figures: Vec::new(),
                time_span: None,
            },
        }
    }

    fn schematic(&self, params: &Params, t: f64) -> Option<Figure> {
        let car = car(params, self.c)?;
        let x = FreeResponse::new(car.sys, car.x0, 0.0).displacement(t);
        let labels = MassLabels {
            mass: "m",
            spring: "k",
            damper: "c",
            base: "road",
        };
        let description = format!(
            "Quarter car at t = {}: the body is {} from rest ({}), road fixed.",
            si(t, "s", 3),
            si(x.abs(), "m", 3),
            if x > 0.0 { "above" } else { "below" }
        );
        Some(mass_spring_damper(
            x / car.x0.abs().max(1e-12),
            0.0,
            &labels,
            description,
        ))
    }
}

fn presets() -> Vec<Preset> {
    // c = ζ·2√(km) for the reference car, so each preset names both views consistently.
    let crit = 2.0 * (M_DEFAULT * K_DEFAULT).sqrt();
    [
        ("Comfort ζ = 0.3", 0.3),
        ("Comfort ζ = 0.4", 0.4),
        ("Performance ζ = 0.65", 0.65),
        ("Performance ζ = 0.7", 0.7),
        ("Critical ζ = 1", 1.0),
        ("Overdamped ζ = 2", 2.0),
    ]
    .into_iter()
    .map(|(label, z)| Preset {
        label,
        values: vec![
            ("m", M_DEFAULT),
            ("k", K_DEFAULT),
            ("x0", X0_DEFAULT),
            ("zeta", z),
            ("c", z * crit),
        ],
    })
    .collect()
}

/// Series style of each family group: (colour, dash, width, marker along the curve).
fn family_style(group: &str) -> (LineStyle, Option<MarkerShape>) {
    let (color, dash, width, marker) = match group {
        "comfort" => (Ink::Vermillion, Dash::Dashed, 1.5, None),
        "performance" => (Ink::Green, Dash::Dotted, 2.0, None),
        "critical" => (Ink::Purple, Dash::Solid, 1.5, Some(MarkerShape::Cross)),
        _ => (Ink::Orange, Dash::Solid, 1.5, Some(MarkerShape::Dot)),
    };
    (
        LineStyle {
            ink: color,
            dash,
            width,
        },
        marker,
    )
}

fn family_legend(group: &str) -> &'static str {
    match group {
        "comfort" => "comfort 0.3, 0.4",
        "performance" => "performance 0.65, 0.7",
        "critical" => "critical 1 (×)",
        _ => "overdamped 2 (●)",
    }
}

/// A percentage as typed on the slider: `5` → `"5 %"`, `2.5` → `"2.5 %"`.
fn pct(v: f64) -> String {
    format!("{} %", (v * 100.0).round() / 100.0)
}

/// How often the body swings through equilibrium before it settles (the solver counts
/// crossings before the settling time; a later rebound inside the band is not counted).
fn crossings_text(m: &FreeMetrics) -> String {
    match (m.zero_crossings, m.rebound_time) {
        (0, None) => "does not cross equilibrium".to_string(),
        (0, Some(_)) => {
            "settles before crossing equilibrium (its rebound stays inside the band)".to_string()
        }
        (1, _) => "crosses equilibrium once before settling".to_string(),
        (n, _) => format!("crosses equilibrium {n} times before settling"),
    }
}

impl QuarterCar {
    fn frame(&mut self, car: &Car) -> Frame {
        let sys = &car.sys;
        let wn = car.wn();
        let metrics = car.metrics(sys);
        let cfg = ZetaSweepConfig {
            wn,
            x0: car.x0,
            v0: 0.0,
            band: car.band,
        };
        let opt_key = [wn, car.band.fraction()];
        let optimum = match self.sweep.optimum {
            Some((key, found)) if key == opt_key => found,
            _ => {
                let found =
                    fastest_settling_zeta(&cfg, OPTIMUM_RANGE.0, OPTIMUM_RANGE.1, OPTIMUM_GRID);
                self.sweep.optimum = Some((opt_key, found));
                found
            }
        };
        let mass_spread = spread(
            &Components::Mechanical {
                m: car.m,
                c: car.c,
                k: car.k,
            },
            Quantity::DampingRatio,
            Varied::One(0),
            car.dm_pct / 100.0,
        );
        let readouts = vec![
            Readout::text("regime", sys.regime().key()),
            Readout::number("wn", sys.natural_frequency(), "rad/s", 4),
            Readout::number("fn", sys.natural_frequency_hz(), "Hz", 4),
            Readout::number("zeta", sys.damping_ratio(), "", 4),
            Readout::number("c", Some(car.c), "N·s/m", 4),
            Readout::number("c_crit", sys.critical_damping(), "N·s/m", 4),
            Readout::number("wd", sys.damped_frequency(), "rad/s", 4),
            Readout::number(
                "settling_time",
                metrics.and_then(|m| m.settling_time),
                "s",
                4,
            ),
            Readout::number("overshoot", metrics.map(|m| 100.0 * m.peak_rebound), "%", 4),
            Readout::number("peak_time", metrics.and_then(|m| m.rebound_time), "s", 4),
            Readout::number("zeta_argmin", optimum.map(|o| o.zeta), "", 4),
            Readout::number("settling_min", optimum.map(|o| o.settling_time), "s", 4),
            Readout::number("zeta_lo", mass_spread.map(|s| s.min), "", 4),
            Readout::number("zeta_hi", mass_spread.map(|s| s.max), "", 4),
        ];
        let (response, t_end) = response_figure(car, metrics);
        let settling = self.settling_figure(car, &cfg, metrics, optimum);
        let strip = sensitivity_figure(car, mass_spread, optimum);
        Frame {
            readouts,
            figures: vec![response, settling, strip],
            time_span: Some((0.0, t_end)),
        }
    }

    fn settling_figure(
        &mut self,
        car: &Car,
        cfg: &ZetaSweepConfig,
        metrics: Option<FreeMetrics>,
        optimum: Option<ZetaOptimum>,
    ) -> Figure {
        let zeta = car.zeta();
        let z_hi = (1.3 * zeta).clamp(2.0, 15.0);
        let z_lo = (0.9 * zeta).clamp(0.02, 0.1);
        let key = [cfg.wn, car.band.fraction(), z_lo, z_hi];
        let cache = &mut self.sweep;
        if cache.key != Some(key) {
            cache.key = Some(key);
            cache.zetas.clear();
            cache.zetas.extend(
                (0..SWEEP_POINTS)
                    .map(|i| z_lo + (z_hi - z_lo) * i as f64 / (SWEEP_POINTS - 1) as f64),
            );
            sweep_zeta_into(&cache.zetas, cfg, &mut cache.curves);
            // Break the line where the settling time jumps: there the number of equilibrium
            // crossings before settling changes (an extremum has dropped inside the band).
            cache.points.clear();
            let mut last_crossings = None;
            for (&z, &ts) in cache.zetas.iter().zip(&cache.curves.settling_time) {
                let crossings = SecondOrder::from_natural(cfg.wn, z)
                    .ok()
                    .and_then(|s| FreeMetrics::exact(&s, cfg.x0, 0.0, cfg.band))
                    .map(|m| m.zero_crossings);
                if last_crossings.is_some() && crossings != last_crossings {
                    cache.points.push((f64::NAN, f64::NAN));
                }
                last_crossings = crossings;
                cache.points.push((z, ts));
            }
        }
        let ts_now = metrics.and_then(|m| m.settling_time);
        // Show the interesting part: up to the slower of ζ = 2, this design and 4× the best.
        let at_two = cache
            .zetas
            .iter()
            .zip(&cache.curves.settling_time)
            .filter(|(z, _)| **z <= 2.0)
            .map(|(_, t)| *t)
            .next_back()
            .unwrap_or(f64::NAN);
        let best = optimum.map_or(f64::NAN, |o| o.settling_time);
        let y_top = finite_extent([at_two, 4.0 * best, ts_now.unwrap_or(f64::NAN)])
            .map_or(1.0, |(_, hi)| 1.12 * hi);
        let points: Vec<(f64, f64)> = cache
            .points
            .iter()
            .map(|&(z, t)| {
                if t <= y_top {
                    (z, t)
                } else {
                    (f64::NAN, f64::NAN)
                }
            })
            .collect();
        let mut markers = Vec::with_capacity(2);
        if let Some(o) = optimum {
            markers.push(Marker {
                label: format!("fastest ζ = {}", si(o.zeta, "", 3)),
                at: (o.zeta, o.settling_time),
                shape: MarkerShape::Cross,
                ink: Ink::Vermillion,
            });
        }
        if let Some(ts) = ts_now {
            markers.push(Marker {
                label: "this design".into(),
                at: (zeta, ts),
                shape: MarkerShape::Dot,
                ink: Ink::Black,
            });
        }
        let band = pct(car.band_pct);
        let mut description = match optimum {
            Some(o) => format!(
                "Settling time into the ±{band} band against ζ for this car: fastest at ζ = {} \
                 ({}), just past a jump; it jumps down each time a rebound drops inside the band.",
                si(o.zeta, "", 3),
                si(o.settling_time, "s", 3)
            ),
            None => format!("Settling time into the ±{band} band against ζ."),
        };
        description.push_str(&match ts_now {
            Some(ts) => format!(
                " This design, ζ = {}, settles in {}.",
                si(zeta, "", 3),
                si(ts, "s", 3)
            ),
            None => format!(" This design, ζ = {}, never settles.", si(zeta, "", 3)),
        });
        Figure {
            description,
            // One curve, named by the axes and the title: no legend box to hide it.
            series: vec![Series {
                label: String::new(),
                points,
                style: LineStyle::solid(Ink::Blue, 2.5),
            }],
            markers,
            ..Figure::plot(
                format!("Settling time into ±{band} against ζ"),
                Axis::linear("damping ratio ζ", "", (0.0, z_hi)),
                Axis::linear("settling time t_s", "s", (0.0, y_top)),
            )
        }
    }
}

fn response_figure(car: &Car, metrics: Option<FreeMetrics>) -> (Figure, f64) {
    let family: Vec<(&str, f64, Option<SecondOrder>)> = FAMILY
        .iter()
        .map(|&(group, z)| (group, z, car.with_zeta(z)))
        .collect();
    let family_ts: Vec<Option<f64>> = family
        .iter()
        .map(|(_, _, s)| s.as_ref().and_then(|s| car.metrics(s)?.settling_time))
        .collect();
    let slowest = family_ts.iter().flatten().fold(0.0f64, |a, &b| a.max(b));
    let slowest = if slowest > 0.0 {
        slowest
    } else {
        6.0 / car.wn()
    };
    let ts_now = metrics.and_then(|m| m.settling_time);
    let t_end = 1.2 * slowest.max(ts_now.map_or(slowest, |t| t.min(2.5 * slowest)));
    let mm = 1000.0;
    let sample = |sys: &SecondOrder| -> Vec<(f64, f64)> {
        let r = FreeResponse::new(*sys, car.x0, 0.0);
        (0..SAMPLES)
            .map(|i| {
                let t = t_end * i as f64 / (SAMPLES - 1) as f64;
                (t, mm * r.displacement(t))
            })
            .collect()
    };
    let mut series = Vec::with_capacity(9);
    let mut markers = Vec::new();
    let mut legend_done: Vec<&str> = Vec::new();
    for (group, _, sys) in &family {
        let Some(sys) = sys else { continue };
        let (style, marker) = family_style(group);
        let points = sample(sys);
        if let Some(shape) = marker {
            // Marks along the curve, so the group is told apart without colour.
            let shift = if shape == MarkerShape::Cross {
                0.3
            } else {
                0.7
            };
            let r = FreeResponse::new(*sys, car.x0, 0.0);
            for j in 0..6 {
                let t = t_end * (j as f64 + shift) / 6.0;
                markers.push(Marker {
                    label: String::new(),
                    at: (t, mm * r.displacement(t)),
                    shape,
                    ink: style.ink,
                });
            }
        }
        let first = !legend_done.contains(group);
        if first {
            legend_done.push(group);
        }
        series.push(Series {
            label: if first {
                family_legend(group).to_string()
            } else {
                String::new()
            },
            points,
            style,
        });
    }
    let h = mm * car.band.fraction() * car.x0.abs();
    for sign in [1.0, -1.0] {
        series.push(Series {
            label: String::new(),
            points: vec![(0.0, sign * h), (t_end, sign * h)],
            style: LineStyle {
                ink: Ink::Black,
                dash: Dash::Dotted,
                width: 1.0,
            },
        });
    }
    let current = sample(&car.sys);
    let (lo, hi) = finite_extent(
        series
            .iter()
            .chain(std::iter::once(&Series {
                label: String::new(),
                points: current.clone(),
                style: LineStyle::solid(Ink::Blue, 1.0),
            }))
            .flat_map(|s| s.points.iter().map(|p| p.1)),
    )
    .unwrap_or((-mm * car.x0, mm * car.x0));
    // Head-room above x₀ for the legend box in the upper right.
    let span = hi - lo;
    let y = (lo - 0.06 * span, hi + 0.6 * span);
    // Named under the lower band line, right of the middle: text hangs below its point, and
    // there the curves are back near rest.
    markers.push(Marker {
        label: format!("±{} band", pct(car.band_pct)),
        at: (0.62 * t_end, -h - 0.015 * span),
        shape: MarkerShape::Label,
        ink: Ink::Black,
    });
    series.push(Series {
        label: format!("this design, ζ {}", si(car.zeta(), "", 3)),
        points: current,
        style: LineStyle::solid(Ink::Blue, 3.0),
    });
    let fig = Figure {
        description: describe_response(car, metrics, &family, &family_ts),
        series,
        markers,
        origin_lines: true,
        ..Figure::plot(
            "Body displacement x(t)",
            Axis::linear("time t", "s", (0.0, t_end)),
            Axis::linear("displacement x", "mm", y),
        )
    };
    (fig, t_end)
}

fn describe_response(
    car: &Car,
    metrics: Option<FreeMetrics>,
    family: &[(&str, f64, Option<SecondOrder>)],
    family_ts: &[Option<f64>],
) -> String {
    let regime = car.sys.regime();
    let band = pct(car.band_pct);
    let now = match metrics {
        Some(m) => {
            let settle = m
                .settling_time
                .map(|t| format!("stays within {band} of x₀ after {}", si(t, "s", 3)))
                .unwrap_or_else(|| "does not settle".to_string());
            let rebound = match m.rebound_time {
                Some(t) => format!(
                    "peak rebound {} at {}",
                    si(100.0 * m.peak_rebound, "%", 3),
                    si(t, "s", 3)
                ),
                None => "no rebound".to_string(),
            };
            format!(
                "This design (ζ = {}, {}): {}, {}, {}.",
                si(car.zeta(), "", 3),
                regime.key(),
                crossings_text(&m),
                settle,
                rebound
            )
        }
        None if regime == Regime::Undamped => format!(
            "This design (ζ = 0, undamped): oscillates forever between ±{} at {}.",
            si(car.x0.abs(), "m", 3),
            si(car.sys.natural_frequency_hz().unwrap_or(0.0), "Hz", 3)
        ),
        None => format!("This design ({}): does not settle.", regime.key()),
    };
    let fam: Vec<String> = family
        .iter()
        .zip(family_ts)
        .map(|((group, z, _), ts)| match ts {
            Some(t) => format!("{group} ζ = {} in {}", si(*z, "", 2), si(*t, "s", 3)),
            None => format!("{group} ζ = {} does not settle", si(*z, "", 2)),
        })
        .collect();
    format!(
        "{now} Preset family on this car, settling into ±{band}: {}.",
        fam.join("; ")
    )
}

fn sensitivity_figure(
    car: &Car,
    mass_spread: Option<Spread>,
    optimum: Option<ZetaOptimum>,
) -> Figure {
    let x = car.dm_pct / 100.0;
    let (m_lo, m_hi) = (car.m * (1.0 - x), car.m * (1.0 + x));
    let zeta_at = |m: f64| {
        SecondOrder::mechanical(m, car.c, car.k)
            .ok()
            .and_then(|s| s.damping_ratio())
            .unwrap_or(f64::NAN)
    };
    let points: Vec<(f64, f64)> = (0..STRIP_POINTS)
        .map(|i| {
            let m = m_lo + (m_hi - m_lo) * i as f64 / (STRIP_POINTS - 1) as f64;
            (zeta_at(m), m)
        })
        .collect();
    let zeta = car.zeta();
    let z_opt = optimum.map(|o| o.zeta);
    let (z_min, z_max) = mass_spread.map_or((zeta, zeta), |s| (s.min, s.max));
    let (xl, xh) = finite_extent([z_min, z_max, zeta, z_opt.unwrap_or(zeta)]).map_or(
        (0.0, 1.0),
        |(lo, hi)| {
            let span = (hi - lo).max(0.02 * hi.abs()).max(1e-6);
            // Room on the right for the marker labels, which are drawn right of their point.
            (lo - 0.1 * span, hi + 0.3 * span)
        },
    );
    let y = padded((m_lo.min(car.m), m_hi.max(car.m)), 0.25);
    // No legend box (it would cover the curve): the axes name the curve, labels the rest.
    let mut series = vec![Series {
        label: String::new(),
        points,
        style: LineStyle::solid(Ink::Blue, 3.0),
    }];
    let mut markers = Vec::with_capacity(4);
    if let Some(z) = z_opt {
        series.push(Series {
            label: String::new(),
            points: vec![(z, y.0), (z, y.1)],
            style: LineStyle {
                ink: Ink::Vermillion,
                dash: Dash::Dashed,
                width: 1.5,
            },
        });
    }
    let dm = pct(car.dm_pct);
    markers.extend([
        Marker {
            label: "nominal".into(),
            at: (zeta, car.m),
            shape: MarkerShape::Dot,
            ink: Ink::Black,
        },
        Marker {
            label: format!("m − {dm}"),
            at: (zeta_at(m_lo), m_lo),
            shape: MarkerShape::Cross,
            ink: Ink::Blue,
        },
        Marker {
            label: format!("m + {dm}"),
            at: (zeta_at(m_hi), m_hi),
            shape: MarkerShape::Cross,
            ink: Ink::Blue,
        },
    ]);
    let x_label = match z_opt {
        Some(z) => format!("damping ratio ζ (dashed: fastest ζ = {})", si(z, "", 3)),
        None => "damping ratio ζ".to_string(),
    };
    let mut description = match mass_spread {
        Some(s) => format!(
            "With the sprung mass between {} and {} (±{}) and the same damper and spring, ζ \
             ranges from {} to {} (nominal {}); the linear estimate is {} to {}.",
            si(m_lo, "kg", 3),
            si(m_hi, "kg", 3),
            pct(car.dm_pct),
            si(s.min, "", 3),
            si(s.max, "", 3),
            si(s.nominal, "", 3),
            si(s.linear_min, "", 3),
            si(s.linear_max, "", 3)
        ),
        None => "The damping-ratio range is undefined for this design.".to_string(),
    };
    if let (Some(z), Some(s)) = (z_opt, mass_spread) {
        description.push_str(&if s.min < z && z < s.max {
            format!(
                " The fastest-settling ζ = {} lies inside this range: loads that push ζ below \
                 it settle markedly later.",
                si(z, "", 3)
            )
        } else {
            format!(
                " The fastest-settling ζ = {} lies outside this range.",
                si(z, "", 3)
            )
        });
    }
    Figure {
        description,
        series,
        markers,
        ..Figure::plot(
            "ζ when the sprung mass varies",
            Axis::linear(x_label, "", (xl, xh)),
            Axis::linear("sprung mass m", "kg", y),
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn spec() -> DemoSpec {
        QuarterCar::new().spec()
    }

    fn run_on(d: &mut QuarterCar, query: &str) -> Frame {
        let (p, _) = crate::params::resolve_query(&spec(), query);
        d.update(&p)
    }

    fn value(f: &Frame, key: &str) -> f64 {
        f.readouts
            .iter()
            .find(|r| r.key == key)
            .map(|r| r.data_value.parse::<f64>().unwrap_or(f64::NAN))
            .unwrap()
    }

    fn close(a: f64, b: f64, tol: f64) -> bool {
        (a - b).abs() <= tol * (1.0 + b.abs())
    }

    #[test]
    fn defaults_of_c_and_zeta_agree() {
        assert!(close(
            C_DEFAULT,
            2.0 * ZETA_DEFAULT * (M_DEFAULT * K_DEFAULT).sqrt(),
            1e-15
        ));
        let f = run_on(&mut QuarterCar::new(), "");
        assert!(close(value(&f, "zeta"), 0.3, 1e-14));
    }

    #[test]
    fn readouts_match_closed_forms() {
        let f = run_on(&mut QuarterCar::new(), "c=1610");
        let wn = 80.0f64.sqrt();
        let zeta = 1610.0 / (2.0 * 7.2e6f64.sqrt());
        assert!(close(value(&f, "wn"), wn, 1e-14));
        assert!(close(value(&f, "fn"), wn / std::f64::consts::TAU, 1e-14));
        assert!(close(value(&f, "zeta"), zeta, 1e-14));
        assert!(close(
            value(&f, "wd"),
            wn * (1.0 - zeta * zeta).sqrt(),
            1e-12
        ));
        let rebound = (-std::f64::consts::PI * zeta / (1.0 - zeta * zeta).sqrt()).exp();
        assert!(close(value(&f, "overshoot"), 100.0 * rebound, 1e-10));
        assert!(close(
            value(&f, "peak_time"),
            std::f64::consts::PI / (wn * (1.0 - zeta * zeta).sqrt()),
            1e-12
        ));
        // 5 % band from rest: the optimum is ln 20/√(π² + ln² 20).
        let l = 20.0f64.ln();
        let z_opt = l / (std::f64::consts::PI.powi(2) + l * l).sqrt();
        assert!(close(value(&f, "zeta_argmin"), z_opt, 1e-6));
        // ±10 % mass: ζ ∝ m^−½.
        assert!(close(value(&f, "zeta_lo"), zeta / 1.1f64.sqrt(), 1e-12));
        assert!(close(value(&f, "zeta_hi"), zeta / 0.9f64.sqrt(), 1e-12));
        let ts = value(&f, "settling_time");
        assert!(ts > 1.105 && ts < 1.2, "{ts}");
    }

    #[test]
    fn moving_zeta_sets_c_and_moving_c_sets_zeta() {
        let s = spec();
        let mut d = QuarterCar::new();
        let mut p = Params::defaults(&s);
        d.update(&p);
        p.set_raw(&s, "zeta", "0.7");
        let f = d.update(&p);
        let crit = 2.0 * 7.2e6f64.sqrt();
        assert!(close(value(&f, "c"), 0.7 * crit, 1e-14));
        assert!(close(value(&f, "zeta"), 0.7, 1e-14));
        assert_eq!(d.derived_params()[0], ("c", value(&f, "c")));
        // Without a write-back the c parameter is stale; moving m keeps the damper.
        p.set_raw(&s, "m", "400");
        let f = d.update(&p);
        assert!(close(value(&f, "c"), 0.7 * crit, 1e-14));
        let z = 0.7 * crit / (2.0 * (400.0f64 * 24_000.0).sqrt());
        assert!(close(value(&f, "zeta"), z, 1e-14));
        // Moving c wins over the (unchanged) ζ slider.
        p.set_raw(&s, "c", "3000");
        let f = d.update(&p);
        assert_eq!(value(&f, "c"), 3000.0);
        // With a write-back of the derived values the next update sees no move.
        for (k, v) in d.derived_params() {
            p.set_raw(&s, k, &format!("{v}"));
        }
        let again = d.update(&p);
        assert_eq!(value(&again, "c"), 3000.0);
        assert_eq!(again.readouts, f.readouts);
        // And a later ζ move after the write-back still counts.
        p.set_raw(&s, "zeta", "1");
        let f = d.update(&p);
        assert!(close(value(&f, "zeta"), 1.0, 1e-14));
    }

    #[test]
    fn url_rule_c_wins_when_both_are_given() {
        let f = run_on(&mut QuarterCar::new(), "zeta=0.9&c=3000");
        assert_eq!(value(&f, "c"), 3000.0);
        let f = run_on(&mut QuarterCar::new(), "c=3000&zeta=0.9");
        assert_eq!(value(&f, "c"), 3000.0);
        let f = run_on(&mut QuarterCar::new(), "zeta=0.9");
        assert!(close(value(&f, "zeta"), 0.9, 1e-14));
    }

    #[test]
    fn presets_give_consistent_c_and_zeta() {
        for preset in spec().presets {
            let q: Vec<String> = preset
                .values
                .iter()
                .map(|(k, v)| format!("{k}={v}"))
                .collect();
            let f = run_on(&mut QuarterCar::new(), &q.join("&"));
            let z = preset.values.iter().find(|(k, _)| *k == "zeta").unwrap().1;
            assert!(close(value(&f, "zeta"), z, 1e-12), "{}", preset.label);
        }
        let crit = run_on(&mut QuarterCar::new(), "zeta=1");
        assert_eq!(
            crit.readouts[0].data_value, "critically damped",
            "ζ = 1 from the slider is exactly critical"
        );
    }

    #[test]
    fn settling_curve_breaks_at_jumps_and_marks_the_minimum() {
        let f = run_on(&mut QuarterCar::new(), "");
        let fig = &f.figures[1];
        let breaks = fig.series[0].points.iter().filter(|p| p.0.is_nan()).count();
        assert!(breaks >= 3, "{breaks}");
        assert!(fig.markers.iter().any(|m| m.label.starts_with("fastest")));
        assert!(fig.description.contains("0.690"), "{}", fig.description);
    }

    #[test]
    fn descriptions_follow_the_design() {
        let mut d = QuarterCar::new();
        let light = run_on(&mut d, "zeta=0.2").figures[0].description.clone();
        let heavy = run_on(&mut QuarterCar::new(), "zeta=2").figures[0]
            .description
            .clone();
        assert!(light.contains("crosses equilibrium"), "{light}");
        assert!(
            heavy.contains("overdamped") && heavy.contains("no rebound"),
            "{heavy}"
        );
        let none = run_on(&mut QuarterCar::new(), "c=0").figures[0]
            .description
            .clone();
        assert!(none.contains("oscillates forever"), "{none}");
        let past_jump = run_on(&mut QuarterCar::new(), "zeta=0.7").figures[0]
            .description
            .clone();
        assert!(past_jump.contains("settles before crossing"), "{past_jump}");
        let strip = run_on(&mut QuarterCar::new(), "zeta=0.7").figures[2]
            .description
            .clone();
        assert!(strip.contains("inside this range"), "{strip}");
    }
}
