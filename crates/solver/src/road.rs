//! Road profiles held as samples: a [`Road`] sampled once on a uniform grid and read back
//! linearly between samples, so that an integrator evaluating the road at every stage pays
//! one interpolation instead of one `sin_cos` per component of a random road.
//!
//! The road height between samples is `u(t) = u_i + (u_{i+1} − u_i)·(t − t_i)/(t_{i+1} − t_i)`
//! (m), its slope `u'(t) = (u_{i+1} − u_i)/(t_{i+1} − t_i)` (m/s); before the first sample
//! and after the last the end height is held (slope 0).
//!
//! ```
//! use zeta_solver::road::SampledRoad;
//! use zeta_solver::two_dof::Road;
//! let bump = Road::Bump { height: 0.05, length: 0.5, speed: 10.0 };
//! let mut table = SampledRoad::default();
//! table.fill_uniform(&bump, 1000.0, 0.1);
//! assert_eq!(table.len(), 101);
//! // Exact at the samples, within h²/8·max|u''| between them.
//! assert_eq!(table.height(0.025), bump.at(0.025).0);
//! assert!((table.height(0.0255) - bump.at(0.0255).0).abs() < 1e-4);
//! ```

use crate::grid::interpolate;
use crate::integrate::System;
use crate::two_dof::{Road, TwoDof};

/// A road given by its heights `u_i` (m) at ascending times `t_i` (s), linear between them.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct SampledRoad {
    t: Vec<f64>,
    u: Vec<f64>,
}

impl SampledRoad {
    /// Replaces the samples by `road` at `t_i = i/rate` for `i = 0 … ⌈t_end·rate⌉` (at least
    /// two samples), `rate` in samples per second. A random road is sampled with its fast
    /// phasor recurrence ([`crate::two_dof::RandomRoad::sample_uniform`]). Reuses the
    /// buffers. A non-positive or non-finite `rate` or `t_end` leaves one sample at `t = 0`.
    pub fn fill_uniform(&mut self, road: &Road, rate: f64, t_end: f64) {
        self.t.clear();
        self.u.clear();
        let steps = (t_end * rate).ceil();
        if !(rate > 0.0 && steps.is_finite() && steps >= 0.0) {
            self.t.push(0.0);
            self.u.push(road.at(0.0).0);
            return;
        }
        let n = steps.max(1.0) as usize;
        self.t.extend((0..=n).map(|i| i as f64 / rate));
        match road {
            Road::Random(r) => {
                self.u.resize(n + 1, 0.0);
                r.sample_uniform(0.0, 1.0 / rate, &mut self.u);
            }
            _ => self.u.extend(self.t.iter().map(|&t| road.at(t).0)),
        }
    }

    /// Replaces the samples by `road` on consecutive segments of equal steps:
    /// `segments = [(t₁, n₁), (t₂, n₂), …]` samples `[0, t₁]` in `n₁` equal intervals, then
    /// `[t₁, t₂]` in `n₂`, and so on (`n ≥ 1`; a segment that does not advance is skipped),
    /// e.g. fine over a short bump and coarse after it. A random road is sampled by its
    /// fast recurrence.
    pub fn fill_segments(&mut self, road: &Road, segments: &[(f64, usize)]) {
        self.t.clear();
        self.u.clear();
        self.t.push(0.0);
        self.u.push(road.at(0.0).0);
        let mut start = 0.0;
        for &(end, n) in segments {
            if !(end.is_finite() && end > start) {
                continue;
            }
            let n = n.max(1);
            let h = (end - start) / n as f64;
            let first = self.t.len();
            self.t.extend((1..n).map(|i| start + i as f64 * h));
            self.t.push(end);
            match road {
                Road::Random(r) => {
                    self.u.resize(self.t.len(), 0.0);
                    r.sample_uniform(start + h, h, &mut self.u[first..]);
                }
                _ => {
                    let (t, u) = (&self.t, &mut self.u);
                    u.extend(t[first..].iter().map(|&t| road.at(t).0));
                }
            }
            start = end;
        }
    }

    /// Number of samples.
    pub fn len(&self) -> usize {
        self.t.len()
    }

    /// Whether there are no samples.
    pub fn is_empty(&self) -> bool {
        self.t.is_empty()
    }

    /// Sample times (s).
    pub fn times(&self) -> &[f64] {
        &self.t
    }

    /// Sampled heights (m).
    pub fn heights(&self) -> &[f64] {
        &self.u
    }

    /// Height `u(t)` (m), linear between samples, end values held; 0 with no samples.
    pub fn height(&self, t: f64) -> f64 {
        interpolate(&self.t, &self.u, t).unwrap_or(0.0)
    }

    /// Slope `u'(t)` (m/s) of the linear interpolant; 0 outside the samples.
    pub fn slope(&self, t: f64) -> f64 {
        let Some(last) = self.t.len().checked_sub(1) else {
            return 0.0;
        };
        if !(t > self.t[0] && t < self.t[last]) {
            return 0.0;
        }
        let i = self.t.partition_point(|&ti| ti <= t);
        let span = self.t[i] - self.t[i - 1];
        if span > 0.0 {
            (self.u[i] - self.u[i - 1]) / span
        } else {
            0.0
        }
    }
}

/// The car on a sampled road: a [`System<4>`] on `[z_s, z_u, z_s', z_u']` with the road
/// `(u, u')` read from the samples (see [`TwoDof::driven`] for the equations).
#[derive(Debug, Clone, Copy)]
pub struct SampledDriven<'a> {
    car: &'a TwoDof,
    road: &'a SampledRoad,
}

impl<'a> SampledDriven<'a> {
    /// `car` on `road`.
    pub fn new(car: &'a TwoDof, road: &'a SampledRoad) -> Self {
        Self { car, road }
    }
}

impl System<4> for SampledDriven<'_> {
    fn rhs(&self, t: f64, y: &[f64; 4], dy: &mut [f64; 4]) {
        let u = self.road.height(t);
        // The slope matters only through tyre damping; skip its search when there is none.
        let du = if self.car.config().c_t == 0.0 {
            0.0
        } else {
            self.road.slope(t)
        };
        self.car.rhs(y, u, du, dy);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::two_dof::{RandomRoad, RandomRoadConfig, TwoDofConfig};

    fn random() -> Road {
        Road::Random(
            RandomRoad::new(RandomRoadConfig {
                components: 32,
                n_min: 0.025,
                n_max: 1.0,
                ..Default::default()
            })
            .unwrap(),
        )
    }

    #[test]
    fn samples_match_the_road_and_interpolate_between() {
        let road = random();
        let mut table = SampledRoad::default();
        table.fill_uniform(&road, 150.0, 2.0);
        assert_eq!(table.len(), 301);
        // The phasor recurrence agrees with direct evaluation (drift ≲ 256·ε per term).
        for (&t, &u) in table.times().iter().zip(table.heights()) {
            assert!((u - road.at(t).0).abs() < 1e-13, "t = {t}");
        }
        let Road::Random(r) = &road else {
            unreachable!()
        };
        let rms = r.variance().sqrt();
        // Between samples: content ≤ 20 Hz sampled at 150 Hz, error ≤ (2π·20/150)²/8 ≈ 9 %
        // of the amplitude of the top component; well within 10 % of the RMS.
        for k in 0..200 {
            let t = 0.003 + 0.01 * f64::from(k);
            assert!((table.height(t) - road.at(t).0).abs() < 0.1 * rms);
        }
        // Slope of the interpolant is the chord slope.
        let (t0, t1) = (table.times()[10], table.times()[11]);
        let chord = (table.heights()[11] - table.heights()[10]) / (t1 - t0);
        assert!((table.slope(0.5 * (t0 + t1)) - chord).abs() < 1e-12 * chord.abs().max(1.0));
        assert_eq!(table.slope(-1.0), 0.0);
    }

    #[test]
    fn the_sampled_system_is_the_solvers_own_at_a_sample() {
        let road = random();
        let mut table = SampledRoad::default();
        table.fill_uniform(&road, 150.0, 2.0);
        let car = TwoDof::new(TwoDofConfig::default()).unwrap();
        let y = [0.01, -0.02, 0.3, -0.1];
        let (mut a, mut b) = ([0.0; 4], [0.0; 4]);
        SampledDriven::new(&car, &table).rhs(0.5, &y, &mut a);
        car.driven(&road).rhs(0.5, &y, &mut b);
        for (x, y) in a.iter().zip(&b) {
            assert!((x - y).abs() < 1e-9 * y.abs().max(1.0));
        }
    }

    #[test]
    fn degenerate_grids_do_not_panic() {
        let mut table = SampledRoad::default();
        assert_eq!(table.height(1.0), 0.0);
        table.fill_uniform(&Road::Step { height: 0.1 }, f64::NAN, 1.0);
        assert_eq!(table.len(), 1);
        // The one sample is u(0) = 0: the kerb comes just after t = 0.
        assert_eq!(table.height(5.0), 0.0);
        table.fill_uniform(&Road::Flat, 100.0, 0.0);
        assert_eq!(table.len(), 2);
    }
}
