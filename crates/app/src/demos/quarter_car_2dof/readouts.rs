//! The two-DOF quarter car's readout table: key, label, unit, precision and getter, once.

use super::{text, Results};
use crate::declare::ReadoutDef;
use crate::demos::rows::readouts;

/// Every readout in display order.
pub(super) fn table() -> Vec<ReadoutDef<Results>> {
    readouts! { Results, |r|;
        number "f_body", "body bounce frequency", "Hz", 4 => Some(r.f_body);
        number "f_wheel", "wheel hop frequency", "Hz", 4 => Some(r.f_wheel);
        number "window", "RMS window: the run from rest, 0 … T", "s", 3
            => r.metrics.map(|m| m.window);
        formatted "rms_body_accel", "RMS body acceleration over 0 … T (comfort)", "m/s²"
            => r.metrics.map(|m| text::over_window(m.rms_body_acceleration, "m/s²", m.window));
        formatted "rms_tyre_deflection", "RMS tyre deflection z_u − u over 0 … T (road holding)",
            "m" => r.metrics.map(|m| text::over_window(m.rms_tyre_deflection, "m", m.window));
        number "max_travel", "largest suspension travel |z_s − z_u|", "m", 3
            => r.metrics.map(|m| m.max_suspension_travel);
        number "static_tyre_deflection", "static tyre deflection (the wheel lifts off beyond it)",
            "m", 3 => Some(r.static_tyre);
        number "lift_off", "first lift-off: the tyre force reaches zero", "s", 3
            => r.metrics.and_then(|m| m.first_lift_off);
        number "airborne_time", "time the wheel is off the road", "s", 3
            => r.metrics.map(|m| m.airborne_time);
        number "rms_road", "RMS road height (random road)", "m", 3 => r.rms_road;
        number "stationary_accel",
            "stationary RMS body acceleration, full ISO 8608 road (random road)", "m/s²", 3
            => r.stationary.map(|s| s.rms_body_acceleration);
        number "stationary_weighted_accel",
            "stationary a_w: RMS body acceleration weighted by ISO 2631-1 W_k (random road)",
            "m/s²", 3 => r.stationary.map(|s| s.rms_weighted_body_acceleration);
        number "body_gain", "body / road amplitude at the sine frequency", "", 4
            => r.sine_frf.map(|f| f.body.abs());
        number "tyre_gain", "tyre deflection / road amplitude at the sine frequency", "", 4
            => r.sine_frf.map(|f| f.tyre_deflection.abs());
    }
}
