//! The two-DOF quarter car's prose: summary, equation and the figures' text alternatives.

use super::RoadKind;
use crate::format::si;
use crate::spec::Preset;
use crate::t;
use zeta_solver::two_dof_exact::ExactMetrics;

pub(super) const SUMMARY: &str =
    "Two masses, two modes. The body (sprung mass m_s) sits on the suspension spring k_s and \
     damper c_s; the wheel (unsprung mass m_u) sits on the tyre spring k_t, which follows \
     the road u(t). Body bounce, around 1–1.5 Hz, is the body moving on the soft \
     suspension; wheel hop, around 10–15 Hz, is the light wheel bouncing between the stiff \
     tyre and the suspension. The frequency responses show both: the body follows slow road \
     waves, rides over fast ones, and shakes most near body bounce; the tyre deflection, \
     which decides grip, peaks at wheel hop. The tyre can only push: when the wheel rises \
     above its static deflection the tyre force is zero and the wheel leaves the road until \
     it lands again. Comfort is judged by the RMS body acceleration, road holding by the RMS \
     tyre deflection, both over the run from rest, 0 … T. The response is exact between road \
     samples, which are close enough to follow every bump and wheel hop. Displacements are \
     from static equilibrium, upward positive; the random road sums 64 sinusoids with the \
     ISO 8608 spectrum over 0.5–20 Hz. On it the page also shows the stationary RMS body \
     acceleration on the full ISO 8608 road, unweighted and weighted by ISO 2631-1's W_k \
     (a_w, the comfort measure), from the Lyapunov equation of the car.";

pub(super) const EQUATION: &str = "<math display=\"block\"><mtable class=\"lines\">\
<mtr><mtd><msub><mi>m</mi><mi>s</mi></msub><msub><mover><mi>z</mi><mo>¨</mo></mover><mi>s</mi></msub>\
<mo>=</mo><mo>−</mo><msub><mi>k</mi><mi>s</mi></msub><mo>(</mo><msub><mi>z</mi><mi>s</mi></msub><mo>−</mo>\
<msub><mi>z</mi><mi>u</mi></msub><mo>)</mo><mo>−</mo><msub><mi>c</mi><mi>s</mi></msub><mo>(</mo>\
<msub><mover><mi>z</mi><mo>˙</mo></mover><mi>s</mi></msub><mo>−</mo>\
<msub><mover><mi>z</mi><mo>˙</mo></mover><mi>u</mi></msub><mo>)</mo></mtd></mtr>\
<mtr><mtd><msub><mi>m</mi><mi>u</mi></msub><msub><mover><mi>z</mi><mo>¨</mo></mover><mi>u</mi></msub>\
<mo>=</mo><msub><mi>k</mi><mi>s</mi></msub><mo>(</mo><msub><mi>z</mi><mi>s</mi></msub><mo>−</mo>\
<msub><mi>z</mi><mi>u</mi></msub><mo>)</mo><mo>+</mo><msub><mi>c</mi><mi>s</mi></msub><mo>(</mo>\
<msub><mover><mi>z</mi><mo>˙</mo></mover><mi>s</mi></msub><mo>−</mo>\
<msub><mover><mi>z</mi><mo>˙</mo></mover><mi>u</mi></msub><mo>)</mo></mtd></mtr>\
<mtr><mtd><mspace width=\"4em\"/><mo>−</mo><mi>min</mi><mo>(</mo>\
<msub><mi>k</mi><mi>t</mi></msub><mo>(</mo><msub><mi>z</mi><mi>u</mi></msub><mo>−</mo><mi>u</mi><mo>(</mo>\
<mi>t</mi><mo>)</mo><mo>)</mo><mo>,</mo><mo>(</mo><msub><mi>m</mi><mi>s</mi></msub><mo>+</mo>\
<msub><mi>m</mi><mi>u</mi></msub><mo>)</mo><mi>g</mi><mo>)</mo></mtd></mtr></mtable></math>";

/// The motion plot in words: largest road height, and the body's and wheel's largest
/// excursions `(t, z)`.
pub(super) fn describe_motion(
    kind: RoadKind,
    road_peak: f64,
    (tb, zb): (f64, f64),
    (tw, zw): (f64, f64),
) -> String {
    let road = match kind {
        RoadKind::Bump => "bump",
        RoadKind::Step => "step",
        RoadKind::Sine => "sine",
        RoadKind::Random => "random",
    };
    t!(
        "quarter-car-2dof-describe-motion",
        road = road,
        road_peak = si(road_peak, "m", 3),
        body = si(zb, "m", 3),
        body_time = si(tb, "s", 3),
        wheel = si(zw, "m", 3),
        wheel_time = si(tw, "s", 3)
    )
}

/// The acceleration plot in words: peak \[m/s²\], the same in g, and the RMS over the
/// window.
pub(super) fn describe_acceleration(peak: f64, peak_g: f64, m: Option<ExactMetrics>) -> String {
    t!(
        "quarter-car-2dof-describe-acceleration",
        peak = si(peak, "m/s²", 3),
        peak_g = si(peak_g, "", 2),
        window = si(m.map_or(f64::NAN, |m| m.window), "s", 3),
        rms = si(m.map_or(f64::NAN, |m| m.rms_body_acceleration), "m/s²", 3)
    )
}

/// The tyre plot in words: range `lo … hi` of the deflection \[m\], its RMS, and when and
/// for how long the wheel leaves the road.
pub(super) fn describe_tyre(lo: f64, hi: f64, static_tyre: f64, m: Option<ExactMetrics>) -> String {
    let rms = si(m.map_or(f64::NAN, |m| m.rms_tyre_deflection), "m", 3);
    let (lo, hi, limit) = (si(lo, "m", 3), si(hi, "m", 3), si(static_tyre, "m", 3));
    match m.and_then(|m| m.first_lift_off.map(|t| (t, m))) {
        Some((t, m)) => t!(
            "quarter-car-2dof-describe-tyre-lift-off",
            low = lo,
            high = hi,
            rms = rms,
            limit = limit,
            time = si(t, "s", 3),
            lift_offs = m.lift_offs,
            airborne = si(m.airborne_time, "s", 3)
        ),
        None => t!(
            "quarter-car-2dof-describe-tyre-contact",
            low = lo,
            high = hi,
            rms = rms,
            limit = limit
        ),
    }
}

/// The frequency responses in words: the body's peak `(f, gain)` near body bounce, its
/// gain at 20 Hz, and the tyre deflection's peak near wheel hop.
pub(super) fn describe_frf((fb, gb): (f64, f64), at20: f64, (fw, gw): (f64, f64)) -> String {
    t!(
        "quarter-car-2dof-describe-frf",
        body_peak = si(gb, "", 3),
        body_frequency = si(fb, "Hz", 3),
        at_20 = si(at20, "", 2),
        tyre_peak = si(gw, "", 3),
        tyre_frequency = si(fw, "Hz", 3)
    )
}

/// Legend of a natural-frequency line, e.g. `f_body 1.23 Hz`.
pub(super) fn frequency_label(name: &str, f: f64) -> String {
    format!("{name} {}", si(f, "Hz", 3))
}

/// The schematic in words.
pub(super) fn describe_car(t: f64, body: f64, wheel: f64, road: f64) -> String {
    t!(
        "quarter-car-2dof-schematic",
        time = si(t, "s", 3),
        body = si(body, "m", 3),
        wheel = si(wheel, "m", 3),
        road = si(road, "m", 3)
    )
}

/// One-click configurations: roads that show each mode and each kind of road. Each sets
/// the `car`'s parameters (their declared defaults), then its changes.
pub(super) fn presets(car: &[(&'static str, f64)]) -> Vec<Preset> {
    let preset = |label, changes: &[(&'static str, f64)]| {
        let mut values = car.to_vec();
        values.extend_from_slice(changes);
        Preset { label, values }
    };
    vec![
        preset(
            "Speed bump 5 cm at 10 m/s",
            &[("road", 0.0), ("h", 0.05), ("L", 0.5), ("V", 10.0)],
        ),
        preset("Kerb step 5 cm", &[("road", 1.0), ("h", 0.05)]),
        preset(
            "Road wave at body bounce",
            &[("road", 2.0), ("h", 0.02), ("f_road", 1.25)],
        ),
        preset(
            "Road wave at wheel hop",
            &[("road", 2.0), ("h", 0.005), ("f_road", 11.5)],
        ),
        preset(
            "Random road, class C, 20 m/s",
            &[("road", 3.0), ("class", 2.0), ("V", 20.0), ("seed", 1.0)],
        ),
        preset(
            "Soft damper on a poor road",
            &[
                ("road", 3.0),
                ("class", 3.0),
                ("V", 20.0),
                ("cs", 500.0),
                ("seed", 1.0),
            ],
        ),
    ]
}

/// An RMS value with its window, e.g. `0.116 m/s² (0–2.50 s)`.
pub(super) fn over_window(v: f64, unit: &str, window: f64) -> (f64, String) {
    (v, format!("{} (0–{})", si(v, unit, 3), si(window, "s", 3)))
}
