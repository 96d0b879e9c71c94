//! The analogy demo's figures: both machines' normalised responses on one plot, the
//! energy exchange in each, and the two machines drawn side by side.

use super::{text, Results};
use crate::figure::{finite_extent, padded, Axis, Figure, LineStyle};
use crate::plot::Ink;
use crate::schematic::{beside, caption, mass_spring_damper, rlc_loop, MassLabels};
use crate::t;
use zeta_solver::integrate::analysis::oscillator_energy;

/// Samples per curve.
const SAMPLES: usize = 600;
/// Where the circuit is drawn relative to the mass (drawing units): beside it, centred.
pub(super) const CIRCUIT_OFFSET: (f64, f64) = (4.7, 1.4);

/// Line styles, in the order the plots list their curves: mechanical solid and thick,
/// electrical thin and broken — `x`, `q`, `v`, `i` (the stores spring, capacitor, mass,
/// inductor), then the mechanical and electrical totals.
const STYLES: [LineStyle; 6] = [
    LineStyle::solid(Ink::Blue, 3.5),
    LineStyle::dashed(Ink::Vermillion, 2.0),
    LineStyle::solid(Ink::Green, 3.5),
    LineStyle::dotted(Ink::Purple, 2.0),
    LineStyle::solid(Ink::Black, 2.5),
    LineStyle::dashed(Ink::Orange, 1.5),
];

pub(super) const RESPONSES_TITLE: &str = "Normalised responses of both machines";
pub(super) const ENERGY_TITLE: &str = "Energy exchange";

/// Sample times `t_end·i/(n − 1)` over the window.
fn times(r: &Results) -> impl Iterator<Item = f64> {
    let t_end = r.t_end;
    (0..SAMPLES).map(move |i| t_end * i as f64 / (SAMPLES - 1) as f64)
}

/// The mechanism's and the circuit's states at `t`: `([x, v], [q, i])`.
fn states(r: &Results, t: f64) -> ([f64; 2], [f64; 2]) {
    let (xr, qr) = r.responses();
    (xr.state(t), qr.state(t))
}

/// The states of both machines normalised by their own scales, `x/x₀`, `v/(x₀ωₙ)`, `q/q₀`
/// and `i/(q₀ω₀)`: with equal numbers in both machines the pairs coincide.
struct Normalised {
    x: Vec<(f64, f64)>,
    v: Vec<(f64, f64)>,
    q: Vec<(f64, f64)>,
    i: Vec<(f64, f64)>,
}

impl Normalised {
    fn of(r: &Results) -> Self {
        let (wn, w0) = (r.wn(), r.w0());
        let mut out = Self {
            x: Vec::with_capacity(SAMPLES),
            v: Vec::with_capacity(SAMPLES),
            q: Vec::with_capacity(SAMPLES),
            i: Vec::with_capacity(SAMPLES),
        };
        for t in times(r) {
            let ([x, v], [q, i]) = states(r, t);
            out.x.push((t, x / r.x0));
            out.v.push((t, v / (r.x0 * wn)));
            out.q.push((t, q / r.q0));
            out.i.push((t, i / (r.q0 * w0)));
        }
        out
    }

    /// The largest difference between a mechanical curve and its electrical twin.
    fn gap(&self) -> f64 {
        let pairs = self.x.iter().zip(&self.q).chain(self.v.iter().zip(&self.i));
        pairs.fold(0.0, |g: f64, (a, b)| g.max((a.1 - b.1).abs()))
    }
}

/// x/x₀ and q/q₀, v/(x₀ωₙ) and i/(q₀ω₀) against time: two pairs of coinciding curves.
pub(super) fn responses(r: &Results) -> Figure {
    let n = Normalised::of(r);
    let all = n.x.iter().chain(&n.v).chain(&n.q).chain(&n.i).map(|p| p.1);
    let (lo, hi) = finite_extent(all).unwrap_or((-1.0, 1.0));
    let (lo, hi) = padded((lo.min(-0.2), hi.max(1.0)), 0.06);
    // Head-room above the data for the legend.
    let y = (lo, hi + 0.45 * (hi - lo));
    let description = text::describe_responses(r, n.gap());
    let lines = [
        (t!("analogy-series-x"), n.x),
        (t!("analogy-series-q"), n.q),
        (t!("analogy-series-v"), n.v),
        (t!("analogy-series-i"), n.i),
    ];
    let y_axis = Axis::linear(t!("analogy-axis-response"), "", y);
    time_plot(r, t!("analogy-plot-responses"), y_axis, lines)
        .with_origin_lines()
        .described(description)
}

/// The energy in each store of both machines, and each machine's total.
pub(super) fn energy(r: &Results) -> Figure {
    let mut spring = Vec::with_capacity(SAMPLES);
    let mut mass = Vec::with_capacity(SAMPLES);
    let mut cap = Vec::with_capacity(SAMPLES);
    let mut ind = Vec::with_capacity(SAMPLES);
    let mut total_mech = Vec::with_capacity(SAMPLES);
    let mut total_elec = Vec::with_capacity(SAMPLES);
    for t in times(r) {
        let ([x, v], [q, i]) = states(r, t);
        spring.push((t, oscillator_energy(&r.mech, [x, 0.0])));
        mass.push((t, oscillator_energy(&r.mech, [0.0, v])));
        cap.push((t, oscillator_energy(&r.elec, [q, 0.0])));
        ind.push((t, oscillator_energy(&r.elec, [0.0, i])));
        total_mech.push((t, oscillator_energy(&r.mech, [x, v])));
        total_elec.push((t, oscillator_energy(&r.elec, [q, i])));
    }
    let e0 = r.energy();
    let left = total_mech.last().map_or(0.0, |p| p.1);
    let kinetic_peak = mass.iter().map(|p| p.1).fold(0.0, f64::max);
    let description = text::describe_energy(r, e0, left, kinetic_peak);
    let lines = [
        (t!("analogy-series-spring"), spring),
        (t!("analogy-series-capacitor"), cap),
        (t!("analogy-series-mass"), mass),
        (t!("analogy-series-inductor"), ind),
        (t!("analogy-series-total-mass"), total_mech),
        (t!("analogy-series-total-circuit"), total_elec),
    ];
    let y_axis = Axis::linear(t!("analogy-axis-energy"), "J", (0.0, 2.1 * e0.max(1e-300)));
    time_plot(r, t!("analogy-plot-energy"), y_axis, lines).described(description)
}

/// A plot against time over the window with `y_axis` and one line per `(label, points)`,
/// drawn in [`STYLES`] in order.
fn time_plot<const N: usize>(
    r: &Results,
    title: String,
    y_axis: Axis,
    lines: [(String, Vec<(f64, f64)>); N],
) -> Figure {
    let plot = Figure::plot(
        title,
        Axis::linear(t!("axis-time"), "s", (0.0, r.t_end)),
        y_axis,
    );
    lines
        .into_iter()
        .zip(STYLES)
        .fold(plot, |fig, ((label, points), style)| {
            fig.with_line(label, points, style)
        })
}

/// The mass and the loop side by side at time `t` \[s\].
pub(super) fn schematic(r: &Results, t: f64) -> Figure {
    let ([x, v], [q, i]) = states(r, t);
    let labels = MassLabels::mkc("");
    // With c ≥ 0 the energy never exceeds its initial value, so |x| ≤ x₀ and
    // |i| ≤ q₀·ω₀: both drawings stay within their frames.
    let mech = mass_spring_damper(x / r.x0, 0.0, &labels, String::new());
    let elec = rlc_loop(i / (r.q0 * r.w0()), q / r.q0, String::new());
    let (dx, _) = CIRCUIT_OFFSET;
    let mut fig = beside(mech, elec, CIRCUIT_OFFSET)
        .with_marker(caption(&t!("analogy-caption-mechanical"), (-1.0, 4.2)))
        .with_marker(caption(&t!("analogy-caption-electrical"), (dx - 1.0, 4.2)))
        .with_marker(caption("≙", (2.05, 1.9)))
        .described(text::describe_schematic(t, [x, v], [q, i]));
    fig.title = t!("analogy-schematic-title");
    fig.y.range = (fig.y.range.0, fig.y.range.1.max(4.4));
    fig
}
