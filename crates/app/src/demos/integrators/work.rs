//! The work–precision plot: largest error against right-hand-side evaluations for every
//! method on one plot, with DP45's order fitted where its tolerance sets its steps.

use super::axes::log_axis;
use super::figures::{mark, DP45_MARK, DP45_STYLE, ERROR_CLIP, LOOKS};
use super::model::FIT_FLOOR;
use super::text::sci;
use super::{text, Results, P};
use crate::figure::{finite_extent, Figure, LineStyle, Marker, Series};
use crate::format::si;
use crate::t;
use zeta_solver::integrate::work_precision::{WorkPrecision, MAX_STABILITY_STEPS, STABILITY_SHARE};

pub(super) const TITLE: &str = "Work–precision: max error against f-evaluations";

/// Error against work, log–log, for every method.
pub(super) fn figure(p: &P, r: &Results) -> Figure {
    let clip = ERROR_CLIP * p.x0;
    let mut series = Vec::new();
    let mut markers = Vec::new();
    let mut words = Vec::new();
    let mut drawn: Vec<(f64, f64)> = Vec::new();
    for (k, look) in LOOKS.iter().enumerate() {
        let Some(sweep) = r.study.fixed.get(k) else {
            continue;
        };
        let pts: Vec<(f64, f64)> = sweep
            .work_precision()
            .into_iter()
            .filter(|q| q.1 > 0.0 && q.1 <= clip)
            .collect();
        if let (Some(first), Some(last)) = (pts.first(), pts.last()) {
            words.push(t!(
                "integrators-work-words",
                method = look.name(),
                error_first = si(first.1, "m", 3),
                work_first = first.0 as i64,
                error_last = si(last.1, "m", 3),
                work_last = last.0 as i64
            ));
        }
        if !p.show[k] {
            continue;
        }
        if let Some(shape) = look.mark {
            markers.extend(pts.iter().map(|&q| mark(shape, look.style.ink, q)));
        }
        drawn.extend(&pts);
        series.push(Series::new(look.legend(), pts, look.style));
    }
    let dp = &r.study.dp45;
    words.push(dp45_words(dp));
    if p.show[4] {
        let pts: Vec<(f64, f64)> = dp
            .points
            .iter()
            .filter(|q| q.work > 0 && q.error.is_finite() && q.error > 0.0 && q.error <= clip)
            .map(|q| (q.work as f64, q.error))
            .collect();
        for q in dp.points.iter().filter(|q| q.work > 0 && q.error <= clip) {
            let at = (q.work as f64, q.error);
            markers.push(if q.tolerance_set() {
                mark(DP45_MARK, DP45_STYLE.ink, at)
            } else {
                Marker::cross("", at, DP45_STYLE.ink)
            });
        }
        if let (Some(law), Some((lo, hi))) = (dp.law, dp.fitted_span()) {
            series.push(Series::new(
                "",
                vec![(lo, law.at(lo)), (hi, law.at(hi))],
                LineStyle::solid(DP45_STYLE.ink, 4.0),
            ));
        }
        let label = match dp.order() {
            Some(o) => t!("integrators-legend-dp45-order", order = si(o, "", 3)),
            None => t!("integrators-legend-dp45-no-order"),
        };
        drawn.extend(&pts);
        series.push(Series::new(label, pts, DP45_STYLE));
    }
    let floor = FIT_FLOOR * p.x0 * 1e-3;
    let tols = r.study.budget.tols;
    let (xlo, xhi) = finite_extent(drawn.iter().map(|q| q.0)).unwrap_or((10.0, 1e5));
    let (ylo, yhi) = finite_extent(drawn.iter().map(|q| q.1)).unwrap_or((floor, p.x0));
    // Every curve is the study's, which h does not change: a backdrop.
    Figure {
        backdrop: series.len(),
        series,
        markers,
        ..Figure::plot(
            t!("integrators-plot-work"),
            log_axis(
                &t!("integrators-axis-evaluations"),
                "",
                (xlo / 1.5, xhi * 1.5),
            ),
            log_axis(
                &t!("integrators-axis-max-error"),
                "m",
                (ylo.max(floor) / 4.0, yhi * 10.0),
            ),
        )
    }
    .described(t!(
        "integrators-describe-work",
        from = tols.first().map_or_else(String::new, |&t| sci(t)),
        to = tols.last().map_or_else(String::new, |&t| sci(t)),
        methods = text::join(&words)
    ))
}

/// What DP45's sweep shows, and why it has an order or not.
fn dp45_words(dp: &WorkPrecision) -> String {
    let runs = dp.points.iter().filter(|q| q.work > 0).count();
    let tail = t!(
        "integrators-dp45-stability-runs",
        share = si(MAX_STABILITY_STEPS * 100.0, "%", 1),
        fraction = si(STABILITY_SHARE * 100.0, "%", 2),
        count = dp.stability_set(),
        runs = runs
    );
    match (dp.order(), dp.fitted_span()) {
        (Some(o), Some((lo, hi))) => t!(
            "integrators-dp45-order",
            order = si(o, "", 3),
            from = lo as i64,
            to = hi as i64,
            runs = tail
        ),
        _ => t!("integrators-dp45-no-order", runs = tail),
    }
}
