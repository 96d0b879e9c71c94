//! The demo registry. Each demo lives in its own file and implements [`Demo`]; adding one
//! is one new file and one line in the registry (`REGISTRY`).

use crate::declare::Declaration;
use crate::figure::Figure;
use crate::params::Params;
use crate::spec::DemoSpec;

pub mod analogy;
pub mod design;
mod digits;
pub mod flutter;
pub mod integrators;
pub mod nonlinear;
pub mod paper;
mod progressive;
pub mod quarter_car;
pub mod quarter_car_2dof;
pub mod regimes;
pub mod resonance;
pub mod rlc;
mod rows;
pub mod uncertainty;
pub mod universality;

#[cfg(test)]
pub(crate) mod regime_cases;
#[cfg(test)]
pub(crate) mod testing;

pub use crate::declare::Readout;

/// What one update produces: readouts and one figure per declared plot, in order.
#[derive(Debug, Clone, PartialEq)]
pub struct Frame {
    /// Readouts in the order of the spec.
    pub readouts: Vec<Readout>,
    /// Figures in the order of the spec's plots.
    pub figures: Vec<Figure>,
    /// Time span \[s\] of the animation and its scrub control, for demos with a schematic.
    pub time_span: Option<(f64, f64)>,
}

/// A live demo. [`Typed`] is the one implementation (the defaults live on [`Model`]).
pub trait Demo {
    /// Parameters, readouts and plots, for the UI to build controls from.
    fn spec(&self) -> DemoSpec;
    /// Recomputes for these (validated) parameter values: the readouts and time span, no
    /// figures. Each figure is built when asked for, [`Demo::figure`]: a page draws only
    /// the plots on screen while a control moves.
    fn recompute(&mut self, params: &Params) -> Frame;
    /// The figure of plot `plot` (an index into the spec's plots) from the last
    /// [`Demo::recompute`]; `None` past the last plot, before the first recompute, or
    /// when the last parameters described no valid system.
    fn figure(&self, plot: usize) -> Option<Figure>;
    /// Recomputes, with every figure: [`Demo::recompute`] and each [`Demo::figure`].
    fn update(&mut self, params: &Params) -> Frame {
        let mut frame = self.recompute(params);
        frame.figures = (0..).map_while(|i| self.figure(i)).collect();
        frame
    }
    /// The schematic at time `t` \[s\] (for demos whose spec sets `schematic`).
    fn schematic(&self, params: &Params, t: f64) -> Option<Figure>;
    /// Parameters the last [`Demo::recompute`] derived from others (e.g. `c` from a moved
    /// `zeta`); the page moves those controls and the URL follows.
    fn derived_params(&self) -> Vec<(&'static str, f64)>;
    /// A click or tap at data point `(x, y)` of plot `plot` (e.g. choosing a design on a
    /// map); returns the parameters to set.
    fn pick(&mut self, plot: &str, x: f64, y: f64) -> Vec<(&'static str, f64)>;
    /// The main response at time `t` \[s\], normalised to about −1…1, for sonification
    /// (pitch follows displacement). `None` for demos without a time response.
    fn sonify(&self, params: &Params, t: f64) -> Option<f64>;
    /// The guided tour of the last [`Demo::recompute`], for the page that checks the paper
    /// (`paper`): exhibits with links and claims with verdicts. `None` for other demos.
    fn tour(&self) -> Option<paper::Tour>;
    /// Progressive studies (issue 13): when `on`, a demo with a heavy study (a large sweep,
    /// a Monte Carlo run) answers [`Demo::recompute`] with a coarse study at once and leaves
    /// the full one to [`Demo::refine`]. Off (the default, and in every native test) the
    /// full study runs inside `update`, as before.
    fn set_progressive(&mut self, on: bool);
    /// Whether a control is held (a drag under way): a progressive demo may answer with an
    /// even coarser study meanwhile, as its every event is one frame of the drag; the full
    /// study still follows at rest.
    fn set_held(&mut self, held: bool);
    /// Does up to about `budget_ms` of the pending full study. `None`: nothing pending;
    /// `Some(f)` with `f < 1`: that fraction done; `Some(1.0)`: the full study just
    /// finished: [`Demo::figure`] shows it at once, the readouts from the next
    /// [`Demo::recompute`]. A study started for parameters that
    /// have since moved on is dropped by the next `update`, never shown.
    fn refine(&mut self, budget_ms: f64) -> Option<f64>;
    /// Keys of the readouts and plots of the last [`Demo::recompute`] that show a coarse,
    /// provisional study while the full one runs (empty when everything shown is final).
    fn provisional(&self) -> Vec<&'static str>;
    /// A count that moves on whenever a [`Demo::recompute`] starts the full study (or a
    /// demo's other work left to [`Demo::refine`]) afresh, for new inputs: the page's
    /// progress bars then start again from 0, and its worker is given the new inputs. The
    /// same while an update only redraws, or moves an input the study does not depend on.
    fn study_round(&self) -> u32;
    /// Whether the page runs the full study in a worker (`on`): [`Demo::refine`] then leaves
    /// it alone and the page hands the worker's result to [`Demo::adopt_study`].
    #[cfg(not(feature = "first"))]
    fn set_worker(&mut self, on: bool);
    /// In a page's worker: computes up to about `budget_ms` of the pending full study
    /// (started by a progressive [`Demo::recompute`] for the page's inputs) without showing
    /// it. `None`: no study pending (the demo has none, or these inputs need none);
    /// `Some(f)`: that fraction done, `Some(1.0)` when [`Demo::export_study`] can send it.
    #[cfg(not(feature = "first"))]
    fn advance_study(&mut self, budget_ms: f64) -> Option<f64>;
    /// In a page's worker: the finished pending study as bytes for [`Demo::adopt_study`].
    #[cfg(not(feature = "first"))]
    fn export_study(&self) -> Option<Vec<u8>>;
    /// In the page: takes in a study a worker computed ([`Demo::export_study`]) if it is
    /// for the pending study's inputs, which then finishes as [`Demo::refine`] finishes it
    /// (`Some(1.0)`); `None`, nothing changed, for a study of inputs since moved on.
    #[cfg(not(feature = "first"))]
    fn adopt_study(&mut self, bytes: &[u8]) -> Option<f64>;
}

/// A demo in the one shape every demo has: a declaration (parameters and readouts as
/// tables), a model step that turns typed parameters into plain results by calling the
/// solver, and figures built from those results. [`Typed`] adapts it to [`Demo`].
pub trait Model: 'static {
    /// The typed parameters, filled from the declaration's parameter table.
    type Params: Default;
    /// What one model step computes: plain numbers and series, no drawing.
    type Results;

    /// The declaration: parameters, readouts, plots, presets, text.
    fn declare() -> Declaration<Self::Params, Self::Results>;

    /// The model step: solver calls only. `None` when the parameters describe no valid
    /// system (unreachable with validated values; the page then shows every readout as
    /// undefined rather than panicking).
    fn step(&mut self, p: &Self::Params) -> Option<Self::Results>;

    /// The figure of declared plot number `plot` from the results; `None` past the last
    /// plot (the registry test checks there is one for each declared plot). Built when the
    /// plot is drawn, possibly frames after the step: what it reads of `self` (a kept sweep
    /// or study) must still be that step's: when a progressive study finishes, `Typed`
    /// steps again at once (see [`Demo::refine`]).
    fn figure(&self, plot: usize, p: &Self::Params, r: &Self::Results) -> Option<Figure>;

    /// Time span \[s\] of the animation, for demos with a schematic.
    fn time_span(&self, _p: &Self::Params, _r: &Self::Results) -> Option<(f64, f64)> {
        None
    }

    /// The schematic at time `t` \[s\].
    fn schematic(&self, _p: &Self::Params, _t: f64) -> Option<Figure> {
        None
    }

    /// Parameters the last step derived from others (see [`Demo::derived_params`]).
    fn derived_params(&self) -> Vec<(&'static str, f64)> {
        Vec::new()
    }

    /// A click at data point `(x, y)` of plot `plot` (see [`Demo::pick`]).
    fn pick(&mut self, _plot: &str, _x: f64, _y: f64) -> Vec<(&'static str, f64)> {
        Vec::new()
    }

    /// The main response at `t`, normalised to about −1…1 (see [`Demo::sonify`]).
    fn sonify(&self, _p: &Self::Params, _t: f64) -> Option<f64> {
        None
    }

    /// A guided tour with checked claims (see [`Demo::tour`]).
    fn tour(&self, _p: &Self::Params, _r: &Self::Results) -> Option<paper::Tour> {
        None
    }

    /// See [`Demo::set_progressive`].
    fn set_progressive(&mut self, _on: bool) {}

    /// See [`Demo::set_held`].
    fn set_held(&mut self, _held: bool) {}

    /// See [`Demo::refine`].
    fn refine(&mut self, _budget_ms: f64) -> Option<f64> {
        None
    }

    /// See [`Demo::provisional`].
    fn provisional(&self) -> Vec<&'static str> {
        Vec::new()
    }

    /// See [`Demo::study_round`].
    fn study_round(&self) -> u32 {
        0
    }

    /// See [`Demo::set_worker`].
    #[cfg(not(feature = "first"))]
    fn set_worker(&mut self, _on: bool) {}

    /// See [`Demo::advance_study`].
    #[cfg(not(feature = "first"))]
    fn advance_study(&mut self, _budget_ms: f64) -> Option<f64> {
        None
    }

    /// See [`Demo::export_study`].
    #[cfg(not(feature = "first"))]
    fn export_study(&self) -> Option<Vec<u8>> {
        None
    }

    /// See [`Demo::adopt_study`].
    #[cfg(not(feature = "first"))]
    fn adopt_study(&mut self, _bytes: &[u8]) -> Option<f64> {
        None
    }
}

/// A [`Model`] with its declaration, as a [`Demo`] the registry can hold.
pub struct Typed<M: Model> {
    model: M,
    decl: Declaration<M::Params, M::Results>,
    tour: Option<paper::Tour>,
    /// The parameters and results of the last step, which figures are built from; `None`
    /// before the first step and when the parameters described no valid system.
    last: Option<(M::Params, M::Results)>,
}

impl<M: Model> Typed<M> {
    /// Steps the model for `p` and keeps the parameters and results (`None` when they
    /// describe no valid system) and the tour they give.
    fn step_and_keep(&mut self, p: M::Params) {
        let r = self.model.step(&p);
        self.tour = r.as_ref().and_then(|r| self.model.tour(&p, r));
        self.last = r.map(|r| (p, r));
    }

    /// After a full study finished (`done` is `Some(1.0)`): the model now holds it, which
    /// figures read, so it steps again so that a figure built before the next recompute
    /// (an export) pairs it with its own results. Returns `done`.
    fn keep_finished(&mut self, done: Option<f64>) -> Option<f64> {
        if done.is_some_and(|f| f >= 1.0) {
            if let Some((p, _)) = self.last.take() {
                self.step_and_keep(p);
            }
        }
        done
    }

    /// Wraps `model` with its declaration.
    pub fn new(model: M) -> Self {
        Self {
            model,
            decl: M::declare(),
            tour: None,
            last: None,
        }
    }
}

impl<M: Model> Demo for Typed<M> {
    fn spec(&self) -> DemoSpec {
        self.decl.spec()
    }

    fn recompute(&mut self, params: &Params) -> Frame {
        self.step_and_keep(self.decl.read(params));
        match &self.last {
            Some((p, r)) => Frame {
                readouts: self.decl.readouts(r),
                figures: Vec::new(),
                time_span: self.model.time_span(p, r),
            },
            None => self.decl.undefined_frame(),
        }
    }

    fn figure(&self, plot: usize) -> Option<Figure> {
        let (p, r) = self.last.as_ref()?;
        self.model.figure(plot, p, r)
    }

    fn schematic(&self, params: &Params, t: f64) -> Option<Figure> {
        self.model.schematic(&self.decl.read(params), t)
    }

    fn derived_params(&self) -> Vec<(&'static str, f64)> {
        self.model.derived_params()
    }

    fn pick(&mut self, plot: &str, x: f64, y: f64) -> Vec<(&'static str, f64)> {
        self.model.pick(plot, x, y)
    }

    fn sonify(&self, params: &Params, t: f64) -> Option<f64> {
        self.model.sonify(&self.decl.read(params), t)
    }

    fn tour(&self) -> Option<paper::Tour> {
        self.tour.clone()
    }

    fn set_progressive(&mut self, on: bool) {
        self.model.set_progressive(on);
    }

    fn set_held(&mut self, held: bool) {
        self.model.set_held(held);
    }

    fn refine(&mut self, budget_ms: f64) -> Option<f64> {
        let done = self.model.refine(budget_ms);
        self.keep_finished(done)
    }

    #[cfg(not(feature = "first"))]
    fn set_worker(&mut self, on: bool) {
        self.model.set_worker(on);
    }

    #[cfg(not(feature = "first"))]
    fn advance_study(&mut self, budget_ms: f64) -> Option<f64> {
        self.model.advance_study(budget_ms)
    }

    #[cfg(not(feature = "first"))]
    fn export_study(&self) -> Option<Vec<u8>> {
        self.model.export_study()
    }

    #[cfg(not(feature = "first"))]
    fn adopt_study(&mut self, bytes: &[u8]) -> Option<f64> {
        let done = self.model.adopt_study(bytes);
        self.keep_finished(done)
    }

    fn provisional(&self) -> Vec<&'static str> {
        self.model.provisional()
    }

    fn study_round(&self) -> u32 {
        self.model.study_round()
    }
}

/// Makes a fresh demo.
type Factory = fn() -> Box<dyn Demo>;

/// `model` with its declaration, as a demo the registry holds.
fn boxed<M: Model>(model: M) -> Box<dyn Demo> {
    Box::new(Typed::new(model))
}

/// The one list of demos, in menu order: `id, English title => factory;`. It defines
/// `MENU` (every id and title) and `REGISTRY` (the factories). The ids and titles here
/// must equal the declarations' (checked by the registry test). `#[first_with("<id>")]`
/// marks a demo that shows another's figures (the paper's tour): its first module also
/// links that demo, the one its first figure comes from (the post-build hook reads the
/// mark; `FIRST_WITH` lists them for the tests).
macro_rules! registry {
    ($($(#[first_with($with:literal)])? $id:literal, $title:literal => $make:expr;)*) => {
        /// Every demo's id and English title, in menu order: a `first` build, which links
        /// only one demo, still lists every demo in its menu.
        const MENU: &[(&str, &str)] = &[$(($id, $title)),*];

        /// Every demo with its factory.
        #[cfg(not(feature = "first"))]
        const REGISTRY: &[(&str, Factory)] = &[$(($id, $make)),*];

        /// Each demo whose first module also links another, with that other.
        #[cfg(test)]
        const FIRST_WITH: &[(&str, &str)] = &[$($(($id, $with),)?)*];

        /// The `first` build (feature `first`): only [`FIRST_DEMO`] is linked (and the demo
        /// its mark names, if any), so its module is small enough to draw the first plot
        /// soon on a slow network; the page then switches to the full module
        /// (web/main.js). `cfg!` is decided at compile time, so the other factories are
        /// never referenced.
        #[cfg(feature = "first")]
        const REGISTRY: &[(&str, Factory)] = &{
            /// A linked demo's factory (each slot below is then filled with its own).
            const fn any_linked() -> Factory {
                $(if cfg!(first_demo = $id) {
                    return $make;
                })*
                panic!("ZETA_FIRST_DEMO names no demo of the registry");
            }
            const LINKED: usize = 0 $(+ cfg!(first_demo = $id) as usize)*;
            let mut linked: [(&str, Factory); LINKED] = [(FIRST_DEMO, any_linked()); LINKED];
            let mut i = 0;
            $(if cfg!(first_demo = $id) {
                linked[i] = ($id, $make);
                i += 1;
            })*
            assert!(i == LINKED);
            linked
        };
    };
}

registry! {
    "regimes", "Damping regimes" => || boxed(regimes::Regimes);
    "quarter-car", "Quarter-car suspension" => || boxed(quarter_car::QuarterCar::new());
    "rlc", "Series RLC circuit" => || boxed(rlc::Rlc);
    "analogy", "One equation, two machines" => || boxed(analogy::Analogy);
    "universality", "One equation, many machines" => || boxed(universality::Universality::default());
    "resonance", "Forced resonance" => || boxed(resonance::Resonance::default());
    "integrators", "Numerical integrators and their error" => || boxed(integrators::Integrators::new());
    "flutter", "Flutter: the Tacoma Narrows bridge" => || boxed(flutter::Flutter::default());
    "nonlinear", "Beyond the linear model" => || boxed(nonlinear::Nonlinear::default());
    "quarter-car-2dof", "Quarter car with body and wheel" => || boxed(quarter_car_2dof::QuarterCar2Dof::default());
    "design", "Design space (k, c)" => || boxed(design::DesignSpace::default());
    "uncertainty", "Tolerance analysis" => || boxed(uncertainty::Uncertainty::default());
    #[first_with("quarter-car")] "paper", "The paper, checked" => || boxed(paper::Paper::default());
}

/// The demo a `first` build opens (the first id of `ZETA_FIRST_DEMO` when it was built, see
/// build.rs; the default demo if unset). A name the registry lacks fails the build
/// (`REGISTRY`).
#[cfg(feature = "first")]
pub const FIRST_DEMO: &str = env!("ZETA_FIRST_DEMO");

/// Ids of every demo this build can create, in menu order.
pub fn ids() -> impl ExactSizeIterator<Item = &'static str> {
    REGISTRY.iter().map(|(id, _)| *id)
}

/// Id and English title of every demo, in menu order, including those this build cannot
/// create (the `first` build).
pub fn menu() -> impl ExactSizeIterator<Item = (&'static str, &'static str)> {
    MENU.iter().copied()
}

/// A new instance of the demo `id`, or `None` if there is no such demo in this build.
pub fn create(id: &str) -> Option<Box<dyn Demo>> {
    REGISTRY
        .iter()
        .find(|(k, _)| *k == id)
        .map(|(_, make)| make())
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::collections::HashSet;

    #[test]
    fn the_menu_lists_every_demo_with_its_declared_title() {
        let declared: Vec<_> = ids()
            .map(|id| (id, create(id).unwrap().spec().title))
            .collect();
        #[cfg(feature = "first")]
        {
            let with = FIRST_WITH.iter().find(|(id, _)| *id == FIRST_DEMO);
            let linked: Vec<_> = menu()
                .filter(|(id, _)| *id == FIRST_DEMO || with.is_some_and(|(_, w)| w == id))
                .collect();
            assert_eq!(declared, linked);
        }
        #[cfg(not(feature = "first"))]
        assert_eq!(menu().collect::<Vec<_>>(), declared);
    }

    #[test]
    fn every_demo_is_consistent_and_draws_finite_figures_from_its_defaults() {
        let mut seen = HashSet::new();
        for id in ids() {
            let mut demo = create(id).unwrap();
            let spec = demo.spec();
            assert_eq!(spec.id, id);
            assert!(seen.insert(spec.id), "duplicate id {id}");
            let mut keys = HashSet::new();
            for p in &spec.params {
                assert!(keys.insert(p.key), "{id}: duplicate key {}", p.key);
                assert!(p.min < p.max && p.step > 0.0, "{id}.{}", p.key);
                assert!(
                    (p.min..=p.max).contains(&p.default),
                    "{id}.{} default out of range",
                    p.key
                );
                if p.scale == crate::spec::Scale::Log {
                    assert!(p.min > 0.0);
                }
            }
            let frame = demo.update(&Params::defaults(&spec));
            let rkeys: Vec<_> = frame.readouts.iter().map(|r| r.key).collect();
            let skeys: Vec<_> = spec.readouts.iter().map(|r| r.key).collect();
            assert_eq!(rkeys, skeys, "{id}: readouts follow the spec");
            assert_eq!(frame.figures.len(), spec.plots.len());
            for f in &frame.figures {
                assert!(f.has_visible_data(), "{id}: {} is empty", f.title);
                assert!(
                    !f.description.is_empty(),
                    "{id}: {} has no text alternative",
                    f.title
                );
            }
            if spec.schematic {
                let (t0, t1) = frame.time_span.expect("animated demos give a time span");
                assert!(t0 < t1);
                for t in [t0, (t0 + t1) / 2.0, t1] {
                    let fig = demo
                        .schematic(&Params::defaults(&spec), t)
                        .expect("schematic");
                    assert!(fig.has_visible_data());
                }
            }
            for preset in &spec.presets {
                for (k, v) in &preset.values {
                    let p = spec
                        .param(k)
                        .unwrap_or_else(|| panic!("{id}: preset names {k}"));
                    assert!(
                        (p.min..=p.max).contains(v),
                        "{id}: preset {} sets {k} out of range",
                        preset.label
                    );
                }
            }
            for r in &frame.readouts {
                assert!(!r.data_value.contains("NaN") && !r.data_value.contains("inf"));
            }
            if let Some(table) = &spec.table {
                let columns = table.columns.len();
                for (key, cells) in &table.rows {
                    assert_eq!(cells.len(), columns, "{id}: table row {key}");
                }
            }
        }
        assert!(create("nope").is_none());
    }

    #[test]
    fn every_demo_survives_its_parameter_extremes() {
        for id in ids() {
            let mut demo = create(id).unwrap();
            let spec = demo.spec();
            for p in &spec.params {
                for v in [p.min, p.max] {
                    let mut params = Params::defaults(&spec);
                    params.set_raw(&spec, p.key, &format!("{v}"));
                    let frame = demo.update(&params);
                    for r in &frame.readouts {
                        assert!(
                            !r.data_value.contains("NaN"),
                            "{id}.{}={v}: {}",
                            p.key,
                            r.key
                        );
                    }
                }
            }
        }
    }
}
