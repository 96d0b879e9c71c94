//! The tour's prose.

use crate::t;

pub(super) const SUMMARY: &str = "Zeta Lab was built from one paper on second-order differential \
equations in mechanical and electrical systems (Ihenacho, Samuel, Okechukwu et al., Science \
Publishing Group, 2026). Here is every figure and \
table of it, drawn live by the demo that reproduces it, and every number it states, checked: \
each claim shows the paper's value, the value the app computes, and a verdict. Follow a link \
to open the demo in exactly that state.";

/// The thumbnail's text when its demo is not registered.
pub(super) fn unavailable() -> String {
    t!("paper-unavailable")
}

/// The thumbnail's text while its demo is not linked (a first module's).
pub(super) fn pending() -> String {
    t!("paper-pending-plot")
}

/// The word in a thumbnail while its demo is not linked.
pub(super) fn loading() -> String {
    t!("paper-pending-mark")
}
