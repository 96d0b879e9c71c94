//! Plain-data figures: what to draw, apart from how to draw it.
//!
//! A demo builds [`Figure`]s; [`crate::render`] draws them on any plotters backend (the
//! canvas in the browser, an SVG string in native tests and exports).

pub use crate::plot::Ink;

/// Axis mapping.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum AxisScale {
    /// Linear axis.
    Linear,
    /// Logarithmic axis; the range must be positive.
    Log,
}

/// One axis: quantity, unit and range.
#[derive(Debug, Clone, PartialEq)]
pub struct Axis {
    /// Quantity with symbol, e.g. `"time t"`.
    pub label: String,
    /// SI unit, e.g. `"s"`; empty for dimensionless.
    pub unit: &'static str,
    /// Shown range `(low, high)`, `low < high`.
    pub range: (f64, f64),
    /// Mapping.
    pub scale: AxisScale,
}

impl Axis {
    /// A linear axis.
    pub fn linear(label: impl Into<String>, unit: &'static str, range: (f64, f64)) -> Self {
        Self {
            label: label.into(),
            unit,
            range: sane_range(range, AxisScale::Linear),
            scale: AxisScale::Linear,
        }
    }

    /// A logarithmic axis; the range is made positive.
    pub fn log(label: impl Into<String>, unit: &'static str, range: (f64, f64)) -> Self {
        Self {
            label: label.into(),
            unit,
            range: sane_range(range, AxisScale::Log),
            scale: AxisScale::Log,
        }
    }

    /// The axis title with its unit in brackets.
    pub fn title(&self) -> String {
        if self.unit.is_empty() {
            self.label.clone()
        } else {
            format!("{} [{}]", self.label, self.unit)
        }
    }

    /// The title's short form: the label's last word, which names the quantity by its
    /// symbol, with the unit (`x [mm]` for `displacement x [mm]`), for an axis too short
    /// for the whole title; `None` for a one-word label, a last word that is a plain word
    /// (three or more lowercase Latin letters: not a symbol) or not a whole term (a
    /// closing bracket whose opening one is in an earlier word).
    pub fn short_title(&self) -> Option<String> {
        let (_, last) = self.label.trim_end().rsplit_once(' ')?;
        let opens = last.matches(['(', '[']).count();
        let closes = last.matches([')', ']']).count();
        let word = last.len() >= 3 && last.bytes().all(|b| b.is_ascii_lowercase());
        if last.is_empty() || word || opens != closes {
            return None;
        }
        Some(match self.unit.is_empty() {
            true => last.to_string(),
            false => format!("{last} [{}]", self.unit),
        })
    }
}

/// Makes a drawable range: finite, ordered, non-empty (and positive for log axes).
pub fn sane_range(r: (f64, f64), scale: AxisScale) -> (f64, f64) {
    let (mut lo, mut hi) = r;
    if !lo.is_finite() || !hi.is_finite() {
        lo = if lo.is_finite() { lo } else { -1.0 };
        hi = if hi.is_finite() { hi } else { lo + 2.0 };
    }
    if lo > hi {
        std::mem::swap(&mut lo, &mut hi);
    }
    if scale == AxisScale::Log {
        lo = lo.max(1e-300);
        hi = hi.max(lo * 10.0);
    }
    if hi - lo <= f64::EPSILON * (lo.abs() + hi.abs()).max(1e-300) {
        let pad = (lo.abs() * 0.1).max(1e-9);
        lo -= pad;
        hi += pad;
    }
    (lo, hi)
}

/// Line dash pattern, so no information is carried by colour alone.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Dash {
    /// Continuous line.
    Solid,
    /// Long dashes.
    Dashed,
    /// Short dashes.
    Dotted,
}

/// How a series is drawn.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LineStyle {
    /// Colour, from the theme's colour-blind-safe palette.
    pub ink: Ink,
    /// Dash pattern.
    pub dash: Dash,
    /// Stroke width in CSS pixels.
    pub width: f64,
}

impl LineStyle {
    /// A solid line, `width` CSS px.
    pub const fn solid(ink: Ink, width: f64) -> Self {
        Self {
            ink,
            dash: Dash::Solid,
            width,
        }
    }

    /// A line of long dashes, `width` CSS px.
    pub const fn dashed(ink: Ink, width: f64) -> Self {
        Self {
            ink,
            dash: Dash::Dashed,
            width,
        }
    }

    /// A dotted line, `width` CSS px.
    pub const fn dotted(ink: Ink, width: f64) -> Self {
        Self {
            ink,
            dash: Dash::Dotted,
            width,
        }
    }
}

impl Series {
    /// A series with a legend entry (`label` empty for none).
    pub fn new(label: impl Into<String>, points: Vec<(f64, f64)>, style: LineStyle) -> Self {
        Self {
            label: label.into(),
            points,
            style,
        }
    }
}

/// A polyline with a legend entry.
#[derive(Debug, Clone, PartialEq)]
pub struct Series {
    /// Legend text; empty for no legend entry.
    pub label: String,
    /// Points `(x, y)`; non-finite points break the line.
    pub points: Vec<(f64, f64)>,
    /// Stroke.
    pub style: LineStyle,
}

/// Marker shapes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum MarkerShape {
    /// `×`, e.g. a pole.
    Cross,
    /// A filled circle, e.g. a design point.
    Dot,
    /// No mark: the label alone, e.g. a name on a schematic.
    Label,
}

/// A labelled point.
#[derive(Debug, Clone, PartialEq)]
pub struct Marker {
    /// Text beside the point; may be empty.
    pub label: String,
    /// Position in data coordinates.
    pub at: (f64, f64),
    /// Shape.
    pub shape: MarkerShape,
    /// Colour.
    pub ink: Ink,
}

impl Marker {
    /// A `×` at `at`, e.g. a pole.
    pub fn cross(label: impl Into<String>, at: (f64, f64), ink: Ink) -> Self {
        Self::new(label, at, MarkerShape::Cross, ink)
    }

    /// A filled circle at `at`, e.g. a design point.
    pub fn dot(label: impl Into<String>, at: (f64, f64), ink: Ink) -> Self {
        Self::new(label, at, MarkerShape::Dot, ink)
    }

    /// A label alone at `at`, e.g. a name on a schematic.
    pub fn text(label: impl Into<String>, at: (f64, f64), ink: Ink) -> Self {
        Self::new(label, at, MarkerShape::Label, ink)
    }

    fn new(label: impl Into<String>, at: (f64, f64), shape: MarkerShape, ink: Ink) -> Self {
        Self {
            label: label.into(),
            at,
            shape,
            ink,
        }
    }
}

/// How a figure is framed.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum FigureKind {
    /// A chart with axes, grid and legend.
    Plot,
    /// A drawing (a schematic): no axes or grid, equal scales on both axes.
    Schematic,
}

/// A colour map over a regular grid, drawn under the series (e.g. a metric over (k, c)).
#[derive(Debug, Clone, PartialEq)]
pub struct Heatmap {
    /// Cells along x.
    pub nx: usize,
    /// Cells along y.
    pub ny: usize,
    /// Row-major values, `values[iy·nx + ix]`; non-finite cells are left blank.
    pub values: Vec<f64>,
    /// x of the first and last cell edges.
    pub x_edges: (f64, f64),
    /// y of the first and last cell edges.
    pub y_edges: (f64, f64),
    /// Colour scale `(low, high)`; values outside are clamped.
    pub scale: (f64, f64),
    /// Whether `values` and `scale` are natural logarithms of the metric (a logarithmic
    /// colour scale): the colour bar then labels `exp` of its positions, in the metric's unit.
    pub log: bool,
    /// What the colour means, with unit, for the legend (e.g. "settling time \[s\]").
    pub label: String,
}

impl Heatmap {
    /// Whether there are cells and a value for each (otherwise only the colour bar is drawn).
    pub fn has_every_cell(&self) -> bool {
        self.nx > 0 && self.ny > 0 && self.values.len() >= self.nx * self.ny
    }
}

/// One plot.
#[derive(Debug, Clone, PartialEq)]
pub struct Figure {
    /// Title drawn above the plot.
    pub title: String,
    /// Chart or drawing.
    pub kind: FigureKind,
    /// Text alternative: the figure described in words, kept current with the data.
    pub description: String,
    /// Horizontal axis.
    pub x: Axis,
    /// Vertical axis.
    pub y: Axis,
    /// Lines.
    pub series: Vec<Series>,
    /// How many of the first `series` are a backdrop: context that only the view moves
    /// (a family of curves behind the current one). A backend that keeps a plot's static
    /// layer keeps them in it, so a held drag does not draw them again. Drawn under the
    /// other series, and ignored under a heatmap (which is drawn over the layer).
    pub backdrop: usize,
    /// Points.
    pub markers: Vec<Marker>,
    /// Horizontal and vertical reference lines through the origin.
    pub origin_lines: bool,
    /// An optional colour map drawn under the series.
    pub heatmap: Option<Heatmap>,
}

impl Figure {
    /// An empty chart with these axes; push series and markers onto it.
    pub fn plot(title: impl Into<String>, x: Axis, y: Axis) -> Self {
        Self {
            title: title.into(),
            kind: FigureKind::Plot,
            description: String::new(),
            x,
            y,
            series: Vec::new(),
            backdrop: 0,
            markers: Vec::new(),
            origin_lines: false,
            heatmap: None,
        }
    }

    /// A drawing (schematic) over these axes: no grid, equal scales.
    pub fn schematic(title: impl Into<String>, x: Axis, y: Axis) -> Self {
        Self {
            kind: FigureKind::Schematic,
            ..Self::plot(title, x, y)
        }
    }

    /// The figure with its text alternative set.
    pub fn described(mut self, description: impl Into<String>) -> Self {
        self.description = description.into();
        self
    }

    /// The figure with one more series.
    pub fn with_line(
        mut self,
        label: impl Into<String>,
        points: Vec<(f64, f64)>,
        style: LineStyle,
    ) -> Self {
        self.series.push(Series::new(label, points, style));
        self
    }

    /// The figure with every series so far as its backdrop (see [`Figure::backdrop`]).
    pub fn with_backdrop(mut self) -> Self {
        self.backdrop = self.series.len();
        self
    }

    /// The figure with one more marker.
    pub fn with_marker(mut self, marker: Marker) -> Self {
        self.markers.push(marker);
        self
    }

    /// The figure with reference lines through the origin.
    pub fn with_origin_lines(mut self) -> Self {
        self.origin_lines = true;
        self
    }

    /// Whether every series point is finite (no line of the figure breaks).
    pub fn all_points_finite(&self) -> bool {
        self.series
            .iter()
            .all(|s| s.points.iter().all(|p| p.0.is_finite() && p.1.is_finite()))
    }

    /// Whether any series or marker point is finite and inside the axes.
    pub fn has_visible_data(&self) -> bool {
        let inside = |&(x, y): &(f64, f64)| {
            x.is_finite()
                && y.is_finite()
                && (self.x.range.0..=self.x.range.1).contains(&x)
                && (self.y.range.0..=self.y.range.1).contains(&y)
        };
        self.series.iter().any(|s| s.points.iter().any(inside))
            || self.markers.iter().any(|m| inside(&m.at))
    }
}

/// `(min, max)` of the finite values, or `None` if there are none.
pub fn finite_extent(values: impl IntoIterator<Item = f64>) -> Option<(f64, f64)> {
    values
        .into_iter()
        .filter(|v| v.is_finite())
        .fold(None, |acc, v| match acc {
            None => Some((v, v)),
            Some((lo, hi)) => Some((lo.min(v), hi.max(v))),
        })
}

/// Pads `(lo, hi)` by `frac` of its span on each side.
pub fn padded((lo, hi): (f64, f64), frac: f64) -> (f64, f64) {
    let span = (hi - lo)
        .abs()
        .max(1e-12 * (lo.abs() + hi.abs()).max(1e-300));
    (lo - frac * span, hi + frac * span)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ranges_are_made_drawable() {
        assert_eq!(sane_range((1.0, 0.0), AxisScale::Linear), (0.0, 1.0));
        let (lo, hi) = sane_range((2.0, 2.0), AxisScale::Linear);
        assert!(lo < 2.0 && hi > 2.0);
        let (lo, hi) = sane_range((f64::NAN, f64::INFINITY), AxisScale::Linear);
        assert!(lo.is_finite() && hi.is_finite() && lo < hi);
        let (lo, hi) = sane_range((-1.0, 0.0), AxisScale::Log);
        assert!(lo > 0.0 && hi > lo);
    }

    #[test]
    fn extent_skips_non_finite() {
        assert_eq!(
            finite_extent([1.0, f64::NAN, -2.0, f64::INFINITY]),
            Some((-2.0, 1.0))
        );
        assert_eq!(finite_extent([f64::NAN]), None);
    }
}
