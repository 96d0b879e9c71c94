//! The `integrators` demo's declaration: parameters, readouts, plots and presets as tables.

use super::{convergence, figures, stability, text, work, Results, P};
use crate::declare::{
    Declaration, Param, ReadoutDef, DAMPING_RATIO, INITIAL_DISPLACEMENT, NATURAL_FREQUENCY,
};
use crate::format::si;
use crate::spec::{PlotSpec, Preset};
use crate::t;

// The readouts of the fixed-step methods, one constructor per kind: `K` is the method's
// index in the results (forward Euler, symplectic Euler, Heun, RK4), so each row of the
// table gives only its key and label.

/// Max error over the run, or the time at which the run overflowed.
fn max_err<const K: usize>(key: &'static str, label: &'static str) -> ReadoutDef<Results> {
    ReadoutDef::number_or_note(key, label, "m", 3, |r| match r.runs[K].overflow {
        Some(t) => Err(t!("integrators-overflow-note", time = si(t, "s", 3))),
        None => Ok(r.max_err[K]),
    })
}

/// Order fitted over the asymptotic range of the convergence study.
fn order<const K: usize>(key: &'static str, label: &'static str) -> ReadoutDef<Results> {
    ReadoutDef::number(key, label, "", 3, |r| r.study.order(K))
}

/// Whether the run is stable at this step: yes or no.
fn stable<const K: usize>(key: &'static str, label: &'static str) -> ReadoutDef<Results> {
    ReadoutDef::text(key, label, |r| {
        if r.stable[K] {
            t!("integrators-stable-yes")
        } else {
            t!("integrators-stable-no")
        }
    })
}

/// Growth factor per step (|R(hλ)|, or the step matrix's spectral radius).
fn growth<const K: usize>(key: &'static str, label: &'static str) -> ReadoutDef<Results> {
    ReadoutDef::number(key, label, "", 4, |r| Some(r.growth[K]))
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
            max_err::<0>("max_err_euler", "max error, forward Euler"),
            max_err::<1>("max_err_symplectic_euler", "max error, symplectic Euler"),
            max_err::<2>("max_err_heun", "max error, Heun"),
            max_err::<3>("max_err_rk4", "max error, RK4"),
            ReadoutDef::number_or_note("max_err_dp45", "max error, DP45", "m", 3, |r| match &r
                .dp45
            {
                Ok(_) => Ok(r.dp45_err),
                Err(_) => Err(t!("integrators-failed")),
            }),
            order::<0>("order_euler", "fitted order, forward Euler"),
            order::<1>("order_symplectic_euler", "fitted order, symplectic Euler"),
            order::<2>("order_heun", "fitted order, Heun"),
            order::<3>("order_rk4", "fitted order, RK4"),
            ReadoutDef::number(
                "order_dp45",
                "observed order, DP45 (error against f-evaluations, where the tolerance sets the steps)",
                "",
                3,
                |r| r.study.dp45.order(),
            ),
            stable::<0>("stable_euler", "stable at this h, forward Euler"),
            stable::<1>("stable_symplectic_euler", "stable at this h, symplectic Euler"),
            stable::<2>("stable_heun", "stable at this h, Heun"),
            stable::<3>("stable_rk4", "stable at this h, RK4"),
            growth::<0>("growth_euler", "growth per step |R(hλ)|, forward Euler"),
            growth::<1>(
                "growth_symplectic_euler",
                "growth per step (spectral radius), symplectic Euler",
            ),
            growth::<2>("growth_heun", "growth per step |R(hλ)|, Heun"),
            growth::<3>("growth_rk4", "growth per step |R(hλ)|, RK4"),
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
