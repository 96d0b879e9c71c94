//! Design tool: monte_carlo.
