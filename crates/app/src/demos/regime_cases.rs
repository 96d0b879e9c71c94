//! Test cases shared by the demos that reach every damping regime by moving one parameter.

use super::testing::{run, value};
use super::Frame;

/// The damping regimes, in the order of increasing damping, as the `regime` readout names
/// them.
pub const REGIMES: [&str; 4] = ["undamped", "underdamped", "critically damped", "overdamped"];

/// Demo `id` run at `base` (a URL query, may be empty) with `key` set to each of `values`,
/// which reach the [`REGIMES`] in order. Checks that each frame shows its regime and draws
/// every figure; returns `(value, regime, frame)` for the demo's own checks.
pub fn each_regime(
    id: &str,
    base: &str,
    key: &str,
    values: [f64; 4],
) -> Vec<(f64, &'static str, Frame)> {
    values
        .into_iter()
        .zip(REGIMES)
        .map(|(v, regime)| {
            let query = [base, &format!("{key}={v}")].join("&");
            let f = run(id, query.trim_start_matches('&'));
            assert_eq!(value(&f, "regime"), regime, "{id}?{query}");
            assert!(f.figures.iter().all(|fig| fig.has_visible_data()));
            (v, regime, f)
        })
        .collect()
}
