//! The paper tour's declaration: the counts of verdicts as readouts, and one thumbnail plot
//! per exhibit of the tour.

use super::tour::EXHIBITS;
use super::{text, Results, Verdict, P};
use crate::declare::Declaration;
use crate::demos::rows::readouts;
use crate::spec::PlotSpec;

/// The demo's declaration.
pub(super) fn declaration() -> Declaration<P, Results> {
    Declaration {
        readouts: readouts! { Results, |r|;
            formatted "claims", "claims checked", "" => count(r.tour.claims.len() - r.count(Verdict::Pending));
            formatted "confirmed", "claims confirmed", "" => count(r.count(Verdict::Confirmed));
            formatted "differs", "claims that differ", "" => count(r.count(Verdict::Differs));
        },
        plots: EXHIBITS
            .iter()
            .map(|e| PlotSpec {
                key: e.id,
                title: e.place,
                aspect: 1.6,
            })
            .collect(),
        ..Declaration::new("paper", "The paper, checked", text::SUMMARY)
    }
}

/// A count as a readout: the number and its text in the interface language's digits.
fn count(n: usize) -> Option<(f64, String)> {
    Some((n as f64, crate::i18n::number::fixed(n as f64, 0)))
}
