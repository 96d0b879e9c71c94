//! Checks each claim against the demo that reproduces it. The computed value is the
//! linked demo's own readout (so the link shows exactly the number the tour states), or a
//! solver computation where the claim is about a formula or a slope. Every sentence is a
//! message of the catalogues, built in the interface language.

use super::tour::{Check, ClaimDef, Exhibit};
use crate::demos::{create, Frame};
use crate::format::si;
use crate::i18n::declared::{self, slug};
use crate::params::resolve_query;
use crate::t;
use serde::Serialize;
use zeta_solver::integrate::analysis::{fit_order, max_error};
use zeta_solver::integrate::{Euler, FixedStep, Linear2};
use zeta_solver::search::maximise;
use zeta_solver::{frf, FreeResponse, SecondOrder};

/// Whether the app confirms a claim.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Verdict {
    /// The computed value agrees with the paper.
    Confirmed,
    /// It does not; the reason says why.
    Differs,
    /// Not checked yet: its demo is not in the page's first module (which links only the
    /// demo of the tour's first figure); the full module, moments later, checks it.
    Pending,
}

/// One checked claim, as the page shows it.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ClaimView {
    /// Stable id (`data-claim`).
    pub id: &'static str,
    /// Section, figure or table.
    pub place: String,
    /// The exhibit it is read beside (empty: after the last one).
    pub beside: &'static str,
    /// What the paper says, paraphrased.
    pub says: String,
    /// Link to the demo state that shows the value (a query string starting `?demo=`).
    pub link: String,
    /// The paper's value, formatted.
    pub claimed: String,
    /// The app's value, formatted.
    pub computed: String,
    /// Confirmed or differs.
    pub verdict: Verdict,
    /// One sentence: why.
    pub reason: String,
}

/// One figure or table of the paper with the link that reproduces it.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ExhibitView {
    /// Stable id, also the key of its thumbnail plot.
    pub id: &'static str,
    /// Figure or table number.
    pub place: String,
    /// What it shows, paraphrased.
    pub shows: String,
    /// Link to the demo state that reproduces it.
    pub link: String,
}

/// The whole tour: what the page lists beside the thumbnails.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Tour {
    /// Figures and tables in the paper's order.
    pub exhibits: Vec<ExhibitView>,
    /// Claims in the paper's order.
    pub claims: Vec<ClaimView>,
}

/// `?demo=<demo>&<query>`.
pub(super) fn link(demo: &str, query: &str) -> String {
    if query.is_empty() {
        format!("?demo={demo}")
    } else {
        format!("?demo={demo}&{query}")
    }
}

/// Demo `demo` updated once at `query`, as the page shows it when the link is opened.
fn run(demo: &str, query: &str) -> Option<Frame> {
    let mut d = create(demo)?;
    let (params, _) = resolve_query(&d.spec(), query);
    Some(d.update(&params))
}

/// The linked demos' frames, each `(demo, query)` computed once per tour: several
/// exhibits and claims share a state (the integrators at h = 0.3 s serve five of them).
#[derive(Default)]
pub(super) struct Runs {
    frames: std::collections::HashMap<(&'static str, &'static str), Option<Frame>>,
    /// Tests: the only demos linked, as in a first module (every registered one if `None`).
    #[cfg(test)]
    only: Option<Vec<&'static str>>,
}

impl Runs {
    /// Tests: runs as a module that links only the demos `only` would make them.
    #[cfg(test)]
    pub(super) fn only(only: &[&'static str]) -> Self {
        Runs {
            only: Some(only.to_vec()),
            ..Runs::default()
        }
    }

    /// Whether this module links demo `demo` (a first module links one or two).
    pub(super) fn linked(&self, demo: &str) -> bool {
        let registered = crate::demos::ids().any(|id| id == demo);
        #[cfg(test)]
        let registered = registered && self.only.as_ref().is_none_or(|o| o.contains(&demo));
        registered
    }

    /// Demo `demo` at `query` (see [`run`]); `None` if the demo is not linked.
    pub(super) fn get(&mut self, demo: &'static str, query: &'static str) -> Option<&Frame> {
        if !self.linked(demo) {
            return None;
        }
        self.frames
            .entry((demo, query))
            .or_insert_with(|| run(demo, query))
            .as_ref()
    }
}

/// Readout `key` of `frame`: its value and the text the demo shows for it.
fn readout(frame: &Frame, key: &str) -> Option<(f64, String)> {
    let r = frame.readouts.iter().find(|r| r.key == key)?;
    Some((r.data_value.parse().ok()?, r.text.clone()))
}

/// The exhibit's place in the interface language: its thumbnail's declared plot title.
pub(super) fn place(e: &Exhibit) -> String {
    declared::tr(&format!("paper-plot-{}", slug(e.id)), e.place)
}

/// The exhibit's entry in the tour.
pub(super) fn exhibit(e: &Exhibit) -> ExhibitView {
    ExhibitView {
        id: e.id,
        place: place(e),
        shows: (e.shows)(),
        link: link(e.at.demo, e.at.query),
    }
}

/// The slope of log(max error) against log(h) for forward Euler over the paper's step
/// `h` and five halvings, on the system of `query` (ζ, ωₙ, x₀, T from the integrators demo's
/// defaults unless the query sets them). Returns `(slope, smallest h, largest h)`.
fn euler_slope(frame_query: &str) -> Option<(f64, f64, f64)> {
    let spec = create("integrators")?.spec();
    let (p, _) = resolve_query(&spec, frame_query);
    let get = |k: &str| p.pairs().find(|(key, _)| *key == k).map(|(_, v)| v);
    let (zeta, wn, h, t_end, x0) = (get("zeta")?, get("wn")?, get("h")?, get("T")?, get("x0")?);
    let sys = SecondOrder::from_natural(wn, zeta).ok()?;
    let exact = FreeResponse::new(sys, x0, 0.0);
    let steps: Vec<f64> = (0..6).map(|k| h / f64::from(1u32 << k)).collect();
    let points: Vec<(f64, f64)> = steps
        .iter()
        .filter_map(|&hk| {
            let sol = Euler
                .solve(&Linear2::free(sys), [x0, 0.0], 0.0, t_end, hk)
                .ok()?;
            let e = max_error(&sol, |t| exact.state(t));
            (e.is_finite() && e > 0.0).then_some((hk, e))
        })
        .collect();
    let slope = fit_order(&points)?;
    Some((slope, *steps.last()?, h))
}

/// The paper's value of a claim, formatted (two or three digits, as the paper gives them).
fn claimed(def: &ClaimDef) -> Option<String> {
    let fmt = |v: f64| si(v, def.unit, 3);
    Some(match def.check {
        Check::Near { claimed, .. } | Check::Slope { claimed, .. } => fmt(claimed),
        Check::Below { bound, .. } => format!("< {}", fmt(bound)),
        Check::Range { claimed, .. } => {
            t!("paper-range", low = fmt(claimed.0), high = fmt(claimed.1))
        }
        Check::PeakFormula { zeta, .. } => si(frf::peak(zeta)?.ratio, "", 6),
    })
}

/// Claim `def` as the page shows it: what the definition says, the paper's value
/// (`claimed`), the app's (`computed`), the verdict and why.
fn view(
    def: &ClaimDef,
    claimed: String,
    computed: String,
    verdict: Verdict,
    reason: String,
) -> ClaimView {
    ClaimView {
        id: def.id,
        place: def.place.text(),
        beside: def.beside,
        says: (def.says)(),
        link: link(def.at.demo, def.at.query),
        claimed,
        computed,
        verdict,
        reason,
    }
}

/// A claim whose demo this module does not link (a first module's): the paper's value,
/// and a verdict to come.
fn pending(def: &ClaimDef) -> Option<ClaimView> {
    Some(view(
        def,
        claimed(def)?,
        t!("paper-pending-value"),
        Verdict::Pending,
        t!("paper-pending"),
    ))
}

/// Checks one claim (pending if its demo is not linked: see [`Verdict::Pending`]); `None`
/// only if a readout it reads is missing.
pub(super) fn judge(def: &ClaimDef, runs: &mut Runs) -> Option<ClaimView> {
    let Some(frame) = runs.get(def.at.demo, def.at.query) else {
        return pending(def);
    };
    let paper = claimed(def)?;
    let fmt = |v: f64| si(v, def.unit, 3);
    let (computed, agrees, why) = match def.check {
        Check::Near {
            readout: key,
            claimed,
            tol,
        } => {
            let (v, shown) = readout(frame, key)?;
            let agrees = (v - claimed).abs() <= tol;
            let tolerance = si(tol, def.unit, 2);
            let why = if agrees {
                t!(
                    "paper-near-agrees",
                    computed = &shown,
                    claimed = &paper,
                    tolerance = tolerance
                )
            } else {
                t!(
                    "paper-near-differs",
                    computed = &shown,
                    claimed = &paper,
                    tolerance = tolerance
                )
            };
            (shown, agrees, why)
        }
        Check::Below {
            readout: key,
            bound,
        } => {
            let (v, shown) = readout(frame, key)?;
            let agrees = v < bound;
            let why = if agrees {
                t!("paper-below-agrees", computed = &shown, bound = fmt(bound))
            } else {
                t!("paper-below-differs", computed = &shown, bound = fmt(bound))
            };
            (shown, agrees, why)
        }
        Check::Range {
            lo,
            hi,
            claimed,
            tol,
        } => {
            let ((a, a_text), (b, b_text)) = (readout(frame, lo)?, readout(frame, hi)?);
            let agrees = (a - claimed.0).abs() <= tol && (b - claimed.1).abs() <= tol;
            let computed = t!("paper-range", low = &a_text, high = &b_text);
            let why = if agrees {
                t!("paper-range-agrees", low = a_text, high = b_text)
            } else {
                t!("paper-range-differs", low = a_text, high = b_text)
            };
            (computed, agrees, why)
        }
        Check::PeakFormula { zeta, tol } => {
            let formula = frf::peak(zeta)?.ratio;
            let (found, _) = maximise(|r| frf::magnitude(r, zeta), 0.0, 2.0)?;
            let agrees = (found - formula).abs() <= tol;
            let why = t!(
                "paper-peak",
                found = si(found, "", 6),
                formula = si(formula, "", 6)
            );
            (si(found, "", 6), agrees, why)
        }
        Check::Slope { claimed, tol } => {
            let (slope, h_min, h_max) = euler_slope(def.at.query)?;
            let agrees = (slope - claimed).abs() <= tol;
            let why = t!(
                "paper-slope",
                step = si(h_max, "s", 3),
                smallest = si(h_min, "s", 3),
                slope = si(slope, "", 3)
            );
            (si(slope, "", 3), agrees, why)
        }
    };
    let mut reason = why;
    if let Some(ctx) = &def.context {
        let query = if ctx.query.is_empty() {
            def.at.query
        } else {
            ctx.query
        };
        if let Some((_, shown)) = readout(runs.get(def.at.demo, query)?, ctx.readout) {
            // Two sentences: the catalogue decides how they join (a space, or none).
            reason = t!(
                "paper-reason-context",
                verdict = &reason,
                context = (ctx.sentence)(shown)
            );
        }
    }
    let verdict = match agrees {
        true => Verdict::Confirmed,
        false => Verdict::Differs,
    };
    Some(view(def, paper, computed, verdict, reason))
}
