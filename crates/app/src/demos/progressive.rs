//! Progressive studies (issue 13), shared by the demos with a heavy study (`design`'s
//! (k, c) sweep, `uncertainty`'s Monte Carlo run): on a page, moved inputs get a coarse
//! study at once and the full one in later short tasks ([`super::Demo::refine`]); the full
//! study replaces the coarse one only if it was computed for the inputs still current. Off
//! (native tests, snapshots) the full study runs in the step. Each demo's own
//! `progressive.rs` holds its study job; this file holds what they share.

/// Where a demo's progressive study stands; `J` is the demo's full-study job.
#[derive(Debug)]
pub(super) struct Progressive<J> {
    /// Whether moved inputs get a coarse study first (on a page).
    on: bool,
    /// Whether the study held is the coarse stand-in for the current inputs.
    provisional: bool,
    /// Whether a control is held (see [`super::Demo::set_held`]).
    held: bool,
    /// The full study under way, if any.
    pub(super) job: Option<J>,
}

impl<J> Default for Progressive<J> {
    fn default() -> Self {
        Self {
            on: false,
            provisional: false,
            held: false,
            job: None,
        }
    }
}

impl<J> Progressive<J> {
    /// Turns progressive studies on or off (see [`super::Demo::set_progressive`]).
    pub(super) fn set_on(&mut self, on: bool) {
        self.on = on;
    }

    /// The size of the study to compute at once for inputs whose full study has size
    /// `full`: `coarse` when progressive and the full study is larger (what is shown is then
    /// provisional until [`Progressive::finished`]), else `full`.
    pub(super) fn size_now(&mut self, full: usize, coarse: usize) -> usize {
        self.provisional = self.on && full > coarse;
        match self.provisional {
            true => coarse,
            false => full,
        }
    }

    /// See [`super::Demo::set_held`].
    pub(super) fn set_held(&mut self, held: bool) {
        self.held = held;
    }

    /// Whether studies are progressive (on a page).
    pub(super) fn is_on(&self) -> bool {
        self.on
    }

    /// Whether a control is held and studies are progressive: a demo may then compute an
    /// even coarser stand-in.
    pub(super) fn is_held(&self) -> bool {
        self.on && self.held
    }

    /// Whether the study held is the coarse stand-in while the full one runs.
    pub(super) fn is_provisional(&self) -> bool {
        self.provisional
    }

    /// The full study has replaced the coarse one.
    pub(super) fn finished(&mut self) {
        self.provisional = false;
    }

    /// The demo's readouts and plots drawn from its study, `keys`, while that study is
    /// provisional; none when everything shown is final (see [`super::Demo::provisional`]).
    pub(super) fn provisional(&self, keys: &[&'static str]) -> Vec<&'static str> {
        match self.provisional {
            true => keys.to_vec(),
            false => Vec::new(),
        }
    }
}

/// The four progressive-study hooks of [`super::Model`] (`set_progressive`, `set_held`,
/// `refine`, `provisional`), inside `impl Model` of a demo whose [`Progressive`] state is its field
/// `progress`: `progressive_hooks!(KEYS, refine_method)`, where `KEYS` are the readouts and
/// plots drawn from its study and `self.refine_method(budget_ms)` continues the full study
/// (see [`super::Demo::refine`]).
macro_rules! progressive_hooks {
    ($keys:expr, $refine:ident) => {
        fn set_progressive(&mut self, on: bool) {
            self.progress.set_on(on);
        }

        fn set_held(&mut self, held: bool) {
            self.progress.set_held(held);
        }

        fn refine(&mut self, budget_ms: f64) -> Option<f64> {
            self.$refine(budget_ms)
        }

        fn provisional(&self) -> Vec<&'static str> {
            self.progress.provisional(&$keys)
        }
    };
}
pub(super) use progressive_hooks;

/// Every readout of a frame but the measured compute time, and its figures: what a
/// progressive study must end up showing exactly as the full study in the step does.
#[cfg(test)]
pub(super) fn shown(f: &super::Frame) -> (Vec<(&str, &str)>, &[crate::figure::Figure]) {
    let readouts = f.readouts.iter().filter(|r| r.key != "compute_time");
    let readouts = readouts.map(|r| (r.key, r.data_value.as_str())).collect();
    (readouts, &f.figures)
}

/// For tests, the page's sequence with a progressive demo: what the full study shows for
/// the query `then` (`want`, progressive off), and a progressive instance (`demo`) that
/// started the study for `first`, got part of the way and then moved to `then`, with the
/// frame it showed for `then` (`coarse`). The overtaken study must never be shown.
#[cfg(test)]
pub(super) struct Overtaken {
    pub(super) want: super::Frame,
    pub(super) demo: Box<dyn super::Demo>,
    pub(super) coarse: super::Frame,
}

/// See [`Overtaken`]; demo `id`, queries `first` then `then` (e.g. `"zeta=0.3"`).
#[cfg(test)]
pub(super) fn overtaken(id: &str, first: &str, then: &str) -> Overtaken {
    let create = || super::create(id).expect("registered demo");
    let params = |q| super::testing::params(id, q);
    let want = create().update(&params(then));
    let mut demo = create();
    demo.set_progressive(true);
    demo.update(&params(first));
    assert!(
        matches!(demo.refine(0.0), Some(f) if f < 1.0),
        "{id}: the study for {first} is under way"
    );
    let coarse = demo.update(&params(then));
    Overtaken { want, demo, coarse }
}
