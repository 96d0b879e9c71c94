//! Text that fits its room: a title, an axis name or a colour-bar label longer than the
//! space it has (a narrow phone, a long language) is drawn smaller, down to
//! [`MIN_SHRINK`] of its size, and cut with an ellipsis only if even that is too long.

use plotters::coord::Shift;
use plotters::prelude::*;
use std::cell::RefCell;
use std::collections::VecDeque;

/// The smallest size a fitted text is drawn at, as a fraction of its normal size.
pub(super) const MIN_SHRINK: f64 = 0.72;

/// Width of `text` at `size` px in the plots' sans-serif face (0 if it cannot be
/// measured).
fn width<DB: DrawingBackend>(area: &DrawingArea<DB, Shift>, text: &str, size: f64) -> f64 {
    let font = (super::SANS, size).into_text_style(area);
    area.estimate_text_size(text, &font)
        .map_or(0.0, |(w, _)| f64::from(w))
}

/// What was fitted: the backend type, the text, its size and room (as bits), and the answer.
type Fitted = (&'static str, String, u64, u64, (String, f64));

/// How many fits [`fit`] remembers: every title, axis name and colour-bar label of the
/// plots on a page, at rest and while a control is held (a held legend below the plot
/// gives the axis names other room), so that catching up the plots out of view at rest
/// does not push out those of the plot a drag redraws. A miss measures up to eight times.
const REMEMBERED: usize = 64;

thread_local! {
    /// Recent fits, newest last. A drag redraws the same titles into the same room every
    /// frame, and a fit that cuts measures its text up to eight times (~1.5 ms a frame for
    /// one label at 4× CPU slowdown).
    static RECENT: RefCell<VecDeque<Fitted>> = const { RefCell::new(VecDeque::new()) };
}

/// The size (≤ `size`) at which `text` fits in `room` px, and the text itself, cut with
/// "…" when it does not fit even at [`MIN_SHRINK`] of `size`. Remembered: the same text,
/// size and room on the same kind of backend are not measured again.
pub(super) fn fit<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    text: &str,
    size: f64,
    room: f64,
) -> (String, f64) {
    let backend = std::any::type_name::<DB>();
    let same = |f: &&Fitted| {
        f.0 == backend && f.1 == text && f.2 == size.to_bits() && f.3 == room.to_bits()
    };
    // A hit moves to the back: a title that changes every frame of a drag adds an entry
    // each frame, and must push out only entries no longer used.
    let hit = RECENT.with_borrow_mut(|r| {
        let i = r.iter().position(|f| same(&f))?;
        let f = r.remove(i)?;
        let answer = f.4.clone();
        r.push_back(f);
        Some(answer)
    });
    if let Some(hit) = hit {
        return hit;
    }
    let answer = measure_fit(area, text, size, room);
    RECENT.with_borrow_mut(|r| {
        if r.len() == REMEMBERED {
            r.pop_front();
        }
        let key = (size.to_bits(), room.to_bits());
        r.push_back((backend, text.to_string(), key.0, key.1, answer.clone()));
    });
    answer
}

/// [`fit`], measuring.
fn measure_fit<DB: DrawingBackend>(
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
