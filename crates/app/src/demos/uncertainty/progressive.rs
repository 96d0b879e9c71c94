//! Progressive Monte Carlo (issue 13): on a page, moved inputs get the first
//! [`COARSE_DRAWS`] draws at once (the same seeded sequence, so they are exactly the first
//! draws of the full run) and the full run a few draws at a time in later short tasks
//! ([`Uncertainty::refine_run`]); the full samples replace the coarse ones only if they were
//! drawn for the inputs still current. Off (native tests, snapshots) the full run happens in
//! the step, as before. The flags and the job live in the state both progressive demos
//! share, `demos/progressive.rs`.

use super::cache::McKey;
use super::{Stopwatch, Uncertainty};
use crate::demos::progressive::StudyJob;
use zeta_solver::design::monte_carlo::{McConfig, McRun, McSamples, MAX_DRAWS};

/// Draws of the coarse run shown while the full one runs.
pub(super) const COARSE_DRAWS: usize = 1_000;

/// Readouts and plots drawn from the coarse run while the full one runs.
pub(super) const PROVISIONAL: [&str; 9] = [
    "yield",
    "zeta_p5",
    "zeta_p95",
    "Q_p5",
    "Q_p95",
    "draws",
    "compute_time",
    "zeta_hist",
    "hist",
];

/// A full run under way: its inputs, configuration, samples so far and the random state.
#[derive(Debug)]
pub(super) struct McJob {
    key: McKey,
    cfg: McConfig,
    run: McRun,
    samples: McSamples,
    /// Compute time so far \[ms\].
    ms: f64,
    /// Whether the samples were drawn elsewhere (the page's worker), the run left as it was.
    taken: bool,
}

impl StudyJob for McJob {
    /// The samples and the compute time \[ms\].
    type Output = (McSamples, f64);

    fn key_text(&self) -> String {
        format!("{:?}", self.key)
    }

    fn advance(&mut self, budget_ms: f64) -> f64 {
        let watch = Stopwatch::start();
        while !self.finished() {
            let upto = self.run.done() + SLICE;
            self.run.advance(&self.cfg, &mut self.samples, upto);
            if watch.elapsed_ms() >= budget_ms {
                break;
            }
        }
        self.ms += watch.elapsed_ms();
        match self.finished() {
            true => 1.0,
            false => self.run.done() as f64 / self.run.total().max(1) as f64,
        }
    }

    fn finished(&self) -> bool {
        self.taken || self.run.finished()
    }

    fn output(&self) -> Self::Output {
        (self.samples.clone(), self.ms)
    }

    fn take_output(&mut self, (samples, ms): Self::Output) -> bool {
        let n = self.run.total();
        let to = &mut self.samples;
        let pairs = [
            (&mut to.zeta, &samples.zeta),
            (&mut to.wn, &samples.wn),
            (&mut to.f0, &samples.f0),
            (&mut to.q, &samples.q),
            (&mut to.bandwidth, &samples.bandwidth),
            (&mut to.settling_time, &samples.settling_time),
        ];
        if pairs.iter().any(|(_, from)| from.len() != n) {
            return false;
        }
        // Into the buffers this job holds (sized once for the largest run), so the page's
        // memory stays as it was.
        for (to, from) in pairs {
            to.clear();
            to.extend_from_slice(from);
        }
        (to.invalid, to.redraws) = (samples.invalid, samples.redraws);
        (self.ms, self.taken) = (ms, true);
        true
    }
}

/// Draws per slice between clock reads.
const SLICE: usize = 100;

impl Uncertainty {
    /// Starts the full run of `key` in the background of the page (see the module docs).
    pub(super) fn start_job(&mut self, key: McKey, cfg: McConfig) {
        self.drop_job();
        // Sized for the largest run once, so the two buffers that take turns never grow
        // again (a page's wasm memory stays flat however the sliders move).
        let mut samples = std::mem::take(&mut self.spare);
        samples.reserve(MAX_DRAWS);
        let run = McRun::start(&cfg, &mut samples);
        self.progress.job = Some(McJob {
            key,
            cfg,
            run,
            samples,
            ms: 0.0,
            taken: false,
        });
    }

    /// Drops the run under way, unseen, keeping its buffers for the next one.
    pub(super) fn drop_job(&mut self) {
        if let Some(job) = self.progress.job.take() {
            self.spare = job.samples;
        }
    }

    /// Continues the pending full run for about `budget_ms`, unless the page's worker
    /// draws it. Returns the fraction done, or `None` when no run is pending here; at 1 the
    /// full samples have replaced the coarse ones.
    pub(super) fn refine_run(&mut self, budget_ms: f64) -> Option<f64> {
        let done = self.progress.refine(budget_ms)?;
        if done < 1.0 {
            return Some(done);
        }
        let job = self.progress.job.take()?;
        // Shown only if drawn for the inputs still current (a step with other inputs drops
        // the job), never as the answer to other inputs.
        if self.key != Some(job.key) {
            self.spare = job.samples;
            return None;
        }
        self.spare = std::mem::replace(&mut self.samples, job.samples);
        self.finish_run(job.ms);
        self.progress.finished();
        self.runs += 1;
        Some(1.0)
    }
}
