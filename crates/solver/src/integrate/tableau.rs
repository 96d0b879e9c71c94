//! Every coefficient of every method, in one place, as exact rational constants.
//!
//! Butcher-tableau notation: stage `i` is evaluated at `t + cᵢ·h` on
//! `y + h·Σⱼ aᵢⱼ·kⱼ`, and the step is `y + h·Σᵢ bᵢ·kᵢ`.
//!
//! ```
//! use zeta_solver::integrate::tableau::{rk4, dopri5};
//! // Weights of a consistent method sum to one.
//! assert!((rk4::B.iter().sum::<f64>() - 1.0).abs() < 1e-15);
//! assert!((dopri5::B.iter().sum::<f64>() - 1.0).abs() < 1e-15);
//! ```

/// Heun's method (explicit trapezoid, RK2): `c = [0, 1]`, `a₂₁ = 1`, `b = [½, ½]`.
pub mod heun {
    /// Weights `b₁ = b₂ = ½`.
    pub const B: [f64; 2] = [0.5, 0.5];
}

/// Classical fourth-order Runge–Kutta: `c = [0, ½, ½, 1]`, `a₂₁ = a₃₂ = ½`, `a₄₃ = 1`,
/// `b = [1/6, 1/3, 1/3, 1/6]`.
pub mod rk4 {
    /// Stage times `cᵢ` (fractions of `h`).
    pub const C: [f64; 4] = [0.0, 0.5, 0.5, 1.0];
    /// Weights `bᵢ`.
    pub const B: [f64; 4] = [1.0 / 6.0, 1.0 / 3.0, 1.0 / 3.0, 1.0 / 6.0];
}

/// Trapezoidal rule (implicit, A-stable): `y₁ = y₀ + h·(θ·f₀ + θ·f₁)` with `θ = ½`.
pub mod trapezoid {
    /// The weight `θ = ½` of each end point.
    pub const THETA: f64 = 0.5;
}

/// Dormand–Prince 5(4) (Dormand & Prince 1980, J. Comput. Appl. Math. 6, 19–26), with the
/// 4th-order continuous extension of Shampine (1986, Math. Comp. 46, 135–150) as used in
/// Hairer–Nørsett–Wanner's DOPRI5. Seven stages, the seventh is the first of the next
/// step (FSAL: first same as last).
pub mod dopri5 {
    /// Stage times `c₂ … c₆` (`c₁ = 0`, `c₇ = 1`).
    pub const C2: f64 = 1.0 / 5.0;
    /// See [`C2`].
    pub const C3: f64 = 3.0 / 10.0;
    /// See [`C2`].
    pub const C4: f64 = 4.0 / 5.0;
    /// See [`C2`].
    pub const C5: f64 = 8.0 / 9.0;

    /// Row 2 of `A`.
    pub const A21: f64 = 1.0 / 5.0;
    /// Row 3 of `A`.
    pub const A3: [f64; 2] = [3.0 / 40.0, 9.0 / 40.0];
    /// Row 4 of `A`.
    pub const A4: [f64; 3] = [44.0 / 45.0, -56.0 / 15.0, 32.0 / 9.0];
    /// Row 5 of `A`.
    pub const A5: [f64; 4] = [
        19372.0 / 6561.0,
        -25360.0 / 2187.0,
        64448.0 / 6561.0,
        -212.0 / 729.0,
    ];
    /// Row 6 of `A`.
    pub const A6: [f64; 5] = [
        9017.0 / 3168.0,
        -355.0 / 33.0,
        46732.0 / 5247.0,
        49.0 / 176.0,
        -5103.0 / 18656.0,
    ];
    /// 5th-order weights `b` for `k₁ … k₆` (`b₂ = 0`, `b₇ = 0`); also row 7 of `A`.
    pub const B: [f64; 6] = [
        35.0 / 384.0,
        0.0,
        500.0 / 1113.0,
        125.0 / 192.0,
        -2187.0 / 6784.0,
        11.0 / 84.0,
    ];
    /// Error weights `e = b − b̂` (5th minus embedded 4th order) for `k₁ … k₇` (`e₂ = 0`).
    pub const E: [f64; 7] = [
        71.0 / 57600.0,
        0.0,
        -71.0 / 16695.0,
        71.0 / 1920.0,
        -17253.0 / 339200.0,
        22.0 / 525.0,
        -1.0 / 40.0,
    ];
    /// Embedded 4th-order weights `b̂` for `k₁ … k₇`, kept to check `E` against.
    pub const B_HAT: [f64; 7] = [
        5179.0 / 57600.0,
        0.0,
        7571.0 / 16695.0,
        393.0 / 640.0,
        -92097.0 / 339200.0,
        187.0 / 2100.0,
        1.0 / 40.0,
    ];
    /// Dense-output weights `d` for `k₁ … k₇` (`d₂ = 0`) of the 4th-order continuous
    /// extension.
    pub const D: [f64; 7] = [
        -12715105075.0 / 11282082432.0,
        0.0,
        87487479700.0 / 32700410799.0,
        -10690763975.0 / 1880347072.0,
        701980252875.0 / 199316789632.0,
        -1453857185.0 / 822651844.0,
        69997945.0 / 29380423.0,
    ];
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn dopri5_rows_sum_to_their_stage_times() {
        // Consistency Σⱼ aᵢⱼ = cᵢ, to rounding.
        assert!((dopri5::A21 - dopri5::C2).abs() < 1e-16);
        assert!((dopri5::A3.iter().sum::<f64>() - dopri5::C3).abs() < 1e-15);
        assert!((dopri5::A4.iter().sum::<f64>() - dopri5::C4).abs() < 1e-15);
        assert!((dopri5::A5.iter().sum::<f64>() - dopri5::C5).abs() < 1e-14);
        assert!((dopri5::A6.iter().sum::<f64>() - 1.0).abs() < 1e-14);
    }

    #[test]
    fn dopri5_error_weights_are_b_minus_b_hat() {
        let b7 = [
            dopri5::B[0],
            dopri5::B[1],
            dopri5::B[2],
            dopri5::B[3],
            dopri5::B[4],
            dopri5::B[5],
            0.0,
        ];
        for i in 0..7 {
            assert!(
                (b7[i] - dopri5::B_HAT[i] - dopri5::E[i]).abs() < 1e-16,
                "e{}",
                i + 1
            );
        }
        assert!((dopri5::B_HAT.iter().sum::<f64>() - 1.0).abs() < 1e-15);
        // The dense weights integrate to zero at θ = 1 (the extension must hit y₁).
        assert!(dopri5::D.iter().sum::<f64>().abs() < 1e-13);
    }

    #[test]
    fn rk4_weights_sum_to_one() {
        assert!((rk4::B.iter().sum::<f64>() - 1.0).abs() < 1e-15);
        assert_eq!(heun::B.iter().sum::<f64>(), 1.0);
    }
}
