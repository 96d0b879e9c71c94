//! # zeta-solver
//!
//! Numerics for second-order systems
//!
//! `a·y'' + b·y' + c·y = f(t)`, with `a > 0`,
//!
//! the equation of a quarter-car suspension (`m·x'' + c·x' + k·x = F`) and of a series RLC
//! loop (`L·q'' + R·q' + q/C = E`). Conventions throughout: time in s, state `[x, v]`,
//! angular frequency in rad/s, phase in rad, gain as a plain ratio unless a name says dB.
//!
//! The crate has no web dependency and never panics on user input: constructors validate
//! and return [`ModelError`]; everything downstream works on validated types.
//!
//! ```
//! use zeta_solver::{FreeResponse, Regime, SecondOrder};
//! let sys = SecondOrder::from_natural(8.944_272, 0.3).unwrap();
//! assert_eq!(sys.regime(), Regime::Underdamped);
//! let x = FreeResponse::new(sys, 0.06, 0.0);
//! assert!(x.displacement(2.0).abs() < 0.06);
//! ```

pub mod base;
mod complex;
pub mod design;
mod error;
pub mod expm;
pub mod flutter;
pub mod forced;
pub mod free;
pub mod frf;
pub mod grid;
pub mod integrate;
pub mod machines;
pub mod metrics;
pub mod model;
pub mod nonlinear;
pub mod regime;
pub mod ride;
pub mod road;
pub mod search;
#[cfg(test)]
mod testing;
pub mod two_dof;
pub mod two_dof_exact;

pub use complex::Complex;
pub use error::ModelError;
pub use free::{linspace, FreeResponse};
pub use model::SecondOrder;
pub use regime::{Regime, ZETA_TOLERANCE};
