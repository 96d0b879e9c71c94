//! Declaration tables as rows of data: a demo with many sliders, readouts or plots writes
//! one row each (used by `flutter`, `nonlinear`, `paper`, `quarter-car-2dof` and
//! `universality`).

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

#[cfg(test)]
mod tests {
    use super::*;

    #[derive(Debug, Default, PartialEq)]
    struct Inner {
        b: f64,
    }

    #[derive(Debug, Default, PartialEq)]
    struct P {
        a: f64,
        inner: Inner,
    }

    struct R {
        a: f64,
    }

    #[test]
    fn a_slider_row_declares_its_slider_and_fills_its_field() {
        let params = sliders! { P;
            linear "a", "first", "a", "m", (0.0, 2.0, 0.1), 1.0 => a;
        };
        let inner = sliders! { P, |p| p.inner;
            log "b", "second", "b", "s", (0.1, 10.0, 0.1), 2.0 => b;
        };
        let mut p = P::default();
        params[0].apply(&mut p, 1.5);
        inner[0].apply(&mut p, 3.0);
        assert_eq!(p.a, 1.5);
        assert_eq!(p.inner.b, 3.0);
        let spec = inner[0].spec();
        assert_eq!(
            (spec.key, spec.label, spec.symbol, spec.unit),
            ("b", "second", "b", "s")
        );
        assert_eq!((spec.min, spec.max, spec.default), (0.1, 10.0, 2.0));
        assert_eq!(spec.scale, crate::spec::Scale::Log);
        assert_eq!(defaults(&params), vec![("a", 1.0)]);
    }

    #[test]
    fn a_readout_row_reads_its_getter() {
        let rows = readouts! { R, |r|;
            number "a", "first", "m", 3 => Some(r.a);
            text "t", "words" => format!("{}", r.a);
        };
        let read: Vec<_> = rows.iter().map(|row| row.read(&R { a: 2.0 })).collect();
        assert_eq!(read[0].key, "a");
        assert_eq!(read[1].text, "2");
    }

    #[test]
    fn a_preset_changes_only_the_keys_of_its_base() {
        let base = [("a", 1.0), ("b", 2.0)];
        let p = preset("p", &base, &[("b", 5.0), ("c", 9.0)]);
        assert_eq!(p.values, vec![("a", 1.0), ("b", 5.0)]);
    }
}
