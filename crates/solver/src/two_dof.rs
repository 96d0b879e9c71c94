//! Two-degree-of-freedom quarter car: sprung and unsprung mass on a tyre spring.
