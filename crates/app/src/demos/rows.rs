//! Declaration tables as rows of data: every demo writes its parameters, readouts and
//! plots one row each.

use crate::declare::Param;
use crate::figure::Figure;
use crate::spec::{PlotSpec, Preset};

/// The parameters that fill the typed struct `P` (sliders, checkboxes and drop-down
/// lists), one row each, in order:
///
/// ```text
/// sliders! { P;
///     linear "key", "label", "symbol", "unit", (min, max, step), default => field;
///     log "key", "label", "symbol", "unit", (min, max, step), default => field;
///     quantity DAMPING_RATIO, (min, max, step), default => field;
///     quantity DAMPING_RATIO, (min, max, step), default => field, log_scale();
///     toggle "key", "label", on => flags[0];
///     choice "key", "label", View::Linear => field;
/// }
/// ```
///
/// Each row names a [`Param`](crate::declare::Param) constructor (`linear`, `log`,
/// `quantity`, `toggle`, `choice`) and all its arguments but the setter: the row fills `field`
/// of `P` (or one element of it, `field[i]`) with the validated value. Builder methods
/// after the field (`, log_scale()`, `, visible_when("key", 1)`) apply to the row's
/// parameter. With `P, |p| place;` the rows fill `place.field` instead (a field of a
/// struct inside `P`, e.g. `|p| p.slots[S].v`).
macro_rules! sliders {
    ($p:ty; $($rows:tt)*) => {
        $crate::demos::rows::sliders!($p, |p| p; $($rows)*)
    };
    ($p:ty, |$q:ident| $place:expr; $(
        $kind:ident $($arg:expr),+ => $field:ident $([$i:expr])?
            $(, $then:ident($($then_arg:expr),*))*;
    )*) => {
        vec![$(
            $crate::declare::Param::<$p>::$kind(
                $($arg),+, |$q, v| $place.$field$([$i])? = v,
            )$(.$then($($then_arg),*))*,
        )*]
    };
}
pub(crate) use sliders;

/// The readouts of the results `R`, one row each, in order:
///
/// ```text
/// readouts! { R, |r|;
///     number "key", "label", "unit", sig => getter;
///     plain "key", "label", "unit", sig => getter;
///     text "key", "label" => getter;
///     formatted "key", "label", "unit" => getter;
///     number_or_note "key", "label", "unit", sig => getter;
/// }
/// ```
///
/// Each row names a [`ReadoutDef`](crate::declare::ReadoutDef) constructor and all its
/// arguments but the getter, then the getter: an expression in `r: &R` of the type that
/// constructor reads (`Option<f64>`, `String`, `Option<(f64, String)>`,
/// `Result<Option<f64>, String>`).
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

/// The figure of row `plot` drawn from `r`; `None` past the last row.
pub(crate) fn figure<R>(rows: &[Drawn<R>], plot: usize, r: &R) -> Option<Figure> {
    rows.get(plot).map(|(_, draw)| draw(r))
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

    crate::declare::choice_enum! {
        /// A test choice.
        enum Pick {
            #[default]
            One => ("one", "first"),
            Two => ("two", "second"),
        }
    }

    #[derive(Debug, Default)]
    struct Q {
        zeta: f64,
        shown: [bool; 2],
        pick: Pick,
    }

    #[test]
    fn quantity_toggle_and_choice_rows_fill_their_fields() {
        use crate::declare::DAMPING_RATIO;
        use crate::spec::Scale;
        let params = sliders! { Q;
            quantity DAMPING_RATIO, (0.01, 2.0, 0.01), 0.1 => zeta, log_scale();
            toggle "b", "second shown", true => shown[1];
            choice "pick", "which", Pick::Two => pick, with_symbol("π");
        };
        let mut q = Q::default();
        params[0].apply(&mut q, 0.5);
        params[1].apply(&mut q, 1.0);
        params[2].apply(&mut q, 0.0);
        assert_eq!((q.zeta, q.shown, q.pick), (0.5, [false, true], Pick::One));
        let zeta = params[0].spec();
        assert_eq!(
            (zeta.key, zeta.label, zeta.scale),
            ("zeta", "damping ratio", Scale::Log)
        );
        assert_eq!((zeta.min, zeta.max, zeta.default), (0.01, 2.0, 0.1));
        assert_eq!((params[1].spec().key, params[1].spec().default), ("b", 1.0));
        assert_eq!(
            (params[2].spec().symbol, params[2].spec().default),
            ("π", 1.0)
        );
        assert_eq!(params[2].options().len(), 2);
    }

    #[test]
    fn every_readout_kind_has_a_row() {
        let rows = readouts! { R, |r|;
            plain "p", "plain", "ms", 3 => Some(r.a);
            formatted "f", "own text", "m" => Some((r.a, format!("{} m", r.a)));
            number_or_note "n", "or a note", "m", 3 => Err(format!("none at {}", r.a));
        };
        let read: Vec<_> = rows.iter().map(|row| row.read(&R { a: 2.0 })).collect();
        assert_eq!(read[0].data_value, "2");
        assert_eq!(
            (read[1].text.as_str(), read[1].data_value.as_str()),
            ("2 m", "2")
        );
        assert_eq!(
            (read[2].text.as_str(), read[2].data_value.as_str()),
            ("none at 2", "")
        );
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
