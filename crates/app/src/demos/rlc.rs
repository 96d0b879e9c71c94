//! `rlc`: natural response of a series RLC loop. The capacitor starts charged to `V₀` with
//! no current; the loop then obeys `L·q'' + R·q' + q/C = 0` with `q(0) = C·V₀`, `q'(0) = 0`,
//! and the plots show the current `i = q'` and the capacitor voltage `v_C = q/C`, each with
//! the critically damped response of the same L and C for comparison.

// Not yet reshaped: still does maths the solver should do (issue "one shape").
#![allow(clippy::disallowed_methods)]

use super::{Demo, Frame, Readout};
use crate::figure::{finite_extent, padded, Axis, Dash, Figure, LineStyle, Series};
use crate::format::si;
use crate::params::Params;
use crate::plot::Ink;
use crate::schematic::rlc_loop;
use crate::spec::{DemoSpec, ParamSpec, PlotSpec, Preset, ReadoutSpec};
use zeta_solver::metrics::{free::FreeMetrics, SettlingBand};
use zeta_solver::{FreeResponse, Regime, SecondOrder};

/// Samples per curve.
const SAMPLES: usize = 800;
/// Longest window in periods `2π/ω₀` for a ringing response (so each period keeps ~65 samples).
const MAX_PERIODS: f64 = 12.0;

const L_DEFAULT: f64 = 0.5;
const C_DEFAULT: f64 = 0.02;
const V0_DEFAULT: f64 = 12.0;

const EQUATION: &str = "<math display=\"block\"><mrow>\
<mi>L</mi><mover><mi>q</mi><mo>¨</mo></mover><mo>+</mo><mi>R</mi><mover><mi>q</mi><mo>˙</mo></mover>\
<mo>+</mo><mfrac><mi>q</mi><mi>C</mi></mfrac><mo>=</mo><mn>0</mn><mo>,</mo><mspace width=\"1em\"/>\
<mi>i</mi><mo>=</mo><mover><mi>q</mi><mo>˙</mo></mover><mo>,</mo><mspace width=\"0.6em\"/>\
<msub><mi>v</mi><mi>C</mi></msub><mo>=</mo><mfrac><mi>q</mi><mi>C</mi></mfrac></mrow></math>";

/// The series RLC demo. Stateless: everything follows from the parameters.
#[derive(Debug, Default, Clone, Copy)]
pub struct Rlc;

/// The loop and its initial charge.
#[derive(Debug, Clone, Copy)]
struct Circuit {
    sys: SecondOrder,
    r: f64,
    cap: f64,
    v0: f64,
}

impl Circuit {
    /// Initial charge `q₀ = C·V₀` \[C\].
    fn q0(&self) -> f64 {
        self.cap * self.v0
    }

    fn response(&self) -> FreeResponse {
        FreeResponse::new(self.sys, self.q0(), 0.0)
    }

    /// `V₀·√(C/L) = q₀·ω₀` \[A\]: the current if all the initial energy were in the inductor,
    /// a bound on `|i|` for every `R ≥ 0`.
    fn current_scale(&self) -> f64 {
        self.q0().abs() * self.sys.natural_frequency().unwrap_or(1.0)
    }

    /// The critically damped loop with the same L and C.
    fn critical(&self) -> Option<SecondOrder> {
        let (l, _, cap) = self.sys.as_electrical()?;
        SecondOrder::electrical(l, self.sys.critical_damping()?, cap).ok()
    }
}

fn circuit(params: &Params) -> Option<Circuit> {
    let (l, r, cap) = (params.get("L"), params.get("R"), params.get("C"));
    Some(Circuit {
        sys: SecondOrder::electrical(l, r, cap).ok()?,
        r,
        cap,
        v0: params.get("V0"),
    })
}

fn readout_specs() -> Vec<ReadoutSpec> {
    [
        ("regime", "regime", ""),
        ("w0", "resonant frequency ω₀ = 1/√(LC)", "rad/s"),
        ("f0", "resonant frequency f₀", "Hz"),
        ("alpha", "decay rate α = R/(2L)", "1/s"),
        ("zeta", "damping ratio ζ", ""),
        ("Q", "quality factor Q = 1/(2ζ)", ""),
        ("bandwidth", "half-power bandwidth R/L", "rad/s"),
        ("R_crit", "critical resistance 2√(L/C)", "Ω"),
        ("wd", "ringing frequency ω_d", "rad/s"),
        ("settling_time", "v_C within 5 % of V₀ after", "s"),
    ]
    .into_iter()
    .map(|(key, label, unit)| ReadoutSpec { key, label, unit })
    .collect()
}

impl Demo for Rlc {
    fn spec(&self) -> DemoSpec {
        DemoSpec {
            id: "rlc",
            title: "Series RLC circuit",
            summary: "A capacitor charged to V₀ is switched into a loop with an inductor and a \
                      resistor at t = 0. Charge q obeys the same equation as a mass on a spring: \
                      L plays the mass, R the damper, 1/C the spring. With R below the critical \
                      resistance 2√(L/C) the energy sloshes between C and L and the current \
                      rings at ω_d, decaying as e^(−αt), α = R/(2L); at R = 2√(L/C) the \
                      capacitor empties fastest without reversing; above it the discharge is \
                      slower again. Q = 1/(2ζ) counts the ringing, and R/L is the width of the \
                      current's resonance. The current is negative while the capacitor \
                      discharges (i = dq/dt).",
            equation_mathml: EQUATION,
            params: vec![
                ParamSpec::linear("R", "resistance", "R", "Ω", (0.0, 100.0, 0.1), 4.0),
                ParamSpec::linear("L", "inductance", "L", "H", (0.05, 5.0, 0.01), L_DEFAULT),
                ParamSpec::log("C", "capacitance", "C", "F", (1e-4, 1.0, 1e-6), C_DEFAULT),
                ParamSpec::linear(
                    "V0",
                    "initial capacitor voltage",
                    "V₀",
                    "V",
                    (0.5, 48.0, 0.5),
                    V0_DEFAULT,
                ),
            ],
            readouts: readout_specs(),
            plots: vec![
                PlotSpec {
                    key: "current",
                    title: "Current i(t)",
                    aspect: 1.35,
                },
                PlotSpec {
                    key: "voltage",
                    title: "Capacitor voltage v_C(t)",
                    aspect: 1.35,
                },
            ],
            primary_plot: "",
            presets: [
                ("Lossless LC, R = 0", 0.0),
                ("Ringing, R = 2 Ω", 2.0),
                ("Underdamped, R = 5 Ω", 5.0),
                ("Critical, R = 10 Ω", 10.0),
                ("Overdamped, R = 20 Ω", 20.0),
            ]
            .into_iter()
            .map(|(label, r)| Preset {
                label,
                values: vec![
                    ("R", r),
                    ("L", L_DEFAULT),
                    ("C", C_DEFAULT),
                    ("V0", V0_DEFAULT),
                ],
            })
            .collect(),
            table: None,
            schematic: true,
        }
    }

    fn update(&mut self, params: &Params) -> Frame {
        match circuit(params) {
            Some(c) => frame(&c),
            // Unreachable with validated parameters; still, never panic.
            None => Frame {
                readouts: readout_specs()
                    .iter()
                    .map(|r| {
                        if r.key == "regime" {
                            Readout::text("regime", "invalid parameters")
                        } else {
                            Readout::number(r.key, None, r.unit, 4)
                        }
                    })
                    .collect(),
                figures: Vec::new(),
                time_span: None,
            },
        }
    }

    fn schematic(&self, params: &Params, t: f64) -> Option<Figure> {
        let c = circuit(params)?;
        let [q, i] = c.response().state(t);
        let description = format!(
            "Series RLC loop at t = {}: current {}, capacitor at {}.",
            si(t, "s", 3),
            si(i, "A", 3),
            si(q / c.cap, "V", 3)
        );
        let q0 = c.q0().abs().max(1e-300);
        Some(rlc_loop(
            i / c.current_scale().max(1e-300),
            q / q0,
            description,
        ))
    }
}

fn frame(c: &Circuit) -> Frame {
    let sys = &c.sys;
    let metrics = FreeMetrics::exact(sys, c.q0(), 0.0, SettlingBand::FREE_DEFAULT);
    let readouts = vec![
        Readout::text("regime", sys.regime().key()),
        Readout::number("w0", sys.natural_frequency(), "rad/s", 4),
        Readout::number("f0", sys.natural_frequency_hz(), "Hz", 4),
        Readout::number("alpha", Some(sys.alpha()), "1/s", 4),
        Readout::number("zeta", sys.damping_ratio(), "", 4),
        Readout::number("Q", sys.quality_factor(), "", 4),
        Readout::number("bandwidth", sys.half_power_bandwidth(), "rad/s", 4),
        Readout::number("R_crit", sys.critical_damping(), "Ω", 4),
        Readout::number("wd", sys.damped_frequency(), "rad/s", 4),
        Readout::number(
            "settling_time",
            metrics.and_then(|m| m.settling_time),
            "s",
            4,
        ),
    ];
    let t_end = time_window(c, metrics);
    let critical = c.critical();
    let current = plot(c, critical, t_end, Signal::Current, metrics);
    let voltage = plot(c, critical, t_end, Signal::Voltage, metrics);
    Frame {
        readouts,
        figures: vec![current, voltage],
        time_span: Some((0.0, t_end)),
    }
}

/// The time shown: until the slower of this loop and the critical one has settled, with
/// at most [`MAX_PERIODS`] periods of ringing (or 4 periods if it never settles).
fn time_window(c: &Circuit, metrics: Option<FreeMetrics>) -> f64 {
    let period = std::f64::consts::TAU / c.sys.natural_frequency().unwrap_or(1.0);
    let settle = |s: &SecondOrder| {
        FreeMetrics::exact(s, c.q0(), 0.0, SettlingBand::FREE_DEFAULT).and_then(|m| m.settling_time)
    };
    let base = c
        .critical()
        .and_then(|s| settle(&s))
        .map_or(2.0 * period, |t| 1.25 * t);
    let own = match metrics.and_then(|m| m.settling_time) {
        Some(ts) if c.sys.regime().oscillates() => (1.25 * ts).min(MAX_PERIODS * period),
        Some(ts) => 1.25 * ts,
        None => 4.0 * period,
    };
    base.max(own)
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Signal {
    Current,
    Voltage,
}

impl Signal {
    /// The plotted quantity from the charge state `[q, q']`.
    fn of(self, c: &Circuit, state: [f64; 2]) -> f64 {
        match self {
            Signal::Current => state[1],
            Signal::Voltage => state[0] / c.cap,
        }
    }
}

fn ohms(r: f64) -> String {
    si(r, "Ω", 3)
}

fn plot(
    c: &Circuit,
    critical: Option<SecondOrder>,
    t_end: f64,
    signal: Signal,
    metrics: Option<FreeMetrics>,
) -> Figure {
    let sample = |sys: &SecondOrder| -> Vec<(f64, f64)> {
        let r = FreeResponse::new(*sys, c.q0(), 0.0);
        (0..SAMPLES)
            .map(|i| {
                let t = t_end * i as f64 / (SAMPLES - 1) as f64;
                (t, signal.of(c, r.state(t)))
            })
            .collect()
    };
    let regime = c.sys.regime();
    let mut series = Vec::with_capacity(4);
    // Decay envelope of a ringing response: v_C = V₀·(ω₀/ω_d)·e^(−αt)·cos(ω_d t − φ) and
    // i = −(V₀/(L·ω_d))·e^(−αt)·sin(ω_d t).
    if let (Some(wd), Some(w0), Some((l, _, _))) = (
        c.sys.damped_frequency(),
        c.sys.natural_frequency(),
        c.sys.as_electrical(),
    ) {
        let amp = match signal {
            Signal::Current => c.v0.abs() / (l * wd),
            Signal::Voltage => c.v0.abs() * w0 / wd,
        };
        let alpha = c.sys.alpha();
        for (sign, label) in [(1.0, "envelope"), (-1.0, "")] {
            let points = (0..=120)
                .map(|i| {
                    let t = t_end * f64::from(i) / 120.0;
                    (t, sign * amp * (-alpha * t).exp())
                })
                .collect();
            series.push(Series {
                label: label.to_string(),
                points,
                style: LineStyle {
                    ink: Ink::Green,
                    dash: Dash::Dotted,
                    width: 1.5,
                },
            });
        }
    }
    if let (Some(crit), false) = (critical, regime == Regime::CriticallyDamped) {
        series.push(Series {
            label: format!("critical R = {}", ohms(crit.b())),
            points: sample(&crit),
            style: LineStyle {
                ink: Ink::Vermillion,
                dash: Dash::Dashed,
                width: 2.0,
            },
        });
    }
    let own = sample(&c.sys);
    let scale = match signal {
        Signal::Current => c.current_scale(),
        Signal::Voltage => c.v0.abs(),
    };
    let (lo, hi) = finite_extent(
        series
            .iter()
            .flat_map(|s| s.points.iter().map(|p| p.1))
            .chain(own.iter().map(|p| p.1))
            .filter(|v| v.abs() <= 2.0 * scale),
    )
    .unwrap_or((-scale, scale));
    let (lo, hi) = (lo.min(-0.1 * scale), hi.max(0.1 * scale));
    // Head-room above the data for the legend in the upper right.
    let span = hi - lo;
    let y = padded((lo, hi + 0.5 * span), 0.05);
    series.push(Series {
        label: format!("R = {}", ohms(c.r)),
        points: own,
        style: LineStyle::solid(Ink::Blue, 3.0),
    });
    let (title, label, unit) = match signal {
        Signal::Current => ("Current i(t)", "current i", "A"),
        Signal::Voltage => ("Capacitor voltage v_C(t)", "capacitor voltage v_C", "V"),
    };
    Figure {
        description: describe(c, signal, metrics),
        series,
        origin_lines: true,
        ..Figure::plot(
            title,
            Axis::linear("time t", "s", (0.0, t_end)),
            Axis::linear(label, unit, y),
        )
    }
}

/// The response described in words, by regime.
fn describe(c: &Circuit, signal: Signal, metrics: Option<FreeMetrics>) -> String {
    let sys = &c.sys;
    let r_crit = sys.critical_damping().unwrap_or(0.0);
    let w0 = sys.natural_frequency().unwrap_or(0.0);
    let bound = si(c.current_scale(), "A", 3);
    let settle = metrics
        .and_then(|m| m.settling_time)
        .map(|t| format!("stays within 5 % of V₀ after {}", si(t, "s", 3)))
        .unwrap_or_else(|| "never settles".to_string());
    // The solver counts zero crossings before the settling time.
    let reversals = match metrics {
        Some(m) if m.zero_crossings == 0 && m.rebound_time.is_some() => format!(
            "reverses only slightly (at most {} of V₀, inside the band)",
            si(100.0 * m.peak_rebound, "%", 3)
        ),
        Some(m) if m.zero_crossings == 1 => "reverses polarity once before settling".to_string(),
        Some(m) if m.zero_crossings > 1 => {
            format!(
                "reverses polarity {} times before settling",
                m.zero_crossings
            )
        }
        _ => "never reverses polarity".to_string(),
    };
    match (sys.regime(), signal) {
        (Regime::Undamped, Signal::Current) => format!(
            "R = {}, undamped (a lossless LC loop): the current oscillates forever at ω₀ = {}, \
             between ±{} (all the energy passes to the inductor and back every half period).",
            ohms(c.r),
            si(w0, "rad/s", 3),
            bound
        ),
        (Regime::Undamped, Signal::Voltage) => format!(
            "R = {}, undamped (a lossless LC loop): the capacitor voltage swings between +{v} \
             and −{v} forever at ω₀ = {}.",
            ohms(c.r),
            si(w0, "rad/s", 3),
            v = si(c.v0.abs(), "V", 3)
        ),
        (Regime::Underdamped, Signal::Current) => format!(
            "R = {} below the critical {}, underdamped: the current rings at ω_d = {} \
             (Q = {}), decaying as e^(−αt) with α = {}; it never exceeds {}.",
            ohms(c.r),
            ohms(r_crit),
            si(sys.damped_frequency().unwrap_or(0.0), "rad/s", 3),
            si(sys.quality_factor().unwrap_or(f64::NAN), "", 3),
            si(sys.alpha(), "1/s", 3),
            bound
        ),
        (Regime::Underdamped, Signal::Voltage) => format!(
            "R = {} below the critical {}, underdamped: the capacitor voltage {}, and {}.",
            ohms(c.r),
            ohms(r_crit),
            reversals,
            settle
        ),
        (Regime::CriticallyDamped, Signal::Current) => format!(
            "R = {} equals the critical resistance, critically damped: one pulse of current \
             (negative, the capacitor discharging) that returns to zero without reversing; it \
             never exceeds {}.",
            ohms(c.r),
            bound
        ),
        (Regime::CriticallyDamped, Signal::Voltage) => format!(
            "R = {} equals the critical resistance, critically damped: the capacitor empties \
             as fast as it can without reversing; it {}.",
            ohms(c.r),
            settle
        ),
        (_, Signal::Current) => format!(
            "R = {} above the critical {}, overdamped: one slow pulse of current (negative, \
             the capacitor discharging) without reversing, slow time constant {}.",
            ohms(c.r),
            ohms(r_crit),
            si(sys.time_constants()[0].unwrap_or(f64::NAN), "s", 3)
        ),
        (_, Signal::Voltage) => format!(
            "R = {} above the critical {}, overdamped: the capacitor discharges slowly \
             without reversing; it {}.",
            ohms(c.r),
            ohms(r_crit),
            settle
        ),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn run(query: &str) -> Frame {
        let mut d = Rlc;
        let (p, _) = crate::params::resolve_query(&d.spec(), query);
        d.update(&p)
    }

    fn value(f: &Frame, key: &str) -> String {
        f.readouts
            .iter()
            .find(|r| r.key == key)
            .map(|r| r.data_value.clone())
            .unwrap()
    }

    fn num(f: &Frame, key: &str) -> f64 {
        value(f, key).parse().unwrap()
    }

    fn close(a: f64, b: f64, tol: f64) -> bool {
        (a - b).abs() <= tol * (1.0 + b.abs())
    }

    #[test]
    fn readouts_match_the_textbook_circuit() {
        // L = 0.5 H, C = 20 mF: ω₀ = 10 rad/s, R_crit = 10 Ω; R = 4 Ω → ζ = 0.4, Q = 1.25.
        let f = run("R=4&L=0.5&C=0.02&V0=12");
        assert!(close(num(&f, "w0"), 10.0, 1e-14));
        assert!(close(num(&f, "R_crit"), 10.0, 1e-14));
        assert!(close(num(&f, "zeta"), 0.4, 1e-14));
        assert!(close(num(&f, "Q"), 1.25, 1e-14));
        assert!(close(num(&f, "alpha"), 4.0, 1e-14));
        assert!(close(num(&f, "bandwidth"), 8.0, 1e-14));
        assert!(close(num(&f, "wd"), (100.0f64 - 16.0).sqrt(), 1e-14));
        assert_eq!(value(&f, "regime"), "underdamped");
    }

    #[test]
    fn every_preset_reaches_its_regime_and_the_plots_start_right() {
        for (r, regime) in [
            (0.0, "undamped"),
            (2.0, "underdamped"),
            (10.0, "critically damped"),
            (20.0, "overdamped"),
        ] {
            let f = run(&format!("R={r}"));
            assert_eq!(value(&f, "regime"), regime);
            // i(0) = 0 and v_C(0) = V₀ on the design's curve (the last series).
            let i0 = f.figures[0].series.last().unwrap().points[0].1;
            let v0 = f.figures[1].series.last().unwrap().points[0].1;
            assert_eq!(i0, 0.0);
            assert!(close(v0, 12.0, 1e-14));
            for fig in &f.figures {
                assert!(
                    fig.description.starts_with(&format!("R = {}", ohms(r))),
                    "{}",
                    fig.description
                );
                assert!(fig.description.contains(regime.split(' ').next().unwrap()));
            }
        }
        let lossless = run("R=0");
        assert_eq!(
            value(&lossless, "Q"),
            "",
            "Q is infinite without resistance"
        );
        assert_eq!(value(&lossless, "settling_time"), "");
    }

    #[test]
    fn the_current_never_exceeds_the_energy_bound() {
        for r in [0.0, 1.0, 4.0, 10.0, 30.0] {
            let f = run(&format!("R={r}"));
            let bound = 12.0 * (0.02f64 / 0.5).sqrt();
            let peak = f.figures[0]
                .series
                .last()
                .unwrap()
                .points
                .iter()
                .map(|p| p.1.abs())
                .fold(0.0, f64::max);
            assert!(peak <= bound * (1.0 + 1e-12), "R={r}: {peak} > {bound}");
            assert!(peak > 0.05 * bound);
        }
    }

    #[test]
    fn the_voltage_text_counts_reversals() {
        let ringing = run("R=2").figures[1].description.clone();
        assert!(ringing.contains("reverses polarity"), "{ringing}");
        let slight = run("R=8").figures[1].description.clone();
        assert!(slight.contains("reverses only slightly"), "{slight}");
        let crit = run("R=10").figures[1].description.clone();
        assert!(crit.contains("without reversing"), "{crit}");
    }
}
