//! Axes held still while a control is dragged, and eased back when it is released.

// Drawing: axis ranges eased geometrically on log axes, not model maths.
#![allow(clippy::disallowed_methods)]

use crate::figure::{AxisScale, Figure, FigureKind};

/// A plot's `(x, y)` axis ranges.
pub type AxisRanges = ((f64, f64), (f64, f64));

/// How far past the data a held axis goes when the data leave it, as a fraction of its
/// new span: a drag that keeps pushing a curve out (a 2-DOF mass ratio raising its peak)
/// then widens the axis every few frames, not on each one, and the frames between start
/// from the plot's kept static layer (which every change of an axis redraws).
pub const WIDEN_MARGIN: f64 = 0.25;

/// While a control is dragged, a plot keeps the ranges it was last drawn with (`held`),
/// widened only where the new figure's own ranges leave them, and then by
/// `WIDEN_MARGIN` past them (not across zero on a linear axis: a range of magnitudes
/// stays one), so the axes hold still and the change the control makes is seen; the
/// figure's own ranges return when the drag ends. An axis whose own range has shrunk under
/// a third of the held one (on log axes, in decades) takes its own at once: held, the
/// curve would be a sliver along it (a current damped to a tenth of the axis, a response
/// ending at a sixth of the time axis). The plot then holds that range. Schematics (equal
/// scales, no axes) are left alone.
pub fn hold_axes(fig: &mut Figure, held: Option<AxisRanges>) {
    let Some((hx, hy)) = held else { return };
    if fig.kind != FigureKind::Plot {
        return;
    }
    let hold = |(lo, hi): (f64, f64), (a, b): (f64, f64), log: bool| {
        // On a log axis, spans and margins are taken in decades.
        let log = log && lo > 0.0 && a > 0.0;
        let to = |v: f64| if log { v.ln() } else { v };
        let from = |v: f64| if log { v.exp() } else { v };
        let (l, h, a_, b_) = (to(lo), to(hi), to(a), to(b));
        if b_ - a_ < (h - l) / 3.0 {
            return (a, b);
        }
        let (below, above) = (a_ < l, b_ > h);
        let margin = WIDEN_MARGIN * (h.max(b_) - l.min(a_));
        let mut lo = if below { from(a_ - margin) } else { lo };
        let mut hi = if above { from(b_ + margin) } else { hi };
        // A linear range on one side of zero stays there.
        if !log && below && a >= 0.0 {
            lo = lo.max(0.0);
        }
        if !log && above && b <= 0.0 {
            hi = hi.min(0.0);
        }
        (lo, hi)
    };
    fig.x.range = hold(hx, fig.x.range, fig.x.scale == AxisScale::Log);
    fig.y.range = hold(hy, fig.y.range, fig.y.scale == AxisScale::Log);
}

/// After a drag, moves a plot's axes from the ranges it was held at (`from`) towards the
/// figure's own, by `f` in 0…1 (1 = the figure's own ranges); log axes move geometrically.
/// Used over a few frames so the rescale is seen as a motion, not a jump.
pub fn ease_axes(fig: &mut Figure, from: Option<AxisRanges>, f: f64) {
    let Some((fx, fy)) = from else { return };
    if fig.kind != FigureKind::Plot || !(0.0..1.0).contains(&f) {
        return;
    }
    let mix = |a: f64, b: f64, log: bool| {
        if log && a > 0.0 && b > 0.0 {
            (a.ln() + f * (b.ln() - a.ln())).exp()
        } else {
            a + f * (b - a)
        }
    };
    let x_log = fig.x.scale == AxisScale::Log;
    let y_log = fig.y.scale == AxisScale::Log;
    let (x, y) = (fig.x.range, fig.y.range);
    fig.x.range = (mix(fx.0, x.0, x_log), mix(fx.1, x.1, x_log));
    fig.y.range = (mix(fy.0, y.0, y_log), mix(fy.1, y.1, y_log));
}
