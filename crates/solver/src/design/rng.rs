//! Design tool: rng.
