//! Small dense matrices: products and the matrix exponential `e^M`, for exact solutions of
//! linear systems `z' = M·z` (`z(t) = e^{M t}·z(0)`).
//!
//! ```
//! use zeta_solver::expm::{expm, mat_vec};
//! // Harmonic oscillator x'' = −x: e^{Mt} is a rotation.
//! let t = 0.7_f64;
//! let e = expm(&[[0.0, t], [-t, 0.0]]);
//! let z = mat_vec(&e, &[1.0, 0.0]);
//! assert!((z[0] - t.cos()).abs() < 1e-15 && (z[1] + t.sin()).abs() < 1e-15);
//! ```

/// `A·B` for `N×N` matrices.
pub fn mat_mul<const N: usize>(a: &[[f64; N]; N], b: &[[f64; N]; N]) -> [[f64; N]; N] {
    let mut c = [[0.0; N]; N];
    for (ci, ai) in c.iter_mut().zip(a) {
        for (k, &aik) in ai.iter().enumerate() {
            if aik != 0.0 {
                for (cij, bkj) in ci.iter_mut().zip(&b[k]) {
                    *cij += aik * bkj;
                }
            }
        }
    }
    c
}

/// `A·x`.
pub fn mat_vec<const N: usize>(a: &[[f64; N]; N], x: &[f64; N]) -> [f64; N] {
    let mut y = [0.0; N];
    for (yi, ai) in y.iter_mut().zip(a) {
        *yi = ai.iter().zip(x).map(|(a, x)| a * x).sum();
    }
    y
}

/// Largest absolute column sum `‖M‖₁`.
fn norm1<const N: usize>(m: &[[f64; N]; N]) -> f64 {
    (0..N)
        .map(|j| m.iter().map(|row| row[j].abs()).sum::<f64>())
        .fold(0.0, f64::max)
}

/// Most squarings (‖M‖₁ up to 2⁶⁰ is more than any finite model here needs).
const MAX_SQUARINGS: i32 = 60;

/// `e^M` by scaling and squaring: `e^M = (e^{M/2ˢ})^{2ˢ}` with `s` chosen so that
/// `‖M/2ˢ‖₁ ≤ ½`, and `e^{M/2ˢ}` from its Taylor series summed until a term no longer
/// changes the sum (at most 30 terms; the truncation error is then below `ε·‖e^{M/2ˢ}‖`).
/// Relative accuracy is a few `ε·‖M‖` for the matrices of mechanical systems; a non-finite
/// entry gives non-finite entries (never a panic).
pub fn expm<const N: usize>(m: &[[f64; N]; N]) -> [[f64; N]; N] {
    let norm = norm1(m);
    let mut s = 0;
    let mut scale = 1.0;
    while norm * scale > 0.5 && s < MAX_SQUARINGS {
        scale *= 0.5;
        s += 1;
    }
    let mut a = *m;
    for row in a.iter_mut() {
        for v in row.iter_mut() {
            *v *= scale;
        }
    }
    let mut sum = [[0.0; N]; N];
    for (i, row) in sum.iter_mut().enumerate() {
        row[i] = 1.0;
    }
    let mut term = sum;
    for k in 1..=30 {
        term = mat_mul(&term, &a);
        let inv = 1.0 / f64::from(k);
        let mut changed = false;
        for (srow, trow) in sum.iter_mut().zip(term.iter_mut()) {
            for (sv, tv) in srow.iter_mut().zip(trow.iter_mut()) {
                *tv *= inv;
                let before = *sv;
                *sv += *tv;
                changed |= *sv != before;
            }
        }
        if !changed {
            break;
        }
    }
    for _ in 0..s {
        sum = mat_mul(&sum, &sum);
    }
    sum
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn exponential_of_a_diagonal_and_a_jordan_block() {
        let e = expm(&[[-2.0, 0.0], [0.0, 3.0]]);
        assert!((e[0][0] - (-2.0f64).exp()).abs() < 1e-15);
        assert!((e[1][1] / 3.0f64.exp() - 1.0).abs() < 1e-14);
        assert_eq!(e[0][1], 0.0);
        // [[λ, 1], [0, λ]]: e^λ·[[1, 1], [0, 1]].
        let l = -1.5f64;
        let e = expm(&[[l, 1.0], [0.0, l]]);
        assert!((e[0][1] / l.exp() - 1.0).abs() < 1e-14);
        assert!((e[0][0] / l.exp() - 1.0).abs() < 1e-14);
    }

    #[test]
    fn a_stiff_oscillator_over_many_periods_is_still_accurate() {
        // ω = 80 rad/s over 1 s: ‖M‖ = 80, six squarings.
        let w = 80.0f64;
        let e = expm(&[[0.0, 1.0], [-w * w, 0.0]]);
        assert!((e[0][0] - w.cos()).abs() < 1e-12, "{}", e[0][0]);
        assert!((e[0][1] - w.sin() / w).abs() < 1e-13);
    }

    #[test]
    fn non_finite_input_does_not_panic() {
        let e = expm(&[[f64::NAN, 0.0], [0.0, 1.0]]);
        assert!(e[0][0].is_nan());
        let e = expm(&[[f64::INFINITY, 0.0], [0.0, 1.0]]);
        assert!(!e[0][0].is_finite());
    }
}
