//! Monte Carlo tolerance analysis: draw the three components from their tolerances, compute
//! ζ, ω_n, f0, Q, bandwidth and the free-response settling time per draw, then summarise
//! with histograms, percentiles and the yield against a specification.
//!
//! Choices, stated once:
//! - **Uniform** tolerance `x`: value `p·(1 + x·(2U − 1))`, flat on `[p(1 − x), p(1 + x)]`.
//! - **Normal** tolerance `x` is **3σ** (resistor practice: 99.73 % of parts within ±x):
//!   value `p·(1 + (x/3)·Z)`.
//! - **Invalid draws** (a non-positive mass/stiffness/L/C or a negative damping/resistance,
//!   possible with a wide normal tolerance) are re-drawn, up to [`MAX_REDRAWS`] times — a
//!   truncated distribution. A draw still invalid after that is kept as invalid: all its
//!   metrics are NaN and it fails every specification.
//! - The settling time is that of a release from rest (`x0 = 1`, `v0 = 0`) into the
//!   configured band (NaN when the draw does not settle, e.g. zero damping).
//! - Draws are generated in a fixed order from [`Rng`] (component 0, 1, 2 per draw), so the
//!   same seed and settings give bit-identical results on every platform.
//!
//! ```
//! use zeta_solver::design::monte_carlo::{run_into, Distribution, McConfig, McSamples, Tolerance};
//! use zeta_solver::design::sensitivity::Components;
//! use zeta_solver::metrics::SettlingBand;
//! let tol = Tolerance { fraction: 0.05, distribution: Distribution::Uniform };
//! let cfg = McConfig {
//!     design: Components::Electrical { l: 0.5, r: 4.0, cap: 0.02 },
//!     tolerances: [tol; 3],
//!     draws: 1000,
//!     seed: 7,
//!     band: SettlingBand::FREE_DEFAULT,
//! };
//! let mut out = McSamples::default();
//! run_into(&cfg, &mut out);
//! assert_eq!(out.zeta.len(), 1000);
//! // ζ = (R/2)·√(C/L) = 0.4 moves at most by the factor 1.05·√(1.05/0.95) = 1.104.
//! assert!(out.zeta.iter().all(|z| (z - 0.4).abs() < 0.4 * 0.105));
//! ```

use super::rng::Rng;
use super::sensitivity::Components;
use crate::metrics::free::FreeShape;
use crate::metrics::SettlingBand;

/// Largest number of draws [`run_into`] performs.
pub const MAX_DRAWS: usize = 100_000;
/// Re-draws allowed for one component value before the draw is declared invalid.
pub const MAX_REDRAWS: u32 = 32;

/// Shape of a component's tolerance.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Distribution {
    /// Flat on `[p(1 − x), p(1 + x)]`.
    Uniform,
    /// Normal with mean `p` and `3σ = x·p`.
    Normal,
}

/// Tolerance of one component.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Tolerance {
    /// Relative tolerance `x` as a fraction (0.05 for ±5 %); negative values act as 0.
    pub fraction: f64,
    /// Its distribution.
    pub distribution: Distribution,
}

/// Settings of a Monte Carlo run.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct McConfig {
    /// Nominal design (also fixes mechanical or electrical).
    pub design: Components,
    /// Tolerances of the components, in the order of [`Components::values`].
    pub tolerances: [Tolerance; 3],
    /// Number of draws (clamped to [`MAX_DRAWS`]).
    pub draws: usize,
    /// Seed of the generator.
    pub seed: u64,
    /// Settling band for the settling time.
    pub band: SettlingBand,
}

/// Per-draw results, one entry per draw (reusable: vectors are resized, not reallocated,
/// when the draw count is unchanged). NaN where undefined or invalid.
#[derive(Debug, Clone, Default, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct McSamples {
    /// Damping ratio \[-\].
    pub zeta: Vec<f64>,
    /// Natural frequency \[rad/s\].
    pub wn: Vec<f64>,
    /// Natural frequency \[Hz\].
    pub f0: Vec<f64>,
    /// Quality factor \[-\].
    pub q: Vec<f64>,
    /// Half-power bandwidth \[rad/s\].
    pub bandwidth: Vec<f64>,
    /// Free-response settling time from rest \[s\].
    pub settling_time: Vec<f64>,
    /// Draws still invalid after [`MAX_REDRAWS`] re-draws (or whose model could not be
    /// built).
    pub invalid: usize,
    /// Total re-draws performed.
    pub redraws: u64,
}

impl McSamples {
    /// The six sample vectors in the order of a draw's metrics row:
    /// `[ζ, ω_n, f0, Q, bandwidth, settling time]`.
    fn columns_mut(&mut self) -> [&mut Vec<f64>; 6] {
        [
            &mut self.zeta,
            &mut self.wn,
            &mut self.f0,
            &mut self.q,
            &mut self.bandwidth,
            &mut self.settling_time,
        ]
    }

    /// Makes room for runs of up to `draws` draws (at most [`MAX_DRAWS`]) without further
    /// allocation, so a caller that keeps its buffers between runs allocates once.
    pub fn reserve(&mut self, draws: usize) {
        let draws = draws.min(MAX_DRAWS);
        for v in self.columns_mut() {
            v.reserve(draws.saturating_sub(v.len()));
        }
    }
}

/// Whether component `i` of the design may take the value `v`: damping/resistance (index
/// 1) must be ≥ 0, the others > 0.
fn admissible(i: usize, v: f64) -> bool {
    v.is_finite() && if i == 1 { v >= 0.0 } else { v > 0.0 }
}

/// Performs the run described by `cfg`, writing into `out`.
pub fn run_into(cfg: &McConfig, out: &mut McSamples) {
    let mut run = McRun::start(cfg, out);
    run.advance(cfg, out, usize::MAX);
}

/// A Monte Carlo run done a few draws at a time (so a page can spread a large run over
/// several short tasks). [`McRun::start`] sizes `out`; [`McRun::advance`] continues the
/// same random sequence, so a run advanced in any steps to the end gives exactly the
/// samples of [`run_into`], and its first `d` draws are those of a run with `draws = d`.
#[derive(Debug, Clone)]
pub struct McRun {
    rng: Rng,
    /// Draws done so far.
    next: usize,
    /// Draws in the run (`cfg.draws`, at most [`MAX_DRAWS`]).
    total: usize,
}

impl McRun {
    /// Starts the run of `cfg`: resizes every sample vector of `out` to the number of draws
    /// (filled with NaN) and zeroes its counters.
    pub fn start(cfg: &McConfig, out: &mut McSamples) -> Self {
        let total = cfg.draws.min(MAX_DRAWS);
        for v in out.columns_mut() {
            v.clear();
            v.resize(total, f64::NAN);
        }
        out.invalid = 0;
        out.redraws = 0;
        Self {
            rng: Rng::new(cfg.seed),
            next: 0,
            total,
        }
    }

    /// Draws done so far.
    pub fn done(&self) -> usize {
        self.next
    }

    /// Draws in the whole run.
    pub fn total(&self) -> usize {
        self.total
    }

    /// Whether every draw is done.
    pub fn finished(&self) -> bool {
        self.next >= self.total
    }

    /// Continues the run up to draw `upto` (exclusive, capped at the run's size), writing
    /// into the `out` given to [`McRun::start`] with the same `cfg`.
    pub fn advance(&mut self, cfg: &McConfig, out: &mut McSamples, upto: usize) {
        let end = upto.min(self.total);
        let rng = &mut self.rng;
        let nominal = cfg.design.values();
        for d in self.next..end {
            let mut values = [0.0; 3];
            let mut valid = true;
            for (i, ((v, &p), tol)) in values
                .iter_mut()
                .zip(&nominal)
                .zip(&cfg.tolerances)
                .enumerate()
            {
                let x = tol.fraction.max(0.0);
                let mut ok = false;
                for attempt in 0..=MAX_REDRAWS {
                    if attempt > 0 {
                        out.redraws += 1;
                    }
                    let dev = match tol.distribution {
                        Distribution::Uniform => x * (2.0 * rng.uniform() - 1.0),
                        Distribution::Normal => x / 3.0 * rng.normal(),
                    };
                    *v = p * (1.0 + dev);
                    if admissible(i, *v) {
                        ok = true;
                        break;
                    }
                }
                valid &= ok;
            }
            let row = if valid { metrics(cfg, values) } else { None };
            if row.is_none() {
                out.invalid += 1;
            }
            let row = row.unwrap_or([f64::NAN; 6]);
            for (v, val) in out.columns_mut().into_iter().zip(row) {
                if let Some(slot) = v.get_mut(d) {
                    *slot = val;
                }
            }
        }
        self.next = self.next.max(end);
    }
}

/// `[ζ, ω_n, f0, Q, bandwidth, settling time]` of one draw.
fn metrics(cfg: &McConfig, values: [f64; 3]) -> Option<[f64; 6]> {
    let sys = cfg.design.with_values(values).system().ok()?;
    let nan = f64::NAN;
    let ts = FreeShape::new(&sys, 1.0, 0.0)
        .and_then(|s| s.settle(cfg.band))
        .map_or(nan, |s| s.time);
    Some([
        sys.damping_ratio().unwrap_or(nan),
        sys.natural_frequency().unwrap_or(nan),
        sys.natural_frequency_hz().unwrap_or(nan),
        sys.quality_factor().unwrap_or(nan),
        sys.velocity_half_power_bandwidth().unwrap_or(nan),
        ts,
    ])
}

/// Counts of the finite values of `data` in `bins` equal bins over `range` (or, if `None`,
/// over `[min, max]` of the finite data), written into `counts` (resized to `bins`). A value
/// equal to the upper end goes into the last bin; values outside the range are not counted.
/// Returns the range used, `None` when `bins = 0`, the range is invalid or there is no
/// finite data to take a range from. A data range of zero width is widened by ±0.5.
pub fn histogram_into(
    data: &[f64],
    bins: usize,
    range: Option<(f64, f64)>,
    counts: &mut Vec<u64>,
) -> Option<(f64, f64)> {
    counts.clear();
    counts.resize(bins, 0);
    if bins == 0 {
        return None;
    }
    let (lo, hi) = match range {
        Some((lo, hi)) if lo.is_finite() && hi.is_finite() && hi > lo => (lo, hi),
        Some(_) => return None,
        None => {
            let finite = data.iter().copied().filter(|v| v.is_finite());
            let (lo, hi) = finite.fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| {
                (a.min(v), b.max(v))
            });
            if lo > hi {
                return None;
            }
            if lo == hi {
                (lo - 0.5, hi + 0.5)
            } else {
                (lo, hi)
            }
        }
    };
    let scale = bins as f64 / (hi - lo);
    for &v in data {
        if v.is_finite() && v >= lo && v <= hi {
            // `as` saturates; the clamp puts v = hi into the last bin.
            let b = (((v - lo) * scale) as usize).min(bins - 1);
            if let Some(c) = counts.get_mut(b) {
                *c += 1;
            }
        }
    }
    Some((lo, hi))
}

/// Percentiles `ps` (fractions in `[0, 1]`: 0.05 for p5) of the finite values of `data`,
/// written into `out` (entries beyond `ps.len()` untouched). Interpolation is linear between
/// order statistics at rank `h = p·(n − 1)` (Hyndman–Fan type 7, NumPy's default "linear"):
/// `x_(⌊h⌋) + (h − ⌊h⌋)·(x_(⌊h⌋+1) − x_(⌊h⌋))`. `scratch` holds the sorted copy and is reused.
/// NaN for an out-of-range `p` or when there is no finite data.
pub fn percentiles_into(data: &[f64], ps: &[f64], scratch: &mut Vec<f64>, out: &mut [f64]) {
    scratch.clear();
    scratch.extend(data.iter().copied().filter(|v| v.is_finite()));
    scratch.sort_unstable_by(f64::total_cmp);
    let n = scratch.len();
    for (o, &p) in out.iter_mut().zip(ps) {
        *o = if n == 0 || !(0.0..=1.0).contains(&p) {
            f64::NAN
        } else {
            let h = p * (n - 1) as f64;
            let i = (h.floor() as usize).min(n - 1);
            let lo = scratch.get(i).copied().unwrap_or(f64::NAN);
            let hi = scratch.get(i + 1).copied().unwrap_or(lo);
            lo + (h - i as f64) * (hi - lo)
        };
    }
}

/// A specification for the yield; `None` fields are not checked. Ranges are inclusive.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct Spec {
    /// Allowed damping ratio `[lo, hi]`.
    pub zeta: Option<(f64, f64)>,
    /// Allowed natural frequency `[lo, hi]` \[Hz\].
    pub f0: Option<(f64, f64)>,
    /// Allowed quality factor `[lo, hi]`.
    pub q: Option<(f64, f64)>,
    /// Longest allowed settling time \[s\].
    pub max_settling_time: Option<f64>,
}

/// Yield \[%\]: the percentage of draws meeting `spec`. A draw with an undefined (NaN)
/// metric fails any check on that metric; invalid draws fail everything. 0 when there are
/// no draws.
pub fn yield_percent(samples: &McSamples, spec: &Spec) -> f64 {
    let n = samples.zeta.len();
    if n == 0 {
        return 0.0;
    }
    let within = |v: f64, r: Option<(f64, f64)>| r.is_none_or(|(lo, hi)| v >= lo && v <= hi);
    let mut pass = 0usize;
    for i in 0..n {
        let get = |v: &Vec<f64>| v.get(i).copied().unwrap_or(f64::NAN);
        let z = get(&samples.zeta);
        let ok = !z.is_nan()
            && within(z, spec.zeta)
            && within(get(&samples.f0), spec.f0)
            && within(get(&samples.q), spec.q)
            && spec
                .max_settling_time
                .is_none_or(|t| get(&samples.settling_time) <= t);
        pass += usize::from(ok);
    }
    100.0 * pass as f64 / n as f64
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn histogram_counts_every_finite_value_in_range_once() {
        let data = [0.0, 0.5, 1.0, 1.0, f64::NAN, 2.0, 5.0];
        let mut counts = Vec::new();
        let r = histogram_into(&data, 4, Some((0.0, 2.0)), &mut counts).unwrap();
        assert_eq!(r, (0.0, 2.0));
        assert_eq!(counts, vec![1, 1, 2, 1]);
        assert_eq!(
            histogram_into(&data, 5, None, &mut counts),
            Some((0.0, 5.0))
        );
        assert_eq!(counts.iter().sum::<u64>(), 6);
        assert_eq!(
            histogram_into(&[3.0, 3.0], 2, None, &mut counts),
            Some((2.5, 3.5))
        );
        assert_eq!(histogram_into(&[f64::NAN], 2, None, &mut counts), None);
    }

    #[test]
    fn percentiles_interpolate_linearly_like_numpy() {
        // numpy.percentile([1, 2, 3, 4], [0, 5, 50, 95, 100]) = [1, 1.15, 2.5, 3.85, 4].
        let mut scratch = Vec::new();
        let mut out = [0.0; 6];
        percentiles_into(
            &[4.0, 1.0, 3.0, 2.0, f64::NAN],
            &[0.0, 0.05, 0.5, 0.95, 1.0, 1.5],
            &mut scratch,
            &mut out,
        );
        let expect = [1.0, 1.15, 2.5, 3.85, 4.0];
        for (o, e) in out.iter().zip(expect) {
            assert!((o - e).abs() < 1e-12, "{out:?}");
        }
        assert!(out[5].is_nan());
    }

    /// An RLC design with every tolerance `fraction` under `distribution`.
    fn rlc(fraction: f64, distribution: Distribution, draws: usize, seed: u64) -> McConfig {
        let tol = Tolerance {
            fraction,
            distribution,
        };
        McConfig {
            design: Components::Electrical {
                l: 0.5,
                r: 4.0,
                cap: 0.02,
            },
            tolerances: [tol; 3],
            draws,
            seed,
            band: SettlingBand::FREE_DEFAULT,
        }
    }

    #[test]
    fn a_run_advanced_in_steps_equals_the_run_done_at_once() {
        let cfg = rlc(0.3, Distribution::Normal, 777, 11);
        let mut whole = McSamples::default();
        run_into(&cfg, &mut whole);
        let mut steps = McSamples::default();
        let mut run = McRun::start(&cfg, &mut steps);
        for upto in [1, 100, 100, 400, 5_000] {
            run.advance(&cfg, &mut steps, upto);
        }
        assert!(run.finished() && run.done() == 777 && run.total() == 777);
        let bits = |s: &McSamples| {
            [&s.zeta, &s.wn, &s.f0, &s.q, &s.bandwidth, &s.settling_time]
                .map(|v| v.iter().map(|x| x.to_bits()).collect::<Vec<_>>())
        };
        assert_eq!(bits(&whole), bits(&steps));
        assert_eq!(
            (whole.invalid, whole.redraws),
            (steps.invalid, steps.redraws)
        );
        // The first draws of a long run are a short run with the same seed.
        let mut short = McSamples::default();
        run_into(&McConfig { draws: 100, ..cfg }, &mut short);
        assert_eq!(bits(&short)[0][..], bits(&whole)[0][..100]);
    }

    #[test]
    fn reserved_buffers_take_any_run_up_to_the_reservation_without_moving() {
        let cfg = rlc(0.1, Distribution::Uniform, 3_000, 5);
        let mut s = McSamples::default();
        s.reserve(3_000);
        let place = |s: &McSamples| {
            [&s.zeta, &s.wn, &s.f0, &s.q, &s.bandwidth, &s.settling_time]
                .map(|v| (v.as_ptr(), v.capacity()))
        };
        let before = place(&s);
        assert!(before.iter().all(|&(_, cap)| cap >= 3_000));
        for draws in [3_000, 10, 2_999] {
            run_into(&McConfig { draws, ..cfg }, &mut s);
            assert_eq!(s.zeta.len(), draws);
            assert_eq!(place(&s), before, "{draws} draws moved a buffer");
        }
        // Capped at the largest run there can be.
        let mut big = McSamples::default();
        big.reserve(usize::MAX);
        assert!(big.q.capacity() >= MAX_DRAWS && big.q.capacity() < 2 * MAX_DRAWS);
    }
}
