//! # zeta-app
//!
//! The browser side of Zeta Lab: every demo's declaration (parameters, readouts, plots),
//! the figures it computes with `zeta-solver`, and their drawing with plotters. The maths
//! lives in `zeta-solver`; this crate only decides what to show and draws it.
//!
//! Native builds (for `cargo test`) contain everything but the wasm bindings in `web`;
//! figures are then drawn into SVG strings instead of canvases.

pub mod declare;
pub mod demos;
pub mod export;
pub mod figure;
pub mod format;
pub mod i18n;
pub mod lecturer;
pub mod params;
pub mod plot;
pub mod render;
pub mod schematic;
pub mod spec;
pub mod theme;

#[cfg(target_arch = "wasm32")]
pub mod canvas;
#[cfg(target_arch = "wasm32")]
pub mod web;
