//! Design tools: sweeps over ζ and (k, c), Pareto fronts, sensitivity and Monte Carlo.

pub mod monte_carlo;
pub mod pareto;
pub mod rng;
pub mod sensitivity;
pub mod sweep;
