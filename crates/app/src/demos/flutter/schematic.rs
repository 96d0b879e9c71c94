//! The deck cross-section twisting in the wind (the animated schematic).

use super::U_MAX;
use crate::figure::{Axis, Figure, LineStyle, Marker};
use crate::format::si;
use crate::plot::Ink;
use crate::t;
use zeta_solver::flutter::{degrees, radians, rotate};

/// How large a small twist is drawn \[deg\].
const DRAWN_MAX_DEG: f64 = 30.0;
/// Twists from this size on are drawn true to scale \[deg\].
const TRUE_SCALE_FROM_DEG: f64 = 10.0;
/// Largest drawn twist \[rad\] (≈ 69°): larger ones are clipped in the drawing.
const CLIP: f64 = 1.2;

/// The deck cross-section (an H: the deck plate between two plate girders, like the 1940
/// deck, 12 units wide and 2.4 deep) twisted by `theta` \[rad\]; when the largest twist on
/// the window, `peak` \[rad\], is under [`DRAWN_MAX_DEG`] it is drawn that large; wind `u`
/// \[m/s\] from the left, at time `t` \[s\].
pub(super) fn deck(theta: f64, peak: f64, u: f64, t: f64) -> Figure {
    // True to scale once the twist is large; small twists drawn larger.
    let gain = if peak > 0.0 && peak < radians(TRUE_SCALE_FROM_DEG) {
        radians(DRAWN_MAX_DEG) / peak
    } else {
        1.0
    };
    let drawn = if (theta * gain).is_finite() {
        (theta * gain).clamp(-CLIP, CLIP)
    } else {
        0.0
    };
    let shape = |pts: &[(f64, f64)]| pts.iter().map(|&p| rotate(p, drawn)).collect::<Vec<_>>();
    let deck = LineStyle::solid(Ink::Blue, 3.0);
    let girder = LineStyle::solid(Ink::Blue, 5.0);
    let wind = LineStyle::solid(Ink::Sky, 2.5);
    let mut fig = Figure::schematic(
        t!("flutter-schematic-title"),
        Axis::linear("", "", (-12.0, 9.0)),
        Axis::linear("", "", (-4.5, 4.5)),
    )
    // Rest position of the deck, for reference.
    .with_line(
        "",
        vec![(-7.0, 0.0), (7.0, 0.0)],
        LineStyle::dotted(Ink::Black, 1.0),
    )
    // Deck plate with a little thickness.
    .with_line(
        "",
        shape(&[
            (-6.0, -0.15),
            (6.0, -0.15),
            (6.0, 0.15),
            (-6.0, 0.15),
            (-6.0, -0.15),
        ]),
        deck,
    )
    // The two plate girders (the bluff H-section that made Tacoma prone to flutter).
    .with_line("", shape(&[(-6.0, -1.2), (-6.0, 1.2)]), girder)
    .with_line("", shape(&[(6.0, -1.2), (6.0, 1.2)]), girder);
    // Wind arrows from the left, their length following U.
    let len = 0.5 + 3.0 * (u / U_MAX).clamp(0.0, 1.0);
    for y in [-2.0, 0.0, 2.0] {
        let tip = (-8.0, y);
        fig = fig
            .with_line("", vec![(tip.0 - len, y), tip], wind)
            .with_line(
                "",
                vec![(tip.0 - 0.4, y + 0.3), tip, (tip.0 - 0.4, y - 0.3)],
                wind,
            );
    }
    // Arc showing the drawn twist angle at the right end.
    let arc: Vec<(f64, f64)> = (0..=20)
        .map(|i| rotate((7.5, 0.0), drawn * f64::from(i) / 20.0))
        .collect();
    fig = fig.with_line("", arc, LineStyle::solid(Ink::Vermillion, 2.0));
    let drawn_as = if (theta * gain).abs() > CLIP {
        t!("flutter-drawn-clipped", angle = si(degrees(CLIP), "°", 2))
    } else if gain == 1.0 {
        t!("flutter-drawn-true-scale")
    } else {
        t!("flutter-drawn-larger", factor = si(gain, "", 2))
    };
    let description = t!(
        "flutter-schematic",
        time = super::text::duration(t),
        twist = si(degrees(theta), "°", 3),
        drawn = &drawn_as,
        wind = si(u, "m/s", 3)
    );
    fig.with_marker(Marker::text(
        t!("flutter-wind", speed = si(u, "m/s", 3)),
        (-11.5, 3.6),
        Ink::Black,
    ))
    .with_marker(Marker::text(
        format!("θ = {}", si(degrees(theta), "°", 3)),
        (3.5, -2.9),
        Ink::Black,
    ))
    .with_marker(Marker::text(
        t!("flutter-drawn-note", drawn = drawn_as),
        (3.5, -3.7),
        Ink::Black,
    ))
    .with_marker(Marker::dot("", (0.0, 0.0), Ink::Black))
    .described(description)
}
