//! Response metrics: step-response figures (`step`) and free-response figures (`free`).

pub mod free;
pub mod step;
