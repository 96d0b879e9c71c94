//! Flutter: a torsional mode whose effective damping falls with wind speed.
