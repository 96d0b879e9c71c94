//! The RLC demo's figures: the current and the capacitor voltage, each against the
//! critically damped loop of the same L and C and inside its decay envelope, and the
//! animated loop.

use super::{text, Results, P};
use crate::figure::{finite_extent, padded, Axis, Figure, LineStyle};
use crate::format::si;
use crate::plot::{curve, Ink};
use crate::schematic::rlc_loop;
use crate::t;
use zeta_solver::{FreeResponse, Regime, SecondOrder};

/// Samples per curve.
const SAMPLES: usize = 800;
/// Samples of each envelope curve (a smooth exponential needs few).
const ENVELOPE_SAMPLES: usize = 121;

pub(super) const CURRENT_TITLE: &str = "Current i(t)";
pub(super) const VOLTAGE_TITLE: &str = "Capacitor voltage v_C(t)";

/// What a plot shows of the charge state `[q, q']`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Signal {
    /// The current `i = q'` \[A\].
    Current,
    /// The capacitor voltage `v_C = q/C` \[V\].
    Voltage,
}

impl Signal {
    /// The plotted quantity from the charge state `[q, q']`.
    fn of(self, p: &P, state: [f64; 2]) -> f64 {
        match self {
            Signal::Current => state[1],
            Signal::Voltage => state[0] / p.cap,
        }
    }

    /// The decay envelope of this signal from that of the charge, `A·e^(−αt)`: the current
    /// of a ringing `q = A·e^(−αt)·cos(ω_d t − φ)` has amplitude `ω₀·A·e^(−αt)`
    /// (as `α² + ω_d² = ω₀²`), the voltage `A·e^(−αt)/C`.
    fn envelope(self, p: &P, w0: f64, charge: f64) -> f64 {
        match self {
            Signal::Current => w0 * charge,
            Signal::Voltage => charge / p.cap,
        }
    }

    /// How large the signal can get: the current bound `q₀·ω₀` or `V₀`.
    fn scale(self, r: &Results) -> f64 {
        match self {
            Signal::Current => r.current_scale(),
            Signal::Voltage => r.p.v0.abs(),
        }
    }
}

/// The signal over the window for `sys` released from the design's `q₀`.
fn sample(r: &Results, sys: SecondOrder, signal: Signal) -> Vec<(f64, f64)> {
    let response = r.p.response(sys);
    // Times `t_end·i/(n − 1)`: the lossless current sums to ~1e-13 over whole periods, a
    // digest that the last bit of each sample time would move.
    (0..SAMPLES)
        .map(|i| {
            let t = r.t_end * i as f64 / (SAMPLES - 1) as f64;
            (t, signal.of(&r.p, response.state(t)))
        })
        .collect()
}

/// The current or the capacitor voltage: the design (solid), the critically damped loop
/// (dashed) and, while it rings, the decay envelope (dotted).
pub(super) fn signal(r: &Results, signal: Signal) -> Figure {
    let (title, label, unit) = match signal {
        Signal::Current => (t!("rlc-plot-current"), t!("rlc-axis-current"), "A"),
        Signal::Voltage => (t!("rlc-plot-voltage"), t!("rlc-axis-voltage"), "V"),
    };
    let mut fig = Figure::plot(
        title,
        Axis::linear(t!("axis-time"), "s", (0.0, r.t_end)),
        Axis::linear(label, unit, (-1.0, 1.0)),
    );
    let response: FreeResponse = r.p.response(r.sys);
    if let (Some(_), Some(w0)) = (response.envelope_amplitude(), r.sys.natural_frequency()) {
        let envelope = |t: f64| signal.envelope(&r.p, w0, response.envelope(t).unwrap_or(0.0));
        let style = LineStyle::dotted(Ink::Green, 1.5);
        fig = fig
            .with_line(
                t!("rlc-envelope"),
                curve((0.0, r.t_end), ENVELOPE_SAMPLES, envelope),
                style,
            )
            .with_line(
                "",
                curve((0.0, r.t_end), ENVELOPE_SAMPLES, |t| -envelope(t)),
                style,
            );
    }
    if let (Some(crit), false) = (r.critical, r.sys.regime() == Regime::CriticallyDamped) {
        fig = fig.with_line(
            t!(
                "rlc-series-critical",
                resistance = text::ohms(crit.damping())
            ),
            sample(r, crit, signal),
            LineStyle::dashed(Ink::Vermillion, 2.0),
        );
    }
    let own = sample(r, r.sys, signal);
    let scale = signal.scale(r);
    let (lo, hi) = finite_extent(
        fig.series
            .iter()
            .flat_map(|s| s.points.iter().map(|p| p.1))
            .chain(own.iter().map(|p| p.1))
            .filter(|v| v.abs() <= 2.0 * scale),
    )
    .unwrap_or((-scale, scale));
    let (lo, hi) = (lo.min(-0.1 * scale), hi.max(0.1 * scale));
    // Head-room above the data for the legend in the upper right.
    let span = hi - lo;
    fig.y.range = padded((lo, hi + 0.5 * span), 0.05);
    fig.with_line(
        format!("R = {}", text::ohms(r.p.r)),
        own,
        LineStyle::solid(Ink::Blue, 3.0),
    )
    .with_origin_lines()
    .described(text::describe(r, signal))
}

/// The loop at time `t` \[s\] in charge state `[q, i]`, the current drawn relative to its
/// bound `scale` \[A\] and the charge relative to `q₀`.
pub(super) fn schematic(p: &P, scale: f64, [q, i]: [f64; 2], t: f64) -> Figure {
    let description = t!(
        "rlc-schematic",
        time = si(t, "s", 3),
        current = si(i, "A", 3),
        voltage = si(q / p.cap, "V", 3)
    );
    let q0 = p.q0().abs().max(1e-300);
    rlc_loop(i / scale.max(1e-300), q / q0, description)
}
