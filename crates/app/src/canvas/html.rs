//! [`HtmlCanvas`]: a plotters backend that draws onto an HTML canvas's 2D context and sets
//! each piece of drawing state (stroke and fill colour, line width, font, text alignment)
//! only when it changes.
//!
//! Setting a colour or a font on a 2D context means building a CSS string in wasm, handing
//! it to JavaScript and having the browser parse it; a plot sets the same few dozen times
//! per frame (every grid line, tick label and legend entry). Profiled at 4× CPU slowdown,
//! colour strings alone were about a sixth of drawing a plot. The context keeps its state
//! between calls, so the backend remembers what it last set and skips the repeats.
//!
//! A backend is made per drawing (`Session::update` makes one per plot per frame), so the
//! memory ([`Memory`]) lives with the canvas (`canvas::Surface`) across frames: a held drag
//! sets again only what differs from the end of the frame before. Anything that resets
//! the context's state (resizing its canvas, even to the same size; a lost and restored
//! context; another backend's drawing on it) must empty the memory; the context's
//! `shadowOffsetX` carries the memory's stamp to tell (see [`Memory::claim`]).
//!
//! A run of lines in one stroke (a plot's grid lines, the two strokes of each `×` marker)
//! is traced into one path and stroked once ([`Batch`]), where each line was a path and a
//! stroke of its own: a plot's frame made ~140 strokes (integrators' response plot: 51
//! grid lines, 12 ticks, 24 crosses) and four calls from wasm into the context each. The
//! pixels are the same but where two lines of a run cross (stroked once, not twice over).
//! First modules batch too, so the full module's take-over draws the same pixels; dots
//! are not batched (a run of them saved little more and cost a first module 135 bytes).

use super::direct::{set_line_dash, CanvasDirect};
use crate::render::corners;
use plotters_backend::text_anchor::{HPos, VPos};
use plotters_backend::{
    BackendColor, BackendCoord, BackendStyle, BackendTextStyle, DrawingBackend, DrawingErrorKind,
    FontTransform,
};
use std::cell::Cell;
use std::f64::consts::TAU;
use std::rc::Rc;
use wasm_bindgen::{JsCast, JsValue};
use web_sys::{CanvasRenderingContext2d, HtmlCanvasElement};

/// A failed call on the 2D context (its JavaScript exception as text).
#[derive(Debug)]
pub struct CanvasError(String);

impl std::fmt::Display for CanvasError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "canvas: {}", self.0)
    }
}

impl std::error::Error for CanvasError {}

fn failed(e: JsValue) -> DrawingErrorKind<CanvasError> {
    let text = e
        .dyn_ref::<js_sys::Error>()
        .map(|e| String::from(e.message()))
        .or_else(|| e.as_string())
        .unwrap_or_else(|| "unknown error".to_owned());
    DrawingErrorKind::DrawingError(CanvasError(text))
}

/// A colour as the context holds it: RGB and the alpha's bits (exact comparison).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) struct Ink(u8, u8, u8, u64);

impl Ink {
    fn of(c: BackendColor) -> Self {
        Ink(c.rgb.0, c.rgb.1, c.rgb.2, c.alpha.to_bits())
    }

    /// The CSS colour: `#rrggbb` when opaque (the cheapest form to parse), else `rgba()`.
    fn css(c: BackendColor) -> String {
        let (r, g, b) = c.rgb;
        if c.alpha >= 1.0 {
            format!("#{r:02x}{g:02x}{b:02x}")
        } else {
            format!("rgba({r},{g},{b},{})", c.alpha)
        }
    }
}

/// What the context's current path holds that is not painted yet: a run of lines in one
/// stroke colour and width (see the module docs). Shared with the canvas's
/// [`CanvasDirect`], which paints it before drawing anything itself.
#[derive(Debug, Default, Clone, Copy, PartialEq, Eq)]
pub(super) enum Batch {
    /// Nothing pending.
    #[default]
    Empty,
    /// Lines, to be stroked with this colour and width (the context's stroke state).
    Lines(Ink, u32),
}

/// Paints what `batch` says the path of `context` holds, and empties it: called before
/// anything else is drawn, a style changes or a dash is set, and when a drawing ends.
#[inline(never)] // called from every drawing method
pub(super) fn paint_batch(context: &CanvasRenderingContext2d, batch: &Cell<Batch>) {
    if batch.replace(Batch::Empty) != Batch::Empty {
        context.stroke();
    }
}

/// What the context was last given, per piece of state (`None`: not yet set by us).
#[derive(Debug, Default, Clone, Copy)]
struct Set {
    stroke: Option<Ink>,
    fill: Option<Ink>,
    line_width: Option<u32>,
    align: Option<&'static str>,
    baseline: Option<&'static str>,
    /// The CSS font shorthand, as its hash (`canvas::width_hash`; two fonts of a session
    /// share one with odds below 10⁻¹⁸).
    font: Option<u64>,
}

thread_local! {
    /// The last stamp given to a [`Memory`].
    static STAMPS: Cell<u32> = const { Cell::new(0) };
}

/// What a canvas's 2D context was last given by this crate's backends ([`Set`]), kept
/// from one drawing to the next (see the module docs), and the stamp that says the context
/// still holds it.
#[derive(Debug)]
pub struct Memory {
    /// This memory's `shadowOffsetX`, unique within the module instance (1, 2, …; the
    /// context's own is 0). A shadow is drawn only in a colour that is not transparent,
    /// and no backend sets one (plotters has no shadows), so the offset changes no pixel.
    stamp: f64,
    set: Cell<Set>,
}

impl Memory {
    /// An empty memory with a stamp of its own.
    pub fn new() -> Rc<Self> {
        let n = STAMPS.with(|s| {
            s.set(s.get().wrapping_add(1).max(1));
            s.get()
        });
        Rc::new(Memory {
            stamp: f64::from(n),
            set: Cell::default(),
        })
    }

    /// Makes this memory the one `context` answers to: if the context does not carry its
    /// stamp, whatever reset it or drew on it since, the memory is emptied and the stamp
    /// put on. One property read per drawing. A first module (feature `first`) draws the
    /// first frames only and is within its download budget by a few hundred bytes: its
    /// memories last one drawing, and it takes the stamp off, so the full module's
    /// memories, which a first module's drawing may follow while it takes over, are
    /// emptied after it.
    fn claim(&self, context: &CanvasRenderingContext2d) {
        if cfg!(feature = "first") {
            self.set.take();
            context.set_shadow_offset_x(0.0);
        } else if context.shadow_offset_x() != self.stamp {
            self.set.take();
            context.set_shadow_offset_x(self.stamp);
        }
    }
}

/// Draws onto an HTML canvas; see the module docs.
pub struct HtmlCanvas {
    canvas: HtmlCanvasElement,
    context: CanvasRenderingContext2d,
    /// What the context holds; in a cell because plotters measures text through `&self`,
    /// shared with the canvas's later backends.
    memory: Rc<Memory>,
    /// Drawing nothing (see `render::Direct::mute`); shared with [`CanvasDirect`].
    muted: Rc<Cell<bool>>,
    /// What the path holds unpainted; shared with [`CanvasDirect`].
    batch: Rc<Cell<Batch>>,
}

impl HtmlCanvas {
    /// Draws on `canvas`; `None` if it has no 2D context.
    pub fn new(canvas: &HtmlCanvasElement) -> Option<Self> {
        let context = super::context_of(canvas)?;
        Some(Self::with_context(canvas.clone(), context, Memory::new()))
    }

    /// Draws on `canvas` through `context`, its 2D context, which `memory` (the canvas's,
    /// kept between drawings) may remember.
    pub(super) fn with_context(
        canvas: HtmlCanvasElement,
        context: CanvasRenderingContext2d,
        memory: Rc<Memory>,
    ) -> Self {
        memory.claim(&context);
        // Solid until told otherwise, even after a drawing that failed half-way.
        set_line_dash(&context, &[]);
        Self {
            canvas,
            context,
            memory,
            muted: Rc::default(),
            batch: Rc::default(),
        }
    }

    /// Paints the pending run (see [`Batch`]).
    fn flush(&self) {
        paint_batch(&self.context, &self.batch);
    }

    /// Whether the next line continues the pending run `run` (then it is only traced);
    /// otherwise the run is painted first.
    fn continues(&self, run: Batch) -> bool {
        if !self.muted.get() && self.batch.get() == run {
            return true;
        }
        self.flush();
        false
    }

    fn stroke_style(&mut self, style: &impl BackendStyle) {
        let ink = Ink::of(style.color());
        let mut set = self.memory.set.get();
        if set.stroke != Some(ink) {
            self.context.set_stroke_style_str(&Ink::css(style.color()));
            set.stroke = Some(ink);
        }
        let width = style.stroke_width();
        if set.line_width != Some(width) {
            self.context.set_line_width(f64::from(width));
            set.line_width = Some(width);
        }
        self.memory.set.set(set);
    }

    /// Sets the fill colour (`fill`) or the stroke colour and width of `style`; `false`,
    /// and nothing set, when it is fully transparent (nothing to draw).
    fn paint(&mut self, style: &impl BackendStyle, fill: bool) -> bool {
        if style.color().alpha == 0.0 || self.muted.get() {
            return false;
        }
        match fill {
            true => self.fill_style(style.color()),
            false => self.stroke_style(style),
        }
        true
    }

    fn fill_style(&mut self, color: BackendColor) {
        let ink = Ink::of(color);
        let mut set = self.memory.set.get();
        if set.fill != Some(ink) {
            self.context.set_fill_style_str(&Ink::css(color));
            set.fill = Some(ink);
            self.memory.set.set(set);
        }
    }

    /// Sets the font of `style` (the CSS shorthand `"<style> <size>px <family>"`).
    fn font(&self, style: &impl BackendTextStyle) {
        self.set_font(super::css_font(style));
    }

    /// Makes `font` (a CSS font shorthand) the context's font, unless it is already.
    fn set_font(&self, font: String) {
        let mut set = self.memory.set.get();
        let hash = super::width_hash(&font, "");
        if set.font != Some(hash) {
            self.context.set_font(&font);
            set.font = Some(hash);
            self.memory.set.set(set);
        }
    }

    fn anchor(&mut self, style: &impl BackendTextStyle) {
        let anchor = style.anchor();
        let align = match anchor.h_pos {
            HPos::Left => "start",
            HPos::Right => "end",
            HPos::Center => "center",
        };
        let mut set = self.memory.set.get();
        if set.align != Some(align) {
            self.context.set_text_align(align);
            set.align = Some(align);
        }
        let baseline = match anchor.v_pos {
            VPos::Top => "top",
            VPos::Center => "middle",
            VPos::Bottom => "bottom",
        };
        if set.baseline != Some(baseline) {
            self.context.set_text_baseline(baseline);
            set.baseline = Some(baseline);
        }
        self.memory.set.set(set);
    }

    /// What this canvas draws itself (dashes, stretched images), through a handle that
    /// lives beside the backend while plotters holds it.
    pub fn direct(&self) -> CanvasDirect {
        CanvasDirect {
            canvas: self.canvas.clone(),
            context: self.context.clone(),
            muted: self.muted.clone(),
            batch: self.batch.clone(),
        }
    }

    /// Traces `points` as one open path, through the vertices that shape it
    /// ([`corners`]: a curve sampled finer than its pixels has many that do not).
    fn trace(&self, points: impl IntoIterator<Item = BackendCoord>) -> bool {
        let mut begun = false;
        corners(points, |(x, y)| {
            let (x, y) = (f64::from(x), f64::from(y));
            if begun {
                self.context.line_to(x, y);
            } else {
                self.context.begin_path();
                self.context.move_to(x, y);
                begun = true;
            }
        });
        begun
    }
}

type Result<T> = std::result::Result<T, DrawingErrorKind<CanvasError>>;

impl Drop for HtmlCanvas {
    /// A drawing's last run is painted when its backend goes (plotters need not call
    /// `present`).
    fn drop(&mut self) {
        self.flush();
    }
}

/// A 1 px line along a pixel row or column lies between two of them and comes out as a
/// blurred 2 px line; half a pixel over puts it on one.
fn crisp(from: BackendCoord, to: BackendCoord) -> ((f64, f64), (f64, f64)) {
    let (mut a, mut b) = (
        (f64::from(from.0), f64::from(from.1)),
        (f64::from(to.0), f64::from(to.1)),
    );
    if from.0 == to.0 {
        a.0 -= 0.5;
        b.0 -= 0.5;
    }
    if from.1 == to.1 {
        a.1 -= 0.5;
        b.1 -= 0.5;
    }
    (a, b)
}

impl DrawingBackend for HtmlCanvas {
    type ErrorType = CanvasError;

    fn get_size(&self) -> (u32, u32) {
        (self.canvas.width(), self.canvas.height())
    }

    fn ensure_prepared(&mut self) -> Result<()> {
        Ok(())
    }

    fn present(&mut self) -> Result<()> {
        self.flush();
        Ok(())
    }

    fn draw_pixel(&mut self, point: BackendCoord, color: BackendColor) -> Result<()> {
        self.flush();
        if color.alpha == 0.0 || self.muted.get() {
            return Ok(());
        }
        self.fill_style(color);
        self.context
            .fill_rect(f64::from(point.0), f64::from(point.1), 1.0, 1.0);
        Ok(())
    }

    fn draw_line<S: BackendStyle>(
        &mut self,
        from: BackendCoord,
        to: BackendCoord,
        style: &S,
    ) -> Result<()> {
        let (a, b) = crisp(from, to);
        let run = Batch::Lines(Ink::of(style.color()), style.stroke_width());
        if self.continues(run) {
            self.context.move_to(a.0, a.1);
            self.context.line_to(b.0, b.1);
            return Ok(());
        }
        if !self.paint(style, false) {
            return Ok(());
        }
        self.context.begin_path();
        self.context.move_to(a.0, a.1);
        self.context.line_to(b.0, b.1);
        self.batch.set(run);
        Ok(())
    }

    fn draw_rect<S: BackendStyle>(
        &mut self,
        upper_left: BackendCoord,
        bottom_right: BackendCoord,
        style: &S,
        fill: bool,
    ) -> Result<()> {
        self.flush();
        if !self.paint(style, fill) {
            return Ok(());
        }
        let (x, y) = (f64::from(upper_left.0), f64::from(upper_left.1));
        let (w, h) = (
            f64::from(bottom_right.0 - upper_left.0),
            f64::from(bottom_right.1 - upper_left.1),
        );
        match fill {
            true => self.context.fill_rect(x, y, w, h),
            false => self.context.stroke_rect(x, y, w, h),
        }
        Ok(())
    }

    fn draw_path<S: BackendStyle, I: IntoIterator<Item = BackendCoord>>(
        &mut self,
        path: I,
        style: &S,
    ) -> Result<()> {
        self.flush();
        if self.paint(style, false) && self.trace(path) {
            self.context.stroke();
        }
        Ok(())
    }

    fn fill_polygon<S: BackendStyle, I: IntoIterator<Item = BackendCoord>>(
        &mut self,
        vert: I,
        style: &S,
    ) -> Result<()> {
        self.flush();
        if self.paint(style, true) && self.trace(vert) {
            self.context.close_path();
            self.context.fill();
        }
        Ok(())
    }

    fn draw_circle<S: BackendStyle>(
        &mut self,
        center: BackendCoord,
        radius: u32,
        style: &S,
        fill: bool,
    ) -> Result<()> {
        self.flush();
        if !self.paint(style, fill) {
            return Ok(());
        }
        let (x, y, r) = (f64::from(center.0), f64::from(center.1), f64::from(radius));
        self.context.begin_path();
        self.context.arc(x, y, r, 0.0, TAU).map_err(failed)?;
        match fill {
            true => self.context.fill(),
            false => self.context.stroke(),
        }
        Ok(())
    }

    fn draw_text<S: BackendTextStyle>(
        &mut self,
        text: &str,
        style: &S,
        pos: BackendCoord,
    ) -> Result<()> {
        self.flush();
        let color = style.color();
        // An empty text (the blank caption that keeps a plot's title band) draws nothing.
        if color.alpha == 0.0 || self.muted.get() || text.is_empty() {
            return Ok(());
        }
        // State first, then save/rotate/restore: the restore returns to what `set` says.
        self.fill_style(color);
        self.font(style);
        self.anchor(style);
        let quarter_turns = match style.transform() {
            FontTransform::None => 0.0,
            FontTransform::Rotate90 => 1.0,
            FontTransform::Rotate180 => 2.0,
            FontTransform::Rotate270 => 3.0,
        };
        let (x, y) = (f64::from(pos.0), f64::from(pos.1));
        if quarter_turns == 0.0 {
            return self.context.fill_text(text, x, y).map_err(failed);
        }
        self.context.save();
        let drawn = self
            .context
            .translate(x, y)
            .and_then(|()| {
                self.context
                    .rotate(quarter_turns * std::f64::consts::FRAC_PI_2)
            })
            .and_then(|()| self.context.fill_text(text, 0.0, 0.0));
        self.context.restore();
        drawn.map_err(failed)
    }

    fn estimate_text_size<S: BackendTextStyle>(&self, text: &str, style: &S) -> Result<(u32, u32)> {
        Ok(super::measure(&self.context, text, style, |font| {
            self.set_font(font)
        }))
    }
}
