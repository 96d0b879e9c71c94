//! Colours for plots: the Okabe–Ito colour-blind-safe palette on light and dark grounds.

use plotters::style::RGBColor;

/// Plot colours for one theme.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Theme {
    /// Canvas background.
    pub background: RGBColor,
    /// Text and axes.
    pub foreground: RGBColor,
    /// Major grid lines.
    pub grid: RGBColor,
    /// Minor grid lines.
    pub grid_minor: RGBColor,
    /// Series colours, indexed by `LineStyle::color` (wrapping).
    pub palette: [RGBColor; 7],
}

impl Theme {
    /// Dark text on white. Okabe–Ito colours, with yellow swapped for a darker amber so every
    /// line keeps ≥ 3:1 contrast on white.
    pub const LIGHT: Theme = Theme {
        background: RGBColor(255, 255, 255),
        foreground: RGBColor(33, 37, 41),
        grid: RGBColor(206, 212, 218),
        grid_minor: RGBColor(236, 239, 242),
        palette: [
            RGBColor(0, 114, 178),   // blue
            RGBColor(213, 94, 0),    // vermillion
            RGBColor(0, 158, 115),   // bluish green
            RGBColor(204, 121, 167), // reddish purple
            RGBColor(230, 159, 0),   // orange
            RGBColor(86, 180, 233),  // sky blue
            RGBColor(33, 37, 41),    // near black
        ],
    };

    /// Light text on near-black, with the palette lightened for contrast.
    pub const DARK: Theme = Theme {
        background: RGBColor(24, 26, 31),
        foreground: RGBColor(230, 233, 237),
        grid: RGBColor(70, 76, 86),
        grid_minor: RGBColor(44, 48, 55),
        palette: [
            RGBColor(86, 180, 233),  // sky blue
            RGBColor(240, 140, 70),  // light vermillion
            RGBColor(60, 200, 160),  // light bluish green
            RGBColor(220, 150, 190), // light reddish purple
            RGBColor(240, 228, 66),  // yellow
            RGBColor(150, 200, 255), // pale blue
            RGBColor(230, 233, 237), // near white
        ],
    };

    /// Palette colour `i`, wrapping.
    pub fn color(&self, i: usize) -> RGBColor {
        self.palette[i % self.palette.len()]
    }
}
