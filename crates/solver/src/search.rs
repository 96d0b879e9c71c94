//! One-dimensional searches: the maximum of a unimodal function on an interval.
//!
//! ```
//! use zeta_solver::search::maximise;
//! let (x, fx) = maximise(|x| -(x - 0.3) * (x - 0.3), 0.0, 1.0).unwrap();
//! assert!((x - 0.3).abs() < 1e-9 && fx.abs() < 1e-15);
//! ```

/// Golden-section steps: the bracket shrinks by 0.618 a step, `0.618^90 ≈ 2e-19` of its width.
const GOLDEN_STEPS: usize = 90;

/// `(x, f(x))` at the maximum of `f` on `[lo, hi]` by golden-section search, for `f`
/// unimodal there; the result is within about `1e-9·(hi − lo)` of the true maximiser
/// (the limit √ε of locating a smooth maximum from function values). `None` for an empty
/// or non-finite interval or a non-finite `f` at the result.
pub fn maximise(f: impl Fn(f64) -> f64, lo: f64, hi: f64) -> Option<(f64, f64)> {
    if !(lo.is_finite() && hi.is_finite() && lo < hi) {
        return None;
    }
    let inv_phi = (5f64.sqrt() - 1.0) / 2.0;
    let (mut a, mut b) = (lo, hi);
    let mut c = b - inv_phi * (b - a);
    let mut d = a + inv_phi * (b - a);
    let (mut fc, mut fd) = (f(c), f(d));
    for _ in 0..GOLDEN_STEPS {
        if fc > fd {
            b = d;
            d = c;
            fd = fc;
            c = b - inv_phi * (b - a);
            fc = f(c);
        } else {
            a = c;
            c = d;
            fc = fd;
            d = a + inv_phi * (b - a);
            fd = f(d);
        }
    }
    let x = 0.5 * (a + b);
    let fx = f(x);
    fx.is_finite().then_some((x, fx))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn finds_the_resonant_peak_of_the_frequency_response() {
        // |H(r)| peaks at r = √(1 − 2ζ²) with gain 1/(2ζ√(1 − ζ²)) for ζ < 1/√2.
        for zeta in [0.01, 0.05, 0.1, 0.3, 0.6] {
            let (r, g) = maximise(|r| crate::frf::magnitude(r, zeta), 0.0, 2.0).unwrap();
            let r_exact = (1.0f64 - 2.0 * zeta * zeta).sqrt();
            let g_exact = 1.0 / (2.0 * zeta * (1.0f64 - zeta * zeta).sqrt());
            assert!((r - r_exact).abs() < 1e-7, "ζ = {zeta}: {r} vs {r_exact}");
            assert!((g / g_exact - 1.0).abs() < 1e-12, "ζ = {zeta}");
        }
    }

    #[test]
    fn rejects_bad_intervals() {
        assert_eq!(maximise(|x| x, 1.0, 1.0), None);
        assert_eq!(maximise(|x| x, f64::NAN, 1.0), None);
        assert_eq!(maximise(|_| f64::NAN, 0.0, 1.0), None);
    }
}
