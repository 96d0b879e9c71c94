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
//! **Streamlined box: the thin flat plate of potential-flow theory, exact.** `A₂*` and `A₃*`
//! are Theodorsen's closed form (NACA Report 496, 1935) written in Scanlan's convention,
//! `A₂* = −π/(8K)·(1 − F − 4G/K)`, `A₃* = π/(2K²)·(F − K·G/4)` with `C(K/2) = F + iG`
//! Theodorsen's function (derivation, and how `C` is evaluated from Bessel functions, in
//! [`super::theodorsen`]). A flat plate is the idealisation streamlined box girders are
//! shaped to approach; measured box-deck derivatives (e.g. the Great Belt East section)
//! follow it at low `V_r` and depart from it in detail, and none could be consulted to
//! tabulate here. [`DeckSection::a2`] and [`DeckSection::a3`] evaluate the closed form
//! directly; the table [`DeckSection::table`] holds its values at the nodes, computed
//! independently with 30-digit Bessel functions (mpmath 1.3) and rounded to 10 significant
//! digits, and the solver tests check that the closed form reproduces every node.
//!
//! **1940 H-section: a teaching approximation, not values read from a publication.** The
//! published wind-tunnel curves for the Tacoma H-section (Scanlan & Tomko, "Airfoil and
//! bridge deck flutter derivatives", J. Eng. Mech. Div. ASCE 97(EM6), 1971, 1717–1737;
//! reproduced by Billah & Scanlan, Am. J. Phys. 59(2), 1991, 118–124) could not be
//! consulted when this table was written (searched again for this version: the copies
//! within reach held only the papers' first pages, and no open data set or code tabulates
//! the values), so no value below is attributed to a figure or page of them.
//! What the table does take from that literature is the *shape* the papers describe: for
//! the bluff H-section, `A₂*` is slightly negative at low reduced velocity and changes
//! sign, turning positive and growing, as `U/(fB)` rises — which is why the deck fluttered
//! in torsion alone; for streamlined (airfoil-like) sections `A₂*` stays negative, so the
//! wind only adds torsional damping.
//!
//! How the H-section table was made:
//! - **`A₂*`**: a piecewise-linear curve chosen so that, with the 1940 deck of
//!   [`super::scanlan::ScanlanConfig::tacoma_1940`] (its `I` and `ζ_s` are themselves
//!   assumptions), torsional flutter starts near 18 m/s (≈ 40 mph) and the twist grows over
//!   tens of minutes at 19 m/s, as on 7 November 1940. Zero at `V_r` = 6, negative below.
//! - **`A₃*`**: the quasi-steady limit `A₃* = C_M′·(V_r/2π)² = C_M′/K²`, with the moment
//!   slope `C_M′` = 0.3 /rad assumed.
//!
//! Between the H-section's nodes the derivatives are interpolated linearly; beyond the last
//! node the last value is held.

use super::theodorsen::flat_plate;
use crate::grid::interpolate;
use std::f64::consts::{FRAC_PI_2, TAU};

/// Moment slope `C_M′` \[1/rad\] assumed for the H-section's `A₃*` (teaching assumption).
pub const H_SECTION_MOMENT_SLOPE: f64 = 0.3;
/// Moment slope `C_M′ = π/2` \[1/rad\] of a thin airfoil about mid-chord: the box's
/// (flat plate's) `A₃*·K²` as `K → 0`.
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

/// `A₂*` of the flat plate (streamlined box) at [`NODES`]: Theodorsen's closed form
/// evaluated with mpmath 1.3 at 30 digits, rounded to 10 significant digits (module doc).
const BOX_A2: [f64; N] = [
    0.0,
    -0.03241422893,
    -0.0713382107,
    -0.1215871274,
    -0.1861546455,
    -0.2667014617,
    -0.363993877,
    -0.4782144223,
    -0.6091722413,
    -0.7564440796,
    -0.9194684441,
    -1.097608279,
    -1.290192441,
    -1.496542854,
    -1.715991973,
    -1.947893688,
    -2.191629782,
    -2.446613409,
    -2.712290564,
    -2.988140244,
    -3.273673755,
    -3.568433492,
    -3.871991406,
    -4.183947312,
    -4.503927136,
    -4.831581162,
    -5.16658233,
    -5.50862461,
    -5.857421459,
    -6.212704374,
    -6.574221554,
    -6.941736646,
    -7.315027592,
    -7.693885568,
    -8.078114002,
    -8.467527675,
    -8.861951893,
    -9.261221724,
    -9.665181308,
    -10.07368321,
    -10.48658782,
];

/// `A₃*` of the flat plate (streamlined box) at [`NODES`], as [`BOX_A2`].
const BOX_A3: [f64; N] = [
    0.0,
    0.02251896614,
    0.09153251311,
    0.2104311915,
    0.38312636,
    0.6133654801,
    0.9044985975,
    1.25942789,
    1.680628419,
    2.170194164,
    2.72988991,
    3.361200904,
    4.065377189,
    4.843471855,
    5.696373405,
    6.624832859,
    7.629486305,
    8.71087362,
    9.869453988,
    11.10561876,
    12.41970216,
    13.81199011,
    15.28272768,
    16.83212526,
    18.4603637,
    20.16759867,
    21.95396432,
    23.81957633,
    25.76453455,
    27.78892519,
    29.89282268,
    32.0762913,
    34.33938653,
    36.68215625,
    39.10464166,
    41.60687827,
    44.18889651,
    46.85072248,
    49.59237844,
    52.41388333,
    55.31525315,
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
    source: "thin flat plate, exact potential flow: Theodorsen (NACA Report 496, 1935) in \
             Scanlan's convention, A₂* = −π/(8K)·(1 − F − 4G/K), A₃* = π/(2K²)·(F − KG/4), \
             C(K/2) = F + iG from Bessel functions; nodes evaluated with mpmath at 30 digits",
};

/// The deck's cross-section, which decides its flutter derivatives.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum DeckSection {
    /// The 1940 Tacoma deck: a concrete slab between two 2.4 m plate girders at its edges,
    /// a bluff H-section.
    #[default]
    HSection,
    /// A streamlined (aerofoil-like) box girder, as modern long-span decks use, idealised
    /// as a thin flat plate (Theodorsen's derivatives).
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

    /// `A₂*` \[-\] at reduced velocity `V_r = U/(fB)`: for the H-section linear between
    /// the nodes, the end value held beyond the table; for the box the flat-plate closed
    /// form at any `V_r` ≥ 0. 0 for a negative (box) or non-finite `V_r`.
    pub fn a2(self, reduced_velocity: f64) -> f64 {
        self.derivative(reduced_velocity, |t| t.a2, |(a2, _)| a2)
    }

    /// `A₃*` \[-\] at reduced velocity `V_r = U/(fB)` (as [`Self::a2`]).
    pub fn a3(self, reduced_velocity: f64) -> f64 {
        self.derivative(reduced_velocity, |t| t.a3, |(_, a3)| a3)
    }

    /// One derivative \[-\] at `V_r`, as [`Self::a2`] describes: the table's `column`
    /// interpolated for the H-section, the `part` of [`flat_plate`]'s `(A₂*, A₃*)` for the
    /// box.
    fn derivative(
        self,
        reduced_velocity: f64,
        column: fn(&DerivativeTable) -> &'static [f64],
        part: fn((f64, f64)) -> f64,
    ) -> f64 {
        match self {
            DeckSection::HSection => {
                let t = self.table();
                interpolate(t.reduced_velocity, column(t), reduced_velocity).unwrap_or(0.0)
            }
            DeckSection::StreamlinedBox => flat_plate(reduced_velocity).map_or(0.0, part),
        }
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
        assert_eq!(DeckSection::StreamlinedBox.a2(f64::NAN), 0.0);
        assert_eq!(DeckSection::StreamlinedBox.a3(-1.0), 0.0);
    }

    #[test]
    fn the_box_closed_form_reproduces_its_independently_computed_table() {
        // The nodes were computed with mpmath at 30 digits and rounded to 10 significant
        // digits: the closed form (Bessel series or Hankel expansion) must agree to
        // 10⁻⁹ relative, the rounding plus the evaluation error.
        let b = DeckSection::StreamlinedBox;
        let t = b.table();
        for ((&v, &a2), &a3) in t.reduced_velocity.iter().zip(t.a2).zip(t.a3) {
            let (g2, g3) = (b.a2(v), b.a3(v));
            assert!(
                (g2 - a2).abs() <= 1e-9 * a2.abs(),
                "A2* at {v}: {g2} vs {a2}"
            );
            assert!(
                (g3 - a3).abs() <= 1e-9 * a3.abs(),
                "A3* at {v}: {g3} vs {a3}"
            );
        }
    }
}
