//! Property tests at scale of the solver's public entry points with arbitrary doubles —
//! NaN, infinities, zero, negatives, huge and tiny values: every call returns a value or a
//! typed error; none panics or hangs (every search has an iteration cap).
#![cfg(not(target_arch = "wasm32"))]
#![allow(clippy::unwrap_used)]

use proptest::prelude::*;
use zeta_solver::metrics::free::FreeMetrics;
use zeta_solver::metrics::step::{StepConfig, StepInfo};
use zeta_solver::metrics::SettlingBand;
use zeta_solver::{frf, FreeResponse, SecondOrder};

fn wild() -> impl Strategy<Value = f64> {
    prop_oneof![
        any::<f64>(),
        Just(0.0),
        Just(-0.0),
        Just(f64::NAN),
        Just(f64::INFINITY),
        Just(f64::MIN_POSITIVE),
        Just(1e300),
        -1e6f64..1e6,
    ]
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(2000))]

    #[test]
    fn constructors_return_values_or_typed_errors(a in wild(), b in wild(), c in wild()) {
        let _ = SecondOrder::new(a, b, c);
        let _ = SecondOrder::mechanical(a, b, c);
        let _ = SecondOrder::electrical(a, b, c);
        let _ = SecondOrder::from_natural(a, b);
    }

    #[test]
    fn every_valid_system_answers_every_question(a in wild(), b in wild(), c in wild(), x0 in wild(), v0 in wild(), t in wild(), band in wild()) {
        if let Ok(sys) = SecondOrder::new(a, b, c) {
            let _ = (sys.natural_frequency(), sys.damping_ratio(), sys.damped_frequency(), sys.quality_factor());
            let _ = (sys.poles(), sys.time_constants(), sys.regime(), sys.critical_damping());
            let r = FreeResponse::new(sys, x0, v0);
            let _ = (r.displacement(t), r.velocity(t), r.acceleration(t));
            if let Ok(band) = SettlingBand::new(band) {
                let _ = FreeMetrics::exact(&sys, x0, v0, band);
                let _ = zeta_solver::metrics::free::settling_time(&sys, x0, v0, band);
            }
            let _ = FreeMetrics::exact(&sys, x0, v0, SettlingBand::FREE_DEFAULT);
            let _ = StepInfo::exact(&sys, x0, &StepConfig::default());
        }
    }

    #[test]
    fn frequency_response_answers_any_ratio(r in wild(), zeta in wild()) {
        let _ = (frf::magnitude(r, zeta), frf::magnitude_db(r, zeta), frf::phase(r, zeta));
        let _ = (frf::peak(zeta), frf::half_power_points(zeta), frf::displacement_half_power_band(zeta));
        let _ = frf::logspace(r, zeta, 16);
    }

    #[test]
    fn sampled_metrics_reject_bad_data_with_typed_errors(t in prop::collection::vec(wild(), 0..40), x in prop::collection::vec(wild(), 0..40)) {
        let _ = FreeMetrics::from_samples(&t, &x, SettlingBand::FREE_DEFAULT);
        let _ = StepInfo::from_samples(&t, &x, None, &StepConfig::default());
    }
}
