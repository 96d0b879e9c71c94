//! The integrators demo's prose: summary, equation, the table of methods and the figures'
//! text alternatives.

use super::model::Run;
use super::{Results, P};
use crate::format::si;
use crate::spec::Table;
use zeta_solver::integrate::analysis::StepLimit;

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
        StepLimit::UpTo(h) => format!("stable for h ≤ {}", si(h, "s", 3)),
        StepLimit::Unconditional => "stable for every h".into(),
        StepLimit::NoStableStep => "unstable for every h".into(),
    }
}

/// `1e-6` style for tolerances.
pub(super) fn sci(v: f64) -> String {
    format!("{v:.0e}")
}

/// What fixed-step method `k` does at this `h`.
pub(super) fn method_words(name: &str, r: &Results, k: usize, run: &Run, clipped: bool) -> String {
    let g = r.growth[k];
    let state = if let Some(t) = run.overflow {
        format!(
            "overflows at t = {} (×{} per step)",
            si(t, "s", 3),
            si(g, "", 3)
        )
    } else if g > 1.0 && !r.stable[k] {
        format!(
            "diverges (×{} per step{}), max error {}",
            si(g, "", 4),
            if clipped { ", clipped" } else { "" },
            r.max_err[k].map_or("—".into(), |e| si(e, "m", 3))
        )
    } else {
        format!(
            "stays bounded (×{} per step), max error {}",
            si(g, "", 4),
            r.max_err[k].map_or("—".into(), |e| si(e, "m", 3))
        )
    };
    format!("{name} {state}")
}

/// What DP45 did.
pub(super) fn dp45_words(p: &P, r: &Results, steps: usize) -> String {
    format!(
        "DP45 took {} steps (tolerance {}), max error {}",
        steps,
        sci(p.tol),
        r.dp45_err.map_or("—".into(), |e| si(e, "m", 3))
    )
}

/// The response plot's text alternative.
pub(super) fn describe_response(p: &P, r: &Results, words: &[String]) -> String {
    let last = if r.h_last < r.h {
        format!(", the last {} to end at T", si(r.h_last, "s", 3))
    } else {
        String::new()
    };
    format!(
        "Each method against the exact decaying oscillation over {} with h = {} ({} steps{last}). \
         {}. The plot shows ±{} of the exact amplitude; curves beyond it are clipped at the edge.",
        si(p.t_end, "s", 3),
        si(r.h, "s", 3),
        r.n,
        words.join("; "),
        super::figures::RESPONSE_RANGE
    )
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
        Some((t, e)) => format!(
            "{name} largest {} at t = {}{}",
            si(e, "m", 3),
            si(t, "s", 3),
            if growth > 1.0 { ", growing" } else { "" }
        ),
        None => format!("{name} has no finite error"),
    }
}

/// The error plot's text alternative.
pub(super) fn describe_error(r: &Results, parts: &[String], clipped: bool, clip: f64) -> String {
    if parts.is_empty() {
        "No method is switched on.".to_string()
    } else {
        format!(
            "Error |x_num − x_exact| on a logarithmic scale at each method's grid points \
             (h = {}): {}.{}",
            si(r.h, "s", 3),
            parts.join("; "),
            if clipped {
                format!(" Errors above {} are clipped at the top.", si(clip, "m", 2))
            } else {
                String::new()
            }
        )
    }
}
