//! `design`: the (k, c) design space of a quarter car. A heat map of one metric (settling
//! time, peak rebound, RMS body acceleration on a random road, peak transmissibility) over a
//! grid of spring and damper rates, recomputed live as the sprung mass moves, with iso-ζ
//! lines, the Pareto front of comfort against settling, and the chosen design's response.

// Not yet reshaped: still does maths the solver should do (issue "one shape").
#![allow(clippy::disallowed_methods)]

use super::{Demo, Frame, Readout};
use crate::figure::{finite_extent, padded, Axis, Dash, Figure, Heatmap, LineStyle, Marker};
use crate::figure::{MarkerShape, Series};
use crate::format::{si, significant};
use crate::params::Params;
use crate::plot::Ink;
use crate::spec::{DemoSpec, ParamSpec, PlotSpec, Preset, ReadoutSpec};
use zeta_solver::design::pareto::pareto_front_into;
use zeta_solver::design::sweep::{
    body_acceleration_rms, iso_zeta_line_into, sweep_kc_into, KcMaps, KcSweepConfig, RoadInput,
};
use zeta_solver::metrics::{free::FreeMetrics, SettlingBand};
use zeta_solver::{FreeResponse, SecondOrder};

/// Initial displacement of the shown response \[m\] (the map's metrics are relative to it).
const X0: f64 = 0.06;
/// Samples of each response curve.
const SAMPLES: usize = 600;
/// Points of each iso-ζ line.
const ISO_POINTS: usize = 120;
/// Damping ratios of the iso-ζ lines.
const ISO_ZETAS: [f64; 5] = [0.2, 0.3, 0.5, 0.7, 1.0];
/// Vehicle speed for the road input \[m/s\] (72 km/h).
const SPEED: f64 = 20.0;
/// The tyre's low-pass on the road input \[rad/s\]: about wheel hop, 10 Hz.
const CUTOFF: f64 = std::f64::consts::TAU * 10.0;
/// ISO 8608 roughness `G_d(n0)` \[m³\] of road classes A–D.
const ROAD_CLASSES: [f64; 4] = [16e-6, 64e-6, 256e-6, 1024e-6];
/// Blank strips beyond the map (fractions of its span) that hold the iso-ζ labels.
const RIGHT_STRIP: f64 = 0.13;
const TOP_STRIP: f64 = 0.09;

/// Wall-clock stopwatch for the compute-time readouts: `performance.now()` in the browser,
/// `Instant` natively. Timing is only reported, never used in any result.
pub(crate) struct Stopwatch {
    #[cfg(target_arch = "wasm32")]
    start: f64,
    #[cfg(not(target_arch = "wasm32"))]
    start: std::time::Instant,
}

#[cfg(target_arch = "wasm32")]
fn browser_now_ms() -> f64 {
    use wasm_bindgen::JsCast;
    let global = js_sys::global();
    js_sys::Reflect::get(&global, &"performance".into())
        .ok()
        .filter(|p| p.is_object())
        .and_then(|perf| {
            let now = js_sys::Reflect::get(&perf, &"now".into()).ok()?;
            let now = now.dyn_into::<js_sys::Function>().ok()?;
            now.call0(&perf).ok()?.as_f64()
        })
        .unwrap_or_else(js_sys::Date::now)
}

impl Stopwatch {
    /// Starts timing.
    pub(crate) fn start() -> Self {
        Self {
            #[cfg(target_arch = "wasm32")]
            start: browser_now_ms(),
            #[cfg(not(target_arch = "wasm32"))]
            start: std::time::Instant::now(),
        }
    }

    /// Milliseconds since [`Stopwatch::start`].
    pub(crate) fn elapsed_ms(&self) -> f64 {
        #[cfg(target_arch = "wasm32")]
        {
            (browser_now_ms() - self.start).max(0.0)
        }
        #[cfg(not(target_arch = "wasm32"))]
        {
            self.start.elapsed().as_secs_f64() * 1e3
        }
    }
}

/// `v` with its unit; accelerations stay in m/s² (no "mm/s²").
fn fmt_unit(v: f64, unit: &str, sig: usize) -> String {
    if unit == "m/s²" {
        format!("{} m/s²", significant(v, sig))
    } else {
        si(v, unit, sig)
    }
}

/// Map axes are in kN/m and kN·s/m so the tick labels stay short.
const KILO: f64 = 1e3;

/// A compute-time readout in milliseconds (the unit the key names).
pub(crate) fn ms_readout(key: &'static str, ms: f64) -> Readout {
    if ms.is_finite() {
        Readout {
            key,
            text: format!("{} ms", significant(ms.max(0.0), 3)),
            data_value: format!("{}", ms.max(0.0)),
        }
    } else {
        Readout::number(key, None, "ms", 3)
    }
}

/// The metric shown on the map.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Metric {
    SettlingTime,
    PeakRebound,
    AccelRms,
    PeakTransmissibility,
}

impl Metric {
    const OPTIONS: [(&'static str, &'static str); 4] = [
        ("settling_time", "settling time"),
        ("peak_rebound", "peak rebound"),
        ("accel_rms", "RMS body acceleration (comfort)"),
        ("peak_transmissibility", "peak transmissibility"),
    ];

    fn from_index(v: f64) -> Self {
        match v.round() as i64 {
            1 => Metric::PeakRebound,
            2 => Metric::AccelRms,
            3 => Metric::PeakTransmissibility,
            _ => Metric::SettlingTime,
        }
    }

    /// Name, unit and factor from the solver's value to the shown one.
    fn describe(self) -> (&'static str, &'static str, f64) {
        match self {
            Metric::SettlingTime => ("settling time", "s", 1.0),
            Metric::PeakRebound => ("peak rebound", "%", 100.0),
            Metric::AccelRms => ("RMS body acceleration", "m/s²", 1.0),
            Metric::PeakTransmissibility => ("peak transmissibility", "", 1.0),
        }
    }

    /// Short name for the plot title.
    fn short(self) -> &'static str {
        match self {
            Metric::SettlingTime => "Settling time",
            Metric::PeakRebound => "Peak rebound",
            Metric::AccelRms => "RMS acceleration",
            Metric::PeakTransmissibility => "Peak transmissibility",
        }
    }

    /// Whether the colours follow the logarithm (metrics spanning decades).
    fn log_colour(self) -> bool {
        !matches!(self, Metric::PeakRebound)
    }

    fn values(self, maps: &KcMaps) -> &[f64] {
        match self {
            Metric::SettlingTime => &maps.settling_time,
            Metric::PeakRebound => &maps.peak_rebound,
            Metric::AccelRms => &maps.accel_rms,
            Metric::PeakTransmissibility => &maps.peak_transmissibility,
        }
    }
}

/// Everything the sweep depends on; the map is recomputed only when this changes.
#[derive(Debug, Clone, Copy, PartialEq)]
struct SweepKey {
    m: f64,
    band: f64,
    road: f64,
    k: (f64, f64),
    c: (f64, f64),
    n: usize,
}

/// The design-space demo. Holds the sweep's buffers so a slider move reuses them.
#[derive(Debug, Default)]
pub struct DesignSpace {
    k_axis: Vec<f64>,
    c_axis: Vec<f64>,
    maps: KcMaps,
    key: Option<SweepKey>,
    /// Duration of the last full sweep \[ms\].
    sweep_ms: f64,
    /// Number of sweeps performed (for tests of the cache).
    sweeps: u64,
    /// Grid indices on the Pareto front, by increasing settling time.
    front: Vec<usize>,
    iso_c: Vec<f64>,
    iso_k: Vec<f64>,
    /// Axes of the last Pareto plot, for picking the nearest front design.
    pareto_ranges: ((f64, f64), (f64, f64)),
}

const EQUATION: &str = "<math display=\"block\"><mrow>\
<mi>m</mi><mover><mi>x</mi><mo>¨</mo></mover><mo>+</mo><mi>c</mi><mover><mi>x</mi><mo>˙</mo></mover>\
<mo>+</mo><mi>k</mi><mi>x</mi><mo>=</mo><mn>0</mn><mo>,</mo><mspace width=\"1em\"/>\
<mi>ζ</mi><mo>=</mo><mfrac><mi>c</mi><mrow><mn>2</mn><msqrt><mi>k</mi><mi>m</mi></msqrt></mrow></mfrac>\
</mrow></math>";

/// Validated inputs of one update.
struct Inputs {
    key: SweepKey,
    metric: Metric,
    k: f64,
    c: f64,
    band: SettlingBand,
    road: RoadInput,
}

fn inputs(params: &Params) -> Option<Inputs> {
    let n = params.get("n").round().clamp(2.0, 400.0) as usize;
    let band_pct = params.get("band");
    let band = SettlingBand::new(band_pct / 100.0).ok()?;
    let road_i = (params.get("road").round().max(0.0) as usize).min(ROAD_CLASSES.len() - 1);
    let road = RoadInput::iso8608(ROAD_CLASSES[road_i], SPEED, CUTOFF).ok()?;
    let key = SweepKey {
        m: params.get("m"),
        band: band_pct,
        road: road_i as f64,
        k: (params.get("k_min"), params.get("k_max")),
        c: (params.get("c_min"), params.get("c_max")),
        n,
    };
    let ok = key.m > 0.0 && key.k.0 > 0.0 && key.k.1 > key.k.0 && key.c.0 > 0.0;
    (ok && key.c.1 > key.c.0).then_some(Inputs {
        key,
        metric: Metric::from_index(params.get("metric")),
        k: params.get("k"),
        c: params.get("c"),
        band,
        road,
    })
}

/// Cell centres of `n` equal cells over `(lo, hi)`, written into `out`.
fn centres_into(lo: f64, hi: f64, n: usize, out: &mut Vec<f64>) {
    out.clear();
    let d = (hi - lo) / n as f64;
    out.extend((0..n).map(|i| lo + (i as f64 + 0.5) * d));
}

/// `(lo, hi)` as "10–60 kN/m": both ends in the unit prefix of `hi`, trailing zeros dropped.
fn span_text(lo: f64, hi: f64, unit: &str) -> String {
    let shown = si(hi, unit, 3);
    let full_unit = shown.split_once(' ').map_or("", |(_, u)| u).to_string();
    let prefix = full_unit.strip_suffix(unit).unwrap_or("");
    let scale = match prefix {
        "G" => 1e9,
        "M" => 1e6,
        "k" => 1e3,
        "m" => 1e-3,
        "µ" => 1e-6,
        _ => 1.0,
    };
    let trim = |v: f64| {
        let t = significant(v / scale, 3);
        if t.contains('.') {
            t.trim_end_matches('0').trim_end_matches('.').to_string()
        } else {
            t
        }
    };
    format!("{}–{} {}", trim(lo), trim(hi), full_unit)
}

impl DesignSpace {
    fn sweep_if_needed(&mut self, inp: &Inputs) {
        if self.key == Some(inp.key) {
            return;
        }
        let key = inp.key;
        let watch = Stopwatch::start();
        centres_into(key.k.0, key.k.1, key.n, &mut self.k_axis);
        centres_into(key.c.0, key.c.1, key.n, &mut self.c_axis);
        let cfg = KcSweepConfig {
            mass: key.m,
            band: inp.band,
            road: inp.road,
        };
        sweep_kc_into(&self.k_axis, &self.c_axis, &cfg, &mut self.maps);
        pareto_front_into(
            &self.maps.settling_time,
            &self.maps.accel_rms,
            &mut self.front,
        );
        self.sweep_ms = watch.elapsed_ms();
        self.sweeps += 1;
        self.key = Some(key);
    }

    /// `(k, c)` of grid cell `i`.
    fn design_at(&self, i: usize) -> Option<(f64, f64)> {
        let n = self.k_axis.len().max(1);
        Some((*self.k_axis.get(i % n)?, *self.c_axis.get(i / n)?))
    }

    fn map_figure(&mut self, inp: &Inputs, sel: &Selected) -> Figure {
        let key = inp.key;
        let (name, unit, factor) = inp.metric.describe();
        let raw = inp.metric.values(&self.maps);
        let range = finite_extent(raw.iter().map(|v| v * factor)).unwrap_or((0.0, 1.0));
        let log = inp.metric.log_colour() && range.0 > 0.0;
        let colour = |v: f64| if log { (v * factor).ln() } else { v * factor };
        let values: Vec<f64> = raw.iter().map(|&v| colour(v)).collect();
        let scale = if log {
            (range.0.ln(), range.1.ln())
        } else {
            range
        };
        let best = raw
            .iter()
            .enumerate()
            .filter(|(_, v)| v.is_finite())
            .min_by(|a, b| a.1.total_cmp(b.1))
            .map(|(i, &v)| (i, v * factor));
        let (k0, k1) = key.k;
        let (c0, c1) = key.c;
        let x_hi = (k1 + RIGHT_STRIP * (k1 - k0)) / KILO;
        let y_hi = (c1 + TOP_STRIP * (c1 - c0)) / KILO;
        let mut series = Vec::with_capacity(ISO_ZETAS.len());
        let mut markers = Vec::with_capacity(ISO_ZETAS.len() + 2);
        for (j, &zeta) in ISO_ZETAS.iter().enumerate() {
            // The part of the line c = 2ζ√(km) inside the map: k from where c = c0 (or k0)
            // to where c = c1 (or k1).
            let k_of_c = |c: f64| (c / (2.0 * zeta)).powi(2) / key.m;
            let ka = k_of_c(c0).max(k0);
            let kb = k_of_c(c1).min(k1);
            if ka >= kb {
                continue;
            }
            self.iso_k.clear();
            self.iso_k.extend(
                (0..ISO_POINTS).map(|i| ka + (kb - ka) * i as f64 / (ISO_POINTS - 1) as f64),
            );
            self.iso_c.resize(ISO_POINTS, f64::NAN);
            iso_zeta_line_into(zeta, key.m, &self.iso_k, &mut self.iso_c);
            let points: Vec<(f64, f64)> = self
                .iso_k
                .iter()
                .zip(&self.iso_c)
                .map(|(&k, &c)| (k / KILO, c.clamp(c0, c1) / KILO))
                .collect();
            let end = points.last().copied().unwrap_or((kb / KILO, c1 / KILO));
            // Label in the blank strip where the line leaves the map (alternating heights
            // on the top strip so neighbours do not collide).
            let (dk, dc) = ((k1 - k0) / KILO, (c1 - c0) / KILO);
            let at = if kb >= k1 * (1.0 - 1e-9) {
                (k1 / KILO + 0.012 * dk, end.1 + 0.03 * dc)
            } else {
                let lift = if j % 2 == 0 { 0.085 } else { 0.045 };
                (end.0 - 0.03 * dk, c1 / KILO + lift * dc)
            };
            markers.push(Marker {
                label: format!("ζ={zeta}"),
                at,
                shape: MarkerShape::Label,
                ink: Ink::Black,
            });
            series.push(Series {
                // Labelled on the plot itself; a legend box would cover the map.
                label: String::new(),
                points,
                style: LineStyle {
                    ink: Ink::Vermillion,
                    dash: Dash::Dashed,
                    width: 2.0,
                },
            });
        }
        let mut best_text = String::from("no cell is defined");
        if let Some((i, v)) = best {
            if let Some((bk, bc)) = self.design_at(i) {
                markers.push(Marker {
                    // Explained in the caption: a label here collides with the iso-ζ labels
                    // (the best cell is usually on an edge).
                    label: String::new(),
                    at: (bk / KILO, bc / KILO),
                    shape: MarkerShape::Cross,
                    ink: Ink::Black,
                });
                best_text = format!(
                    "lowest {} at k = {}, c = {}",
                    fmt_unit(v, unit, 3),
                    si(bk, "N/m", 3),
                    si(bc, "N·s/m", 3)
                );
            }
        }
        let inside = |v: f64, lo: f64, hi: f64| v >= lo && v <= hi;
        if inside(inp.k, k0, k1) && inside(inp.c, c0, c1) {
            markers.push(Marker {
                label: "selected".into(),
                at: (inp.k / KILO, inp.c / KILO),
                shape: MarkerShape::Dot,
                ink: Ink::Black,
            });
        }
        let shown = |v: f64| fmt_unit(v, unit, 3);
        let selected_text = match (sel.zeta, sel.settling_time) {
            (Some(z), Some(t)) => format!(
                "selected design ζ = {} settles in {}",
                significant(z, 2),
                si(t, "s", 3)
            ),
            (Some(z), None) => format!("selected design ζ = {} does not settle", significant(z, 2)),
            _ => "no valid design selected".to_string(),
        };
        let outside = if inside(inp.k, k0, k1) && inside(inp.c, c0, c1) {
            ""
        } else {
            " (outside the map)"
        };
        let description = format!(
            "{} over k {} and c {} ({} × {} grid, m = {}): {}; {}{}. Colour from dark purple \
             ({}) to yellow ({}){}. Dashed iso-ζ lines for ζ = 0.2, 0.3, 0.5, 0.7 and 1; × marks the lowest \
             cell, ● the selected design.",
            capitalise(name),
            span_text(k0, k1, "N/m"),
            span_text(c0, c1, "N·s/m"),
            key.n,
            key.n,
            si(key.m, "kg", 3),
            best_text,
            selected_text,
            outside,
            shown(range.0),
            shown(range.1),
            if log { " on a logarithmic scale" } else { "" },
        );
        let legend_unit = if unit.is_empty() {
            String::new()
        } else {
            format!(" [{unit}]")
        };
        Figure {
            description,
            series,
            markers,
            heatmap: Some(Heatmap {
                nx: key.n,
                ny: key.n,
                values,
                x_edges: (k0 / KILO, k1 / KILO),
                y_edges: (c0 / KILO, c1 / KILO),
                scale,
                label: format!("{}{name}{legend_unit}", if log { "log of " } else { "" }),
            }),
            ..Figure::plot(
                format!(
                    "{}: {} → {}",
                    inp.metric.short(),
                    shown(range.0),
                    shown(range.1)
                ),
                Axis::linear("spring rate k", "kN/m", (k0 / KILO, x_hi)),
                Axis::linear("damper rate c", "kN·s/m", (c0 / KILO, y_hi)),
            )
        }
    }

    fn pareto_figure(&mut self, inp: &Inputs, sel: &Selected) -> Figure {
        let pts: Vec<(f64, f64)> = self
            .front
            .iter()
            .filter_map(|&i| {
                Some((
                    *self.maps.settling_time.get(i)?,
                    *self.maps.accel_rms.get(i)?,
                ))
            })
            .collect();
        let sel_pt = sel.settling_time.zip(sel.accel_rms);
        let xs = pts.iter().map(|p| p.0).chain(sel_pt.map(|p| p.0));
        let ys = pts.iter().map(|p| p.1).chain(sel_pt.map(|p| p.1));
        let xr = padded(finite_extent(xs).unwrap_or((0.0, 1.0)), 0.08);
        let yr = padded(finite_extent(ys).unwrap_or((0.0, 1.0)), 0.1);
        let xr = (xr.0.max(0.0), xr.1);
        let yr = (yr.0.max(0.0), yr.1);
        self.pareto_ranges = (xr, yr);
        let mut series = Vec::with_capacity(2);
        // Designs with the selected spring and every damper on the grid: how c alone trades
        // comfort against settling.
        let n = self.k_axis.len();
        let column = self
            .k_axis
            .iter()
            .enumerate()
            .min_by(|a, b| (a.1 - inp.k).abs().total_cmp(&(b.1 - inp.k).abs()))
            .map(|(i, &k)| (i, k));
        if let Some((ik, kcol)) = column {
            let inside = |(x, y): (f64, f64)| x >= xr.0 && x <= xr.1 && y >= yr.0 && y <= yr.1;
            let points: Vec<(f64, f64)> = (0..self.c_axis.len())
                .map(|ic| {
                    let i = ic * n + ik;
                    let p = (
                        self.maps.settling_time.get(i).copied().unwrap_or(f64::NAN),
                        self.maps.accel_rms.get(i).copied().unwrap_or(f64::NAN),
                    );
                    if inside(p) {
                        p
                    } else {
                        (f64::NAN, f64::NAN)
                    }
                })
                .collect();
            series.push(Series {
                label: format!("k = {}, c varied", si(kcol, "N/m", 3)),
                points,
                style: LineStyle {
                    ink: Ink::Green,
                    dash: Dash::Dotted,
                    width: 2.0,
                },
            });
        }
        let front_len = pts.len();
        let ends = (pts.first().copied(), pts.last().copied());
        series.push(Series {
            label: "Pareto front".into(),
            points: pts,
            style: LineStyle::solid(Ink::Blue, 2.5),
        });
        let mut markers = Vec::new();
        if let Some(p) = sel_pt {
            markers.push(Marker {
                label: "selected".into(),
                at: p,
                shape: MarkerShape::Dot,
                ink: Ink::Vermillion,
            });
        }
        let description = match ends {
            (Some(a), Some(b)) => format!(
                "Pareto front of {} non-dominated designs: from the fastest, settling in {} \
                 with {} RMS acceleration, to the smoothest, {} with {}. {}",
                front_len,
                si(a.0, "s", 3),
                fmt_unit(a.1, "m/s²", 3),
                fmt_unit(b.1, "m/s²", 3),
                si(b.0, "s", 3),
                match sel_pt {
                    Some((t, a)) => format!(
                        "The selected design settles in {} with {}.",
                        si(t, "s", 3),
                        fmt_unit(a, "m/s²", 3)
                    ),
                    None => "The selected design has no settling time.".into(),
                }
            ),
            _ => "No design on the grid has both a settling time and an RMS acceleration.".into(),
        };
        Figure {
            description,
            series,
            markers,
            ..Figure::plot(
                "Comfort vs settling: Pareto front",
                Axis::linear("settling time", "s", xr),
                Axis::linear("RMS body acceleration", "m/s²", yr),
            )
        }
    }
}

fn capitalise(s: &str) -> String {
    let mut c = s.chars();
    match c.next() {
        Some(f) => f.to_uppercase().chain(c).collect(),
        None => String::new(),
    }
}

/// The selected design's figures of merit.
struct Selected {
    sys: Option<SecondOrder>,
    zeta: Option<f64>,
    settling_time: Option<f64>,
    overshoot: Option<f64>,
    accel_rms: Option<f64>,
}

fn selected(inp: &Inputs, m: f64) -> Selected {
    let sys = SecondOrder::mechanical(m, inp.c, inp.k).ok();
    let metrics = sys.and_then(|s| FreeMetrics::exact(&s, X0, 0.0, inp.band));
    Selected {
        sys,
        zeta: sys.and_then(|s| s.damping_ratio()),
        settling_time: metrics.and_then(|m| m.settling_time),
        overshoot: metrics.map(|m| 100.0 * m.peak_rebound),
        accel_rms: body_acceleration_rms(m, inp.c, inp.k, &inp.road),
    }
}

fn response_figure(inp: &Inputs, sel: &Selected, best: Option<(f64, f64)>) -> Figure {
    let best_sys = best.and_then(|(k, c)| SecondOrder::mechanical(inp.key.m, c, k).ok());
    let best_ts = best_sys
        .and_then(|s| FreeMetrics::exact(&s, X0, 0.0, inp.band))
        .and_then(|m| m.settling_time);
    let longest = sel
        .settling_time
        .into_iter()
        .chain(best_ts)
        .fold(0.0f64, f64::max);
    let t_end = if longest > 0.0 {
        (1.4 * longest).clamp(0.3, 30.0)
    } else {
        4.0
    };
    let curve = |sys: &SecondOrder| -> Vec<(f64, f64)> {
        let r = FreeResponse::new(*sys, X0, 0.0);
        (0..SAMPLES)
            .map(|i| {
                let t = t_end * i as f64 / (SAMPLES - 1) as f64;
                (t, r.displacement(t))
            })
            .collect()
    };
    let h = inp.band.fraction() * X0;
    let mut series = Vec::with_capacity(4);
    for (sign, label) in [(1.0, "settling band"), (-1.0, "")] {
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
    if let Some(sys) = best_sys {
        series.push(Series {
            label: "fastest on the grid".into(),
            points: curve(&sys),
            style: LineStyle {
                ink: Ink::Green,
                dash: Dash::Dashed,
                width: 2.0,
            },
        });
    }
    let mut markers = Vec::new();
    if let Some(sys) = &sel.sys {
        series.push(Series {
            label: "selected design".into(),
            points: curve(sys),
            style: LineStyle::solid(Ink::Blue, 2.5),
        });
        if let Some(t) = sel.settling_time.filter(|&t| t <= t_end) {
            let x = FreeResponse::new(*sys, X0, 0.0).displacement(t);
            markers.push(Marker {
                label: "settled".into(),
                at: (t, x),
                shape: MarkerShape::Cross,
                ink: Ink::Vermillion,
            });
        }
    }
    let ys = series.iter().flat_map(|s| s.points.iter().map(|p| p.1));
    let (lo, hi) = padded(finite_extent(ys).unwrap_or((-X0, X0)), 0.08);
    // Headroom above the curves for the legend box.
    let y = (lo, hi + 0.55 * (hi - lo));
    let description = match (sel.zeta, sel.settling_time, sel.overshoot) {
        (Some(z), Some(t), Some(o)) => format!(
            "Selected design (ζ = {}) released from {}: rebounds {} and stays within {} % \
             after {}{}.",
            significant(z, 3),
            si(X0, "m", 2),
            si(o, "%", 3),
            inp.key.band,
            si(t, "s", 3),
            match best_ts {
                Some(tb) => format!(
                    "; the fastest design on the grid (k = {}, c = {}) settles in {}",
                    best.map_or(String::new(), |b| si(b.0, "N/m", 3)),
                    best.map_or(String::new(), |b| si(b.1, "N·s/m", 3)),
                    si(tb, "s", 3)
                ),
                None => String::new(),
            }
        ),
        _ => "The selected design does not settle.".into(),
    };
    Figure {
        description,
        series,
        markers,
        origin_lines: true,
        ..Figure::plot(
            "Selected design: free response x(t)",
            Axis::linear("time t", "s", (0.0, t_end)),
            Axis::linear("displacement x", "m", y),
        )
    }
}

impl Demo for DesignSpace {
    fn spec(&self) -> DemoSpec {
        DemoSpec {
            id: "design",
            title: "Design space (k, c)",
            summary: "Every cell of the map is one quarter car (sprung mass m on spring k and \
                      damper c), coloured by the chosen metric: settling time and peak rebound \
                      of a release from rest, RMS body acceleration on a random ISO 8608 road \
                      at 72 km/h (the tyre filters the input above 10 Hz), or peak \
                      transmissibility. Dashed lines join designs of equal damping ratio \
                      ζ = c/(2√(km)). The Pareto front holds the designs no other beats in both \
                      comfort and settling. Click the map (or a point of the front) to choose a \
                      design; move the mass to see the whole map shift.",
            equation_mathml: EQUATION,
            params: vec![
                ParamSpec::linear("m", "sprung mass", "m", "kg", (100.0, 800.0, 1.0), 300.0),
                ParamSpec::choice("metric", "map metric", &Metric::OPTIONS, 0),
                ParamSpec::linear("band", "settling band", "", "%", (1.0, 20.0, 0.5), 5.0),
                ParamSpec::choice(
                    "road",
                    "road (ISO 8608)",
                    &[
                        ("a", "class A (very good)"),
                        ("b", "class B (good)"),
                        ("c", "class C (average)"),
                        ("d", "class D (poor)"),
                    ],
                    1,
                ),
                ParamSpec::linear(
                    "k_min",
                    "map: lowest spring rate",
                    "k_min",
                    "N/m",
                    (2_000.0, 30_000.0, 500.0),
                    10_000.0,
                ),
                ParamSpec::linear(
                    "k_max",
                    "map: highest spring rate",
                    "k_max",
                    "N/m",
                    (35_000.0, 150_000.0, 500.0),
                    60_000.0,
                ),
                ParamSpec::linear(
                    "c_min",
                    "map: lowest damper rate",
                    "c_min",
                    "N·s/m",
                    (100.0, 2_000.0, 50.0),
                    500.0,
                ),
                ParamSpec::linear(
                    "c_max",
                    "map: highest damper rate",
                    "c_max",
                    "N·s/m",
                    (2_500.0, 15_000.0, 100.0),
                    8_000.0,
                ),
                ParamSpec::linear(
                    "k",
                    "selected spring rate",
                    "k",
                    "N/m",
                    (2_000.0, 150_000.0, 100.0),
                    24_000.0,
                ),
                ParamSpec::linear(
                    "c",
                    "selected damper rate",
                    "c",
                    "N·s/m",
                    (100.0, 15_000.0, 10.0),
                    2_000.0,
                ),
                ParamSpec::linear(
                    "n",
                    "grid cells per axis",
                    "n",
                    "",
                    (20.0, 160.0, 1.0),
                    100.0,
                ),
            ],
            readouts: vec![
                ReadoutSpec {
                    key: "k",
                    label: "selected spring rate k",
                    unit: "N/m",
                },
                ReadoutSpec {
                    key: "c",
                    label: "selected damper rate c",
                    unit: "N·s/m",
                },
                ReadoutSpec {
                    key: "zeta",
                    label: "damping ratio ζ",
                    unit: "",
                },
                ReadoutSpec {
                    key: "settling_time",
                    label: "settling time",
                    unit: "s",
                },
                ReadoutSpec {
                    key: "overshoot",
                    label: "peak rebound",
                    unit: "%",
                },
                ReadoutSpec {
                    key: "accel_rms",
                    label: "RMS body acceleration",
                    unit: "m/s²",
                },
                ReadoutSpec {
                    key: "grid_size",
                    label: "grid size (cells)",
                    unit: "",
                },
                ReadoutSpec {
                    key: "compute_time",
                    label: "sweep compute time",
                    unit: "ms",
                },
            ],
            plots: vec![
                PlotSpec {
                    key: "map",
                    title: "Metric over (k, c) with iso-ζ lines",
                    aspect: 1.35,
                },
                PlotSpec {
                    key: "pareto",
                    title: "Comfort vs settling: Pareto front",
                    aspect: 1.35,
                },
                PlotSpec {
                    key: "response",
                    title: "Selected design: free response x(t)",
                    aspect: 1.35,
                },
            ],
            primary_plot: "",
            presets: vec![
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
            ],
            table: None,
            schematic: false,
        }
    }

    fn update(&mut self, params: &Params) -> Frame {
        let Some(inp) = inputs(params) else {
            return invalid_frame();
        };
        self.sweep_if_needed(&inp);
        let sel = selected(&inp, inp.key.m);
        let best_settling = self
            .maps
            .settling_time
            .iter()
            .enumerate()
            .filter(|(_, v)| v.is_finite())
            .min_by(|a, b| a.1.total_cmp(b.1))
            .and_then(|(i, _)| self.design_at(i));
        let n = inp.key.n;
        let cells = n * n;
        let readouts = vec![
            Readout::number("k", Some(inp.k), "N/m", 4),
            Readout::number("c", Some(inp.c), "N·s/m", 4),
            Readout::number("zeta", sel.zeta, "", 3),
            Readout::number("settling_time", sel.settling_time, "s", 4),
            Readout::number("overshoot", sel.overshoot, "%", 3),
            match sel.accel_rms.filter(|v| v.is_finite()) {
                Some(a) => Readout {
                    key: "accel_rms",
                    text: fmt_unit(a, "m/s²", 3),
                    data_value: format!("{a}"),
                },
                None => Readout::number("accel_rms", None, "m/s²", 3),
            },
            Readout {
                key: "grid_size",
                text: format!("{n} × {n} = {cells}"),
                data_value: format!("{cells}"),
            },
            ms_readout("compute_time", self.sweep_ms),
        ];
        let figures = vec![
            self.map_figure(&inp, &sel),
            self.pareto_figure(&inp, &sel),
            response_figure(&inp, &sel, best_settling),
        ];
        Frame {
            readouts,
            figures,
            time_span: None,
        }
    }

    fn pick(&mut self, plot: &str, x: f64, y: f64) -> Vec<(&'static str, f64)> {
        let Some(key) = self.key else {
            return Vec::new();
        };
        match plot {
            "map" => {
                let (k0, k1) = key.k;
                let (c0, c1) = key.c;
                let (x, y) = (x * KILO, y * KILO);
                if !(x >= k0 && x <= k1 && y >= c0 && y <= c1) {
                    return Vec::new();
                }
                // Round to 10 N/m and 1 N·s/m: finer than a cell, and tidy in the URL.
                vec![("k", (x / 10.0).round() * 10.0), ("c", y.round().max(1.0))]
            }
            "pareto" => {
                let ((x0, x1), (y0, y1)) = self.pareto_ranges;
                let (sx, sy) = ((x1 - x0).max(1e-12), (y1 - y0).max(1e-12));
                let nearest = self
                    .front
                    .iter()
                    .filter_map(|&i| {
                        let t = *self.maps.settling_time.get(i)?;
                        let a = *self.maps.accel_rms.get(i)?;
                        let d = ((t - x) / sx).powi(2) + ((a - y) / sy).powi(2);
                        Some((i, d))
                    })
                    .min_by(|a, b| a.1.total_cmp(&b.1));
                match nearest.and_then(|(i, _)| self.design_at(i)) {
                    Some((k, c)) => vec![("k", k), ("c", c)],
                    None => Vec::new(),
                }
            }
            _ => Vec::new(),
        }
    }
}

/// Unreachable with validated parameters; still, never panic.
fn invalid_frame() -> Frame {
    Frame {
        readouts: vec![
            Readout::number("k", None, "N/m", 4),
            Readout::number("c", None, "N·s/m", 4),
            Readout::number("zeta", None, "", 3),
            Readout::number("settling_time", None, "s", 4),
            Readout::number("overshoot", None, "%", 3),
            Readout::number("accel_rms", None, "m/s²", 3),
            Readout::number("grid_size", None, "", 3),
            Readout::number("compute_time", None, "ms", 3),
        ],
        figures: Vec::new(),
        time_span: None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn run(d: &mut DesignSpace, query: &str) -> Frame {
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
    fn readouts_are_the_selected_design_from_the_solver() {
        let mut d = DesignSpace::default();
        let f = run(&mut d, "m=300&k=24000&c=2000");
        let zeta = 2000.0 / (2.0 * (24_000.0f64 * 300.0).sqrt());
        assert!((value(&f, "zeta") - zeta).abs() < 1e-12);
        let sys = SecondOrder::mechanical(300.0, 2000.0, 24_000.0).unwrap();
        let m = FreeMetrics::exact(&sys, X0, 0.0, SettlingBand::FREE_DEFAULT).unwrap();
        assert_eq!(value(&f, "settling_time"), m.settling_time.unwrap());
        // Release from rest: rebound e^{−πζ/√(1−ζ²)}.
        let rebound = 100.0 * (-std::f64::consts::PI * zeta / (1.0 - zeta * zeta).sqrt()).exp();
        assert!((value(&f, "overshoot") - rebound).abs() < 1e-9);
        assert_eq!(value(&f, "grid_size"), 10_000.0);
        assert!(value(&f, "compute_time") >= 0.0);
        let map = f.figures[0].heatmap.as_ref().unwrap();
        assert_eq!((map.nx, map.ny, map.values.len()), (100, 100, 10_000));
        assert!(f.figures[0]
            .description
            .starts_with("Settling time over k 10–60 kN/m"));
    }

    #[test]
    fn the_map_is_recomputed_only_when_its_inputs_change() {
        let mut d = DesignSpace::default();
        run(&mut d, "k=24000");
        run(&mut d, "k=30000&c=3000");
        run(&mut d, "k=30000&c=3000&metric=accel_rms");
        assert_eq!(d.sweeps, 1, "selection and metric reuse the sweep");
        run(&mut d, "m=400");
        run(&mut d, "m=400&n=40");
        assert_eq!(d.sweeps, 3);
        assert_eq!(d.maps.zeta.len(), 1600);
    }

    #[test]
    fn the_map_cells_hold_the_solver_metrics_at_their_centres() {
        let mut d = DesignSpace::default();
        let f = run(&mut d, "n=20&metric=peak_rebound");
        let map = f.figures[0].heatmap.as_ref().unwrap();
        // Cell (ix, iy) = (3, 7): k = 10 000 + 3.5·2 500, c = 500 + 7.5·375.
        let (k, c) = (18_750.0, 3_312.5);
        let z = c / (2.0 * (k * 300.0f64).sqrt());
        let expect = 100.0 * (-std::f64::consts::PI * z / (1.0 - z * z).sqrt()).exp();
        assert!((map.values[7 * 20 + 3] - expect).abs() < 1e-9);
    }

    #[test]
    fn clicking_picks_a_design_and_the_front_is_non_dominated() {
        let mut d = DesignSpace::default();
        run(&mut d, "");
        assert_eq!(
            d.pick("map", 31.234, 4.3214),
            vec![("k", 31_230.0), ("c", 4_321.0)]
        );
        assert!(d.pick("map", 70.0, 4.0).is_empty(), "outside the map");
        assert!(d.pick("response", 1.0, 0.0).is_empty());
        assert!(d.front.len() > 3);
        let (ts, acc) = (&d.maps.settling_time, &d.maps.accel_rms);
        for w in d.front.windows(2) {
            assert!(ts[w[0]] <= ts[w[1]] && acc[w[0]] >= acc[w[1]]);
        }
        // Picking next to the front's first point chooses that design.
        let first = d.front[0];
        let picked = d.pick("pareto", ts[first], acc[first]);
        let (k, c) = d.design_at(first).unwrap();
        assert_eq!(picked, vec![("k", k), ("c", c)]);
    }

    #[test]
    fn iso_zeta_lines_lie_on_their_damping_ratio() {
        let mut d = DesignSpace::default();
        let f = run(&mut d, "");
        let map = &f.figures[0];
        assert_eq!(map.series.len(), 5);
        for (s, zeta) in map.series.iter().zip(ISO_ZETAS) {
            let (k, c) = (
                s.points[s.points.len() / 2].0 * KILO,
                s.points[s.points.len() / 2].1 * KILO,
            );
            assert!((c / (2.0 * (k * 300.0f64).sqrt()) - zeta).abs() < 1e-9);
        }
        assert!(map.markers.iter().any(|m| m.label == "ζ=0.7"));
    }
}
