//! `paper`: "The paper, checked" — a guided tour of the paper Zeta Lab was built from
//! (Ihenacho, Samuel, Okechukwu et al., "Modelling and Simulation of Engineering Design, A
//! Second-Order Differential Equations in Mechanical and Electrical Systems", 2026): each
//! figure and table with a live thumbnail drawn by the demo that reproduces it and a link
//! to that exact state, and each quantitative claim with the value the app computes and a
//! verdict, confirmed or differs, with the reason.
//!
//! The model step (this file) runs the linked demos through the registry, so a value in
//! the tour is the very readout the link opens. `declaration.rs` declares the demo (the
//! counts of verdicts and one thumbnail plot per exhibit); `tour.rs` is the tour as data;
//! `verdict.rs` judges the claims; `text.rs` holds the prose.

mod declaration;
mod text;
mod tour;
mod verdict;

pub use verdict::{ClaimView, ExhibitView, Tour, Verdict};

use super::Model;
use crate::declare::Declaration;
use crate::figure::{Axis, Figure, Marker};
use crate::plot::Ink;
use tour::{CLAIMS, EXHIBITS};

/// The tour. The paper does not change; what a first module could not check yet does.
#[derive(Debug, Default, Clone)]
pub struct Paper {
    /// The readouts and thumbnails of the last step still to come (see
    /// [`Verdict::Pending`]): none with the full module.
    pending: Vec<&'static str>,
}

/// No parameters: the tour is the paper's own configuration.
#[derive(Debug, Default, Clone, Copy)]
pub struct P;

/// The checked tour and the thumbnails.
pub struct Results {
    tour: Tour,
    thumbnails: Vec<Figure>,
}

impl Results {
    fn count(&self, verdict: Verdict) -> usize {
        self.tour
            .claims
            .iter()
            .filter(|c| c.verdict == verdict)
            .count()
    }
}

/// The thumbnail of exhibit `id`: its demo's plot, or the demo's primary plot; `None` when
/// its demo is not linked (a first module's: see [`Verdict::Pending`]).
fn thumbnail(e: &tour::Exhibit, runs: &mut verdict::Runs) -> Option<Figure> {
    if !runs.linked(e.at.demo) {
        return None;
    }
    let drawn = crate::demos::create(e.at.demo).and_then(|d| {
        let spec = d.spec();
        let key = if e.plot.is_empty() {
            spec.primary()
        } else {
            e.plot
        };
        let i = spec.plots.iter().position(|p| p.key == key)?;
        runs.get(e.at.demo, e.at.query)?.figures.get(i).cloned()
    });
    Some(drawn.unwrap_or_else(|| {
        let says = text::unavailable();
        placeholder(e, says.clone(), says)
    }))
}

/// A thumbnail with only the text `mark` in it, described as `says`, in place of exhibit
/// `e`'s figure.
fn placeholder(e: &tour::Exhibit, mark: String, says: String) -> Figure {
    Figure::schematic(
        verdict::place(e),
        Axis::linear("", "", (0.0, 1.0)),
        Axis::linear("", "", (0.0, 1.0)),
    )
    .with_marker(Marker::text(mark, (0.5, 0.5), Ink::Black))
    .described(says)
}

impl Paper {
    /// The tour checked with the demos `runs` can run; what it cannot (a first module's)
    /// is pending.
    fn check(&mut self, mut runs: verdict::Runs) -> Results {
        let tour = Tour {
            exhibits: EXHIBITS.iter().map(verdict::exhibit).collect(),
            claims: CLAIMS
                .iter()
                .filter_map(|c| verdict::judge(c, &mut runs))
                .collect(),
        };
        self.pending.clear();
        if tour.claims.iter().any(|c| c.verdict == Verdict::Pending) {
            self.pending.extend(["claims", "confirmed", "differs"]);
        }
        let thumbnails = (EXHIBITS.iter())
            .map(|e| {
                thumbnail(e, &mut runs).unwrap_or_else(|| {
                    self.pending.push(e.id);
                    placeholder(e, text::loading(), text::pending())
                })
            })
            .collect();
        Results { tour, thumbnails }
    }
}

impl Model for Paper {
    type Params = P;
    type Results = Results;

    fn step(&mut self, _p: &P) -> Option<Results> {
        Some(self.check(verdict::Runs::default()))
    }

    /// What the first module could not check or draw yet: the full module does, moments
    /// later (the page marks them provisional meanwhile).
    fn provisional(&self) -> Vec<&'static str> {
        self.pending.clone()
    }

    /// One round while something is pending: the page shows its marks from the start.
    fn study_round(&self) -> u32 {
        u32::from(!self.pending.is_empty())
    }

    fn figure(&self, plot: usize, _p: &P, r: &Results) -> Option<Figure> {
        r.thumbnails.get(plot).cloned()
    }

    fn tour(&self, _p: &P, r: &Results) -> Option<Tour> {
        Some(r.tour.clone())
    }

    fn declare() -> Declaration<P, Results> {
        declaration::declaration()
    }
}

#[cfg(test)]
mod tests;
