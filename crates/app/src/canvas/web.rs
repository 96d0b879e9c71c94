//! [`Web`]: the page's canvas and SVG export's backend as one type (full module only).

use super::{context_of, CanvasError, HtmlCanvas};
use plotters::prelude::SVGBackend;
use plotters_backend::{
    BackendColor, BackendCoord, BackendStyle, BackendTextStyle, DrawingBackend, DrawingErrorKind,
};
use web_sys::{CanvasRenderingContext2d, HtmlCanvasElement};

/// The backends the page draws on, as one type.
pub enum Web<'a> {
    /// Drawing onto an HTML canvas.
    Canvas(HtmlCanvas),
    /// Writing an SVG document; text measured with `measure`.
    Svg {
        /// The SVG being written.
        svg: SVGBackend<'a>,
        /// Any 2D context (even of a canvas not in the page), for measuring text.
        measure: CanvasRenderingContext2d,
    },
}

/// A drawing error of either [`Web`] backend.
pub enum WebError {
    /// From the canvas backend.
    Canvas(CanvasError),
    /// From the SVG backend.
    Svg(std::io::Error),
}

// Each side's own text, so messages read as they did before the backends were one type.
impl std::fmt::Debug for WebError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            WebError::Canvas(e) => e.fmt(f),
            WebError::Svg(e) => e.fmt(f),
        }
    }
}

impl std::fmt::Display for WebError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            WebError::Canvas(e) => e.fmt(f),
            WebError::Svg(e) => e.fmt(f),
        }
    }
}

impl std::error::Error for WebError {}

/// A backend error as a [`WebError`] (font errors pass through).
fn lift<E>(wrap: fn(E) -> WebError) -> impl Fn(DrawingErrorKind<E>) -> DrawingErrorKind<WebError>
where
    E: std::error::Error + Send + Sync,
{
    move |e| match e {
        DrawingErrorKind::DrawingError(e) => DrawingErrorKind::DrawingError(wrap(e)),
        DrawingErrorKind::FontError(e) => DrawingErrorKind::FontError(e),
    }
}

/// `DrawingBackend` methods of [`Web`] that hand their arguments to the backend it holds.
macro_rules! forward_to_either {
    ($(fn $name:ident $(<$($g:ident: $bound:path),+>)? ($($arg:ident: $ty:ty),*);)*) => {$(
        fn $name $(<$($g: $bound),+>)? (&mut self, $($arg: $ty),*) -> Result<(), WebError> {
            match self {
                Web::Canvas(b) => b.$name($($arg),*).map_err(lift(WebError::Canvas)),
                Web::Svg { svg, .. } => svg.$name($($arg),*).map_err(lift(WebError::Svg)),
            }
        }
    )*};
}

type Result<T, E> = std::result::Result<T, DrawingErrorKind<E>>;

impl DrawingBackend for Web<'_> {
    type ErrorType = WebError;

    fn get_size(&self) -> (u32, u32) {
        match self {
            Web::Canvas(b) => b.get_size(),
            Web::Svg { svg, .. } => svg.get_size(),
        }
    }

    forward_to_either! {
        fn ensure_prepared();
        fn present();
        fn draw_pixel(point: BackendCoord, color: BackendColor);
        fn draw_line<S: BackendStyle>(from: BackendCoord, to: BackendCoord, style: &S);
        fn draw_rect<S: BackendStyle>(upper_left: BackendCoord, bottom_right: BackendCoord, style: &S, fill: bool);
        fn draw_path<S: BackendStyle, I: IntoIterator<Item = BackendCoord>>(path: I, style: &S);
        fn draw_circle<S: BackendStyle>(center: BackendCoord, radius: u32, style: &S, fill: bool);
        fn fill_polygon<S: BackendStyle, I: IntoIterator<Item = BackendCoord>>(vert: I, style: &S);
        fn draw_text<S: BackendTextStyle>(text: &str, style: &S, pos: BackendCoord);
    }

    fn estimate_text_size<S: BackendTextStyle>(
        &self,
        text: &str,
        style: &S,
    ) -> Result<(u32, u32), WebError> {
        match self {
            Web::Canvas(b) => b
                .estimate_text_size(text, style)
                .map_err(lift(WebError::Canvas)),
            Web::Svg { measure, .. } => Ok(super::measure(measure, text, style, |font| {
                measure.set_font(&font)
            })),
        }
    }
}

impl Web<'_> {
    /// For a canvas, what it draws itself (see `render::Direct`); an SVG is drawn
    /// through plotters alone.
    pub fn direct(&self) -> Option<super::CanvasDirect> {
        match self {
            Web::Canvas(b) => Some(b.direct()),
            Web::Svg { .. } => None,
        }
    }
}

impl<'a> Web<'a> {
    /// Writes SVG through `svg`, measuring text with the 2D context of `measure` (any
    /// canvas, even one that is not in the page).
    pub fn svg(svg: SVGBackend<'a>, measure: &HtmlCanvasElement) -> Option<Self> {
        Some(Web::Svg {
            svg,
            measure: context_of(measure)?,
        })
    }
}
