//! Backends used in the browser: plotters-canvas (and, for SVG export, plotters' SVG
//! backend), with text measured by a canvas 2D context.
//!
//! Both are one type, [`Web`], so the render code is compiled once for the page: a
//! generic drawing function is a copy of machine code per backend type, and the SVG
//! export's copy of every render function cost about 10 KB brotli of wasm.
//!
//! plotters' default text measurement on the web inserts a styled `<span>` into the page
//! and reads its layout, once per label. That is slow (a forced layout per label, every
//! frame) and is blocked by a strict Content-Security-Policy (`style-src 'self'`). This
//! wrapper measures with `CanvasRenderingContext2d.measureText` instead and delegates all
//! drawing to the wrapped backend.

use plotters::prelude::SVGBackend;
use plotters_backend::{
    BackendColor, BackendCoord, BackendStyle, BackendTextStyle, DrawingBackend, DrawingErrorKind,
};
use plotters_canvas::CanvasBackend;
use wasm_bindgen::JsCast;
use web_sys::{CanvasRenderingContext2d, HtmlCanvasElement};

/// Any plotters backend, with text measured by a canvas 2D context.
pub struct Measured<B> {
    inner: B,
    context: CanvasRenderingContext2d,
    /// Whether `context` is the drawing target, so bitmaps can go straight to it.
    draws_on_context: bool,
}

/// A plotters backend drawing onto an HTML canvas.
pub type Canvas = Measured<Web<'static>>;

/// The backends the page draws on, as one type: an HTML canvas, or an SVG document being
/// written into a string (export).
pub enum Web<'a> {
    /// Drawing onto an HTML canvas.
    Canvas(CanvasBackend),
    /// Writing an SVG document.
    Svg(SVGBackend<'a>),
}

/// A drawing error of either [`Web`] backend.
pub enum WebError {
    /// From the canvas backend.
    Canvas(<CanvasBackend as DrawingBackend>::ErrorType),
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
                Web::Svg(b) => b.$name($($arg),*).map_err(lift(WebError::Svg)),
            }
        }
    )*};
}

impl DrawingBackend for Web<'_> {
    type ErrorType = WebError;

    fn get_size(&self) -> (u32, u32) {
        match self {
            Web::Canvas(b) => b.get_size(),
            Web::Svg(b) => b.get_size(),
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
        fn blit_bitmap(pos: BackendCoord, size: (u32, u32), src: &[u8]);
    }
}

fn context_of(canvas: &HtmlCanvasElement) -> Option<CanvasRenderingContext2d> {
    canvas
        .get_context("2d")
        .ok()??
        .dyn_into::<CanvasRenderingContext2d>()
        .ok()
}

impl Canvas {
    /// Wraps `canvas`; `None` if it has no 2D context.
    pub fn new(canvas: &HtmlCanvasElement) -> Option<Self> {
        let context = context_of(canvas)?;
        let inner = Web::Canvas(CanvasBackend::with_canvas_object(canvas.clone())?);
        Some(Self {
            inner,
            context,
            draws_on_context: true,
        })
    }
}

impl<'a> Measured<Web<'a>> {
    /// Writes SVG through `svg`, measuring text with the 2D context of `measure` (any
    /// canvas, even one that is not in the page).
    pub fn svg(svg: SVGBackend<'a>, measure: &HtmlCanvasElement) -> Option<Self> {
        Some(Self {
            inner: Web::Svg(svg),
            context: context_of(measure)?,
            draws_on_context: false,
        })
    }
}

type Result<T, E> = std::result::Result<T, DrawingErrorKind<E>>;

/// `DrawingBackend` methods of `Measured<B>` that return `Result<(), B::ErrorType>` and only
/// hand their arguments to the wrapped backend (its own drawing, not the trait's defaults).
macro_rules! forward_to_inner {
    ($(fn $name:ident $(<$($g:ident: $bound:path),+>)? ($($arg:ident: $ty:ty),*);)*) => {$(
        fn $name $(<$($g: $bound),+>)? (&mut self, $($arg: $ty),*) -> Result<(), B::ErrorType> {
            self.inner.$name($($arg),*)
        }
    )*};
}

impl<B: DrawingBackend> DrawingBackend for Measured<B> {
    type ErrorType = B::ErrorType;

    fn get_size(&self) -> (u32, u32) {
        self.inner.get_size()
    }

    forward_to_inner! {
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
    ) -> Result<(u32, u32), B::ErrorType> {
        // The font string CanvasBackend::draw_text sets, so measuring and drawing agree.
        self.context.set_font(&format!(
            "{} {}px {}",
            style.style().as_str(),
            style.size(),
            style.family().as_str()
        ));
        let width = self
            .context
            .measure_text(text)
            .map(|m| m.width())
            .unwrap_or(0.0);
        Ok((
            width.ceil().max(0.0) as u32,
            style.size().ceil().max(0.0) as u32,
        ))
    }

    fn blit_bitmap(
        &mut self,
        pos: BackendCoord,
        size: (u32, u32),
        src: &[u8],
    ) -> Result<(), B::ErrorType> {
        if !self.draws_on_context {
            return self.inner.blit_bitmap(pos, size, src);
        }
        // One putImageData instead of a fillRect per pixel (the default).
        let (w, h) = size;
        let n = (w as usize) * (h as usize);
        if src.len() < n * 3 || n == 0 {
            return Ok(());
        }
        let mut rgba = Vec::with_capacity(n * 4);
        for px in src.chunks_exact(3).take(n) {
            rgba.extend_from_slice(&[px[0], px[1], px[2], 255]);
        }
        if let Ok(image) =
            web_sys::ImageData::new_with_u8_clamped_array_and_sh(wasm_bindgen::Clamped(&rgba), w, h)
        {
            // A failed put leaves the plot without its colour map; never worth a panic.
            let _ = self
                .context
                .put_image_data(&image, f64::from(pos.0), f64::from(pos.1));
        }
        Ok(())
    }
}
