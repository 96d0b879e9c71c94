//! Progressive studies (issue 13), shared by the demos with a heavy study (`design`'s
//! (k, c) sweep, `uncertainty`'s Monte Carlo run): on a page, moved inputs get a coarse
//! study at once and the full one in later short tasks ([`super::Demo::refine`]); the full
//! study replaces the coarse one only if it was computed for the inputs still current. Off
//! (native tests, snapshots) the full study runs in the step. Each demo's own
//! `progressive.rs` holds its study job; this file holds what they share.
//!
//! A page may run the full study in a worker instead ([`StudyJob`]): the worker's instance
//! of the demo, given the same inputs, starts the same job and runs it to the end
//! ([`Progressive::advance`]); what it computed crosses back as bytes
//! ([`Progressive::export`]) and fills the page's pending job ([`Progressive::import`]) if
//! that job is for the same inputs, which then finishes as if refined in the page.

use serde::de::DeserializeOwned;
use serde::Serialize;

/// A demo's full-study job, as it runs in slices and, in a page's worker, to the end.
/// A first module (feature `first`) has no worker: what only a worker needs goes unused,
/// and stays out of its download.
#[cfg_attr(feature = "first", allow(dead_code))]
pub(super) trait StudyJob {
    /// What the job computes (the part a worker sends back).
    type Output: Serialize + DeserializeOwned;
    /// The inputs the job is for, as text two instances agree on exactly when the inputs
    /// are equal (the key's `Debug`: every `f64` in its shortest round-trip form).
    fn key_text(&self) -> String;
    /// Computes for about `budget_ms` (at least one unit of work); returns the fraction done.
    fn advance(&mut self, budget_ms: f64) -> f64;
    /// Whether everything is computed.
    fn finished(&self) -> bool;
    /// A copy of what was computed (a finished job's, in a worker).
    fn output(&self) -> Self::Output;
    /// Takes in `out`, computed elsewhere for the same inputs: the job is then finished.
    /// Returns `false`, the job unchanged, when `out` does not fit it (sizes).
    fn take_output(&mut self, out: Self::Output) -> bool;
}

/// Where a demo's progressive study stands; `J` is the demo's full-study job.
#[derive(Debug)]
pub(super) struct Progressive<J> {
    /// Whether moved inputs get a coarse study first (on a page).
    on: bool,
    /// Whether the study held is the coarse stand-in for the current inputs.
    provisional: bool,
    /// Whether a control is held (see [`super::Demo::set_held`]).
    held: bool,
    /// Whether the page's worker computes the full study (see [`super::Demo::set_worker`]).
    worker: bool,
    /// The full study under way, if any.
    pub(super) job: Option<J>,
    /// How many coarse studies were computed: each starts its full study afresh (see
    /// [`super::Demo::study_round`]). Wraps.
    rounds: u32,
}

impl<J> Default for Progressive<J> {
    fn default() -> Self {
        Self {
            on: false,
            provisional: false,
            held: false,
            worker: false,
            job: None,
            rounds: 0,
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
        if self.provisional {
            self.rounds = self.rounds.wrapping_add(1);
        }
        match self.provisional {
            true => coarse,
            false => full,
        }
    }

    /// See [`super::Demo::set_held`].
    pub(super) fn set_held(&mut self, held: bool) {
        self.held = held;
    }

    #[cfg(not(feature = "first"))]
    /// See [`super::Demo::set_worker`].
    pub(super) fn set_worker(&mut self, worker: bool) {
        self.worker = worker;
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

    /// A count that moves on each time a coarse study starts the full one afresh (see
    /// [`super::Demo::study_round`]).
    pub(super) fn rounds(&self) -> u32 {
        self.rounds
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

impl<J: StudyJob> Progressive<J> {
    /// In the page: computes the pending job for about `budget_ms`, unless a worker
    /// computes it (then only a job it filled, [`Progressive::import`], counts). The fraction
    /// done; at 1 the demo takes the job and shows it. `None` when none is pending here.
    pub(super) fn refine(&mut self, budget_ms: f64) -> Option<f64> {
        let job = self.job.as_mut()?;
        match (job.finished(), self.worker) {
            (true, _) => Some(1.0),
            (false, true) => None,
            (false, false) => Some(job.advance(budget_ms)),
        }
    }

    #[cfg(not(feature = "first"))]
    /// Computes the pending job for about `budget_ms` without finishing it into the demo
    /// (in a worker, whose demo only computes): the fraction done, `None` when none is pending.
    pub(super) fn advance(&mut self, budget_ms: f64) -> Option<f64> {
        let job = self.job.as_mut()?;
        Some(match job.finished() {
            true => 1.0,
            false => job.advance(budget_ms),
        })
    }

    #[cfg(not(feature = "first"))]
    /// The finished pending job's inputs and output as bytes (postcard); `None` if no job is
    /// pending or it is not finished.
    pub(super) fn export(&self) -> Option<Vec<u8>> {
        let job = self.job.as_ref().filter(|j| j.finished())?;
        postcard::to_allocvec(&(job.key_text(), job.output())).ok()
    }

    #[cfg(not(feature = "first"))]
    /// Fills the pending job with `bytes` from [`Progressive::export`] when they were
    /// computed for the same inputs. Returns whether it took them: not when no job is
    /// pending (the inputs moved on and the study restarted, or it finished), the inputs
    /// differ, or the bytes do not read.
    pub(super) fn import(&mut self, bytes: &[u8]) -> bool {
        let Some(job) = self.job.as_mut() else {
            return false;
        };
        match postcard::from_bytes::<(String, J::Output)>(bytes) {
            Ok((key, out)) if key == job.key_text() => job.take_output(out),
            _ => false,
        }
    }
}

/// The hooks of [`super::Model`] that only hand on to a demo's [`Progressive`] state, its
/// field `progress` (`set_progressive`, `set_held`, `set_worker`, and the worker's
/// `advance_study`, `export_study`, `adopt_study`), inside `impl Model`:
/// `study_hooks!(refine_method)`, where `self.refine_method(budget_ms)` continues the full
/// study (see [`super::Demo::refine`]); a study taken from the worker finishes through it.
/// For a demo whose `refine`, `provisional` and `study_round` do more than its study's
/// (integrators').
macro_rules! study_hooks {
    ($refine:ident) => {
        fn set_progressive(&mut self, on: bool) {
            self.progress.set_on(on);
        }

        fn set_held(&mut self, held: bool) {
            self.progress.set_held(held);
        }

        #[cfg(not(feature = "first"))]
        fn set_worker(&mut self, worker: bool) {
            self.progress.set_worker(worker);
        }

        #[cfg(not(feature = "first"))]
        fn advance_study(&mut self, budget_ms: f64) -> Option<f64> {
            self.progress.advance(budget_ms)
        }

        #[cfg(not(feature = "first"))]
        fn export_study(&self) -> Option<Vec<u8>> {
            self.progress.export()
        }

        #[cfg(not(feature = "first"))]
        fn adopt_study(&mut self, bytes: &[u8]) -> Option<f64> {
            match self.progress.import(bytes) {
                true => self.$refine(0.0),
                false => None,
            }
        }
    };
}
pub(super) use study_hooks;

/// Every progressive-study hook of [`super::Model`]: those of [`study_hooks`], and
/// `refine`, `provisional` and `study_round` from the study alone: `progressive_hooks!(KEYS,
/// refine_method)`, where `KEYS` are the readouts and plots drawn from the study.
macro_rules! progressive_hooks {
    ($keys:expr, $refine:ident) => {
        $crate::demos::progressive::study_hooks!($refine);

        fn refine(&mut self, budget_ms: f64) -> Option<f64> {
            self.$refine(budget_ms)
        }

        fn provisional(&self) -> Vec<&'static str> {
            self.progress.provisional(&$keys)
        }

        fn study_round(&self) -> u32 {
            self.progress.rounds()
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

/// A study computed in a worker ([`super::Demo::advance_study`], `export_study`) and taken
/// in by the page's instance ([`super::Demo::adopt_study`]) shows exactly what the full
/// study in the step shows; one for inputs since moved on, or bytes that do not read, is
/// never taken.
#[cfg(test)]
#[cfg(not(feature = "first"))]
mod worker {
    use super::super::{create, testing::params, Demo};
    use super::shown;

    /// The page's instance of `id` at `query`, its study left to a worker.
    fn page(id: &str, query: &str) -> Box<dyn Demo> {
        let mut demo = create(id).expect("registered demo");
        demo.set_progressive(true);
        demo.set_worker(true);
        demo.update(&params(id, query));
        assert!(
            !demo.provisional().is_empty(),
            "{id}?{query}: a study is pending"
        );
        assert_eq!(
            demo.refine(50.0),
            None,
            "{id}: the page leaves it to the worker"
        );
        demo
    }

    /// The worker's instance of `id` computing the study for `query`; its bytes.
    fn worker(id: &str, query: &str) -> Vec<u8> {
        let mut demo = create(id).expect("registered demo");
        demo.set_progressive(true);
        demo.recompute(&params(id, query));
        assert!(
            demo.export_study().is_none(),
            "{id}: nothing to send before it is done"
        );
        let mut rounds = 0;
        while demo.advance_study(1.0) != Some(1.0) {
            rounds += 1;
            assert!(rounds < 10_000, "{id}: the study finishes");
        }
        demo.export_study().expect("a finished study")
    }

    fn round_trip(id: &str, query: &str, other: &str) {
        let want = create(id)
            .expect("registered demo")
            .update(&params(id, query));
        let bytes = worker(id, query);

        let mut demo = page(id, query);
        assert_eq!(
            demo.adopt_study(&bytes[..bytes.len() / 2]),
            None,
            "{id}: cut bytes"
        );
        assert_eq!(
            demo.adopt_study(&worker(id, other)),
            None,
            "{id}: other inputs"
        );
        assert!(!demo.provisional().is_empty(), "{id}: still provisional");
        assert_eq!(demo.adopt_study(&bytes), Some(1.0), "{id}: taken");
        let got = demo.update(&params(id, query));
        assert!(demo.provisional().is_empty(), "{id}: final");
        // Debug text: the figures may hold NaN gaps, which `==` never equates.
        assert_eq!(
            format!("{:?}", shown(&got)),
            format!("{:?}", shown(&want)),
            "{id}"
        );

        // The inputs moved on before the result came: it is dropped, the new study pending.
        let mut demo = page(id, query);
        demo.update(&params(id, other));
        assert_eq!(demo.adopt_study(&bytes), None, "{id}: overtaken");
        assert!(
            !demo.provisional().is_empty(),
            "{id}: the new study is pending"
        );
    }

    #[test]
    fn a_sweep_from_the_worker_is_the_full_sweep() {
        round_trip("design", "m=420", "m=500");
    }

    #[test]
    fn a_monte_carlo_run_from_the_worker_is_the_full_run() {
        round_trip("uncertainty", "dm=12", "dm=15");
    }

    #[test]
    fn a_convergence_study_from_the_worker_is_the_full_study() {
        round_trip("integrators", "zeta=0.1", "zeta=0.3");
    }
}

/// The page's progress bars start again from 0, and its worker is given new inputs,
/// exactly when an update starts the full study afresh: [`super::Demo::study_round`] moves
/// then, and only then; a redraw, or an input the study does not depend on, carries on
/// with the study under way.
#[cfg(test)]
#[cfg(not(feature = "first"))]
mod rounds {
    use super::super::{create, testing::params};

    /// Demo `id` at `first` with part of its study done, then at `first` again and at
    /// `same` (an input the study does not depend on), then at `moved`.
    fn rounds(id: &str, first: &str, same: &str, moved: &str) {
        let mut demo = create(id).expect("registered demo");
        demo.set_progressive(true);
        let before = demo.study_round();
        demo.update(&params(id, first));
        let round = demo.study_round();
        assert_ne!(round, before, "{id}?{first}: a study started");
        let done = demo.refine(0.0).expect("a study under way");
        assert!(done < 1.0, "{id}: part of it done ({done})");
        for query in [first, same] {
            demo.update(&params(id, query));
            assert_eq!(demo.study_round(), round, "{id}?{query}: the same study");
            assert!(
                !demo.provisional().is_empty(),
                "{id}?{query}: still provisional"
            );
        }
        let next = demo.refine(0.0).expect("still under way");
        assert!(
            next > done,
            "{id}: it went on from {done}, not from the start ({next})"
        );
        demo.update(&params(id, moved));
        assert_ne!(demo.study_round(), round, "{id}?{moved}: a new study");
    }

    #[test]
    fn a_sweep_starts_afresh_only_when_the_map_moves() {
        rounds("design", "m=420", "m=420&k=30000", "m=500");
    }

    #[test]
    fn a_monte_carlo_run_starts_afresh_only_when_the_parts_move() {
        rounds("uncertainty", "dm=12", "dm=12&ts_max=0.7", "dm=15");
    }

    #[test]
    fn a_convergence_study_starts_afresh_only_when_the_system_moves() {
        rounds("integrators", "zeta=0.1", "zeta=0.1&euler=0", "zeta=0.3");
    }
}
