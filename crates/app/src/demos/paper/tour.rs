//! The tour as data: the paper's figures, tables and quantitative claims in the paper's
//! order, each with the demo state that reproduces it. Only the paper's own claimed
//! numbers are typed in here; every value shown beside them is computed by the linked demo.
//! The prose (what an exhibit shows, what a claim says, the sentence that explains a
//! verdict) is a message of the catalogues, one id an entry.

use crate::t;

/// A demo in one state: the demo and its URL query (without `demo=`).
#[derive(Debug, Clone, Copy)]
pub(super) struct State {
    /// The demo's id.
    pub demo: &'static str,
    /// Its URL query (without `demo=`; empty: its defaults).
    pub query: &'static str,
}

impl State {
    const fn new(demo: &'static str, query: &'static str) -> Self {
        Self { demo, query }
    }
}

/// The quarter car at its defaults (Figure 1).
const QUARTER_CAR: State = State::new("quarter-car", "");
/// The circuit of Figure 2.
const FIG2: State = State::new("rlc", "R=5&L=0.5&C=0.02&V0=12");
/// The lightly damped oscillator of Figure 3.
const FIG3: State = State::new("resonance", "zeta=0.05&r=1");
/// The integrators' test problem of Figure 4 and Table 3.
const FIG4: State = State::new("integrators", "zeta=0.05&wn=2&h=0.3");

/// A figure or table of the paper, reproduced live by a demo.
pub(super) struct Exhibit {
    /// Stable id, also the thumbnail's plot key (`fig1a`, `table1`, …).
    pub id: &'static str,
    /// Where it stands in the paper (in English: it is also the thumbnail's declared plot
    /// title, `paper-plot-<id>`).
    pub place: &'static str,
    /// What it shows, paraphrased, in the interface language.
    pub shows: fn() -> String,
    /// The demo state that reproduces it.
    pub at: State,
    /// Which of that demo's plots is its thumbnail.
    pub plot: &'static str,
}

/// How a claim is checked against the linked demo's readouts.
pub(super) enum Check {
    /// The readout lies within `tol` of the claimed value.
    Near {
        readout: &'static str,
        claimed: f64,
        tol: f64,
    },
    /// The readout is below the claimed bound.
    Below { readout: &'static str, bound: f64 },
    /// The readouts `lo` and `hi` span the claimed range, each end within `tol`.
    Range {
        lo: &'static str,
        hi: &'static str,
        claimed: (f64, f64),
        tol: f64,
    },
    /// The paper's peak formula `r = √(1 − 2ζ²)` against the maximum of `|H(r)|` found by
    /// search, within `tol`.
    PeakFormula { zeta: f64, tol: f64 },
    /// The least-squares slope of log error against log step over the paper's step and
    /// its halvings (computed by the solver) lies within `tol` of the claimed slope.
    Slope { claimed: f64, tol: f64 },
}

/// A quantitative claim of the paper.
pub(super) struct ClaimDef {
    /// Stable id (`data-claim`).
    pub id: &'static str,
    /// Section or figure of the paper.
    pub place: Place,
    /// The exhibit this claim is read beside in the tour (empty: after the last one).
    pub beside: &'static str,
    /// What the paper says, paraphrased (never quoted at length), in the interface
    /// language.
    pub says: fn() -> String,
    /// The demo state that shows the value.
    pub at: State,
    /// The check.
    pub check: Check,
    /// Unit of the values, for formatting.
    pub unit: &'static str,
    /// A second value that explains the verdict: a readout of the same demo at `query`
    /// (empty: the claim's own query), shown in `sentence`.
    pub context: Option<Context>,
}

/// A readout that explains a verdict.
pub(super) struct Context {
    /// Query of the claim's demo (empty: the claim's own).
    pub query: &'static str,
    /// The readout.
    pub readout: &'static str,
    /// The sentence around the readout's text, in the interface language.
    pub sentence: fn(String) -> String,
}

/// Where a claim stands in the paper; the numbers are the paper's own labels.
pub(super) enum Place {
    /// `Figure 3`, `Figure 1(b)`.
    Figure(&'static str),
    /// `Section 7.2`.
    Section(&'static str),
    /// A section and the figure it discusses.
    SectionFigure(&'static str, &'static str),
}

impl Place {
    /// The place in the interface language.
    pub fn text(&self) -> String {
        match *self {
            Place::Figure(n) => t!("paper-figure", number = n),
            Place::Section(n) => t!("paper-section", number = n),
            Place::SectionFigure(s, f) => t!("paper-section-figure", section = s, figure = f),
        }
    }
}

/// The figures and tables, in the paper's order.
pub(super) const EXHIBITS: &[Exhibit] = &[
    Exhibit {
        id: "fig1a",
        place: "Figure 1(a)",
        shows: || t!("paper-exhibit-fig1a"),
        at: QUARTER_CAR,
        plot: "response",
    },
    Exhibit {
        id: "fig1b",
        place: "Figure 1(b)",
        shows: || t!("paper-exhibit-fig1b"),
        at: QUARTER_CAR,
        plot: "settling",
    },
    Exhibit {
        id: "fig2a",
        place: "Figure 2(a)",
        shows: || t!("paper-exhibit-fig2a"),
        at: FIG2,
        plot: "current",
    },
    Exhibit {
        id: "fig2b",
        place: "Figure 2(b)",
        shows: || t!("paper-exhibit-fig2b"),
        at: FIG2,
        plot: "voltage",
    },
    Exhibit {
        id: "fig3a",
        place: "Figure 3(a)",
        shows: || t!("paper-exhibit-fig3a"),
        at: FIG3,
        plot: "magnitude",
    },
    Exhibit {
        id: "fig3b",
        place: "Figure 3(b)",
        shows: || t!("paper-exhibit-fig3b"),
        at: FIG3,
        plot: "phase",
    },
    Exhibit {
        id: "fig4a",
        place: "Figure 4(a)",
        shows: || t!("paper-exhibit-fig4a"),
        at: FIG4,
        plot: "response",
    },
    Exhibit {
        id: "fig4b",
        place: "Figure 4(b)",
        shows: || t!("paper-exhibit-fig4b"),
        at: FIG4,
        plot: "convergence",
    },
    Exhibit {
        id: "fig5",
        place: "Figure 5",
        shows: || t!("paper-exhibit-fig5"),
        at: State::new("universality", ""),
        plot: "",
    },
    Exhibit {
        id: "table1",
        place: "Table 1",
        shows: || t!("paper-exhibit-table1"),
        at: State::new("analogy", ""),
        plot: "",
    },
    Exhibit {
        id: "table2",
        place: "Table 2",
        shows: || t!("paper-exhibit-table2"),
        at: State::new("regimes", ""),
        plot: "",
    },
    Exhibit {
        id: "table3",
        place: "Table 3",
        shows: || t!("paper-exhibit-table3"),
        at: FIG4,
        plot: "stability",
    },
];

/// The quantitative claims, in the paper's order.
pub(super) const CLAIMS: &[ClaimDef] = &[
    ClaimDef {
        id: "fig1-zeta-optimum",
        beside: "fig1b",
        place: Place::Figure("1(b)"),
        says: || t!("paper-claim-fig1-zeta-optimum"),
        at: State::new("quarter-car", "band=5"),
        check: Check::Near {
            readout: "zeta_argmin",
            claimed: 0.7,
            tol: 0.05,
        },
        unit: "",
        context: Some(Context {
            query: "band=2",
            readout: "zeta_argmin",
            sentence: |value| t!("paper-claim-fig1-zeta-optimum-context", value = value),
        }),
    },
    ClaimDef {
        id: "sec3-natural-frequency",
        beside: "fig1b",
        place: Place::Section("3"),
        says: || t!("paper-claim-sec3-natural-frequency"),
        at: State::new("quarter-car", "m=300&k=24000"),
        check: Check::Near {
            readout: "wn",
            claimed: 8.9,
            tol: 0.05,
        },
        unit: "rad/s",
        context: Some(Context {
            query: "",
            readout: "fn",
            sentence: |value| t!("paper-claim-sec3-natural-frequency-context", value = value),
        }),
    },
    ClaimDef {
        id: "sec4-critical-resistance",
        beside: "fig2b",
        place: Place::Section("4"),
        says: || t!("paper-claim-sec4-critical-resistance"),
        at: State::new("rlc", "R=10&L=0.5&C=0.02&V0=12"),
        check: Check::Near {
            readout: "R_crit",
            claimed: 10.0,
            tol: 0.005,
        },
        unit: "Ω",
        context: None,
    },
    ClaimDef {
        id: "fig3-q-factor",
        beside: "fig3a",
        place: Place::Figure("3"),
        says: || t!("paper-claim-fig3-q-factor"),
        at: FIG3,
        check: Check::Near {
            readout: "Q",
            claimed: 10.0,
            tol: 0.005,
        },
        unit: "",
        context: None,
    },
    ClaimDef {
        id: "fig3-q-factor-light",
        beside: "fig3a",
        place: Place::Figure("3"),
        says: || t!("paper-claim-fig3-q-factor-light"),
        at: State::new("resonance", "zeta=0.01&r=1"),
        check: Check::Near {
            readout: "Q",
            claimed: 50.0,
            tol: 0.005,
        },
        unit: "",
        context: None,
    },
    ClaimDef {
        id: "sec5-peak-frequency",
        beside: "fig3b",
        place: Place::Section("5"),
        says: || t!("paper-claim-sec5-peak-frequency"),
        at: State::new("resonance", "zeta=0.1&r=1"),
        check: Check::PeakFormula {
            zeta: 0.1,
            tol: 1e-6,
        },
        unit: "",
        context: None,
    },
    ClaimDef {
        id: "fig4-euler-error",
        beside: "fig4a",
        place: Place::SectionFigure("6.5", "4(a)"),
        says: || t!("paper-claim-fig4-euler-error"),
        at: FIG4,
        check: Check::Near {
            readout: "max_err_euler",
            claimed: 0.08,
            tol: 0.02,
        },
        unit: "m",
        context: Some(Context {
            query: "",
            readout: "growth_euler",
            sentence: |value| t!("paper-claim-fig4-euler-error-context", value = value),
        }),
    },
    ClaimDef {
        id: "fig4-rk4-error",
        beside: "fig4a",
        place: Place::SectionFigure("6.5", "4(a)"),
        says: || t!("paper-claim-fig4-rk4-error"),
        at: FIG4,
        check: Check::Below {
            readout: "max_err_rk4",
            bound: 0.001,
        },
        unit: "m",
        context: Some(Context {
            query: "",
            readout: "growth_rk4",
            sentence: |value| t!("paper-claim-fig4-rk4-error-context", value = value),
        }),
    },
    ClaimDef {
        id: "fig4-euler-slope",
        beside: "fig4b",
        place: Place::Figure("4(b)"),
        says: || t!("paper-claim-fig4-euler-slope"),
        at: FIG4,
        check: Check::Slope {
            claimed: 1.0,
            tol: 0.15,
        },
        unit: "",
        context: Some(Context {
            query: "",
            readout: "order_euler",
            sentence: |value| t!("paper-claim-fig4-euler-slope-context", value = value),
        }),
    },
    ClaimDef {
        id: "sec7-mass-tolerance",
        beside: "",
        place: Place::Section("7.2"),
        says: || t!("paper-claim-sec7-mass-tolerance"),
        at: State::new("uncertainty", "system=0&m=300&k=24000&zeta=1&dm=10"),
        check: Check::Range {
            lo: "zeta_min",
            hi: "zeta_max",
            claimed: (0.91, 1.10),
            tol: 0.005,
        },
        unit: "",
        context: Some(Context {
            query: "",
            readout: "wn_min",
            sentence: |value| t!("paper-claim-sec7-mass-tolerance-context", value = value),
        }),
    },
];
