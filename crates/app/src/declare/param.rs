//! Parameters declared together with the field of the typed parameter struct they fill.

use crate::spec::{ChoiceOption, ParamSpec, Quantity, Scale};

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
///
/// A choice over some values of a type declared elsewhere (e.g. a solver enum, whose
/// `Choice` table would differ per demo) is a newtype around it, with its default and
/// options listed the same way:
///
/// ```ignore
/// choice_enum! {
///     /// The road class.
///     pub struct Road(pub(super) IsoClass) {
///         default IsoClass::C;
///         IsoClass::A => ("a", "class A (very good)"),
///         IsoClass::C => ("c", "class C (average)"),
///     }
/// }
/// ```
macro_rules! choice_enum {
    (
        $(#[$meta:meta])*
        $vis:vis struct $name:ident($inner_vis:vis $inner:ty) {
            default $default:expr;
            $($value:expr => ($key:literal, $label:literal),)+
        }
    ) => {
        $(#[$meta])*
        #[derive(Debug, Clone, Copy, PartialEq, Eq)]
        $vis struct $name($inner_vis $inner);

        impl Default for $name {
            fn default() -> Self {
                $name($default)
            }
        }

        impl $crate::declare::Choice for $name {
            const OPTIONS: &'static [(Self, &'static str, &'static str)] =
                &[$(($name($value), $key, $label)),+];
        }
    };
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

/// Natural frequency ωₙ \[rad/s\] (`wn`).
pub const NATURAL_FREQUENCY: Quantity = Quantity::new("wn", "natural frequency", "ωₙ", "rad/s");
/// Damping ratio ζ \[-\] (`zeta`).
pub const DAMPING_RATIO: Quantity = Quantity::new("zeta", "damping ratio", "ζ", "");
/// Initial displacement x₀ \[m\] (`x0`).
pub const INITIAL_DISPLACEMENT: Quantity = Quantity::new("x0", "initial displacement", "x₀", "m");
/// Initial velocity v₀ \[m/s\] (`v0`).
pub const INITIAL_VELOCITY: Quantity = Quantity::new("v0", "initial velocity", "v₀", "m/s");

/// The slider constructors of [`Param`], one per [`Scale`], all with the same arguments.
macro_rules! sliders {
    ($($(#[$doc:meta])* $name:ident: $scale:expr;)+) => {
        $(
            $(#[$doc])*
            pub fn $name(
                key: &'static str,
                label: &'static str,
                symbol: &'static str,
                unit: &'static str,
                range: (f64, f64, f64),
                default: f64,
                set: fn(&mut P, f64),
            ) -> Self {
                Self::quantity(Quantity::new(key, label, symbol, unit), range, default, set)
                    .with_scale($scale)
            }
        )+
    };
}

/// Fills one field of the typed parameter struct `P` from a validated value.
type Setter<P> = Box<dyn Fn(&mut P, f64)>;

/// One declared parameter: its spec, and how its validated value fills the typed struct `P`.
pub struct Param<P> {
    spec: ParamSpec,
    set: Setter<P>,
}

impl<P: 'static> Param<P> {
    sliders! {
        /// A linear slider over `range = (min, max, step)`.
        linear: Scale::Linear;
        /// A logarithmic slider over `range = (min, max, step)`, `min > 0`.
        log: Scale::Log;
    }

    /// A linear slider for a quantity many demos declare alike (e.g. [`DAMPING_RATIO`]).
    pub fn quantity(
        q: Quantity,
        range: (f64, f64, f64),
        default: f64,
        set: fn(&mut P, f64),
    ) -> Self {
        Self {
            spec: ParamSpec::slider(q, range, default, Scale::Linear),
            set: Box::new(set),
        }
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
    pub fn log_scale(self) -> Self {
        self.with_scale(Scale::Log)
    }

    fn with_scale(mut self, scale: Scale) -> Self {
        self.spec.scale = scale;
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

#[cfg(test)]
mod tests {
    use super::Choice;

    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    enum Grade {
        Low,
        Mid,
        High,
    }

    choice_enum! {
        /// Two of the three grades, Mid by default.
        struct Picked(Grade) {
            default Grade::Mid;
            Grade::Low => ("low", "the low grade"),
            Grade::Mid => ("mid", "the middle grade"),
        }
    }

    #[test]
    fn a_newtype_choice_lists_its_values_in_order_with_its_own_default() {
        assert_eq!(Picked::default(), Picked(Grade::Mid));
        let keys: Vec<_> = Picked::OPTIONS.iter().map(|o| (o.0 .0, o.1, o.2)).collect();
        assert_eq!(
            keys,
            [
                (Grade::Low, "low", "the low grade"),
                (Grade::Mid, "mid", "the middle grade")
            ]
        );
        assert_eq!(Picked(Grade::Mid).key(), "mid");
        assert!(!Picked::OPTIONS.iter().any(|o| o.0 .0 == Grade::High));
    }
}
