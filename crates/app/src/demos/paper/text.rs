//! The tour's prose.

pub(super) const SUMMARY: &str = "Zeta Lab was built from one paper on second-order differential \
equations in mechanical and electrical systems (Ihenacho, Samuel, Okechukwu et al., Science \
Publishing Group, 2026). Here is every figure and \
table of it, drawn live by the demo that reproduces it, and every number it states, checked: \
each claim shows the paper's value, the value the app computes, and a verdict. Follow a link \
to open the demo in exactly that state.";

pub(super) const UNAVAILABLE: &str = "this figure's demo is not available";
