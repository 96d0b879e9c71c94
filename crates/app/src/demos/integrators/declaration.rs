//! The `integrators` demo's declaration: parameters, readouts, plots and presets as tables,
//! one row each.

use super::{convergence, figures, stability, text, work, Results, P};
use crate::declare::{Declaration, DAMPING_RATIO, INITIAL_DISPLACEMENT, NATURAL_FREQUENCY};
use crate::demos::rows::{self, readouts, sliders};
use crate::format::si;
use crate::spec::Preset;
use crate::t;

/// Parameters, readouts, plots and presets of `integrators`.
pub(super) fn declaration() -> Declaration<P, Results> {
    Declaration {
        equation_mathml: text::EQUATION,
        params: sliders! { P;
            quantity DAMPING_RATIO, (0.0, 2.0, 0.01), 0.05 => zeta;
            quantity NATURAL_FREQUENCY, (0.5, 20.0, 0.01), 2.0 => wn;
            log "h", "step size", "h", "s", (1e-3, 2.0, 1e-4), 0.3 => h;
            linear "T", "duration", "T", "s", (1.0, 60.0, 0.5), 20.0 => t_end;
            quantity INITIAL_DISPLACEMENT, (0.05, 2.0, 0.01), 1.0 => x0;
            log "tol", "DP45 tolerance (relative; absolute tol·x₀)", "tol", "",
                (1e-10, 1e-2, 1e-10), 1e-6 => tol;
            toggle "euler", "forward Euler", true => show[0];
            toggle "symplectic_euler", "symplectic Euler", true => show[1];
            toggle "heun", "Heun (RK2)", true => show[2];
            toggle "rk4", "RK4", true => show[3];
            toggle "dp45", "Dormand–Prince 5(4), adaptive", true => show[4];
        },
        // The fixed-step methods by their index in the results: forward Euler, symplectic
        // Euler, Heun, RK4. The errors lead: a phone's strip shows the first two while any
        // slider is held. The steps come last, together: the step actually used changes only
        // with h (its slider shows it too) and T.
        readouts: readouts! { Results, |r|;
            number_or_note "max_err_euler", "max error, forward Euler", "m", 3 => max_err(r, 0);
            number_or_note "max_err_symplectic_euler", "max error, symplectic Euler", "m", 3
                => max_err(r, 1);
            number_or_note "max_err_heun", "max error, Heun", "m", 3 => max_err(r, 2);
            number_or_note "max_err_rk4", "max error, RK4", "m", 3 => max_err(r, 3);
            number_or_note "max_err_dp45", "max error, DP45", "m", 3
                => r.dp45.as_ref().map(|_| r.dp45_err).map_err(|_| t!("integrators-failed"));
            number "order_euler", "fitted order, forward Euler", "", 3 => r.study.order(0);
            number "order_symplectic_euler", "fitted order, symplectic Euler", "", 3
                => r.study.order(1);
            number "order_heun", "fitted order, Heun", "", 3 => r.study.order(2);
            number "order_rk4", "fitted order, RK4", "", 3 => r.study.order(3);
            number "order_dp45",
                "observed order, DP45 (error against f-evaluations, where the tolerance sets the steps)",
                "", 3 => r.study.dp45.order();
            text "stable_euler", "stable at this h, forward Euler" => stable(r, 0);
            text "stable_symplectic_euler", "stable at this h, symplectic Euler" => stable(r, 1);
            text "stable_heun", "stable at this h, Heun" => stable(r, 2);
            text "stable_rk4", "stable at this h, RK4" => stable(r, 3);
            number "growth_euler", "growth per step |R(hλ)|, forward Euler", "", 4
                => Some(r.growth[0]);
            number "growth_symplectic_euler", "growth per step (spectral radius), symplectic Euler",
                "", 4 => Some(r.growth[1]);
            number "growth_heun", "growth per step |R(hλ)|, Heun", "", 4 => Some(r.growth[2]);
            number "growth_rk4", "growth per step |R(hλ)|, RK4", "", 4 => Some(r.growth[3]);
            number "steps_dp45", "DP45 accepted steps", "", 3
                => r.dp45.as_ref().ok().map(|o| o.solution.stats.n_accepted as f64);
            number "h_used", "step used, every step but the last", "s", 4
                => Some(r.h);
            number "h_last", "last step, ending the run at T", "s", 4 => Some(r.h_last);
        },
        // Key, title and width / height.
        plots: rows::plots(&[
            ("response", figures::RESPONSE_TITLE, 1.6),
            ("error", figures::ERROR_TITLE, 1.2),
            ("convergence", convergence::TITLE, 1.25),
            ("work", work::TITLE, 1.25),
            ("stability", stability::TITLE, 1.3),
        ]),
        presets: vec![
            preset("Lightly damped, h = 0.3 s", 0.05, 2.0, 0.3),
            preset("Euler just stable, h = 0.04 s", 0.05, 2.0, 0.04),
            preset("RK4 beyond its limit, h = 1.6 s", 0.05, 2.0, 1.6),
            preset("Undamped, h = 0.1 s", 0.0, 2.0, 0.1),
            Preset {
                label: "Stiff overdamped ζ = 2, ωₙ = 20",
                values: vec![("zeta", 2.0), ("wn", 20.0), ("h", 0.03), ("T", 5.0)],
            },
        ],
        table: Some(text::methods_table()),
        ..Declaration::new(
            "integrators",
            "Numerical integrators and their error",
            text::SUMMARY,
        )
    }
}

/// Max error over the run of fixed-step method `k` \[m\], or the time at which it overflowed.
fn max_err(r: &Results, k: usize) -> Result<Option<f64>, String> {
    match r.fixed.runs[k].overflow {
        Some(t) => Err(t!("integrators-overflow-note", time = si(t, "s", 3))),
        None => Ok(r.fixed.max_err[k]),
    }
}

/// Whether fixed-step method `k` is stable at this step: yes or no.
fn stable(r: &Results, k: usize) -> String {
    if r.stable[k] {
        t!("integrators-stable-yes")
    } else {
        t!("integrators-stable-no")
    }
}

/// A preset that sets ζ, ωₙ and h (the duration and the rest stay).
fn preset(label: &'static str, zeta: f64, wn: f64, h: f64) -> Preset {
    Preset {
        label,
        values: vec![("zeta", zeta), ("wn", wn), ("h", h)],
    }
}
