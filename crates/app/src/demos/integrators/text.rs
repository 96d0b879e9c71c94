//! The integrators demo's prose: summary, equation, the table of methods and the figures'
//! text alternatives.

use super::model::{Budget, FULL};
use super::runs::Run;
use super::{Results, P};
use crate::format::{si, significant};
use crate::spec::Table;
use crate::t;
use zeta_solver::integrate::analysis::StepLimit;
use zeta_solver::integrate::IntegrationError;

pub(super) const SUMMARY: &str =
    "The free oscillator integrated by forward Euler, symplectic Euler, Heun \
                      (RK2) and classical RK4 at a fixed step h, and by Dormand–Prince 5(4) with \
                      adaptive steps, each compared with the exact solution. A one-step method \
                      multiplies each mode by R(hλ) per step: when |R| > 1 the numbers grow no \
                      matter how well the method fits the equation, which is why forward Euler \
                      blows up a lightly damped oscillator unless h < 2ζ/ωₙ. When it is stable, \
                      halving h divides the error by 2^p, where p is the method's order: the \
                      convergence plot measures p. Switching a method off hides its curves; its \
                      readouts are still computed.";

/// The MathML of the model problem.
pub(super) const EQUATION: &str = "<math display=\"block\"><mrow>\
<mover><mi>x</mi><mo>¨</mo></mover><mo>+</mo><mn>2</mn><mi>ζ</mi><msub><mi>ω</mi><mi>n</mi></msub>\
<mover><mi>x</mi><mo>˙</mo></mover><mo>+</mo><msubsup><mi>ω</mi><mi>n</mi><mn>2</mn></msubsup><mi>x</mi>\
<mo>=</mo><mn>0</mn><mo>,</mo><mspace width=\"1em\"/><mi>x</mi><mo>(</mo><mn>0</mn><mo>)</mo><mo>=</mo>\
<msub><mi>x</mi><mn>0</mn></msub><mo>,</mo><mspace width=\"0.5em\"/>\
<mover><mi>x</mi><mo>˙</mo></mover><mo>(</mo><mn>0</mn><mo>)</mo><mo>=</mo><mn>0</mn></mrow></math>";

/// The methods side by side.
pub(super) fn methods_table() -> Table {
    Table {
        caption: "The methods",
        columns: vec![
            "method",
            "order p",
            "f-evaluations per step",
            "amplification R(z)",
            "on an undamped oscillator",
        ],
        rows: vec![
            (
                "euler",
                vec![
                    "forward Euler",
                    "1",
                    "1",
                    "1 + z",
                    "always grows: |R(iωh)| = √(1 + ω²h²) > 1",
                ],
            ),
            (
                "symplectic_euler",
                vec![
                    "symplectic Euler",
                    "1",
                    "2",
                    "2×2 matrix, not a scalar R",
                    "bounded energy error while ωh ≤ 2",
                ],
            ),
            (
                "heun",
                vec![
                    "Heun (RK2)",
                    "2",
                    "2",
                    "1 + z + z²/2",
                    "slowly grows: |R(iy)|² = 1 + y⁴/4",
                ],
            ),
            (
                "rk4",
                vec![
                    "classical RK4",
                    "4",
                    "4",
                    "1 + z + z²/2 + z³/6 + z⁴/24",
                    "slightly damps while ωh ≤ 2√2",
                ],
            ),
            (
                "dp45",
                vec![
                    "Dormand–Prince 5(4)",
                    "5",
                    "6 (first same as last)",
                    "adaptive: h follows the error estimate",
                    "stable: rejected steps shrink h",
                ],
            ),
        ],
        highlight_readout: "",
    }
}

/// "stable for h ≤ …" in words.
pub(super) fn limit_text(l: StepLimit) -> String {
    match l {
        StepLimit::UpTo(h) => t!("integrators-limit-up-to", step = si(h, "s", 3)),
        StepLimit::Unconditional => t!("integrators-limit-every"),
        StepLimit::NoStableStep => t!("integrators-limit-none"),
    }
}

/// Clauses about each method, joined into one list in the interface language.
pub(super) fn join(words: &[String]) -> String {
    words.join(&t!("integrators-join"))
}

/// `1e-6` style for tolerances.
pub(super) fn sci(v: f64) -> String {
    format!("{v:.0e}")
}

/// A maximum error, or "—" where there is none.
fn error_text(e: Option<f64>) -> String {
    e.map_or("—".into(), |e| si(e, "m", 3))
}

/// What fixed-step method `k` does at this `h`.
pub(super) fn method_words(name: &str, r: &Results, k: usize, run: &Run, clipped: bool) -> String {
    let g = r.growth[k];
    if let Some(t) = run.overflow {
        t!(
            "integrators-method-overflows",
            method = name,
            time = si(t, "s", 3),
            growth = si(g, "", 3)
        )
    } else if g > 1.0 && !r.stable[k] {
        let error = error_text(r.fixed.max_err[k]);
        let growth = si(g, "", 4);
        if clipped {
            t!(
                "integrators-method-diverges-clipped",
                method = name,
                growth = growth,
                error = error
            )
        } else {
            t!(
                "integrators-method-diverges",
                method = name,
                growth = growth,
                error = error
            )
        }
    } else {
        t!(
            "integrators-method-bounded",
            method = name,
            growth = si(g, "", 4),
            error = error_text(r.fixed.max_err[k])
        )
    }
}

/// What DP45 did.
pub(super) fn dp45_words(p: &P, r: &Results, steps: usize) -> String {
    t!(
        "integrators-dp45-words",
        steps = steps,
        tolerance = sci(p.tol),
        error = error_text(r.dp45_err)
    )
}

/// Why DP45 could not finish, in words.
pub(super) fn dp45_failed(e: &IntegrationError) -> String {
    let reason = match *e {
        IntegrationError::StepSizeUnderflow { t } => {
            t!("integrators-failed-underflow", time = si(t, "s", 3))
        }
        IntegrationError::MaxSteps { t, n } => {
            t!(
                "integrators-failed-max-steps",
                time = si(t, "s", 3),
                steps = n
            )
        }
        IntegrationError::NonFinite { t } => {
            t!("integrators-failed-non-finite", time = si(t, "s", 3))
        }
        // Invalid settings: the sliders' ranges keep these out of reach.
        ref other => other.to_string(),
    };
    t!("integrators-dp45-failed", reason = reason)
}

/// The response plot's text alternative.
pub(super) fn describe_response(p: &P, r: &Results, words: &[String]) -> String {
    let duration = si(p.t_end, "s", 3);
    let step = si(r.h, "s", 3);
    let methods = join(words);
    let range = significant(super::figures::RESPONSE_RANGE, 1);
    if r.h_last < r.h {
        t!(
            "integrators-describe-response-last",
            duration = duration,
            step = step,
            steps = r.n,
            last = si(r.h_last, "s", 3),
            methods = methods,
            range = range
        )
    } else {
        t!(
            "integrators-describe-response",
            duration = duration,
            step = step,
            steps = r.n,
            methods = methods,
            range = range
        )
    }
}

/// Where one method's error peaks.
pub(super) fn error_words(name: &str, pts: &[(f64, f64)], growth: f64) -> String {
    let peak =
        pts.iter()
            .filter(|q| q.1.is_finite())
            .fold(None::<(f64, f64)>, |acc, &q| match acc {
                Some(a) if a.1 >= q.1 => Some(a),
                _ => Some(q),
            });
    match peak {
        Some((t, e)) if growth > 1.0 => t!(
            "integrators-error-peak-growing",
            method = name,
            error = si(e, "m", 3),
            time = si(t, "s", 3)
        ),
        Some((t, e)) => t!(
            "integrators-error-peak",
            method = name,
            error = si(e, "m", 3),
            time = si(t, "s", 3)
        ),
        None => t!("integrators-error-none", method = name),
    }
}

/// The error plot's text alternative.
pub(super) fn describe_error(r: &Results, parts: &[String], clipped: bool, clip: f64) -> String {
    if parts.is_empty() {
        t!("integrators-error-no-method")
    } else if clipped {
        t!(
            "integrators-describe-error-clipped",
            step = si(r.h, "s", 3),
            methods = join(parts),
            clip = si(clip, "m", 2)
        )
    } else {
        t!(
            "integrators-describe-error",
            step = si(r.h, "s", 3),
            methods = join(parts)
        )
    }
}

/// `fig`, drawn from the fixed-step runs, described as drawn from the runs so far while
/// the rest are under way (see `runs.rs`).
pub(super) fn runs_so_far(
    mut fig: crate::figure::Figure,
    p: &P,
    r: &Results,
) -> crate::figure::Figure {
    // The first module computes whole runs: never a start only.
    if let (false, Some(until)) = (cfg!(feature = "first"), r.fixed.until) {
        fig.description = t!(
            "integrators-runs-provisional",
            until = si(until, "s", 3),
            duration = si(p.t_end, "s", 3),
            description = std::mem::take(&mut fig.description)
        );
    }
    fig
}

/// A figure drawn from the coarse study (`coarse`) while the full one runs, marked as
/// provisional in its description (its title is left as it is: it already fills a phone's
/// width).
pub(super) fn provisional(
    mut fig: crate::figure::Figure,
    coarse: &Budget,
) -> crate::figure::Figure {
    let last = |b: &Budget| b.tols.last().map_or_else(String::new, |&t| sci(t));
    fig.description = t!(
        "integrators-provisional",
        budget = coarse.steps,
        euler_budget = coarse.euler,
        tol = last(coarse),
        full_budget = FULL.steps,
        full_euler_budget = FULL.euler,
        full_tol = last(&FULL),
        description = std::mem::take(&mut fig.description)
    );
    fig
}
