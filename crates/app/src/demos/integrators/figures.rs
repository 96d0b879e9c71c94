//! The integrators demo's time plots: each method against the exact solution, and the
//! error over time; and how each method is drawn.

use super::axes::log_axis;
use super::{text, Results, P};
use crate::figure::{Axis, Figure, LineStyle, Marker, MarkerShape, Series};
use crate::format::si;
use crate::plot::Ink;
use crate::t;

pub(super) const RESPONSE_TITLE: &str = "Numerical solutions and the exact x(t)";
pub(super) const ERROR_TITLE: &str = "Error over time";

/// Samples of the exact curve and of DP45's dense output.
const SAMPLES: usize = 1000;
/// Most points of one drawn series.
const MAX_DRAWN: usize = 1000;
/// Most step markers drawn per method.
const MAX_MARKS: usize = 60;
/// Half-height of the response plot, in units of the exact solution's largest |x|.
pub(super) const RESPONSE_RANGE: f64 = 2.0;
/// Largest error drawn, in units of x₀ (larger values are clipped at the top).
pub(super) const ERROR_CLIP: f64 = 1e8;

/// How one fixed-step method is drawn and named.
#[derive(Debug, Clone, Copy)]
pub(super) struct Look {
    /// Which method: `euler`, `symplectic_euler`, `heun` or `rk4`.
    pub key: &'static str,
    pub style: LineStyle,
    /// Marker drawn on the curve so it is told apart without colour.
    pub mark: Option<MarkerShape>,
}

impl Look {
    /// The method's name in prose.
    pub fn name(&self) -> String {
        match self.key {
            "euler" => t!("integrators-method-euler"),
            "symplectic_euler" => t!("integrators-method-symplectic-euler"),
            "heun" => t!("integrators-method-heun"),
            _ => t!("integrators-method-rk4"),
        }
    }

    /// The method's legend entry.
    pub fn legend(&self) -> String {
        match self.key {
            "euler" => t!("integrators-legend-euler"),
            "symplectic_euler" => t!("integrators-legend-symplectic-euler"),
            "heun" => t!("integrators-legend-heun"),
            _ => "RK4".to_string(),
        }
    }
}

/// The fixed-step methods' looks, in readout order.
pub(super) const LOOKS: [Look; 4] = [
    Look {
        key: "euler",
        style: LineStyle::dashed(Ink::Vermillion, 2.0),
        mark: None,
    },
    Look {
        key: "symplectic_euler",
        style: LineStyle::dashed(Ink::Purple, 1.5),
        mark: Some(MarkerShape::Cross),
    },
    Look {
        key: "heun",
        style: LineStyle::dotted(Ink::Orange, 2.5),
        mark: None,
    },
    Look {
        key: "rk4",
        style: LineStyle::solid(Ink::Blue, 1.8),
        mark: None,
    },
];

const EXACT_STYLE: LineStyle = LineStyle::solid(Ink::Black, 3.5);
pub(super) const DP45_STYLE: LineStyle = LineStyle::dotted(Ink::Green, 2.0);

/// DP45's legend entry.
pub(super) fn dp45_legend() -> String {
    t!("integrators-legend-dp45")
}
pub(super) const DP45_MARK: MarkerShape = MarkerShape::Dot;

/// Each method against the exact decaying oscillation.
pub(super) fn response(p: &P, r: &Results) -> Figure {
    let exact: Vec<(f64, f64)> = sample_times(p.t_end)
        .map(|t| (t, r.resp.displacement(t)))
        .collect();
    let amp = exact
        .iter()
        .map(|q| q.1.abs())
        .fold(0.0f64, f64::max)
        .max(1e-12 * p.x0);
    let y_range = (-RESPONSE_RANGE * amp, RESPONSE_RANGE * amp);
    let inside = |y: f64| y.is_finite() && y.abs() <= RESPONSE_RANGE * amp;
    let mut series = vec![Series::new(
        t!("integrators-series-exact"),
        exact,
        EXACT_STYLE,
    )];
    let mut markers = Vec::new();
    let mut words = Vec::new();
    for (k, look) in LOOKS.iter().enumerate() {
        let run = &r.fixed.runs[k];
        let sol = &run.sol;
        let clipped = sol.y.iter().any(|y| !inside(y[0]));
        words.push(text::method_words(&look.name(), r, k, run, clipped));
        if !p.show[k] {
            continue;
        }
        // Strides over the whole grid, so that runs so far keep their spacing.
        let points = r.n + 1;
        let stride = points.div_ceil(MAX_DRAWN).max(1);
        let pts: Vec<(f64, f64)> = strided(sol.t.len(), stride)
            .map(|i| (sol.t[i], sol.y[i][0]))
            .collect();
        if let Some(shape) = look.mark {
            let every = points.div_ceil(MAX_MARKS / 2).max(1);
            markers.extend(
                strided(sol.t.len(), every)
                    .filter(|&i| inside(sol.y[i][0]))
                    .map(|i| mark(shape, look.style.ink, (sol.t[i], sol.y[i][0]))),
            );
        }
        let label = if r.growth[k] > 1.0 && clipped {
            t!(
                "integrators-legend-growing",
                legend = look.legend(),
                growth = si(r.growth[k], "", 3)
            )
        } else {
            look.legend()
        };
        series.push(Series::new(label, pts, look.style));
    }
    match &r.dp45 {
        Ok(out) => {
            let steps = &out.solution;
            words.push(text::dp45_words(p, r, steps.stats.n_accepted));
            if p.show[4] {
                let pts = sample_times(p.t_end)
                    .filter_map(|t| out.dense.eval(t).map(|y| (t, y[0])))
                    .collect();
                series.push(Series::new(dp45_legend(), pts, DP45_STYLE));
                let every = steps.t.len().div_ceil(MAX_MARKS).max(1);
                markers.extend(
                    strided(steps.t.len(), every)
                        .filter(|&i| inside(steps.y[i][0]))
                        .map(|i| mark(DP45_MARK, DP45_STYLE.ink, (steps.t[i], steps.y[i][0]))),
                );
            }
        }
        Err(e) => words.push(text::dp45_failed(e)),
    }
    // The exact solution does not depend on h, the tolerance or the methods shown.
    let fig = Figure {
        series,
        backdrop: 1,
        markers,
        ..Figure::plot(
            t!("integrators-plot-response"),
            Axis::linear(t!("axis-time"), "s", (0.0, p.t_end)),
            Axis::linear(t!("axis-displacement"), "m", y_range),
        )
    }
    .with_origin_lines()
    .described(text::describe_response(p, r, &words));
    text::runs_so_far(fig, p, r)
}

/// `|x_num − x_exact|` on a log scale at each method's own grid points.
pub(super) fn error(p: &P, r: &Results) -> Figure {
    let mut series = Vec::new();
    let mut markers = Vec::new();
    let mut lo = f64::INFINITY;
    let mut hi = 0.0f64;
    let mut parts = Vec::new();
    let clip = ERROR_CLIP * p.x0;
    for (k, look) in LOOKS.iter().enumerate() {
        if !p.show[k] {
            continue;
        }
        let sol = &r.fixed.runs[k].sol;
        let errs = |i: usize| {
            let e = (sol.y[i][0] - r.fixed.exact.get(i).map_or(f64::NAN, |x| x[0])).abs();
            if e > 0.0 {
                e
            } else {
                f64::NAN
            }
        };
        let pts = bucket_max(sol.t.len(), |i| (sol.t[i], errs(i)));
        for q in pts.iter().filter(|q| q.1.is_finite()) {
            lo = lo.min(q.1);
            hi = hi.max(q.1);
        }
        if let Some(shape) = look.mark {
            // Over the whole grid, as in the response plot.
            let every = (r.n + 1).div_ceil(MAX_MARKS / 2).max(1);
            markers.extend(
                strided(sol.t.len(), every)
                    .map(|i| (sol.t[i], errs(i)))
                    .filter(|q| q.1.is_finite() && q.1 <= clip)
                    .map(|q| mark(shape, look.style.ink, q)),
            );
        }
        parts.push(text::error_words(&look.name(), &pts, r.growth[k]));
        series.push(Series::new(look.legend(), pts, look.style));
    }
    if let (true, Ok(out)) = (p.show[4], &r.dp45) {
        let sol = &out.solution;
        let pts: Vec<(f64, f64)> = sol
            .t
            .iter()
            .zip(&sol.y)
            .map(|(&t, y)| {
                let e = (y[0] - r.resp.displacement(t)).abs();
                (t, if e > 0.0 { e } else { f64::NAN })
            })
            .collect();
        for q in pts.iter().filter(|q| q.1.is_finite()) {
            lo = lo.min(q.1);
            hi = hi.max(q.1);
        }
        let every = pts.len().div_ceil(MAX_MARKS).max(1);
        markers.extend(
            strided(pts.len(), every)
                .map(|i| pts[i])
                .filter(|q| q.1.is_finite())
                .map(|q| mark(DP45_MARK, DP45_STYLE.ink, q)),
        );
        parts.push(text::error_words("DP45", &pts, 1.0));
        series.push(Series::new(dp45_legend(), pts, DP45_STYLE));
    }
    let floor = 1e-16 * p.x0;
    let (lo, hi) = if lo.is_finite() && hi > 0.0 {
        (
            (lo.max(floor)) / 3.0,
            (hi * 3.0).min(clip).max(lo.max(floor) * 10.0),
        )
    } else {
        (floor, p.x0)
    };
    let fig = Figure {
        series,
        markers,
        ..Figure::plot(
            t!("integrators-plot-error"),
            Axis::linear(t!("axis-time"), "s", (0.0, p.t_end)),
            log_axis(&t!("integrators-axis-error"), "m", (lo, hi)),
        )
    }
    .described(text::describe_error(r, &parts, hi >= clip, clip));
    text::runs_so_far(fig, p, r)
}

/// Indices `0, stride, 2·stride, …` and always the last one.
fn strided(len: usize, stride: usize) -> impl Iterator<Item = usize> {
    let stride = stride.max(1);
    (0..len)
        .step_by(stride)
        .chain((len > 0 && !(len - 1).is_multiple_of(stride)).then(|| len - 1))
}

/// At most [`MAX_DRAWN`] points: each bucket of consecutive points keeps its largest
/// value (so an error's peaks survive the thinning); a NaN value in a bucket is kept as a
/// line break.
fn bucket_max(len: usize, point: impl Fn(usize) -> (f64, f64)) -> Vec<(f64, f64)> {
    let size = len.div_ceil(MAX_DRAWN).max(1);
    (0..len)
        .step_by(size)
        .map(|start| {
            let mut best = point(start);
            for i in start + 1..(start + size).min(len) {
                let q = point(i);
                if !best.1.is_finite() || q.1 > best.1 {
                    best = q;
                }
            }
            best
        })
        .collect()
}

/// An unlabelled marker.
pub(super) fn mark(shape: MarkerShape, ink: Ink, at: (f64, f64)) -> Marker {
    Marker {
        label: String::new(),
        at,
        shape,
        ink,
    }
}

/// [`SAMPLES`] times from 0 to `t_end` inclusive, the last exactly `t_end`.
fn sample_times(t_end: f64) -> impl Iterator<Item = f64> {
    (0..SAMPLES).map(move |i| t_end * i as f64 / (SAMPLES - 1) as f64)
}
