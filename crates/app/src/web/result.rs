//! What the session's calls return to the page, serialised as plain objects.

use crate::params::Notice;
use serde::Serialize;

#[derive(Serialize)]
pub(super) struct SetResult {
    pub(super) value: f64,
    pub(super) notice: Option<Notice>,
}

/// What [`Session::update`] returns to the page.
#[derive(Serialize)]
pub(super) struct UpdateResult<'a> {
    pub(super) readouts: &'a [crate::demos::Readout],
    /// `[{key, text}]`: the text alternative of each plot built this update (those on
    /// screen, and the first plot, whose text is announced); the others come with
    /// [`StaleResult`] when they are drawn.
    pub(super) descriptions: Vec<Description<'a>>,
    /// `[start, end]` of the animation in s, if the demo animates.
    pub(super) time_span: Option<(f64, f64)>,
    /// `[[key, value]]` of parameters the demo derived from others this update.
    pub(super) derived: Vec<(&'static str, f64)>,
    /// Keys of readouts and plots showing a coarse study while the full one runs.
    pub(super) provisional: Vec<&'static str>,
    /// Whether this update started the full study afresh (see
    /// [`Demo::study_round`](crate::demos::Demo::study_round)): its progress is back to 0.
    pub(super) restarted: bool,
    /// The guided tour with its checked claims, for the demo that has one (`paper`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) tour: Option<crate::demos::paper::Tour>,
}

/// What [`Session::draw_stale`] returns to the page.
#[derive(Serialize)]
pub(super) struct StaleResult<'a> {
    /// Whether any plot still shows an older frame than the last update's.
    pub(super) left: bool,
    /// `[{key, text}]`: the text alternative of each plot drawn by this call.
    pub(super) descriptions: Vec<Description<'a>>,
}

#[derive(Serialize)]
pub(super) struct Description<'a> {
    pub(super) key: &'static str,
    pub(super) text: &'a str,
}
