//! Parameters declared together with the field of the typed parameter struct they fill.

use crate::spec::{ChoiceOption, ParamSpec, Scale};

/// A choice parameter's options as a typed enum: the page shows `label`, the URL carries
/// `key`, the model step receives the variant.
pub trait Choice: Copy + PartialEq + 'static {
    /// Every option in menu order: (variant, URL key, label). Never empty.
    const OPTIONS: &'static [(Self, &'static str, &'static str)];

    /// The variant at menu position `i` (the last one past the end).
    fn from_index(i: usize) -> Self {
        let last = Self::OPTIONS.len().saturating_sub(1);
        Self::OPTIONS[i.min(last)].0
    }

    /// The menu position of `self`.
    fn index(self) -> usize {
        Self::OPTIONS
            .iter()
            .position(|(v, _, _)| *v == self)
            .unwrap_or(0)
    }

    /// The URL key of `self`.
    fn key(self) -> &'static str {
        Self::OPTIONS[self.index()].1
    }

    /// The label of `self`.
    fn label(self) -> &'static str {
        Self::OPTIONS[self.index()].2
    }
}

/// Declares an enum and its [`Choice`] option table as one list, in menu order: each
/// variant with its URL key and label (`#[default]` marks the default variant).
///
/// ```ignore
/// choice_enum! {
///     /// How the magnitude is shown.
///     pub enum View {
///         /// The plain ratio.
///         #[default]
///         Linear => ("linear", "linear |H|"),
///         Db => ("db", "decibels"),
///     }
/// }
/// ```
macro_rules! choice_enum {
    (
        $(#[$meta:meta])*
        $vis:vis enum $name:ident {
            $($(#[$vmeta:meta])* $variant:ident => ($key:literal, $label:literal),)+
        }
    ) => {
        $(#[$meta])*
        #[derive(Debug, Default, Clone, Copy, PartialEq, Eq)]
        $vis enum $name {
            $($(#[$vmeta])* $variant,)+
        }

        impl $crate::declare::Choice for $name {
            const OPTIONS: &'static [(Self, &'static str, &'static str)] =
                &[$(($name::$variant, $key, $label)),+];
        }
    };
}
pub(crate) use choice_enum;

/// A quantity many demos declare alike: URL key, label, symbol and unit (each demo gives
/// its own range, default and field; see [`Param::quantity`]).
#[derive(Debug, Clone, Copy)]
pub struct Quantity {
    key: &'static str,
    label: &'static str,
    symbol: &'static str,
    unit: &'static str,
}

impl Quantity {
    const fn new(
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

/// Natural frequency ωₙ \[rad/s\] (`wn`).
pub const NATURAL_FREQUENCY: Quantity = Quantity::new("wn", "natural frequency", "ωₙ", "rad/s");
/// Damping ratio ζ \[-\] (`zeta`).
pub const DAMPING_RATIO: Quantity = Quantity::new("zeta", "damping ratio", "ζ", "");
/// Initial displacement x₀ \[m\] (`x0`).
pub const INITIAL_DISPLACEMENT: Quantity = Quantity::new("x0", "initial displacement", "x₀", "m");
/// Initial velocity v₀ \[m/s\] (`v0`).
pub const INITIAL_VELOCITY: Quantity = Quantity::new("v0", "initial velocity", "v₀", "m/s");

/// Fills one field of the typed parameter struct `P` from a validated value.
type Setter<P> = Box<dyn Fn(&mut P, f64)>;

/// One declared parameter: its spec, and how its validated value fills the typed struct `P`.
pub struct Param<P> {
    spec: ParamSpec,
    set: Setter<P>,
}

impl<P: 'static> Param<P> {
    /// A linear slider over `range = (min, max, step)`.
    pub fn linear(
        key: &'static str,
        label: &'static str,
        symbol: &'static str,
        unit: &'static str,
        range: (f64, f64, f64),
        default: f64,
        set: fn(&mut P, f64),
    ) -> Self {
        Self {
            spec: ParamSpec::linear(key, label, symbol, unit, range, default),
            set: Box::new(set),
        }
    }

    /// A logarithmic slider over `range = (min, max, step)`, `min > 0`.
    pub fn log(
        key: &'static str,
        label: &'static str,
        symbol: &'static str,
        unit: &'static str,
        range: (f64, f64, f64),
        default: f64,
        set: fn(&mut P, f64),
    ) -> Self {
        Self {
            spec: ParamSpec::log(key, label, symbol, unit, range, default),
            set: Box::new(set),
        }
    }

    /// A linear slider for a quantity many demos declare alike (e.g. [`DAMPING_RATIO`]).
    pub fn quantity(
        q: Quantity,
        range: (f64, f64, f64),
        default: f64,
        set: fn(&mut P, f64),
    ) -> Self {
        Self::linear(q.key, q.label, q.symbol, q.unit, range, default, set)
    }

    /// A checkbox, on or off by default.
    pub fn toggle(key: &'static str, label: &'static str, on: bool, set: fn(&mut P, bool)) -> Self {
        Self {
            spec: ParamSpec::toggle(key, label, on),
            set: Box::new(move |p, v| set(p, v != 0.0)),
        }
    }

    /// A drop-down list of the options of `C`.
    pub fn choice<C: Choice>(
        key: &'static str,
        label: &'static str,
        default: C,
        set: fn(&mut P, C),
    ) -> Self {
        let options: Vec<(&'static str, &'static str)> =
            C::OPTIONS.iter().map(|&(_, k, l)| (k, l)).collect();
        Self {
            spec: ParamSpec::choice(key, label, &options, default.index()),
            set: Box::new(move |p, v| set(p, C::from_index(v.max(0.0) as usize))),
        }
    }

    /// The same slider on a logarithmic scale (`min > 0`).
    pub fn log_scale(mut self) -> Self {
        self.spec.scale = Scale::Log;
        self
    }

    /// The same parameter with its symbol set (e.g. a choice shown with a symbol).
    pub fn with_symbol(mut self, symbol: &'static str) -> Self {
        self.spec.symbol = symbol;
        self
    }

    /// The same parameter, shown only while the parameter `key` has the value `index`
    /// (e.g. a machine's sliders while that machine is chosen; see
    /// [`ParamSpec::visible_when`]).
    pub fn visible_when(mut self, key: &'static str, index: usize) -> Self {
        self.spec.visible_when = Some((key, index));
        self
    }
}

impl<P> Param<P> {
    /// What the page builds the control from.
    pub fn spec(&self) -> &ParamSpec {
        &self.spec
    }

    /// Fills this parameter's field of `p` with the validated value `v`.
    pub fn apply(&self, p: &mut P, v: f64) {
        (self.set)(p, v)
    }

    /// Options, for a choice.
    pub fn options(&self) -> &[ChoiceOption] {
        &self.spec.options
    }
}
