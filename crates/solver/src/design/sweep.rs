//! Sweeps for the design explorer: free-response metrics against ζ, the ζ that settles
//! fastest, and (k, c) maps of a quarter car with a ride-comfort figure.
//!
//! **Settling time against ζ** is piecewise smooth with downward jumps: each time an
//! extremum of the free response drops inside the band as ζ grows, the settling time jumps
//! from just after that extremum to the earlier crossing before it. Its minimum is therefore
//! usually the limit from one side of a jump (for a release from rest and a 5 % band,
//! `ζ → 0.690⁺`), which a grid alone only finds to the grid step.
//! [`fastest_settling_zeta`] refines the best grid point: if a neighbour lies on another
//! smooth piece (the number of extrema outside the band differs), the jump between them is
//! located by bisection on that piece number, and the minimum is then sought on the best
//! point's own piece only, by golden-section search up to the jump. Pieces narrower than the
//! grid step can be missed; the result is exact on the piece it reports.
//!
//! **Comfort.** The road's vertical *velocity* is white noise (displacement PSD ∝ n⁻², the
//! ISO 8608 shape). For the one-mass quarter car `m·x'' + c·(x' − u') + k·(x − u) = 0` the
//! body acceleration per road velocity is `H(s) = s·(cs + k)/(ms² + cs + k)`, which tends to
//! `c/m` at high frequency: the damper passes white velocity straight into the body and the
//! acceleration variance is infinite for any `c > 0`. In the real car the tyre cuts the
//! input off above wheel hop, so the road velocity is modelled as white noise of intensity
//! `q` (autocorrelation `q·δ(τ)`, two-sided PSD `q/2π` per rad/s) passed through a
//! first-order low-pass at `ω_c`. See [`body_acceleration_rms`] for the exact variance.
//!
//! ```
//! use zeta_solver::design::sweep::{fastest_settling_zeta, ZetaSweepConfig};
//! let cfg = ZetaSweepConfig::release_from_rest(1.0);
//! let best = fastest_settling_zeta(&cfg, 0.3, 1.5, 200).unwrap();
//! // Release from rest, 5 % band: the first rebound peak touches the band at
//! // ζ = ln 20 / √(π² + ln² 20) = 0.6901.
//! assert!((best.zeta - 0.690_106).abs() < 1e-5);
//! assert!(best.at_jump);
//! ```

use crate::error::{positive, ModelError};
use crate::metrics::free::{FreeShape, Settling};
use crate::metrics::SettlingBand;
use crate::model::SecondOrder;
use crate::two_dof::IsoClass;

/// Initial condition, natural frequency and band for sweeps over ζ.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ZetaSweepConfig {
    /// Natural frequency `ω_n` \[rad/s\]; settling times scale as `1/ω_n`.
    pub wn: f64,
    /// Initial displacement (any unit; metrics are relative to it).
    pub x0: f64,
    /// Initial velocity (unit of `x0` per s).
    pub v0: f64,
    /// Settling band as a fraction of `|x0|`.
    pub band: SettlingBand,
}

impl ZetaSweepConfig {
    /// Release from rest (`x0 = 1`, `v0 = 0`) at `ω_n = wn` with the 5 % band.
    pub fn release_from_rest(wn: f64) -> Self {
        Self {
            wn,
            x0: 1.0,
            v0: 0.0,
            band: SettlingBand::FREE_DEFAULT,
        }
    }

    fn settle(&self, zeta: f64) -> Option<(Settling, FreeShape)> {
        let sys = SecondOrder::from_natural(self.wn, zeta).ok()?;
        let shape = FreeShape::new(&sys, self.x0, self.v0)?;
        Some((shape.settle(self.band)?, shape))
    }
}

/// Reusable output of [`sweep_zeta_into`]; NaN where a metric is undefined (ζ ≤ 0).
#[derive(Debug, Clone, Default, PartialEq)]
pub struct ZetaCurves {
    /// Free-response settling time \[s\] per ζ.
    pub settling_time: Vec<f64>,
    /// Peak rebound as a fraction of `|x0|` \[-\] per ζ.
    pub peak_rebound: Vec<f64>,
}

/// Settling time and peak rebound for each ζ in `zetas`, written into `out` (whose vectors
/// are resized to `zetas.len()`, reallocating only when they grow).
pub fn sweep_zeta_into(zetas: &[f64], cfg: &ZetaSweepConfig, out: &mut ZetaCurves) {
    out.settling_time.resize(zetas.len(), f64::NAN);
    out.peak_rebound.resize(zetas.len(), f64::NAN);
    let rows = out
        .settling_time
        .iter_mut()
        .zip(out.peak_rebound.iter_mut());
    for ((ts, pr), &zeta) in rows.zip(zetas) {
        match cfg.settle(zeta) {
            Some((s, shape)) => {
                *ts = s.time;
                *pr = shape.rebound().0;
            }
            None => {
                *ts = f64::NAN;
                *pr = f64::NAN;
            }
        }
    }
}

/// The ζ of fastest settling found by [`fastest_settling_zeta`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ZetaOptimum {
    /// Damping ratio \[-\].
    pub zeta: f64,
    /// Settling time there \[s\].
    pub settling_time: f64,
    /// Whether the optimum is the one-sided limit at a jump (then `zeta` is within
    /// `1e-12·ζ` of the jump, on the side of the smaller settling time).
    pub at_jump: bool,
}

/// Bisection steps locating a jump: `2^-64` of a grid step is below double precision.
const JUMP_BISECTIONS: usize = 64;
/// Golden-section steps: `0.618^80 ≈ 2e-17` of the starting interval.
const GOLDEN_STEPS: usize = 80;

/// The ζ in `[lo, hi]` (`0 < lo < hi`) with the shortest settling time: an `n`-point grid
/// (`n ≥ 3`), then local refinement as described in the module docs. `None` for an invalid
/// range or when nothing settles.
pub fn fastest_settling_zeta(
    cfg: &ZetaSweepConfig,
    lo: f64,
    hi: f64,
    n: usize,
) -> Option<ZetaOptimum> {
    if !(lo > 0.0 && hi > lo && hi.is_finite()) || n < 3 {
        return None;
    }
    let step = (hi - lo) / (n - 1) as f64;
    let at = |i: usize| if i + 1 == n { hi } else { lo + step * i as f64 };
    let mut best: Option<(usize, Settling)> = None;
    for i in 0..n {
        if let Some((s, _)) = cfg.settle(at(i)) {
            if best.is_none_or(|(_, b)| s.time < b.time) {
                best = Some((i, s));
            }
        }
    }
    let (ib, sb) = best?;
    let mut out = ZetaOptimum {
        zeta: at(ib),
        settling_time: sb.time,
        at_jump: false,
    };
    let neighbours = [ib.checked_sub(1), (ib + 1 < n).then_some(ib + 1)];
    for j in neighbours.into_iter().flatten() {
        let (zb, zj) = (at(ib), at(j));
        let same_piece = |z: f64| cfg.settle(z).is_some_and(|(s, _)| s.piece == sb.piece);
        // Shrink [zb, far] to the part of the neighbour interval on the best point's piece.
        let (mut inside, mut outside) = (zb, zj);
        let jump = !same_piece(zj);
        if jump {
            for _ in 0..JUMP_BISECTIONS {
                let mid = 0.5 * (inside + outside);
                if same_piece(mid) {
                    inside = mid;
                } else {
                    outside = mid;
                }
            }
        }
        if let Some((z, t)) = golden_min(|z| cfg.settle(z).map(|(s, _)| s.time), zb, inside) {
            let near_jump = jump && (z - inside).abs() <= 1e-9 * (inside - zb).abs();
            let candidate = if near_jump {
                let t_edge = cfg.settle(inside).map_or(f64::INFINITY, |(s, _)| s.time);
                (inside, t_edge.min(t), true)
            } else {
                (z, t, false)
            };
            if candidate.1 < out.settling_time {
                out = ZetaOptimum {
                    zeta: candidate.0,
                    settling_time: candidate.1,
                    at_jump: candidate.2,
                };
            }
        }
    }
    Some(out)
}

/// Golden-section minimum of `f` between `a` and `b` (either order); `None` if `f` is
/// undefined at the probe points. Exact for a unimodal `f`; for a monotone `f` it converges
/// to the lower end.
fn golden_min(f: impl Fn(f64) -> Option<f64>, a: f64, b: f64) -> Option<(f64, f64)> {
    const INV_PHI: f64 = 0.618_033_988_749_894_9;
    let (mut a, mut b) = (a, b);
    let mut c = b - INV_PHI * (b - a);
    let mut d = a + INV_PHI * (b - a);
    let (mut fc, mut fd) = (f(c)?, f(d)?);
    for _ in 0..GOLDEN_STEPS {
        if fc < fd {
            b = d;
            d = c;
            fd = fc;
            c = b - INV_PHI * (b - a);
            fc = f(c)?;
        } else {
            a = c;
            c = d;
            fc = fd;
            d = a + INV_PHI * (b - a);
            fd = f(d)?;
        }
    }
    Some(if fc < fd { (c, fc) } else { (d, fd) })
}

/// Random road for the comfort metric: road vertical velocity = white noise of intensity
/// `q` through a first-order low-pass at `cutoff` (see the module docs).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RoadInput {
    q: f64,
    cutoff: f64,
}

impl RoadInput {
    /// Road-velocity intensity `q` \[m²/s\] (autocorrelation `q·δ(τ)`) and input cutoff
    /// `ω_c` \[rad/s\] (the tyre's low-pass; about wheel hop, 2π·10 Hz, for a car).
    pub fn new(q: f64, cutoff: f64) -> Result<Self, ModelError> {
        let q = positive("road velocity intensity q", "m²/s", q)?;
        let cutoff = positive("road input cutoff ω_c", "rad/s", cutoff)?;
        Ok(Self { q, cutoff })
    }

    /// From ISO 8608: displacement PSD `G_d(n) = G_d(n0)·(n/n0)⁻²` (one-sided, `n0 = 0.1`
    /// cycle/m; `G_d(n0)` \[m³\] is 16e-6 for class A, 64e-6 B, 256e-6 C, 1024e-6 D) driven
    /// at `speed` \[m/s\]. The road velocity then has the constant one-sided PSD
    /// `G_v = 4π²·G_d(n0)·n0²·V` per Hz, i.e. `q = G_v/2 = 2π²·G_d(n0)·n0²·V`.
    pub fn iso8608(gd_n0: f64, speed: f64, cutoff: f64) -> Result<Self, ModelError> {
        let gd = positive("ISO 8608 roughness G_d(n0)", "m³", gd_n0)?;
        let v = positive("vehicle speed", "m/s", speed)?;
        let n0 = 0.1;
        Self::new(
            2.0 * std::f64::consts::PI.powi(2) * gd * n0 * n0 * v,
            cutoff,
        )
    }

    /// [`RoadInput::iso8608`] for an ISO 8608 class, with the class's `G_d(n0)` from
    /// [`IsoClass::g_d_n0`] (the one table of road classes).
    pub fn iso_class(class: IsoClass, speed: f64, cutoff: f64) -> Result<Self, ModelError> {
        Self::iso8608(class.g_d_n0(), speed, cutoff)
    }

    /// Intensity `q` \[m²/s\].
    pub fn intensity(&self) -> f64 {
        self.q
    }

    /// Cutoff `ω_c` \[rad/s\].
    pub fn cutoff(&self) -> f64 {
        self.cutoff
    }
}

/// RMS body acceleration \[m/s²\] of the quarter car (`m` \[kg\], `c` \[N·s/m\], `k` \[N/m\])
/// on `road`; `None` unless `m, c, k > 0` and finite.
///
/// Derivation. With the input filter, road velocity `V = ω_c/(s + ω_c)·Ξ`, and the body
/// acceleration per unit white noise is
/// `H(s) = ω_c·s·(cs + k)/((ms² + cs + k)(s + ω_c)) = (b2·s² + b1·s)/(a3·s³ + a2·s² + a1·s + a0)`
/// with `b2 = ω_c·c`, `b1 = ω_c·k`, `a3 = m`, `a2 = c + m·ω_c`, `a1 = k + c·ω_c`,
/// `a0 = k·ω_c`. Its variance `σ² = q·(1/2π)∫|H(jω)|²dω` is the steady solution of the
/// 3-state Lyapunov equation `AP + PAᵀ + q·BBᵀ = 0` of any realisation of `H`; for a cubic
/// denominator that solution reduces to the classical closed form
/// `(1/2π)∫|H|²dω = (b2²·a0·a1 + (b1² − 2·b0·b2)·a0·a3 + b0²·a2·a3) / (2·a0·a3·(a1·a2 − a0·a3))`,
/// here with `b0 = 0` and `a1·a2 − a0·a3 = c·(k + c·ω_c + m·ω_c²)`:
///
/// `σ² = q·ω_c²·(c²·(k + c·ω_c) + m·k²) / (2·m·c·(k + c·ω_c + m·ω_c²))`.
///
/// Checks: `σ² → ∞` as `c → 0` (undamped resonance) and grows like `q·ω_c·c²/(2m²)` as
/// `ω_c → ∞` (the divergence the filter removes). The tests compare it with numerical
/// integration of `|H(jω)|²·q/2π` to 1e-6.
pub fn body_acceleration_rms(m: f64, c: f64, k: f64, road: &RoadInput) -> Option<f64> {
    if !(m > 0.0 && c > 0.0 && k > 0.0 && m.is_finite() && c.is_finite() && k.is_finite()) {
        return None;
    }
    let wc = road.cutoff;
    let num = wc * wc * (c * c * (k + c * wc) + m * k * k);
    let den = 2.0 * m * c * (k + c * wc + m * wc * wc);
    let var = road.q * num / den;
    var.is_finite().then(|| var.sqrt())
}

/// Peak displacement transmissibility `max_r |X/U|` \[-\] at damping ratio `ζ > 0`: the
/// value of [`base::peak_transmissibility`](crate::base::peak_transmissibility), at
/// `r² = (√(1 + 8ζ²) − 1)/(4ζ²)` (where `d|X/U|²/dr = 0`). `None` for `ζ ≤ 0` (unbounded)
/// or an infinite ζ.
pub fn peak_transmissibility(zeta: f64) -> Option<f64> {
    if !zeta.is_finite() {
        return None;
    }
    crate::base::peak_transmissibility(zeta).map(|peak| peak.gain)
}

/// Settings of [`sweep_kc_into`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct KcSweepConfig {
    /// Sprung mass `m` \[kg\].
    pub mass: f64,
    /// Settling band for a release from rest, fraction of the initial displacement.
    pub band: SettlingBand,
    /// Road for the comfort metric.
    pub road: RoadInput,
}

/// Reusable output of [`sweep_kc_into`]: one value per grid point, row-major with `c`
/// along rows: index `i_c·k.len() + i_k`. NaN where undefined.
#[derive(Debug, Clone, Default, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct KcMaps {
    /// Settling time of a release from rest \[s\].
    pub settling_time: Vec<f64>,
    /// Peak rebound of a release from rest, fraction of the initial displacement \[-\].
    pub peak_rebound: Vec<f64>,
    /// RMS body acceleration on the configured road \[m/s²\].
    pub accel_rms: Vec<f64>,
    /// Peak displacement transmissibility \[-\].
    pub peak_transmissibility: Vec<f64>,
    /// Damping ratio `c/(2√(km))` \[-\].
    pub zeta: Vec<f64>,
}

impl KcMaps {
    fn resize(&mut self, n: usize) {
        for v in [
            &mut self.settling_time,
            &mut self.peak_rebound,
            &mut self.accel_rms,
            &mut self.peak_transmissibility,
            &mut self.zeta,
        ] {
            v.resize(n, f64::NAN);
        }
    }
}

/// Fills `out` with the metrics of the quarter car of mass `cfg.mass` over the grid
/// `k_axis × c_axis` (\[N/m\] × \[N·s/m\]). Vectors are resized to the grid size, which
/// reallocates only when the grid grows. Invalid points (`k ≤ 0`, `c ≤ 0`, non-finite) are NaN.
pub fn sweep_kc_into(k_axis: &[f64], c_axis: &[f64], cfg: &KcSweepConfig, out: &mut KcMaps) {
    sweep_kc_start(k_axis, c_axis, out);
    sweep_kc_rows(k_axis, c_axis, 0..c_axis.len(), cfg, out);
}

/// Prepares `out` for a sweep over `k_axis × c_axis` done a few rows at a time with
/// [`sweep_kc_rows`] (so a page can spread a large sweep over several short tasks): resizes
/// every map to the grid size and fills it with NaN.
pub fn sweep_kc_start(k_axis: &[f64], c_axis: &[f64], out: &mut KcMaps) {
    let n = k_axis.len().saturating_mul(c_axis.len());
    out.resize(n);
    for v in [
        &mut out.settling_time,
        &mut out.peak_rebound,
        &mut out.accel_rms,
        &mut out.peak_transmissibility,
        &mut out.zeta,
    ] {
        v.fill(f64::NAN);
    }
}

/// Fills rows `rows` (indices into `c_axis`) of a sweep started with [`sweep_kc_start`].
/// Rows outside the grid are ignored. Doing every row, in any order and any grouping,
/// gives exactly the maps of [`sweep_kc_into`].
pub fn sweep_kc_rows(
    k_axis: &[f64],
    c_axis: &[f64],
    rows: std::ops::Range<usize>,
    cfg: &KcSweepConfig,
    out: &mut KcMaps,
) {
    let m = cfg.mass;
    let nk = k_axis.len();
    for (row, &c) in c_axis.iter().enumerate().take(rows.end).skip(rows.start) {
        for (col, &k) in k_axis.iter().enumerate() {
            let idx = row * nk + col;
            let point = point_metrics(m, c, k, cfg);
            for (v, val) in [
                (&mut out.settling_time, point[0]),
                (&mut out.peak_rebound, point[1]),
                (&mut out.accel_rms, point[2]),
                (&mut out.peak_transmissibility, point[3]),
                (&mut out.zeta, point[4]),
            ] {
                if let Some(slot) = v.get_mut(idx) {
                    *slot = val;
                }
            }
        }
    }
}

/// `[settling, rebound, accel rms, peak transmissibility, ζ]` at one grid point.
fn point_metrics(m: f64, c: f64, k: f64, cfg: &KcSweepConfig) -> [f64; 5] {
    let nan = [f64::NAN; 5];
    if !(c > 0.0 && k > 0.0) {
        return nan;
    }
    let Ok(sys) = SecondOrder::mechanical(m, c, k) else {
        return nan;
    };
    let zeta = sys.damping_ratio().unwrap_or(f64::NAN);
    let (ts, rebound) = match FreeShape::new(&sys, 1.0, 0.0) {
        Some(shape) => (
            shape.settle(cfg.band).map_or(f64::NAN, |s| s.time),
            shape.rebound().0,
        ),
        None => (f64::NAN, f64::NAN),
    };
    [
        ts,
        rebound,
        body_acceleration_rms(m, c, k, &cfg.road).unwrap_or(f64::NAN),
        peak_transmissibility(zeta).unwrap_or(f64::NAN),
        zeta,
    ]
}

/// Iso-ζ line in the (k, c) plane: `c_out[i] = 2ζ·√(k_i·m)` \[N·s/m\] for each `k_i` in
/// `k_axis` \[N/m\] (NaN where `k_i < 0`), so `(k_i, c_out[i])` is the polyline. Extra
/// entries of the longer slice are left alone. Allocation-free.
pub fn iso_zeta_line_into(zeta: f64, mass: f64, k_axis: &[f64], c_out: &mut [f64]) {
    for (c, &k) in c_out.iter_mut().zip(k_axis) {
        *c = if k >= 0.0 {
            2.0 * zeta * (k * mass).sqrt()
        } else {
            f64::NAN
        };
    }
}

/// Spring rate \[N/m\] on the iso-ζ line through damper rate `c` \[N·s/m\]: the inverse
/// of [`iso_zeta_line_into`], `k = (c/(2ζ))²/m`. `None` unless `ζ > 0`, `m > 0` and the
/// result is finite.
pub fn iso_zeta_stiffness(zeta: f64, mass: f64, c: f64) -> Option<f64> {
    let half = c / (2.0 * zeta);
    let k = half * half / mass;
    (zeta > 0.0 && mass > 0.0 && k.is_finite()).then_some(k)
}

/// The part of the iso-ζ line `c = 2ζ√(km)` inside the map `k ∈ [k0, k1]`, `c ∈ [c0, c1]`:
/// the spring-rate interval `(max(k0, k(c0)), min(k1, k(c1)))` \[N/m\], with `k(c)` from
/// [`iso_zeta_stiffness`]. `None` when the line misses the map.
pub fn iso_zeta_span(
    zeta: f64,
    mass: f64,
    (k0, k1): (f64, f64),
    (c0, c1): (f64, f64),
) -> Option<(f64, f64)> {
    let ka = iso_zeta_stiffness(zeta, mass, c0)?.max(k0);
    let kb = iso_zeta_stiffness(zeta, mass, c1)?.min(k1);
    (ka < kb).then_some((ka, kb))
}

/// Peak rebound of a release from rest (`x₀ ≠ 0`, `v₀ = 0`) as a fraction of `x₀` \[-\]:
/// `e^(−πζ/√(1−ζ²))` for `0 ≤ ζ < 1`, the textbook step overshoot, reached at `t = π/ω_d`.
/// `None` outside `[0, 1)` (no rebound when critically or over-damped, growth below 0).
pub fn rebound_from_rest(zeta: f64) -> Option<f64> {
    (0.0..1.0)
        .contains(&zeta)
        .then(|| (-std::f64::consts::PI * zeta / (1.0 - zeta * zeta).sqrt()).exp())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::base::transmissibility;

    #[test]
    fn peak_transmissibility_is_the_maximum_over_frequency() {
        for &zeta in &[0.05, 0.2, 0.5, 1.0, 2.0] {
            let peak = peak_transmissibility(zeta).unwrap();
            let brute = (1..200_000)
                .map(|i| transmissibility(i as f64 * 2e-5, zeta))
                .fold(0.0, f64::max);
            assert!(
                peak >= brute && peak - brute < 1e-8 * peak,
                "ζ={zeta}: {peak} vs {brute}"
            );
        }
        assert!(peak_transmissibility(0.0).is_none());
    }

    #[test]
    fn road_input_is_validated() {
        assert!(RoadInput::new(-1.0, 60.0).is_err());
        assert!(RoadInput::iso8608(64e-6, 0.0, 60.0).is_err());
        // Class B at 20 m/s: q = 2π²·64e-6·0.01·20 = 2.5266e-4 m²/s.
        let r = RoadInput::iso8608(64e-6, 20.0, 60.0).unwrap();
        assert!(
            (r.intensity() - 2.0 * std::f64::consts::PI.powi(2) * 64e-6 * 0.01 * 20.0).abs()
                < 1e-18
        );
    }

    #[test]
    fn a_sweep_done_in_rows_equals_the_sweep_done_at_once() {
        let k: Vec<f64> = (0..7).map(|i| 5_000.0 + 9_000.0 * i as f64).collect();
        let c: Vec<f64> = (0..6).map(|i| 200.0 + 1_500.0 * i as f64).collect();
        let cfg = KcSweepConfig {
            mass: 300.0,
            band: SettlingBand::new(0.05).unwrap(),
            road: RoadInput::new(1e-4, 60.0).unwrap(),
        };
        let mut whole = KcMaps::default();
        sweep_kc_into(&k, &c, &cfg, &mut whole);
        let mut parts = KcMaps::default();
        sweep_kc_start(&k, &c, &mut parts);
        for rows in [4..6, 0..1, 1..4, 9..12] {
            sweep_kc_rows(&k, &c, rows, &cfg, &mut parts);
        }
        let bits = |m: &KcMaps| {
            [
                &m.settling_time,
                &m.peak_rebound,
                &m.accel_rms,
                &m.peak_transmissibility,
                &m.zeta,
            ]
            .map(|v| v.iter().map(|x| x.to_bits()).collect::<Vec<_>>())
        };
        assert_eq!(bits(&whole), bits(&parts));
    }
}
