//! Declaration tables as rows of data: a demo with many sliders, readouts or plots writes
//! one row each (used by `flutter`, `nonlinear`, `quarter-car-2dof` and `universality`).

use crate::declare::Param;
use crate::figure::Figure;
use crate::spec::{PlotSpec, Preset};

/// The sliders of the typed parameters `P`, one row each, in order:
///
/// ```text
/// sliders! { P;
///     linear "key", "label", "symbol", "unit", (min, max, step), default => field;
///     log "key", "label", "symbol", "unit", (min, max, step), default => field;
/// }
/// ```
///
/// `linear` and `log` are the [`Param`](crate::declare::Param) constructors; each slider
/// fills `field` of `P`. With `P, |p| place;` it fills `place.field` instead (a field of a
/// struct inside `P`, e.g. `|p| p.slots[S].v`); a key may be any `&'static str`
/// expression.
macro_rules! sliders {
    ($p:ty; $($rows:tt)*) => {
        $crate::demos::rows::sliders!($p, |p| p; $($rows)*)
    };
    ($p:ty, |$q:ident| $place:expr; $(
        $scale:ident $key:expr, $label:literal, $symbol:literal, $unit:literal,
        $range:expr, $default:expr => $field:ident;
    )*) => {
        vec![$(
            $crate::declare::Param::<$p>::$scale(
                $key, $label, $symbol, $unit, $range, $default, |$q, v| $place.$field = v,
            ),
        )*]
    };
}
pub(crate) use sliders;

/// The readouts of the results `R`, one row each, in order:
///
/// ```text
/// readouts! { R, |r|;
///     number "key", "label", "unit", sig => getter;
///     text "key", "label" => getter;
/// }
/// ```
///
/// Each row names a [`ReadoutDef`](crate::declare::ReadoutDef) constructor and its
/// arguments; the getter is an expression in `r: &R`.
macro_rules! readouts {
    ($r:ty, |$q:ident|; $($kind:ident $($arg:expr),+ => $get:expr;)*) => {
        vec![$(
            $crate::declare::ReadoutDef::<$r>::$kind($($arg),+, |$q| $get),
        )*]
    };
}
pub(crate) use readouts;

/// One plot: key, title (also the canvas's accessible name) and width / height.
pub(crate) type Plot = (&'static str, &'static str, f64);

/// One plot and the figure it shows, drawn from the results `R`.
pub(crate) type Drawn<R> = (Plot, fn(&R) -> Figure);

/// The plots of these rows, in order.
pub(crate) fn plots(rows: &[Plot]) -> Vec<PlotSpec> {
    rows.iter()
        .map(|&(key, title, aspect)| PlotSpec { key, title, aspect })
        .collect()
}

/// The plots of these rows, in order.
pub(crate) fn drawn_plots<R>(rows: &[Drawn<R>]) -> Vec<PlotSpec> {
    plots(&rows.iter().map(|row| row.0).collect::<Vec<_>>())
}

/// The figures of these rows drawn from `r`, in the order of their plots.
pub(crate) fn figures<R>(rows: &[Drawn<R>], r: &R) -> Vec<Figure> {
    rows.iter().map(|(_, draw)| draw(r)).collect()
}

/// Every parameter's key and default value, in order: what a preset starts from.
pub(crate) fn defaults<P>(params: &[Param<P>]) -> Vec<(&'static str, f64)> {
    params
        .iter()
        .map(|p| (p.spec().key, p.spec().default))
        .collect()
}

/// A preset that sets every parameter of `base`, each to its value in `changes` if it has
/// one there (keys `base` lacks are ignored), else to its value in `base`.
pub(crate) fn preset(
    label: &'static str,
    base: &[(&'static str, f64)],
    changes: &[(&'static str, f64)],
) -> Preset {
    let mut values = base.to_vec();
    for &(key, v) in changes {
        if let Some(slot) = values.iter_mut().find(|(k, _)| *k == key) {
            slot.1 = v;
        }
    }
    Preset { label, values }
}
