//! `analogy`: one equation, two machines. A mass on a spring and damper and a series RLC
//! loop obey the same `a·y'' + b·y' + c·y = f(t)`; under the force–voltage analogy
//! (m ↔ L, c ↔ R, k ↔ 1/C, F ↔ E, x ↔ q) the circuit here is given the *same numbers* as
//! the mechanism — L \[H\] = m \[kg\], R \[Ω\] = c \[N·s/m\], 1/C \[1/F\] = k \[N/m\],
//! q₀ \[C\] = x₀ \[m\] — so both free responses, released from rest, are one curve on
//! normalised axes, and the energy swaps spring ↔ mass exactly as capacitor ↔ inductor.

// Not yet reshaped: still does maths the solver should do (issue "one shape").
#![allow(clippy::disallowed_methods)]

use super::{Demo, Frame, Readout};
use crate::figure::{
    finite_extent, padded, Axis, Dash, Figure, LineStyle, Marker, MarkerShape, Series,
};
use crate::format::si;
use crate::params::Params;
use crate::plot::Ink;
use crate::schematic::{mass_spring_damper, rlc_loop, MassLabels};
use crate::spec::{DemoSpec, ParamSpec, PlotSpec, Preset, ReadoutSpec, Table};
use std::f64::consts::TAU;
use zeta_solver::integrate::analysis::oscillator_energy;
use zeta_solver::{FreeResponse, Regime, SecondOrder};

/// Samples per curve.
const SAMPLES: usize = 600;
/// Undamped periods shown while the system oscillates.
const PERIODS: f64 = 4.0;
/// Horizontal shift of the circuit drawing next to the mass (drawing units).
const CIRCUIT_DX: f64 = 4.7;
/// Vertical shift of the circuit drawing, to centre it on the mass drawing.
const CIRCUIT_DY: f64 = 1.4;

/// The analogy demo. Stateless: everything follows from the parameters.
#[derive(Debug, Default, Clone, Copy)]
pub struct Analogy;

const EQUATION: &str = "<math display=\"block\"><mrow>\
<mi>m</mi><mover><mi>x</mi><mo>¨</mo></mover><mo>+</mo><mi>c</mi><mover><mi>x</mi><mo>˙</mo></mover>\
<mo>+</mo><mi>k</mi><mi>x</mi><mo>=</mo><mi>F</mi><mo>(</mo><mi>t</mi><mo>)</mo>\
</mrow></math>\
<math display=\"block\"><mrow><mo>⟷</mo><mspace width=\"0.5em\"/><mi>L</mi><mover><mi>q</mi><mo>¨</mo></mover><mo>+</mo><mi>R</mi><mover><mi>q</mi><mo>˙</mo></mover>\
<mo>+</mo><mfrac><mi>q</mi><mi>C</mi></mfrac><mo>=</mo><mi>E</mi><mo>(</mo><mi>t</mi><mo>)</mo>\
</mrow></math>";

/// The two machines, built independently through the solver's mechanical and electrical
/// constructors.
#[derive(Debug, Clone, Copy)]
struct Twins {
    mech: SecondOrder,
    elec: SecondOrder,
    /// Inductance \[H\], resistance \[Ω\], capacitance \[F\], read back from `elec`.
    lrc: (f64, f64, f64),
    /// Initial displacement \[m\] and charge \[C\].
    x0: f64,
    q0: f64,
}

/// The electrical twin of `(m, c, k, x0)` under the force–voltage analogy with unit scale
/// factors: `L = m`, `R = c`, `C = 1/k`, `q₀ = x₀` (numbers equal, units H, Ω, F, C).
fn twins(params: &Params) -> Option<Twins> {
    let (m, c, k, x0) = (
        params.get("m"),
        params.get("c"),
        params.get("k"),
        params.get("x0"),
    );
    let mech = SecondOrder::mechanical(m, c, k).ok()?;
    let elec = SecondOrder::electrical(m, c, 1.0 / k).ok()?;
    let lrc = elec.as_electrical()?;
    (x0.is_finite() && x0 != 0.0).then_some(Twins {
        mech,
        elec,
        lrc,
        x0,
        q0: x0,
    })
}

impl Twins {
    fn responses(&self) -> (FreeResponse, FreeResponse) {
        (
            FreeResponse::new(self.mech, self.x0, 0.0),
            FreeResponse::new(self.elec, self.q0, 0.0),
        )
    }

    fn wn(&self) -> f64 {
        self.mech.natural_frequency().unwrap_or(1.0)
    }

    fn w0(&self) -> f64 {
        self.elec.natural_frequency().unwrap_or(1.0)
    }

    /// A few undamped periods while it oscillates; five slow time constants (capped) when
    /// it creeps back without oscillating.
    fn window(&self) -> f64 {
        let tn = TAU / self.wn();
        match self.mech.regime() {
            Regime::Overdamped | Regime::CriticallyDamped => {
                let slow = self.mech.time_constants()[0].unwrap_or(tn);
                (5.0 * slow).clamp(2.0 * tn, 50.0 * tn)
            }
            _ => PERIODS * tn,
        }
    }

    fn times(&self) -> impl Iterator<Item = f64> + Clone {
        let t_end = self.window();
        (0..SAMPLES).map(move |i| t_end * i as f64 / (SAMPLES - 1) as f64)
    }
}

fn line(label: impl Into<String>, points: Vec<(f64, f64)>, style: LineStyle) -> Series {
    Series {
        label: label.into(),
        points,
        style,
    }
}

fn styled(color: Ink, dash: Dash, width: f64) -> LineStyle {
    LineStyle {
        ink: color,
        dash,
        width,
    }
}

/// A dimensionless number with 3 significant digits and no trailing zeros (`0.05`, `2`).
fn plain(v: f64) -> String {
    let s = si(v, "", 3);
    if s.contains('.') && !s.contains('e') {
        s.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        s
    }
}

fn label(text: &str, at: (f64, f64)) -> Marker {
    Marker {
        label: text.to_string(),
        at,
        shape: MarkerShape::Label,
        ink: Ink::Black,
    }
}

/// Draws `right` beside `left`: shifts every point and marker of `right` by `(dx, dy)`,
/// merges them into `left` and widens its ranges to hold both. Both must be schematics.
fn side_by_side(mut left: Figure, right: Figure, dx: f64, dy: f64) -> Figure {
    let shift = |p: (f64, f64)| (p.0 + dx, p.1 + dy);
    for mut s in right.series {
        for p in &mut s.points {
            *p = shift(*p);
        }
        left.series.push(s);
    }
    for mut m in right.markers {
        m.at = shift(m.at);
        left.markers.push(m);
    }
    left.x.range = (
        left.x.range.0.min(right.x.range.0 + dx),
        left.x.range.1.max(right.x.range.1 + dx),
    );
    left.y.range = (
        left.y.range.0.min(right.y.range.0 + dy),
        left.y.range.1.max(right.y.range.1 + dy),
    );
    left
}

impl Demo for Analogy {
    fn spec(&self) -> DemoSpec {
        DemoSpec {
            id: "analogy",
            title: "One equation, two machines",
            summary: "A mass on a spring and damper and a series inductor–resistor–capacitor \
                      loop obey the same second-order equation. In the force–voltage analogy \
                      mass m ↔ inductance L, damping c ↔ resistance R, stiffness k ↔ 1/C, force \
                      F ↔ voltage E and displacement x ↔ charge q (so velocity ↔ current). \
                      Here the circuit is given the same numbers as the mechanism (L in H = m \
                      in kg, R in Ω = c in N·s/m, 1/C in 1/F = k in N/m, q₀ in C = x₀ in m), \
                      both released from rest: change any slider and both machines change \
                      together, their normalised responses stay one curve, and the energy \
                      swings between spring and mass exactly as between capacitor and inductor.",
            equation_mathml: EQUATION,
            params: vec![
                ParamSpec::log(
                    "m",
                    "mass (≙ inductance L)",
                    "m",
                    "kg",
                    (0.1, 10.0, 0.01),
                    1.0,
                ),
                ParamSpec::linear(
                    "c",
                    "damping (≙ resistance R)",
                    "c",
                    "N·s/m",
                    (0.0, 50.0, 0.01),
                    2.0,
                ),
                ParamSpec::log(
                    "k",
                    "spring rate (≙ 1/C)",
                    "k",
                    "N/m",
                    (1.0, 1000.0, 0.1),
                    100.0,
                ),
                ParamSpec::linear(
                    "x0",
                    "initial displacement (≙ charge q₀)",
                    "x₀",
                    "m",
                    (0.001, 0.1, 0.001),
                    0.05,
                ),
            ],
            readouts: vec![
                ReadoutSpec {
                    key: "m",
                    label: "mass m",
                    unit: "kg",
                },
                ReadoutSpec {
                    key: "L",
                    label: "inductance L (≙ mass m)",
                    unit: "H",
                },
                ReadoutSpec {
                    key: "c",
                    label: "damping c",
                    unit: "N·s/m",
                },
                ReadoutSpec {
                    key: "R",
                    label: "resistance R (≙ damping c)",
                    unit: "Ω",
                },
                ReadoutSpec {
                    key: "k",
                    label: "spring rate k",
                    unit: "N/m",
                },
                ReadoutSpec {
                    key: "C",
                    label: "capacitance C (≙ 1/k)",
                    unit: "F",
                },
                ReadoutSpec {
                    key: "x0",
                    label: "initial displacement x₀",
                    unit: "m",
                },
                ReadoutSpec {
                    key: "q0",
                    label: "initial charge q₀ (≙ x₀)",
                    unit: "C",
                },
                ReadoutSpec {
                    key: "wn",
                    label: "natural frequency ωₙ = √(k/m)",
                    unit: "rad/s",
                },
                ReadoutSpec {
                    key: "w0",
                    label: "resonant frequency ω₀ = 1/√(LC) (≙ ωₙ)",
                    unit: "rad/s",
                },
                ReadoutSpec {
                    key: "zeta",
                    label: "damping ratio ζ (both)",
                    unit: "",
                },
                ReadoutSpec {
                    key: "regime",
                    label: "regime (both)",
                    unit: "",
                },
                ReadoutSpec {
                    key: "Q",
                    label: "quality factor Q (both)",
                    unit: "",
                },
                ReadoutSpec {
                    key: "energy",
                    label: "stored energy ½kx₀² = ½q₀²/C",
                    unit: "J",
                },
            ],
            plots: vec![
                PlotSpec {
                    key: "responses",
                    title: "Normalised responses of both machines",
                    aspect: 1.6,
                },
                PlotSpec {
                    key: "energy",
                    title: "Energy exchange",
                    aspect: 1.4,
                },
            ],
            primary_plot: "",
            presets: vec![
                Preset {
                    label: "Frictionless spring ↔ LC tank (c = R = 0)",
                    values: vec![("m", 1.0), ("c", 0.0), ("k", 100.0)],
                },
                Preset {
                    label: "Light damping ζ = 0.05",
                    values: vec![("m", 1.0), ("c", 1.0), ("k", 100.0)],
                },
                Preset {
                    label: "Critical ζ = 1 (c = 2√(mk), R = 2√(L/C))",
                    values: vec![("m", 1.0), ("c", 20.0), ("k", 100.0)],
                },
                Preset {
                    label: "Overdamped ζ = 2",
                    values: vec![("m", 1.0), ("c", 40.0), ("k", 100.0)],
                },
                Preset {
                    label: "Heavy and soft: m = 4 kg ↔ L = 4 H, k = 25 N/m ↔ C = 40 mF",
                    values: vec![("m", 4.0), ("c", 2.0), ("k", 25.0)],
                },
            ],
            table: Some(Table {
                caption: "The force–voltage analogy: a·y″ + b·y′ + c·y = f(t) read two ways",
                columns: vec![
                    "role in the equation",
                    "mechanical",
                    "unit",
                    "electrical",
                    "unit",
                ],
                rows: vec![
                    (
                        "inertia",
                        vec!["inertia a", "mass m", "kg", "inductance L", "H"],
                    ),
                    (
                        "dissipation",
                        vec![
                            "dissipation b",
                            "damping coefficient c",
                            "N·s/m",
                            "resistance R",
                            "Ω",
                        ],
                    ),
                    (
                        "stiffness",
                        vec![
                            "stiffness c",
                            "spring rate k",
                            "N/m",
                            "elastance 1/C (capacitance C)",
                            "1/F (F)",
                        ],
                    ),
                    (
                        "drive",
                        vec!["drive f(t)", "force F", "N", "voltage E", "V"],
                    ),
                    (
                        "coordinate",
                        vec!["coordinate y", "displacement x", "m", "charge q", "C"],
                    ),
                    (
                        "rate",
                        vec!["rate y′", "velocity v = ẋ", "m/s", "current i = q̇", "A"],
                    ),
                    (
                        "natural frequency",
                        vec![
                            "natural frequency",
                            "ωₙ = √(k/m)",
                            "rad/s",
                            "ω₀ = 1/√(LC)",
                            "rad/s",
                        ],
                    ),
                    (
                        "damping ratio",
                        vec!["damping ratio ζ", "c/(2√(mk))", "—", "(R/2)·√(C/L)", "—"],
                    ),
                    (
                        "potential energy",
                        vec![
                            "stored by the stiffness",
                            "spring ½kx²",
                            "J",
                            "capacitor ½q²/C",
                            "J",
                        ],
                    ),
                    (
                        "kinetic energy",
                        vec![
                            "stored by the inertia",
                            "mass ½mv²",
                            "J",
                            "inductor ½Li²",
                            "J",
                        ],
                    ),
                    (
                        "power lost",
                        vec!["dissipated power", "c·v²", "W", "R·i²", "W"],
                    ),
                ],
                // No row matches a regime name: the table is a fixed dictionary, not a
                // selection, so nothing is highlighted.
                highlight_readout: "regime",
            }),
            schematic: true,
        }
    }

    fn update(&mut self, params: &Params) -> Frame {
        match twins(params) {
            Some(tw) => frame(&tw),
            // Unreachable with validated parameters; still, never panic.
            None => Frame {
                readouts: [
                    ("m", "kg"),
                    ("L", "H"),
                    ("c", "N·s/m"),
                    ("R", "Ω"),
                    ("k", "N/m"),
                    ("C", "F"),
                    ("x0", "m"),
                    ("q0", "C"),
                    ("wn", "rad/s"),
                    ("w0", "rad/s"),
                    ("zeta", ""),
                ]
                .into_iter()
                .map(|(k, u)| Readout::number(k, None, u, 4))
                .chain([
                    Readout::text("regime", "invalid parameters"),
                    Readout::number("Q", None, "", 4),
                    Readout::number("energy", None, "J", 4),
                ])
                .collect(),
                figures: Vec::new(),
                time_span: None,
            },
        }
    }

    fn schematic(&self, params: &Params, t: f64) -> Option<Figure> {
        let tw = twins(params)?;
        let (xr, qr) = tw.responses();
        let [x, v] = xr.state(t);
        let [q, i] = qr.state(t);
        let labels = MassLabels {
            mass: "m",
            spring: "k",
            damper: "c",
            base: "",
        };
        // With c ≥ 0 the energy never exceeds its initial value, so |x| ≤ x₀ and
        // |i| ≤ q₀·ω₀: both drawings stay within their frames.
        let mech = mass_spring_damper(x / tw.x0, 0.0, &labels, String::new());
        let elec = rlc_loop(i / (tw.q0 * tw.w0()), q / tw.q0, String::new());
        let mut fig = side_by_side(mech, elec, CIRCUIT_DX, CIRCUIT_DY);
        fig.title = "Mechanical and electrical twins".to_string();
        fig.markers.push(label("mechanical", (-1.0, 4.2)));
        fig.markers
            .push(label("electrical", (CIRCUIT_DX - 1.0, 4.2)));
        fig.markers.push(label("≙", (2.05, 1.9)));
        fig.y.range = (fig.y.range.0, fig.y.range.1.max(4.4));
        fig.description = format!(
            "At t = {}: the mass is displaced {} and moves at {}; the capacitor holds {} and \
             the current is {}. The same numbers in different units.",
            si(t, "s", 3),
            si(x, "m", 3),
            si(v, "m/s", 3),
            si(q, "C", 3),
            si(i, "A", 3),
        );
        Some(fig)
    }
}

fn frame(tw: &Twins) -> Frame {
    let (m, c, k) = tw.mech.as_mechanical();
    let (l, r, cap) = tw.lrc;
    let readouts = vec![
        Readout::number("m", Some(m), "kg", 4),
        Readout::number("L", Some(l), "H", 4),
        Readout::number("c", Some(c), "N·s/m", 4),
        Readout::number("R", Some(r), "Ω", 4),
        Readout::number("k", Some(k), "N/m", 4),
        Readout::number("C", Some(cap), "F", 4),
        Readout::number("x0", Some(tw.x0), "m", 4),
        Readout::number("q0", Some(tw.q0), "C", 4),
        Readout::number("wn", tw.mech.natural_frequency(), "rad/s", 4),
        Readout::number("w0", tw.elec.natural_frequency(), "rad/s", 4),
        Readout::number("zeta", tw.mech.damping_ratio(), "", 4),
        Readout::text("regime", tw.mech.regime().key()),
        Readout::number("Q", tw.mech.quality_factor(), "", 4),
        Readout::number(
            "energy",
            Some(oscillator_energy(&tw.mech, [tw.x0, 0.0])),
            "J",
            4,
        ),
    ];
    Frame {
        readouts,
        figures: vec![response_figure(tw), energy_figure(tw)],
        time_span: Some((0.0, tw.window())),
    }
}

fn response_figure(tw: &Twins) -> Figure {
    let (xr, qr) = tw.responses();
    let (wn, w0) = (tw.wn(), tw.w0());
    let n = SAMPLES;
    let mut xs = Vec::with_capacity(n);
    let mut vs = Vec::with_capacity(n);
    let mut qs = Vec::with_capacity(n);
    let mut is = Vec::with_capacity(n);
    let mut gap: f64 = 0.0;
    for t in tw.times() {
        let [x, v] = xr.state(t);
        let [q, i] = qr.state(t);
        let (xn, vn, qn, in_) = (x / tw.x0, v / (tw.x0 * wn), q / tw.q0, i / (tw.q0 * w0));
        gap = gap.max((xn - qn).abs()).max((vn - in_).abs());
        xs.push((t, xn));
        vs.push((t, vn));
        qs.push((t, qn));
        is.push((t, in_));
    }
    let all = xs.iter().chain(&vs).chain(&qs).chain(&is).map(|p| p.1);
    let (lo, hi) = finite_extent(all).unwrap_or((-1.0, 1.0));
    let (lo, hi) = padded((lo.min(-0.2), hi.max(1.0)), 0.06);
    let y = (lo, hi + 0.45 * (hi - lo));
    let regime = tw.mech.regime();
    let zeta = tw.mech.damping_ratio().unwrap_or(0.0);
    let motion = match tw.mech.damped_frequency() {
        Some(wd) if zeta > 0.0 => format!(
            "both oscillate at ω_d = {} and decay with time constant 1/(ζωₙ) = {}",
            si(wd, "rad/s", 3),
            si(1.0 / (zeta * wn), "s", 3)
        ),
        Some(wd) => format!(
            "both oscillate for ever at ω₀ = ωₙ = {}",
            si(wd, "rad/s", 3)
        ),
        None => "both creep back to rest without oscillating".to_string(),
    };
    let same = if gap == 0.0 {
        "identical to the last digit".to_string()
    } else {
        format!("largest difference {}", si(gap, "", 2))
    };
    let description = format!(
        "{} (ζ = {}): the mechanical x/x₀ and electrical q/q₀ coincide, as do the \
         velocity v/(x₀ωₙ) and current i/(q₀ω₀) ({}); {}.",
        regime.key(),
        plain(zeta),
        same,
        motion
    );
    Figure {
        description,
        series: vec![
            line("x/x₀ mass", xs, LineStyle::solid(Ink::Blue, 3.5)),
            line(
                "q/q₀ circuit",
                qs,
                styled(Ink::Vermillion, Dash::Dashed, 2.0),
            ),
            line("v/(x₀ωₙ) mass", vs, LineStyle::solid(Ink::Green, 3.5)),
            line(
                "i/(q₀ω₀) circuit",
                is,
                styled(Ink::Purple, Dash::Dotted, 2.0),
            ),
        ],
        origin_lines: true,
        ..Figure::plot(
            "Normalised responses of both machines",
            Axis::linear("time t", "s", (0.0, tw.window())),
            Axis::linear("normalised response", "", y),
        )
    }
}

fn energy_figure(tw: &Twins) -> Figure {
    let (xr, qr) = tw.responses();
    let n = SAMPLES;
    let mut spring = Vec::with_capacity(n);
    let mut mass = Vec::with_capacity(n);
    let mut cap = Vec::with_capacity(n);
    let mut ind = Vec::with_capacity(n);
    let mut tot_m = Vec::with_capacity(n);
    let mut tot_e = Vec::with_capacity(n);
    for t in tw.times() {
        let [x, v] = xr.state(t);
        let [q, i] = qr.state(t);
        let (pe, ke) = (
            oscillator_energy(&tw.mech, [x, 0.0]),
            oscillator_energy(&tw.mech, [0.0, v]),
        );
        let (ce, le) = (
            oscillator_energy(&tw.elec, [q, 0.0]),
            oscillator_energy(&tw.elec, [0.0, i]),
        );
        spring.push((t, pe));
        mass.push((t, ke));
        cap.push((t, ce));
        ind.push((t, le));
        tot_m.push((t, oscillator_energy(&tw.mech, [x, v])));
        tot_e.push((t, oscillator_energy(&tw.elec, [q, i])));
    }
    let e0 = oscillator_energy(&tw.mech, [tw.x0, 0.0]);
    let left = tot_m.last().map_or(0.0, |p| p.1);
    let kinetic_peak = mass.iter().map(|p| p.1).fold(0.0, f64::max);
    let t_end = tw.window();
    let exchange = if tw.mech.damped_frequency().is_some() {
        format!(
            "It swings to the mass (inductor), at most {} at once, and back, twice per cycle",
            si(kinetic_peak, "J", 3)
        )
    } else {
        format!(
            "Without oscillating, at most {} passes through the mass (inductor)",
            si(kinetic_peak, "J", 3)
        )
    };
    let loss = if left >= 0.999_999 * e0 {
        format!(
            "with no damper (resistor) it is all still there after {}",
            si(t_end, "s", 3)
        )
    } else {
        format!(
            "the damper c (resistor R) turns it into heat, leaving {} ({}) after {}",
            si(left, "J", 3),
            si(100.0 * left / e0.max(1e-300), "%", 3),
            si(t_end, "s", 3)
        )
    };
    let description = format!(
        "At t = 0 all {} is stored in the spring, and equally in the capacitor. {}; {}. \
         The mechanical and electrical curves coincide.",
        si(e0, "J", 3),
        exchange,
        loss
    );
    Figure {
        description,
        series: vec![
            line("½kx² spring", spring, LineStyle::solid(Ink::Blue, 3.5)),
            line(
                "½q²/C capacitor",
                cap,
                styled(Ink::Vermillion, Dash::Dashed, 2.0),
            ),
            line("½mv² mass", mass, LineStyle::solid(Ink::Green, 3.5)),
            line("½Li² inductor", ind, styled(Ink::Purple, Dash::Dotted, 2.0)),
            line("total, mass", tot_m, LineStyle::solid(Ink::Black, 2.5)),
            line(
                "total, circuit",
                tot_e,
                styled(Ink::Orange, Dash::Dashed, 1.5),
            ),
        ],
        ..Figure::plot(
            "Energy exchange",
            Axis::linear("time t", "s", (0.0, t_end)),
            Axis::linear("energy", "J", (0.0, 2.1 * e0.max(1e-300))),
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn run(query: &str) -> Frame {
        let mut d = Analogy;
        let spec = d.spec();
        let (p, _) = crate::params::resolve_query(&spec, query);
        d.update(&p)
    }

    fn value(f: &Frame, key: &str) -> Option<f64> {
        f.readouts
            .iter()
            .find(|r| r.key == key)
            .and_then(|r| r.data_value.parse().ok())
    }

    fn text(f: &Frame, key: &str) -> String {
        f.readouts
            .iter()
            .find(|r| r.key == key)
            .map(|r| r.data_value.clone())
            .unwrap()
    }

    #[test]
    fn the_circuit_mirrors_the_mechanism() {
        let f = run("m=4&c=2&k=25&x0=0.02");
        assert_eq!(value(&f, "L"), Some(4.0));
        assert_eq!(value(&f, "R"), Some(2.0));
        assert!((value(&f, "C").unwrap() - 0.04).abs() < 1e-15);
        assert_eq!(value(&f, "q0"), Some(0.02));
        let wn = value(&f, "wn").unwrap();
        assert!((wn - 2.5).abs() < 1e-12);
        assert!((value(&f, "w0").unwrap() - wn).abs() < 1e-12);
        assert!((value(&f, "zeta").unwrap() - 0.1).abs() < 1e-12);
        assert!((value(&f, "Q").unwrap() - 5.0).abs() < 1e-12);
        assert_eq!(text(&f, "regime"), "underdamped");
        // ½kx₀² = ½·25·0.02² = 5 mJ.
        assert!((value(&f, "energy").unwrap() - 0.005).abs() < 1e-15);
    }

    #[test]
    fn normalised_curves_coincide_in_every_regime() {
        for (c, regime) in [
            (0.0, "undamped"),
            (1.0, "underdamped"),
            (20.0, "critically damped"),
            (40.0, "overdamped"),
        ] {
            let f = run(&format!("m=1&k=100&c={c}"));
            assert_eq!(text(&f, "regime"), regime);
            let s = &f.figures[0].series;
            for (a, b) in s[0].points.iter().zip(&s[1].points) {
                assert!((a.1 - b.1).abs() < 1e-12);
            }
            let e = &f.figures[1].series;
            for (a, b) in e[0].points.iter().zip(&e[1].points) {
                assert!((a.1 - b.1).abs() < 1e-12 * e[0].points[0].1);
            }
            assert!(f.figures[0].description.starts_with(regime));
            assert!(f.figures.iter().all(|fig| fig.has_visible_data()));
        }
    }

    #[test]
    fn energy_is_conserved_without_damping_and_lost_with_it() {
        let free = run("c=0");
        let tot = &free.figures[1].series[4].points;
        let e0 = tot[0].1;
        assert!(tot.iter().all(|p| (p.1 - e0).abs() < 1e-9 * e0));
        let damped = run("c=2");
        let tot = &damped.figures[1].series[4].points;
        assert!(tot.last().unwrap().1 < 0.5 * tot[0].1);
    }

    #[test]
    fn the_schematic_shows_both_machines_side_by_side() {
        let d = Analogy;
        let spec = d.spec();
        let p = Params::defaults(&spec);
        let fig = d.schematic(&p, 0.1).unwrap();
        let labels: Vec<&str> = fig.markers.iter().map(|m| m.label.as_str()).collect();
        for l in ["m", "k", "c", "L", "R", "C", "mechanical", "electrical"] {
            assert!(labels.contains(&l), "{l} in {labels:?}");
        }
        let xs = fig.series.iter().flat_map(|s| s.points.iter().map(|p| p.0));
        let (lo, hi) = finite_extent(xs).unwrap();
        assert!(lo < 0.0 && hi > CIRCUIT_DX, "both drawings present");
        assert!(hi <= fig.x.range.1 && lo >= fig.x.range.0);
        assert!(fig.description.contains("capacitor"));
    }

    #[test]
    fn plain_numbers_drop_trailing_zeros_only() {
        assert_eq!(plain(0.05), "0.05");
        assert_eq!(plain(0.0), "0");
        assert_eq!(plain(20.0), "20");
        assert_eq!(plain(1.5), "1.5");
    }

    #[test]
    fn table_rows_have_every_column() {
        let t = Analogy.spec().table.unwrap();
        for (_, cells) in &t.rows {
            assert_eq!(cells.len(), t.columns.len());
        }
    }
}
