//! The tour as data: the paper's figures, tables and quantitative claims in the paper's
//! order, each with the demo state that reproduces it. Only the paper's own claimed
//! numbers are typed in here; every value shown beside them is computed by the linked demo.

/// A figure or table of the paper, reproduced live by a demo.
pub(super) struct Exhibit {
    /// Stable id, also the thumbnail's plot key (`fig1a`, `table1`, …).
    pub id: &'static str,
    /// Where it stands in the paper.
    pub place: &'static str,
    /// What it shows, paraphrased.
    pub shows: &'static str,
    /// The demo and query that reproduce it.
    pub demo: &'static str,
    /// URL query of that demo (without `demo=`).
    pub query: &'static str,
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
    /// Section, figure or table of the paper.
    pub place: &'static str,
    /// The exhibit this claim is read beside in the tour (empty: after the last one).
    pub beside: &'static str,
    /// What the paper says, paraphrased (never quoted at length).
    pub says: &'static str,
    /// The demo that shows the value.
    pub demo: &'static str,
    /// URL query of that demo (without `demo=`).
    pub query: &'static str,
    /// The check.
    pub check: Check,
    /// Unit of the values, for formatting.
    pub unit: &'static str,
    /// A second value that explains the verdict: a readout of the same demo at `query`
    /// (empty: the claim's own query), shown in `sentence` where it says `{}`.
    pub context: Option<Context>,
}

/// A readout that explains a verdict.
pub(super) struct Context {
    /// Query of the claim's demo (empty: the claim's own).
    pub query: &'static str,
    /// The readout.
    pub readout: &'static str,
    /// The sentence, with `{}` where the value goes.
    pub sentence: &'static str,
}

/// The figures and tables, in the paper's order.
pub(super) const EXHIBITS: &[Exhibit] = &[
    Exhibit { id: "fig1a", place: "Figure 1(a)", shows: "Free response of the quarter car (m = 300 kg, k = 24 kN/m, x₀ = 60 mm) for comfort, performance, critical and overdamped settings.", demo: "quarter-car", query: "", plot: "response" },
    Exhibit { id: "fig1b", place: "Figure 1(b)", shows: "Settling time against damping ratio, with its minimum.", demo: "quarter-car", query: "", plot: "settling" },
    Exhibit { id: "fig2a", place: "Figure 2(a)", shows: "Current in the series RLC loop (L = 0.5 H, C = 20 mF, V₀ = 12 V) as the resistance spans the regimes.", demo: "rlc", query: "R=5&L=0.5&C=0.02&V0=12", plot: "current" },
    Exhibit { id: "fig2b", place: "Figure 2(b)", shows: "Capacitor voltage of the same loop.", demo: "rlc", query: "R=5&L=0.5&C=0.02&V0=12", plot: "voltage" },
    Exhibit { id: "fig3a", place: "Figure 3(a)", shows: "Magnitude of the frequency response for a family of damping ratios.", demo: "resonance", query: "zeta=0.05&r=1", plot: "magnitude" },
    Exhibit { id: "fig3b", place: "Figure 3(b)", shows: "Phase of the frequency response.", demo: "resonance", query: "zeta=0.05&r=1", plot: "phase" },
    Exhibit { id: "fig4a", place: "Figure 4(a)", shows: "Euler and RK4 against the exact response of a lightly damped oscillator (ζ = 0.05, ωₙ = 2 rad/s) at h = 0.3 s.", demo: "integrators", query: "zeta=0.05&wn=2&h=0.3", plot: "response" },
    Exhibit { id: "fig4b", place: "Figure 4(b)", shows: "Maximum error against step size on log–log axes, with slopes.", demo: "integrators", query: "zeta=0.05&wn=2&h=0.3", plot: "convergence" },
    Exhibit { id: "fig5", place: "Figure 5", shows: "One equation in many machines: mechanical, electrical and other systems with the same a·y'' + b·y' + c·y = f(t).", demo: "universality", query: "", plot: "" },
    Exhibit { id: "table1", place: "Table 1", shows: "The mechanical–electrical analogy: mass ↔ inductance, damper ↔ resistance, spring ↔ 1/capacitance.", demo: "analogy", query: "", plot: "" },
    Exhibit { id: "table2", place: "Table 2", shows: "The damping regimes: condition, roots, behaviour and examples.", demo: "regimes", query: "", plot: "" },
    Exhibit { id: "table3", place: "Table 3", shows: "The integration methods compared: error, order and stability at one step size.", demo: "integrators", query: "zeta=0.05&wn=2&h=0.3", plot: "stability" },
];

/// The quantitative claims, in the paper's order.
pub(super) const CLAIMS: &[ClaimDef] = &[
    ClaimDef { id: "fig1-zeta-optimum", beside: "fig1b", place: "Figure 1(b)", says: "A damping ratio of about 0.7 gives the shortest settling time (5 % band).", demo: "quarter-car", query: "band=5", check: Check::Near { readout: "zeta_argmin", claimed: 0.7, tol: 0.05 }, unit: "", context: Some(Context { query: "band=2", readout: "zeta_argmin", sentence: "For a 2 % band the fastest-settling ζ is {} instead." }) },
    ClaimDef { id: "sec3-natural-frequency", beside: "fig1b", place: "Section 3", says: "The quarter car's natural frequency is about 8.9 rad/s (about 1.4 Hz).", demo: "quarter-car", query: "m=300&k=24000", check: Check::Near { readout: "wn", claimed: 8.9, tol: 0.05 }, unit: "rad/s", context: Some(Context { query: "", readout: "fn", sentence: "In hertz: fₙ = {}." }) },
    ClaimDef { id: "sec4-critical-resistance", beside: "fig2b", place: "Section 4", says: "The loop is critically damped at R = 2√(L/C) = 10 Ω.", demo: "rlc", query: "R=10&L=0.5&C=0.02&V0=12", check: Check::Near { readout: "R_crit", claimed: 10.0, tol: 0.005 }, unit: "Ω", context: None },
    ClaimDef { id: "fig3-q-factor", beside: "fig3a", place: "Figure 3", says: "Q = 10 at ζ = 0.05.", demo: "resonance", query: "zeta=0.05&r=1", check: Check::Near { readout: "Q", claimed: 10.0, tol: 0.005 }, unit: "", context: None },
    ClaimDef { id: "fig3-q-factor-light", beside: "fig3a", place: "Figure 3", says: "Q = 50 at ζ = 0.01.", demo: "resonance", query: "zeta=0.01&r=1", check: Check::Near { readout: "Q", claimed: 50.0, tol: 0.005 }, unit: "", context: None },
    ClaimDef { id: "sec5-peak-frequency", beside: "fig3b", place: "Section 5", says: "The response peaks at ω = ωₙ√(1 − 2ζ²), just below ωₙ (checked at ζ = 0.1).", demo: "resonance", query: "zeta=0.1&r=1", check: Check::PeakFormula { zeta: 0.1, tol: 1e-6 }, unit: "", context: None },
    ClaimDef { id: "fig4-euler-error", beside: "fig4a", place: "Section 6.5, Figure 4(a)", says: "At h = 0.3 s Euler's maximum error is about 0.08.", demo: "integrators", query: "zeta=0.05&wn=2&h=0.3", check: Check::Near { readout: "max_err_euler", claimed: 0.08, tol: 0.02 }, unit: "m", context: Some(Context { query: "", readout: "growth_euler", sentence: "Euler is unstable at this step: |1 + hλ| = {} per step, so its error grows without bound." }) },
    ClaimDef { id: "fig4-rk4-error", beside: "fig4a", place: "Section 6.5, Figure 4(a)", says: "At h = 0.3 s RK4's maximum error is below 0.001.", demo: "integrators", query: "zeta=0.05&wn=2&h=0.3", check: Check::Below { readout: "max_err_rk4", bound: 0.001 }, unit: "m", context: Some(Context { query: "", readout: "growth_rk4", sentence: "RK4 is stable at this step (|R(hλ)| = {} per step), yet over the whole window its error exceeds the bound." }) },
    ClaimDef { id: "fig4-euler-slope", beside: "fig4b", place: "Figure 4(b)", says: "Euler's error falls with slope ≈ 1 on the log–log plot.", demo: "integrators", query: "zeta=0.05&wn=2&h=0.3", check: Check::Slope { claimed: 1.0, tol: 0.15 }, unit: "", context: Some(Context { query: "", readout: "order_euler", sentence: "The order fitted over small steps, where the error is asymptotic, is {}." }) },
    ClaimDef { id: "sec7-mass-tolerance", beside: "", place: "Section 7.2", says: "A ±10 % uncertainty in the sprung mass moves ζ = 1.0 to between 0.91 and 1.10.", demo: "uncertainty", query: "system=0&m=300&k=24000&zeta=1&dm=10", check: Check::Range { lo: "zeta_min", hi: "zeta_max", claimed: (0.91, 1.10), tol: 0.005 }, unit: "", context: Some(Context { query: "", readout: "wn_min", sentence: "ζ = c/(2√(km)) varies as 1/√m, so a ±10 % mass moves it by only about ±5 % (ωₙ drops to {} at +10 %)." }) },
];
