//! What a demo declares about itself: its parameters, readouts and plots.
//!
//! The web front end builds every control from this declaration (sent to JavaScript with
//! serde-wasm-bindgen), so adding a demo touches Rust only. Keys are part of the URL
//! contract (`?demo=<id>&<key>=<value>`) and must stay stable.

use serde::Serialize;

/// How a slider maps its position to a value.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Scale {
    /// Evenly spaced values.
    Linear,
    /// Evenly spaced logarithms (`min > 0`).
    Log,
}

/// What control a parameter gets.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Kind {
    /// A range slider with a paired number box.
    Slider,
    /// A checkbox; the value is 0 or 1 (URL: `1`/`0`, `true`/`false`, `on`/`off`).
    Toggle,
    /// A drop-down list; the value is the option's index (URL: the option's key or index).
    Choice,
}

/// What a parameter is: URL key, label, symbol and unit (see [`ParamSpec`]).
#[derive(Debug, Clone, Copy)]
pub struct Quantity {
    key: &'static str,
    label: &'static str,
    symbol: &'static str,
    unit: &'static str,
}

impl Quantity {
    /// A quantity (`unit` empty when dimensionless).
    pub const fn new(
        key: &'static str,
        label: &'static str,
        symbol: &'static str,
        unit: &'static str,
    ) -> Self {
        Self {
            key,
            label,
            symbol,
            unit,
        }
    }
}

/// One option of a [`Kind::Choice`] parameter.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ChoiceOption {
    /// URL value, e.g. `"settling_time"`.
    pub key: &'static str,
    /// Human label.
    pub label: &'static str,
}

/// One parameter: a slider with a paired number box, a checkbox or a drop-down list.
/// Values are always numbers (0/1 for toggles, the option index for choices).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ParamSpec {
    /// URL key, e.g. `"zeta"`.
    pub key: &'static str,
    /// Human label, e.g. `"damping ratio"`.
    pub label: &'static str,
    /// Mathematical symbol, e.g. `"ζ"`.
    pub symbol: &'static str,
    /// SI unit, empty for dimensionless quantities.
    pub unit: &'static str,
    /// Smallest allowed value.
    pub min: f64,
    /// Largest allowed value.
    pub max: f64,
    /// Slider step (for log sliders, the step of the number box).
    pub step: f64,
    /// Value when none is given.
    pub default: f64,
    /// Slider mapping.
    pub scale: Scale,
    /// Which control.
    pub kind: Kind,
    /// Options of a choice (empty otherwise).
    pub options: Vec<ChoiceOption>,
    /// Shown only while the parameter `key` has the value `index` (a choice's option
    /// index, or 0/1 for a toggle); `None`: always shown. The page hides the control
    /// otherwise (`web/conditional.js`); its value still counts, and a URL may set it.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub visible_when: Option<(&'static str, usize)>,
    /// The id of the demo that declares it (set by the declaration; it names the label's
    /// message, see [`ParamSpec::display_label`]).
    #[serde(skip)]
    pub demo: &'static str,
}

impl ParamSpec {
    /// The label in the interface language (message `<demo>-param-<key>`).
    pub fn display_label(&self) -> String {
        use crate::i18n::declared;
        declared::tr(
            &format!("{}-param-{}", self.demo, declared::slug(self.key)),
            self.label,
        )
    }

    /// A slider for quantity `q` over `range = (min, max, step)`.
    pub fn slider(q: Quantity, range: (f64, f64, f64), default: f64, scale: Scale) -> Self {
        Self {
            key: q.key,
            label: q.label,
            symbol: q.symbol,
            unit: q.unit,
            min: range.0,
            max: range.1,
            step: range.2,
            default,
            scale,
            kind: Kind::Slider,
            options: Vec::new(),
            visible_when: None,
            demo: "",
        }
    }

    /// A checkbox, on (1) or off (0) by default.
    pub fn toggle(key: &'static str, label: &'static str, on: bool) -> Self {
        Self {
            kind: Kind::Toggle,
            ..Self::slider(
                Quantity::new(key, label, "", ""),
                (0.0, 1.0, 1.0),
                if on { 1.0 } else { 0.0 },
                Scale::Linear,
            )
        }
    }

    /// A drop-down list of `(key, label)` options; `default` is an index.
    pub fn choice(
        key: &'static str,
        label: &'static str,
        options: &[(&'static str, &'static str)],
        default: usize,
    ) -> Self {
        let n = options.len().max(1);
        Self {
            kind: Kind::Choice,
            options: options
                .iter()
                .map(|&(key, label)| ChoiceOption { key, label })
                .collect(),
            ..Self::slider(
                Quantity::new(key, label, "", ""),
                (0.0, (n - 1) as f64, 1.0),
                default.min(n - 1) as f64,
                Scale::Linear,
            )
        }
    }
}

/// One readout: a number with a unit, or a text.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ReadoutSpec {
    /// Key, used in `data-readout="<key>"`.
    pub key: &'static str,
    /// Human label.
    pub label: &'static str,
    /// SI unit of `data-value` (percent for quantities named in percent).
    pub unit: &'static str,
}

/// One plot: a canvas the demo draws a figure onto.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct PlotSpec {
    /// Key, used as the canvas's `data-plot`.
    pub key: &'static str,
    /// Title, also the canvas's accessible name.
    pub title: &'static str,
    /// Width over height of the canvas.
    pub aspect: f64,
}

/// A named set of parameter values, applied with one click (e.g. a textbook configuration).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Preset {
    /// Button text.
    pub label: &'static str,
    /// Values to set; parameters not named keep their value.
    pub values: Vec<(&'static str, f64)>,
}

/// A reference table shown with the demo; the row whose key equals the current value of
/// the readout `highlight_readout` is highlighted.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Table {
    /// Caption.
    pub caption: &'static str,
    /// Column headings.
    pub columns: Vec<&'static str>,
    /// Rows: a key (matched against the readout) and the cells.
    pub rows: Vec<(&'static str, Vec<&'static str>)>,
    /// The readout whose value selects the highlighted row.
    pub highlight_readout: &'static str,
}

/// Live cells: a table cell whose whole text is `{readout:<key>}` (write it with
/// [`live_cell!`](crate::live_cell)) shows the current text of readout `key` of the same
/// demo, refreshed on every update by the page (`fillLiveCells` in `web/ui.js`). Everything else about
/// the table stays static text; a table without such cells is unchanged.
///
/// ```
/// use zeta_app::spec::Table;
/// let table = Table {
///     caption: "Two machines",
///     columns: vec!["quantity", "value"],
///     rows: vec![("inertia", vec!["mass m [kg]", zeta_app::live_cell!("m")])],
///     highlight_readout: "",
/// };
/// assert_eq!(table.live_cells(), vec![("inertia", 1, "m")]);
/// assert_eq!(Table::live_key("{readout:m}"), Some("m"));
/// assert_eq!(Table::live_key("mass m"), None);
/// ```
impl Table {
    /// The readout key a live cell names, `None` for a static cell.
    pub fn live_key(cell: &str) -> Option<&str> {
        let key = cell.strip_prefix("{readout:")?.strip_suffix('}')?;
        let valid = !key.is_empty()
            && key
                .chars()
                .all(|c| c.is_ascii_alphanumeric() || c == '_' || c == '-');
        valid.then_some(key)
    }

    /// Every live cell as `(row key, column index, readout key)`, in reading order.
    pub fn live_cells(&self) -> Vec<(&'static str, usize, &'static str)> {
        self.rows
            .iter()
            .flat_map(|(row, cells)| {
                cells
                    .iter()
                    .enumerate()
                    .filter_map(move |(i, c)| Some((*row, i, Table::live_key(c)?)))
            })
            .collect()
    }
}

/// A live table cell showing the current text of readout `$key` (see [`Table::live_cells`]):
/// `live_cell!("L")` is `"{readout:L}"`.
#[macro_export]
macro_rules! live_cell {
    ($key:literal) => {
        concat!("{readout:", $key, "}")
    };
}

/// Everything the front end needs to build a demo's controls.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct DemoSpec {
    /// Stable id, the `demo=` URL value.
    pub id: &'static str,
    /// Title shown in the page.
    pub title: &'static str,
    /// One-paragraph explanation (plain text).
    pub summary: &'static str,
    /// The equation, as MathML markup built by the demo (trusted, not from the URL).
    pub equation_mathml: &'static str,
    /// Parameters in display order.
    pub params: Vec<ParamSpec>,
    /// Readouts in display order.
    pub readouts: Vec<ReadoutSpec>,
    /// Plots in display order. The first is the primary plot (see [`DemoSpec::primary`]).
    pub plots: Vec<PlotSpec>,
    /// One-click configurations.
    pub presets: Vec<Preset>,
    /// An optional reference table.
    pub table: Option<Table>,
    /// Whether the demo draws an animated schematic ([`crate::demos::Demo::schematic`]).
    pub schematic: bool,
}

impl DemoSpec {
    /// The primary plot's key: the plot that answers the sliders most directly, kept in view
    /// beside the controls (the page stages it) and shown first in the embed view. It is the
    /// first plot declared, the one whose figure every update builds (its text is announced,
    /// and the page lays the stage out with its caption before the first frame draws).
    pub fn primary(&self) -> &'static str {
        self.plots.first().map_or("", |p| p.key)
    }

    /// The parameter with this key.
    pub fn param(&self, key: &str) -> Option<&ParamSpec> {
        self.params.iter().find(|p| p.key == key)
    }
}

#[cfg(test)]
mod tests {
    use super::Table;
    use crate::demos;

    #[test]
    fn live_cell_keys_are_exact() {
        assert_eq!(Table::live_key(crate::live_cell!("x0")), Some("x0"));
        for not_live in [
            "{readout:}",
            "{readout:a b}",
            "readout:L",
            "{readout:L} V",
            "L",
        ] {
            assert_eq!(Table::live_key(not_live), None, "{not_live}");
        }
    }

    #[test]
    fn every_live_cell_names_a_readout_of_its_demo() {
        for id in demos::ids() {
            let spec = demos::create(id).unwrap().spec();
            let Some(table) = &spec.table else { continue };
            for (row, col, key) in table.live_cells() {
                assert!(
                    spec.readouts.iter().any(|r| r.key == key),
                    "{id}: table row {row}, column {col} names readout {key}, which {id} lacks"
                );
            }
        }
    }
}
