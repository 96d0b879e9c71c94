//! Design tools: sweeps over ζ and (k, c), Pareto fronts, sensitivity and Monte Carlo.
//!
//! ```
//! use zeta_solver::design::sweep::{fastest_settling_zeta, ZetaSweepConfig};
//! // Released from rest, the 5 % settling time is shortest near ζ ≈ 0.69.
//! let best = fastest_settling_zeta(&ZetaSweepConfig::release_from_rest(8.944), 0.1, 2.0, 200).unwrap();
//! assert!((best.zeta - 0.690).abs() < 0.01);
//! ```

pub mod map;
pub mod monte_carlo;
pub mod pareto;
pub mod rng;
pub mod sensitivity;
pub mod sweep;
