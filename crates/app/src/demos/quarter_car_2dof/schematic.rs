//! The animated quarter car: body and wheel on their springs and damper over the road
//! profile, at one instant of the run.

use super::text;
use crate::figure::{Axis, Figure, LineStyle, Marker};
use crate::format::si;
use crate::plot::{curve, Ink};
use crate::schematic::{damper, rect, spring};
use crate::t;

/// Half the drawn travel of a part moved by `reach` \[drawing units\].
const AMP: f64 = 0.45;

/// The quarter car drawn at state `s` over road height `u` (all lengths divided by
/// `reach`, the largest excursion of the run), with the road profile around the tyre
/// (`road(dt)` is the road height `dt` seconds later, i.e. `V·dt` metres ahead).
pub(super) fn car(
    s: [f64; 4],
    u: f64,
    reach: f64,
    road: impl Fn(f64) -> f64,
    speed: f64,
    t: f64,
) -> Figure {
    let norm = |v: f64| {
        if v.is_finite() {
            (v / reach).clamp(-1.3, 1.3) * AMP
        } else {
            0.0
        }
    };
    let ground = 0.0;
    let road_y = ground + norm(u);
    let wheel_c = 1.2 + norm(s[1]);
    let body_c = 3.1 + norm(s[0]);
    let (wheel_h, body_h) = (0.5, 0.7);
    let (top, bottom) = (body_c - body_h / 2.0, wheel_c + wheel_h / 2.0);
    let solid = LineStyle::solid;
    // Road profile: 1 drawing unit per metre along the road, the car moving right.
    let profile = curve((-1.8, 1.8), 61, |x| ground + norm(road(x / speed.max(0.1))));
    let mut fig = Figure::schematic(
        t!("quarter-car-2dof-schematic-title"),
        Axis::linear("", "", (-1.9, 1.9)),
        Axis::linear("", "", (-0.8, 4.4)),
    )
    .with_line("", profile, solid(Ink::Black, 2.5))
    // Tyre spring from the road to the wheel.
    .with_line(
        "",
        spring(0.0, road_y, wheel_c - wheel_h / 2.0, 4, 0.15),
        solid(Ink::Vermillion, 2.5),
    )
    .with_line(
        "",
        rect((0.0, wheel_c), 0.9, wheel_h),
        solid(Ink::Vermillion, 3.0),
    )
    // Suspension spring (left) and damper (right) from the wheel to the body.
    .with_line(
        "",
        spring(-0.4, bottom, top, 5, 0.16),
        solid(Ink::Blue, 2.5),
    );
    for part in damper(0.4, bottom, top, 0.14) {
        fig = fig.with_line("", part, solid(Ink::Green, 2.5));
    }
    fig = fig.with_line("", rect((0.0, body_c), 1.8, body_h), solid(Ink::Blue, 3.0));
    // Rest positions, for reference.
    for rest in [1.2, 3.1] {
        fig = fig.with_line(
            "",
            vec![(1.1, rest), (1.5, rest)],
            LineStyle::dashed(Ink::Black, 1.0),
        );
    }
    let labels = [
        ("m_s".to_string(), (-0.2, body_c + 0.12)),
        ("m_u".to_string(), (-0.2, wheel_c + 0.1)),
        ("k_s".to_string(), (-1.15, (top + bottom) / 2.0 + 0.1)),
        ("c_s".to_string(), (0.62, (top + bottom) / 2.0 + 0.1)),
        ("k_t".to_string(), (0.25, (road_y + wheel_c) / 2.0 + 0.1)),
        (format!("→ {}", si(speed, "m/s", 3)), (-1.7, 4.2)),
    ];
    for (label, at) in labels {
        fig = fig.with_marker(Marker::text(label, at, Ink::Black));
    }
    fig.described(text::describe_car(t, s[0], s[1], u))
}
