//! Torsional flutter derivatives `A₂*` and `A₃*` of two deck sections, tabulated against
//! the reduced velocity `V_r = U/(f·B) = 2π/K` (`K = B·ω/U` the reduced frequency, `f` the
//! oscillation frequency \[Hz\], `B` the deck width \[m\]), the axis on which wind-tunnel
//! results are usually plotted.
//!
//! Convention (Simiu & Scanlan, *Wind Effects on Structures*): the self-excited moment per
//! unit length on a deck twisting by `θ` is
//!
//! `M = ½ρU²B²·[K·A₂*(K)·B·θ'/U + K²·A₃*(K)·θ]`,
//!
//! so `A₂* > 0` feeds energy into the twist (negative aerodynamic damping) and `A₃* > 0`
//! softens it. (Scanlan & Tomko, 1971, wrote the moment with `2B²` in place of `B²`; their
//! plotted values are half of these.)
//!
//! # Where the numbers come from — read this before quoting them
//!
//! **Both tables are teaching approximations, not values read from a publication.** The
//! published wind-tunnel curves for the 1940 Tacoma H-section (Scanlan & Tomko, 1971,
//! J. Eng. Mech. Div. ASCE 97; reproduced by Billah & Scanlan, 1991, Am. J. Phys. 59(2)
//! 118–124) could not be consulted when these tables were written, so no value below is
//! attributed to a figure or page of them. What the tables do take from that literature is
//! the *shape* the papers describe: for the bluff H-section, `A₂*` is slightly negative at
//! low reduced velocity and changes sign, turning positive and growing, as `U/(fB)` rises —
//! which is why the deck fluttered in torsion alone; for streamlined (airfoil-like)
//! sections `A₂*` stays negative, so the wind only adds torsional damping.
//!
//! How each table was made:
//! - **H-section `A₂*`**: a piecewise-linear curve chosen so that, with the 1940 deck of
//!   [`super::scanlan::ScanlanConfig::tacoma_1940`] (its `I` and `ζ_s` are themselves
//!   assumptions), torsional flutter starts near 18 m/s (≈ 40 mph) and the twist grows over
//!   tens of minutes at 19 m/s, as on 7 November 1940. Zero at `V_r` = 6, negative below.
//! - **Box `A₂*`**: `A₂* = −0.025·V_r`, a straight line that stays negative.
//! - **`A₃*` of both**: the quasi-steady limit `A₃* = C_M′·(V_r/2π)² = C_M′/K²`, with the
//!   moment slope `C_M′` = 0.3 /rad assumed for the H-section and `C_M′ = π/2` /rad for the
//!   box (the thin-airfoil value about mid-chord: lift slope 2π acting a quarter chord ahead
//!   of the centre).
//!
//! Between nodes the derivatives are interpolated linearly; beyond the last node the last
//! value is held.

use crate::grid::interpolate;
use std::f64::consts::{FRAC_PI_2, TAU};

/// Moment slope `C_M′` \[1/rad\] assumed for the H-section's `A₃*` (teaching assumption).
pub const H_SECTION_MOMENT_SLOPE: f64 = 0.3;
/// Moment slope `C_M′ = π/2` \[1/rad\] of a thin airfoil about mid-chord, used for the box.
pub const BOX_MOMENT_SLOPE: f64 = FRAC_PI_2;

/// Number of table nodes.
const N: usize = 41;

/// Reduced velocities `V_r = U/(fB)` \[-\] of the table nodes.
const NODES: [f64; N] = [
    0.0, 1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0, 9.0, 10.0, 11.0, 12.0, 13.0, 14.0, 15.0, 16.0,
    17.0, 18.0, 19.0, 20.0, 21.0, 22.0, 23.0, 24.0, 25.0, 26.0, 27.0, 28.0, 29.0, 30.0, 31.0, 32.0,
    33.0, 34.0, 35.0, 36.0, 37.0, 38.0, 39.0, 40.0,
];

/// `A₂*` of the H-section at [`NODES`] (teaching approximation, see the module doc).
const H_SECTION_A2: [f64; N] = [
    0.0, -0.01, -0.02, -0.03, -0.035, -0.03, 0.0, 0.08, 0.2, 0.33, 0.46, 0.59, 0.72, 0.85, 0.98,
    1.11, 1.24, 1.37, 1.5, 1.63, 1.76, 1.89, 2.02, 2.15, 2.28, 2.41, 2.54, 2.67, 2.8, 2.93, 3.06,
    3.19, 3.32, 3.45, 3.58, 3.71, 3.84, 3.97, 4.1, 4.23, 4.36,
];

/// `A₂* = −0.025·V_r` of the box at [`NODES`].
const BOX_A2: [f64; N] = [
    0.0, -0.025, -0.05, -0.075, -0.1, -0.125, -0.15, -0.175, -0.2, -0.225, -0.25, -0.275, -0.3,
    -0.325, -0.35, -0.375, -0.4, -0.425, -0.45, -0.475, -0.5, -0.525, -0.55, -0.575, -0.6, -0.625,
    -0.65, -0.675, -0.7, -0.725, -0.75, -0.775, -0.8, -0.825, -0.85, -0.875, -0.9, -0.925, -0.95,
    -0.975, -1.0,
];

/// `A₃* = C_M′·(V_r/2π)²` at [`NODES`] for moment slope `slope` \[1/rad\].
const fn quasi_steady_a3(slope: f64) -> [f64; N] {
    let mut out = [0.0; N];
    let mut i = 0;
    while i < N {
        let k_inv = NODES[i] / TAU;
        out[i] = slope * k_inv * k_inv;
        i += 1;
    }
    out
}

const H_SECTION_A3: [f64; N] = quasi_steady_a3(H_SECTION_MOMENT_SLOPE);
const BOX_A3: [f64; N] = quasi_steady_a3(BOX_MOMENT_SLOPE);

/// A table of `A₂*` and `A₃*` against reduced velocity, with where it came from.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DerivativeTable {
    /// Reduced velocities `V_r = U/(fB)` \[-\] of the nodes, ascending.
    pub reduced_velocity: &'static [f64],
    /// `A₂*` \[-\] at each node.
    pub a2: &'static [f64],
    /// `A₃*` \[-\] at each node.
    pub a3: &'static [f64],
    /// Where the values come from and how they were made, in one sentence.
    pub source: &'static str,
}

static H_SECTION: DerivativeTable = DerivativeTable {
    reduced_velocity: &NODES,
    a2: &H_SECTION_A2,
    a3: &H_SECTION_A3,
    source: "teaching approximation: A₂* shaped like the published H-section curves (sign \
             change with rising U/fB) and set so that the 1940 deck flutters near 18 m/s; \
             A₃* quasi-steady with C_M′ = 0.3 /rad (assumed)",
};

static BOX: DerivativeTable = DerivativeTable {
    reduced_velocity: &NODES,
    a2: &BOX_A2,
    a3: &BOX_A3,
    source: "teaching approximation: A₂* = −0.025·U/(fB), negative like an airfoil's; \
             A₃* quasi-steady with the thin-airfoil C_M′ = π/2 /rad",
};

/// The deck's cross-section, which decides its flutter derivatives.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum DeckSection {
    /// The 1940 Tacoma deck: a concrete slab between two 2.4 m plate girders at its edges,
    /// a bluff H-section.
    #[default]
    HSection,
    /// A streamlined (aerofoil-like) box girder, as modern long-span decks use.
    StreamlinedBox,
}

impl DeckSection {
    /// This section's table.
    pub fn table(self) -> &'static DerivativeTable {
        match self {
            DeckSection::HSection => &H_SECTION,
            DeckSection::StreamlinedBox => &BOX,
        }
    }

    /// `A₂*` \[-\] at reduced velocity `V_r = U/(fB)` (linear between nodes, the end value
    /// held beyond the table, 0 for a non-finite `V_r`).
    pub fn a2(self, reduced_velocity: f64) -> f64 {
        let t = self.table();
        interpolate(t.reduced_velocity, t.a2, reduced_velocity).unwrap_or(0.0)
    }

    /// `A₃*` \[-\] at reduced velocity `V_r = U/(fB)` (as [`Self::a2`]).
    pub fn a3(self, reduced_velocity: f64) -> f64 {
        let t = self.table();
        interpolate(t.reduced_velocity, t.a3, reduced_velocity).unwrap_or(0.0)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tables_are_well_formed() {
        for s in [DeckSection::HSection, DeckSection::StreamlinedBox] {
            let t = s.table();
            assert_eq!(t.reduced_velocity.len(), t.a2.len());
            assert_eq!(t.reduced_velocity.len(), t.a3.len());
            assert!(t.reduced_velocity.windows(2).all(|w| w[0] < w[1]));
            assert!(!t.source.is_empty());
        }
        assert_eq!(DeckSection::HSection.a2(f64::NAN), 0.0);
    }
}
