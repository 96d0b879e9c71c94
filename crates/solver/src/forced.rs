//! Forced responses: step, impulse and harmonic forcing, transient plus steady state.
