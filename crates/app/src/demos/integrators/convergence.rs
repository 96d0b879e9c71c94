//! The convergence plot: largest error at the common check points against the step h for
//! the fixed-step methods, with the power laws fitted over each asymptotic range (drawn
//! over exactly that range) and reference slopes.

use super::axes::log_axis;
use super::figures::{mark, ERROR_CLIP, LOOKS};
use super::model::{FIT_CEILING, FIT_FLOOR, LEVELS, SPREAD};
use super::{text, Results, P};
use crate::figure::{Figure, LineStyle, Marker, MarkerShape, Series};
use crate::format::{si, significant};
use crate::plot::{sampled, Ink};
use crate::t;
use zeta_solver::grid::{exp10, log10, logspace};
use zeta_solver::integrate::convergence::{NestedStudy, PowerLaw, RunStatus};

pub(super) const TITLE: &str = "Convergence: max error against step h";

/// Legend and drawing of one method's sweep.
struct Sweep<'a> {
    sweep: &'a NestedStudy,
    name: String,
    legend: String,
    style: LineStyle,
    shape: Option<MarkerShape>,
    show: bool,
}

/// Everything drawn so far, and the data's extent.
struct Canvas {
    series: Vec<Series>,
    markers: Vec<Marker>,
    words: Vec<String>,
    x: (f64, f64),
    y: (f64, f64),
    clip: f64,
}

impl Canvas {
    fn add(&mut self, s: Sweep) {
        let study = &s.sweep.study;
        let pts: Vec<(f64, f64)> = study
            .points
            .iter()
            .filter(|q| q.error.is_finite() && q.error > 0.0)
            .map(|q| (q.h, q.error))
            .collect();
        let overflowed = s
            .sweep
            .status
            .iter()
            .zip(&study.points)
            .filter(|(st, _)| **st == RunStatus::Overflow)
            .map(|(_, q)| q.h)
            .fold(0.0f64, f64::max);
        let limit = si(overflowed, "s", 3);
        let w = match (study.order, study.fitted_span(), overflowed > 0.0) {
            (Some(o), Some((lo, hi)), overflows) => {
                let (slope, from, to) = (si(o, "", 3), si(lo, "s", 3), si(hi, "s", 3));
                if overflows {
                    t!(
                        "integrators-fit-overflows",
                        method = &s.name,
                        slope = slope,
                        from = from,
                        to = to,
                        limit = limit
                    )
                } else {
                    t!(
                        "integrators-fit",
                        method = &s.name,
                        slope = slope,
                        from = from,
                        to = to
                    )
                }
            }
            (_, _, true) => t!(
                "integrators-no-fit-overflows",
                method = &s.name,
                limit = limit
            ),
            (_, _, false) => t!("integrators-no-fit", method = &s.name),
        };
        self.words.push(w);
        if !s.show {
            return;
        }
        for &(h, e) in &pts {
            self.x = (self.x.0.min(h), self.x.1.max(h));
            self.y = (self.y.0.min(e), self.y.1.max(e));
        }
        if let Some(shape) = s.shape {
            let clip = self.clip;
            self.markers.extend(
                pts.iter()
                    .filter(|q| q.1 <= clip)
                    .map(|&q| mark(shape, s.style.ink, q)),
            );
        }
        if let (Some(law), Some((lo, hi))) = (study.power_law(), study.fitted_span()) {
            self.series.push(Series::new(
                "",
                vec![(lo, law.at(lo)), (hi, law.at(hi))],
                LineStyle::solid(s.style.ink, 4.0),
            ));
        }
        let label = match study.order {
            Some(o) => t!(
                "integrators-legend-order",
                legend = &s.legend,
                order = si(o, "", 3)
            ),
            None => t!("integrators-legend-no-fit", legend = &s.legend),
        };
        self.series.push(Series::new(label, pts, s.style));
    }
}

/// Error against h for every method, log–log.
pub(super) fn figure(p: &P, r: &Results) -> Figure {
    let study = &r.study;
    let mut c = Canvas {
        series: Vec::new(),
        markers: Vec::new(),
        words: Vec::new(),
        x: (r.h, r.h),
        y: (f64::INFINITY, 0.0),
        clip: ERROR_CLIP * p.x0,
    };
    for (k, look) in LOOKS.iter().enumerate() {
        if let Some(sweep) = study.fixed.get(k) {
            c.add(Sweep {
                sweep,
                name: look.name(),
                legend: look.legend(),
                style: look.style,
                shape: look.mark,
                show: p.show[k],
            });
        }
    }
    let (mut ylo, mut yhi) = c.y;
    if !(ylo.is_finite() && yhi > 0.0) {
        ylo = FIT_FLOOR * p.x0;
        yhi = p.x0;
    }
    let yhi = yhi.min(c.clip).max(ylo * 100.0);
    let x_range = (c.x.0 / 1.6, c.x.1 * 1.6);
    let y_range = (ylo / 4.0, yhi * 1000.0);
    // Reference slopes 1 and 4 through the geometric middle of the drawn data.
    let middle = |a: f64, b: f64| exp10(0.5 * (log10(a) + log10(b)));
    let (xm, ym) = (middle(x_range.0, x_range.1), middle(ylo, yhi));
    let hs = logspace(x_range.0, x_range.1, 41).unwrap_or_default();
    for order in [1.0, 4.0] {
        let line = PowerLaw::through((xm, ym * 0.1), order);
        c.series.push(Series::new(
            "",
            sampled(&hs, |h| line.at(h))
                .into_iter()
                .filter(|q| q.1 >= y_range.0 && q.1 <= y_range.1)
                .collect(),
            LineStyle::dotted(Ink::Black, 1.2),
        ));
        // Name the line where it leaves the plot on the left (or at its lowest point).
        let h_at = (x_range.0 * 1.15).max(line.step_for(y_range.0 * 3.0));
        if h_at < x_range.1 {
            c.markers.push(Marker::text(
                t!("integrators-slope", order = significant(order, 1)),
                (h_at, line.at(h_at)),
                Ink::Black,
            ));
        }
    }
    // The study and the reference slopes do not depend on h: a backdrop.
    let backdrop = c.series.len();
    c.markers.push(Marker::text(
        format!("h = {}", si(r.h, "s", 3)),
        (r.h * 1.1, y_range.0 * 30.0),
        Ink::Sky,
    ));
    c.series.push(Series::new(
        "",
        vec![(r.h, y_range.0), (r.h, y_range.1)],
        LineStyle::dashed(Ink::Sky, 1.2),
    ));
    let description = t!(
        "integrators-describe-convergence",
        points = study.grids.intervals() + 1,
        levels = LEVELS,
        from = si(study.grids.step(0), "s", 3),
        budget = study.budget.steps,
        euler_budget = study.budget.euler,
        methods = text::join(&c.words),
        spread = significant(SPREAD, 1),
        ceiling = si(FIT_CEILING * 100.0, "%", 2)
    );
    Figure {
        series: c.series,
        backdrop,
        markers: c.markers,
        ..Figure::plot(
            t!("integrators-plot-convergence"),
            log_axis(&t!("integrators-axis-step"), "s", x_range),
            log_axis(&t!("integrators-axis-max-error"), "m", y_range),
        )
    }
    .described(description)
}
