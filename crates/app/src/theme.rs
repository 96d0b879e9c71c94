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

/// Perceptually uniform, colour-blind-safe sequential map (viridis), as 9 stops.
const VIRIDIS: [(u8, u8, u8); 9] = [
    (68, 1, 84),
    (71, 44, 122),
    (59, 81, 139),
    (44, 113, 142),
    (33, 144, 141),
    (39, 173, 129),
    (92, 200, 99),
    (170, 220, 50),
    (253, 231, 37),
];

/// The viridis colour at `f` in \[0, 1\] (clamped), interpolated between stops.
pub fn viridis(f: f64) -> RGBColor {
    let f = if f.is_finite() {
        f.clamp(0.0, 1.0)
    } else {
        0.0
    };
    let x = f * (VIRIDIS.len() - 1) as f64;
    let i = (x.floor() as usize).min(VIRIDIS.len() - 2);
    let t = x - i as f64;
    let (a, b) = (VIRIDIS[i], VIRIDIS[i + 1]);
    let mix = |p: u8, q: u8| (p as f64 + (q as f64 - p as f64) * t).round() as u8;
    RGBColor(mix(a.0, b.0), mix(a.1, b.1), mix(a.2, b.2))
}
