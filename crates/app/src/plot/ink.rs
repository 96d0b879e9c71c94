//! Named inks: the theme's colour-blind-safe palette by name, so no figure carries a bare
//! colour index and dark mode can swap every colour at once.

/// A palette entry of [`crate::theme::Theme`] (Okabe–Ito, adjusted for contrast).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Ink {
    /// The main curve.
    #[default]
    Blue,
    /// A second curve or a highlighted point.
    Vermillion,
    /// A third curve, or a reference.
    Green,
    /// A fourth curve.
    Purple,
    /// A fifth curve, or a warning band.
    Orange,
    /// A sixth curve.
    Sky,
    /// Text-coloured ink for labels and neutral guides.
    Black,
}

impl Ink {
    /// Every ink in palette order.
    pub const ALL: [Ink; 7] = [
        Ink::Blue,
        Ink::Vermillion,
        Ink::Green,
        Ink::Purple,
        Ink::Orange,
        Ink::Sky,
        Ink::Black,
    ];

    /// The palette index the theme draws this ink with.
    pub const fn index(self) -> usize {
        self as usize
    }

    /// The `i`-th ink, wrapping: for the members of a family of curves.
    pub const fn nth(i: usize) -> Ink {
        Self::ALL[i % Self::ALL.len()]
    }
}

impl From<Ink> for usize {
    fn from(ink: Ink) -> usize {
        ink.index()
    }
}
