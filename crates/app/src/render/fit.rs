//! Text that fits its room: a title, an axis name or a colour-bar label longer than the
//! space it has (a narrow phone, a long language) is drawn smaller, down to
//! [`MIN_SHRINK`] of its size, and cut with an ellipsis only if even that is too long.

use plotters::coord::Shift;
use plotters::prelude::*;

/// The smallest size a fitted text is drawn at, as a fraction of its normal size.
pub(super) const MIN_SHRINK: f64 = 0.72;

/// Width of `text` at `size` px in the plots' sans-serif face (0 if it cannot be
/// measured).
fn width<DB: DrawingBackend>(area: &DrawingArea<DB, Shift>, text: &str, size: f64) -> f64 {
    let font = (super::SANS, size).into_text_style(area);
    area.estimate_text_size(text, &font)
        .map_or(0.0, |(w, _)| f64::from(w))
}

/// The size (≤ `size`) at which `text` fits in `room` px, and the text itself, cut with
/// "…" when it does not fit even at [`MIN_SHRINK`] of `size`.
pub(super) fn fit<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    text: &str,
    size: f64,
    room: f64,
) -> (String, f64) {
    let full = width(area, text, size);
    if full <= room || full <= 0.0 || room <= 0.0 {
        return (text.to_string(), size);
    }
    let shrunk = (size * room / full).max(size * MIN_SHRINK);
    if width(area, text, shrunk) <= room {
        return (text.to_string(), shrunk);
    }
    // Longest prefix (whole characters) that fits with the ellipsis.
    let chars: Vec<char> = text.chars().collect();
    let (mut lo, mut hi) = (0, chars.len());
    while lo < hi {
        let mid = (lo + hi).div_ceil(2);
        let candidate: String = chars[..mid].iter().collect::<String>() + "…";
        if width(area, &candidate, shrunk) <= room {
            lo = mid;
        } else {
            hi = mid - 1;
        }
    }
    let cut: String = chars[..lo].iter().collect();
    (format!("{}…", cut.trim_end()), shrunk)
}
