//! Design tool: pareto.
