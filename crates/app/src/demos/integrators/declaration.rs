//! The `integrators` demo's declaration: parameters, readouts, plots and presets as tables.

use super::{convergence, figures, stability, text, work, Results, P};
use crate::declare::{
    Declaration, Param, ReadoutDef, DAMPING_RATIO, INITIAL_DISPLACEMENT, NATURAL_FREQUENCY,
};
use crate::format::si;
use crate::spec::{PlotSpec, Preset};
use crate::t;

/// A fixed-step method's readout: a number, or the time at which its run overflowed.
fn max_err(r: &Results, k: usize) -> Result<Option<f64>, String> {
    match r.runs[k].overflow {
        Some(t) => Err(t!("integrators-overflow-note", time = si(t, "s", 3))),
        None => Ok(r.max_err[k]),
    }
}

fn stable(r: &Results, k: usize) -> String {
    if r.stable[k] {
        t!("integrators-stable-yes")
    } else {
        t!("integrators-stable-no")
    }
}

/// Parameters, readouts, plots and presets of `integrators`.
pub(super) fn declaration() -> Declaration<P, Results> {
    Declaration {
        equation_mathml: text::EQUATION,
        params: vec![
            Param::quantity(DAMPING_RATIO, (0.0, 2.0, 0.01), 0.05, |p, v| p.zeta = v),
            Param::quantity(NATURAL_FREQUENCY, (0.5, 20.0, 0.01), 2.0, |p, v| p.wn = v),
            Param::log(
                "h",
                "step size",
                "h",
                "s",
                (1e-3, 2.0, 1e-4),
                0.3,
                |p, v| p.h = v,
            ),
            Param::linear("T", "duration", "T", "s", (1.0, 60.0, 0.5), 20.0, |p, v| {
                p.t_end = v
            }),
            Param::quantity(INITIAL_DISPLACEMENT, (0.05, 2.0, 0.01), 1.0, |p, v| p.x0 = v),
            Param::log(
                "tol",
                "DP45 tolerance (relative; absolute tol·x₀)",
                "tol",
                "",
                (1e-10, 1e-2, 1e-10),
                1e-6,
                |p, v| p.tol = v,
            ),
            Param::toggle("euler", "forward Euler", true, |p, on| p.show[0] = on),
            Param::toggle("symplectic_euler", "symplectic Euler", true, |p, on| {
                p.show[1] = on
            }),
            Param::toggle("heun", "Heun (RK2)", true, |p, on| p.show[2] = on),
            Param::toggle("rk4", "RK4", true, |p, on| p.show[3] = on),
            Param::toggle("dp45", "Dormand–Prince 5(4), adaptive", true, |p, on| {
                p.show[4] = on
            }),
        ],
        readouts: vec![
            ReadoutDef::number(
                "h_used",
                "step used: exactly h (a shorter last step ends the run at T)",
                "s",
                4,
                |r| Some(r.h),
            ),
            ReadoutDef::number("h_last", "last step, ending the run at T", "s", 4, |r| {
                Some(r.h_last)
            }),
            ReadoutDef::number_or_note(
                "max_err_euler",
                "max error, forward Euler",
                "m",
                3,
                |r| max_err(r, 0),
            ),
            ReadoutDef::number_or_note(
                "max_err_symplectic_euler",
                "max error, symplectic Euler",
                "m",
                3,
                |r| max_err(r, 1),
            ),
            ReadoutDef::number_or_note("max_err_heun", "max error, Heun", "m", 3, |r| {
                max_err(r, 2)
            }),
            ReadoutDef::number_or_note("max_err_rk4", "max error, RK4", "m", 3, |r| {
                max_err(r, 3)
            }),
            ReadoutDef::number_or_note("max_err_dp45", "max error, DP45", "m", 3, |r| match &r
                .dp45
            {
                Ok(_) => Ok(r.dp45_err),
                Err(_) => Err(t!("integrators-failed")),
            }),
            ReadoutDef::number("order_euler", "fitted order, forward Euler", "", 3, |r| {
                r.study.order(0)
            }),
            ReadoutDef::number(
                "order_symplectic_euler",
                "fitted order, symplectic Euler",
                "",
                3,
                |r| r.study.order(1),
            ),
            ReadoutDef::number("order_heun", "fitted order, Heun", "", 3, |r| {
                r.study.order(2)
            }),
            ReadoutDef::number("order_rk4", "fitted order, RK4", "", 3, |r| {
                r.study.order(3)
            }),
            ReadoutDef::number(
                "order_dp45",
                "observed order, DP45 (error against f-evaluations, where the tolerance sets the steps)",
                "",
                3,
                |r| r.study.dp45.order(),
            ),
            ReadoutDef::text("stable_euler", "stable at this h, forward Euler", |r| {
                stable(r, 0)
            }),
            ReadoutDef::text(
                "stable_symplectic_euler",
                "stable at this h, symplectic Euler",
                |r| stable(r, 1),
            ),
            ReadoutDef::text("stable_heun", "stable at this h, Heun", |r| stable(r, 2)),
            ReadoutDef::text("stable_rk4", "stable at this h, RK4", |r| stable(r, 3)),
            ReadoutDef::number(
                "growth_euler",
                "growth per step |R(hλ)|, forward Euler",
                "",
                4,
                |r| Some(r.growth[0]),
            ),
            ReadoutDef::number(
                "growth_symplectic_euler",
                "growth per step (spectral radius), symplectic Euler",
                "",
                4,
                |r| Some(r.growth[1]),
            ),
            ReadoutDef::number(
                "growth_heun",
                "growth per step |R(hλ)|, Heun",
                "",
                4,
                |r| Some(r.growth[2]),
            ),
            ReadoutDef::number("growth_rk4", "growth per step |R(hλ)|, RK4", "", 4, |r| {
                Some(r.growth[3])
            }),
            ReadoutDef::number("steps_dp45", "DP45 accepted steps", "", 3, |r| {
                r.dp45
                    .as_ref()
                    .ok()
                    .map(|o| o.solution.stats.n_accepted as f64)
            }),
        ],
        plots: vec![
            PlotSpec {
                key: "response",
                title: figures::RESPONSE_TITLE,
                aspect: 1.6,
            },
            PlotSpec {
                key: "error",
                title: figures::ERROR_TITLE,
                aspect: 1.2,
            },
            PlotSpec {
                key: "convergence",
                title: convergence::TITLE,
                aspect: 1.25,
            },
            PlotSpec {
                key: "work",
                title: work::TITLE,
                aspect: 1.25,
            },
            PlotSpec {
                key: "stability",
                title: stability::TITLE,
                aspect: 1.3,
            },
        ],
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

fn preset(label: &'static str, zeta: f64, wn: f64, h: f64) -> Preset {
    Preset {
        label,
        values: vec![("zeta", zeta), ("wn", wn), ("h", h)],
    }
}
