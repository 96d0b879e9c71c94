//! Dense LU factorisation with partial pivoting for the small implicit solves.

/// `LU = P·M` of an `N×N` matrix, stored in place; `perm[i]` is the original row of row `i`.
pub(crate) struct Lu<const N: usize> {
    lu: [[f64; N]; N],
    perm: [usize; N],
}

impl<const N: usize> Lu<N> {
    /// Factorises `m`; `None` when a pivot is zero or not finite (singular matrix).
    pub(crate) fn new(mut m: [[f64; N]; N]) -> Option<Self> {
        let mut perm = [0usize; N];
        for (i, p) in perm.iter_mut().enumerate() {
            *p = i;
        }
        for col in 0..N {
            // Largest pivot in this column keeps the multipliers ≤ 1.
            let mut best = col;
            for row in col + 1..N {
                if m[row][col].abs() > m[best][col].abs() {
                    best = row;
                }
            }
            let pivot = m[best][col];
            if pivot == 0.0 || !pivot.is_finite() {
                return None;
            }
            m.swap(col, best);
            perm.swap(col, best);
            for row in col + 1..N {
                let factor = m[row][col] / pivot;
                m[row][col] = factor;
                for k in col + 1..N {
                    m[row][k] -= factor * m[col][k];
                }
            }
        }
        Some(Self { lu: m, perm })
    }

    /// Solves `M·x = b`.
    pub(crate) fn solve(&self, b: &[f64; N]) -> [f64; N] {
        let mut x = [0.0; N];
        for i in 0..N {
            let mut s = b[self.perm[i]];
            for k in 0..i {
                s -= self.lu[i][k] * x[k];
            }
            x[i] = s;
        }
        for i in (0..N).rev() {
            let mut s = x[i];
            for k in i + 1..N {
                s -= self.lu[i][k] * x[k];
            }
            x[i] = s / self.lu[i][i];
        }
        x
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn solves_a_system_that_needs_pivoting() {
        let m = [[0.0, 2.0, 1.0], [1.0, 1.0, 0.0], [3.0, 0.0, 1.0]];
        let x_true = [1.0, -2.0, 0.5];
        let mut b = [0.0; 3];
        for i in 0..3 {
            b[i] = (0..3).map(|j| m[i][j] * x_true[j]).sum();
        }
        let x = Lu::new(m).unwrap().solve(&b);
        for i in 0..3 {
            assert!((x[i] - x_true[i]).abs() < 1e-15);
        }
        assert!(Lu::new([[1.0, 2.0], [2.0, 4.0]]).is_none());
    }
}
