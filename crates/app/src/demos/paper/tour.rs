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
/// The demos of Figure 5 and Tables 1 and 2, at their defaults.
const UNIVERSALITY: State = State::new("universality", "");
const ANALOGY: State = State::new("analogy", "");
const REGIMES: State = State::new("regimes", "");

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

/// Exhibit `id` at `place`, reproduced by plot `plot` of the demo state `at`, showing what
/// `shows` says.
const fn exhibit(
    id: &'static str,
    place: &'static str,
    at: State,
    plot: &'static str,
    shows: fn() -> String,
) -> Exhibit {
    Exhibit {
        id,
        place,
        shows,
        at,
        plot,
    }
}

/// The figures and tables, in the paper's order.
pub(super) const EXHIBITS: &[Exhibit] = &[
    exhibit("fig1a", "Figure 1(a)", QUARTER_CAR, "response", || {
        t!("paper-exhibit-fig1a")
    }),
    exhibit("fig1b", "Figure 1(b)", QUARTER_CAR, "settling", || {
        t!("paper-exhibit-fig1b")
    }),
    exhibit("fig2a", "Figure 2(a)", FIG2, "current", || {
        t!("paper-exhibit-fig2a")
    }),
    exhibit("fig2b", "Figure 2(b)", FIG2, "voltage", || {
        t!("paper-exhibit-fig2b")
    }),
    exhibit("fig3a", "Figure 3(a)", FIG3, "magnitude", || {
        t!("paper-exhibit-fig3a")
    }),
    exhibit("fig3b", "Figure 3(b)", FIG3, "phase", || {
        t!("paper-exhibit-fig3b")
    }),
    exhibit("fig4a", "Figure 4(a)", FIG4, "response", || {
        t!("paper-exhibit-fig4a")
    }),
    exhibit("fig4b", "Figure 4(b)", FIG4, "convergence", || {
        t!("paper-exhibit-fig4b")
    }),
    exhibit("fig5", "Figure 5", UNIVERSALITY, "", || {
        t!("paper-exhibit-fig5")
    }),
    exhibit("table1", "Table 1", ANALOGY, "", || {
        t!("paper-exhibit-table1")
    }),
    exhibit("table2", "Table 2", REGIMES, "", || {
        t!("paper-exhibit-table2")
    }),
    exhibit("table3", "Table 3", FIG4, "stability", || {
        t!("paper-exhibit-table3")
    }),
];

/// A claim being written down: `claim(id).says(…).beside(…).at(…)`, ended by its check
/// (`near`, `below`, `range`, `peak_formula`, `slope`), then `unit` and `context` where it
/// has them. A part left out stays empty, which the tour's tests reject.
pub(super) struct Draft {
    id: &'static str,
    says: fn() -> String,
    place: Place,
    beside: &'static str,
    at: State,
}

/// Claim `id` (see [`Draft`]).
const fn claim(id: &'static str) -> Draft {
    Draft {
        id,
        says: String::new,
        place: Place::Section(""),
        beside: "",
        at: State::new("", ""),
    }
}

impl Draft {
    /// What the paper says, in the interface language.
    const fn says(mut self, says: fn() -> String) -> Self {
        self.says = says;
        self
    }

    /// Where it stands in the paper, and the exhibit it is read beside (empty: after the
    /// last one).
    const fn beside(mut self, exhibit: &'static str, place: Place) -> Self {
        self.place = place;
        self.beside = exhibit;
        self
    }

    /// The demo state that shows the value.
    const fn at(mut self, at: State) -> Self {
        self.at = at;
        self
    }

    /// The claim, checked by `check`.
    const fn check(self, check: Check) -> ClaimDef {
        let Draft {
            id,
            says,
            place,
            beside,
            at,
        } = self;
        ClaimDef {
            id,
            place,
            beside,
            says,
            at,
            check,
            unit: "",
            context: None,
        }
    }

    /// Checked by [`Check::Near`].
    const fn near(self, readout: &'static str, claimed: f64, tol: f64) -> ClaimDef {
        self.check(Check::Near {
            readout,
            claimed,
            tol,
        })
    }

    /// Checked by [`Check::Below`].
    const fn below(self, readout: &'static str, bound: f64) -> ClaimDef {
        self.check(Check::Below { readout, bound })
    }

    /// Checked by [`Check::Range`] on the readouts `lo` and `hi`.
    const fn range(
        self,
        (lo, hi): (&'static str, &'static str),
        claimed: (f64, f64),
        tol: f64,
    ) -> ClaimDef {
        self.check(Check::Range {
            lo,
            hi,
            claimed,
            tol,
        })
    }

    /// Checked by [`Check::PeakFormula`].
    const fn peak_formula(self, zeta: f64, tol: f64) -> ClaimDef {
        self.check(Check::PeakFormula { zeta, tol })
    }

    /// Checked by [`Check::Slope`].
    const fn slope(self, claimed: f64, tol: f64) -> ClaimDef {
        self.check(Check::Slope { claimed, tol })
    }
}

impl ClaimDef {
    /// The claim with its values in `unit`.
    const fn unit(mut self, unit: &'static str) -> Self {
        self.unit = unit;
        self
    }

    /// The claim with the readout `readout` of its demo at `query` (empty: the claim's own)
    /// explaining the verdict in `sentence`.
    const fn context(
        mut self,
        query: &'static str,
        readout: &'static str,
        sentence: fn(String) -> String,
    ) -> Self {
        self.context = Some(Context {
            query,
            readout,
            sentence,
        });
        self
    }
}

/// The quantitative claims, in the paper's order.
pub(super) const CLAIMS: &[ClaimDef] = &[
    claim("fig1-zeta-optimum")
        .says(|| t!("paper-claim-fig1-zeta-optimum"))
        .beside("fig1b", Place::Figure("1(b)"))
        .at(State::new("quarter-car", "band=5"))
        .near("zeta_argmin", 0.7, 0.05)
        .context("band=2", "zeta_argmin", |value| {
            t!("paper-claim-fig1-zeta-optimum-context", value = value)
        }),
    claim("sec3-natural-frequency")
        .says(|| t!("paper-claim-sec3-natural-frequency"))
        .beside("fig1b", Place::Section("3"))
        .at(State::new("quarter-car", "m=300&k=24000"))
        .near("wn", 8.9, 0.05)
        .unit("rad/s")
        .context("", "fn", |value| {
            t!("paper-claim-sec3-natural-frequency-context", value = value)
        }),
    claim("sec4-critical-resistance")
        .says(|| t!("paper-claim-sec4-critical-resistance"))
        .beside("fig2b", Place::Section("4"))
        .at(State::new("rlc", "R=10&L=0.5&C=0.02&V0=12"))
        .near("R_crit", 10.0, 0.005)
        .unit("Ω"),
    claim("fig3-q-factor")
        .says(|| t!("paper-claim-fig3-q-factor"))
        .beside("fig3a", Place::Figure("3"))
        .at(FIG3)
        .near("Q", 10.0, 0.005),
    claim("fig3-q-factor-light")
        .says(|| t!("paper-claim-fig3-q-factor-light"))
        .beside("fig3a", Place::Figure("3"))
        .at(State::new("resonance", "zeta=0.01&r=1"))
        .near("Q", 50.0, 0.005),
    claim("sec5-peak-frequency")
        .says(|| t!("paper-claim-sec5-peak-frequency"))
        .beside("fig3b", Place::Section("5"))
        .at(State::new("resonance", "zeta=0.1&r=1"))
        .peak_formula(0.1, 1e-6),
    claim("fig4-euler-error")
        .says(|| t!("paper-claim-fig4-euler-error"))
        .beside("fig4a", Place::SectionFigure("6.5", "4(a)"))
        .at(FIG4)
        .near("max_err_euler", 0.08, 0.02)
        .unit("m")
        .context("", "growth_euler", |value| {
            t!("paper-claim-fig4-euler-error-context", value = value)
        }),
    claim("fig4-rk4-error")
        .says(|| t!("paper-claim-fig4-rk4-error"))
        .beside("fig4a", Place::SectionFigure("6.5", "4(a)"))
        .at(FIG4)
        .below("max_err_rk4", 0.001)
        .unit("m")
        .context("", "growth_rk4", |value| {
            t!("paper-claim-fig4-rk4-error-context", value = value)
        }),
    claim("fig4-euler-slope")
        .says(|| t!("paper-claim-fig4-euler-slope"))
        .beside("fig4b", Place::Figure("4(b)"))
        .at(FIG4)
        .slope(1.0, 0.15)
        .context("", "order_euler", |value| {
            t!("paper-claim-fig4-euler-slope-context", value = value)
        }),
    claim("sec7-mass-tolerance")
        .says(|| t!("paper-claim-sec7-mass-tolerance"))
        .beside("", Place::Section("7.2"))
        .at(State::new(
            "uncertainty",
            "system=0&m=300&k=24000&zeta=1&dm=10",
        ))
        .range(("zeta_min", "zeta_max"), (0.91, 1.10), 0.005)
        .context("", "wn_min", |value| {
            t!("paper-claim-sec7-mass-tolerance-context", value = value)
        }),
];
