//! [`CanvasDirect`]: what the canvas draws itself beside plotters' calls (see
//! `render::Direct`): line dashes, images of a pixel per cell stretched over a heatmap, a
//! muted trial layout, and each plot's static layer (background, grid, ticks, axis names,
//! backdrop) kept as a copy once it has come twice in a row, so a held drag starts each
//! frame from it; for a plot with a backdrop also the part under it, for a drag that moves
//! the backdrop.

use crate::render::{Direct, Kept, LayerKeys, LayerNote, Stretched};
use std::cell::{Cell, RefCell};
use std::rc::Rc;
use wasm_bindgen::{JsCast, JsValue};
use web_sys::{CanvasRenderingContext2d, HtmlCanvasElement};

/// The canvas's [`Direct`] drawing (see [`super::direct`]).
pub struct CanvasDirect {
    pub(super) canvas: HtmlCanvasElement,
    pub(super) context: CanvasRenderingContext2d,
    pub(super) muted: Rc<Cell<bool>>,
    /// The backend's unstroked run of lines, painted before this draws anything or sets a
    /// dash.
    pub(super) batch: Rc<Cell<super::html::Batch>>,
}

impl CanvasDirect {
    /// Paints the backend's pending run (see `html::Batch`).
    fn flush(&self) {
        super::html::paint_batch(&self.context, &self.batch);
    }
}

/// A canvas's static layer: the whole of it and, for a plot with a backdrop, the part
/// under the backdrop, each kept as a copy once it has come twice in a row (see [`Part`]),
/// with what the whole layer's drawing noted. The part under the backdrop serves a drag
/// that moves the backdrop too (an exact solution under the numerical ones).
struct Layer {
    canvas: HtmlCanvasElement,
    whole: Part,
    axes: Part,
    note: LayerNote,
}

impl Layer {
    fn new(canvas: &HtmlCanvasElement) -> Self {
        Self {
            canvas: canvas.clone(),
            whole: Part::default(),
            axes: Part::default(),
            note: LayerNote::default(),
        }
    }
}

/// One part of a static layer: the key last begun, in how many frames in a row, and a
/// copy of it, `valid` once the key has come twice in a row (a plot whose axes change
/// every frame is never copied, nor is the whole layer of one whose backdrop does). A plot
/// whose backdrop only the view moves (resonance's family) keeps the part under it too,
/// unused: a second canvas and a second copy on the frames that keep one, the price of not
/// telling the two kinds of backdrop apart.
#[derive(Default)]
struct Part {
    key: u64,
    frames: u32,
    copy: Option<HtmlCanvasElement>,
    valid: bool,
}

impl Part {
    /// Counts a frame that begins with `key`.
    fn count(&mut self, key: u64) {
        if self.key == key {
            self.frames = self.frames.saturating_add(1);
        } else {
            (self.key, self.frames, self.valid) = (key, 1, false);
        }
    }

    /// The copy, if it holds this key at `size` (a resized canvas was cleared).
    fn held(&self, size: (u32, u32)) -> Option<&HtmlCanvasElement> {
        let copy = self.copy.as_ref()?;
        (self.valid && (copy.width(), copy.height()) == size).then_some(copy)
    }

    /// Keeps what `canvas` shows as this part's copy if `key` has come twice in a row.
    fn keep(&mut self, key: u64, canvas: &HtmlCanvasElement) -> bool {
        if self.key != key || self.frames < 2 {
            return false;
        }
        if self.copy.is_none() {
            self.copy = offscreen();
        }
        let Some(copy) = &self.copy else {
            return false;
        };
        let (w, h) = (canvas.width(), canvas.height());
        let resized = (copy.width(), copy.height()) != (w, h);
        // Resizing also clears it; setting the same size again would set its storage up
        // anew, so at the same size it is only cleared.
        if resized {
            copy.set_width(w);
            copy.set_height(h);
        }
        self.valid = super::context_of(copy).is_some_and(|c| {
            if !resized {
                c.clear_rect(0.0, 0.0, f64::from(w), f64::from(h));
            }
            c.draw_image_with_html_canvas_element(canvas, 0.0, 0.0)
                .is_ok()
        });
        self.valid
    }
}

/// A canvas outside the page of one size, with its context (see `SCRATCH`), and the hash
/// of the image last put on it (0: none; see [`image_key`]).
struct Scratch {
    size: (u32, u32),
    canvas: HtmlCanvasElement,
    context: CanvasRenderingContext2d,
    holds: u64,
}

/// The pixels of `rgb` as a hash, never 0: a scratch canvas that holds them already is
/// not given them again (a colour bar is the same image every frame, a map the same while
/// only the design point moves). Not in a first module, which draws for seconds only.
fn image_key(rgb: &[u8]) -> u64 {
    use std::hash::Hasher;
    if cfg!(feature = "first") {
        return 0;
    }
    let mut h = rustc_hash::FxHasher::default();
    h.write(rgb);
    h.finish().max(1)
}

/// How many sizes of scratch canvas are kept.
const SCRATCHES: usize = 4;

/// Runs `draw` with a scratch canvas of `size` (kept, or made now); nothing if none can be
/// made.
fn with_scratch(size: (u32, u32), draw: impl FnOnce(&mut Scratch)) {
    SCRATCH.with_borrow_mut(|kept| {
        if !kept.iter().any(|s| s.size == size) {
            let Some(canvas) = offscreen() else {
                return;
            };
            canvas.set_width(size.0);
            canvas.set_height(size.1);
            let Some(context) = super::context_of(&canvas) else {
                return;
            };
            if kept.len() >= SCRATCHES {
                kept.remove(0);
            }
            kept.push(Scratch {
                size,
                canvas,
                context,
                holds: 0,
            });
        }
        if let Some(s) = kept.iter_mut().find(|s| s.size == size) {
            draw(s);
        }
    });
}

/// How many canvases' layers are kept: every plot of a page, and a few of the last.
const LAYERS: usize = 12;

/// A demo's first module keeps no layer: it draws only until the full module takes over
/// (seconds after the first plot), and its bytes are the first plot's wait.
const KEEPS_NO_LAYER: bool = cfg!(feature = "first");

/// A new canvas outside the page.
fn offscreen() -> Option<HtmlCanvasElement> {
    web_sys::window()?
        .document()?
        .create_element("canvas")
        .ok()?
        .dyn_into::<HtmlCanvasElement>()
        .ok()
}

thread_local! {
    /// Canvases outside the page that hold an image before it is stretched, one per size
    /// (a heatmap and its colour bar differ): resizing a canvas clears it and sets its
    /// storage up again, and a drag draws both every frame.
    static SCRATCH: RefCell<Vec<Scratch>> = const { RefCell::new(Vec::new()) };
    /// The static layers of the canvases drawn last, most recent last.
    static KEPT: RefCell<Vec<Layer>> = const { RefCell::new(Vec::new()) };
}

/// Makes the canvases that will hold `canvas`'s static layer now (and the part under its
/// backdrop, for a plot drawn with one), sized and with their 2D contexts, unless they
/// exist: done while the controls rest, so the first drag does not pay for a new canvas
/// (about 10 ms at 4× CPU slowdown, the largest cost of that frame).
pub fn prepare(canvas: &HtmlCanvasElement) {
    if KEEPS_NO_LAYER {
        return;
    }
    KEPT.with_borrow_mut(|kept| {
        let i = match kept.iter().position(|l| l.canvas == *canvas) {
            Some(i) => i,
            None => {
                if kept.len() >= LAYERS {
                    kept.remove(0);
                }
                kept.push(Layer::new(canvas));
                kept.len() - 1
            }
        };
        let layer = &mut kept[i];
        // A part under a backdrop has a key once a plot with a backdrop was drawn here.
        let backdrop = layer.axes.key != 0;
        for part in [Some(&mut layer.whole), backdrop.then_some(&mut layer.axes)]
            .into_iter()
            .flatten()
            .filter(|part| part.copy.is_none())
        {
            part.copy = blank_like(canvas);
        }
    });
}

/// A new canvas outside the page of `canvas`'s size, its storage set up.
fn blank_like(canvas: &HtmlCanvasElement) -> Option<HtmlCanvasElement> {
    let copy = offscreen()?;
    copy.set_width(canvas.width());
    copy.set_height(canvas.height());
    // A first drawing makes the browser set the canvas's storage up now.
    super::context_of(&copy)?.clear_rect(0.0, 0.0, 1.0, 1.0);
    Some(copy)
}

/// Whether `canvas` keeps a copy of the static layer last drawn on it, at its size (a
/// drag's next frame then starts from it).
#[cfg(not(feature = "first"))]
pub fn keeps_layer(canvas: &HtmlCanvasElement) -> bool {
    let size = (canvas.width(), canvas.height());
    KEPT.with_borrow(|kept| {
        kept.iter()
            .any(|l| l.canvas == *canvas && l.whole.held(size).is_some())
    })
}

impl Direct for CanvasDirect {
    fn dash(&self, pattern: &[f64]) {
        self.flush();
        set_line_dash(&self.context, pattern);
    }

    fn mute(&self, on: bool) {
        self.flush();
        self.muted.set(on);
    }

    fn begin_layer(&self, keys: LayerKeys) -> Option<Kept> {
        self.flush();
        if KEEPS_NO_LAYER {
            return None;
        }
        KEPT.with_borrow_mut(|kept| {
            let mut layer = match kept.iter().position(|l| l.canvas == self.canvas) {
                Some(i) => kept.remove(i),
                None => Layer::new(&self.canvas),
            };
            layer.whole.count(keys.whole);
            if keys.has_backdrop() {
                layer.axes.count(keys.axes);
            }
            let size = (self.canvas.width(), self.canvas.height());
            // Drawn whole, a copy covers what was there; drawImage leaves the state the
            // backend caches as it was.
            let draw = |copy: &HtmlCanvasElement| {
                self.context
                    .draw_image_with_html_canvas_element(copy, 0.0, 0.0)
                    .is_ok()
            };
            let drawn = if layer.whole.held(size).is_some_and(draw) {
                Some(Kept::Whole(layer.note))
            } else if keys.has_backdrop() && layer.axes.held(size).is_some_and(draw) {
                Some(Kept::Axes)
            } else {
                None
            };
            self.muted.set(drawn.is_some());
            if kept.len() >= LAYERS {
                kept.remove(0);
            }
            kept.push(layer);
            drawn
        })
    }

    fn axes_done(&self, keys: LayerKeys) {
        self.flush();
        if self.muted.replace(false) || KEEPS_NO_LAYER || !keys.has_backdrop() {
            return;
        }
        KEPT.with_borrow_mut(|kept| {
            if let Some(layer) = kept.iter_mut().find(|l| l.canvas == self.canvas) {
                layer.axes.keep(keys.axes, &self.canvas);
            }
        });
    }

    fn end_layer(&self, keys: LayerKeys, note: LayerNote) {
        self.flush();
        if self.muted.replace(false) || KEEPS_NO_LAYER {
            return;
        }
        KEPT.with_borrow_mut(|kept| {
            let Some(layer) = kept.iter_mut().find(|l| l.canvas == self.canvas) else {
                return;
            };
            if layer.whole.keep(keys.whole, &self.canvas) {
                layer.note = note;
            }
        });
    }

    fn stretch(&self, image: &Stretched<'_>) {
        self.flush();
        let (w, h) = image.size;
        let n = (w as usize) * (h as usize);
        if image.rgb.len() < n * 3 || n == 0 {
            return;
        }
        let rgb = &image.rgb[..n * 3];
        let key = image_key(rgb);
        // Every pixel of the scratch canvas is put: nothing of an earlier image shows.
        with_scratch((w, h), |s| {
            // A context that was reset (lost and restored) has lost the image too, and
            // its shadow offset, which is set when an image is put (putImageData ignores
            // it, and nothing else is drawn on a scratch canvas).
            if key == 0 || s.holds != key || s.context.shadow_offset_x() != 1.0 {
                s.holds = 0;
                let mut rgba = Vec::with_capacity(n * 4);
                for px in rgb.chunks_exact(3) {
                    rgba.extend_from_slice(&[px[0], px[1], px[2], 255]);
                }
                let Ok(data) = web_sys::ImageData::new_with_u8_clamped_array_and_sh(
                    wasm_bindgen::Clamped(&rgba),
                    w,
                    h,
                ) else {
                    return;
                };
                if s.context.put_image_data(&data, 0.0, 0.0).is_err() {
                    return;
                }
                s.context.set_shadow_offset_x(1.0);
                s.holds = key;
            }
            let canvas = &s.canvas;
            let [l, t, r, b] = image.to.map(f64::from);
            let [cl, ct, cr, cb] = image.clip.map(f64::from);
            let c = &self.context;
            // Saved and restored, so the state the backend caches stays true.
            c.save();
            c.begin_path();
            c.rect(cl, ct, cr - cl, cb - ct);
            c.clip();
            c.set_image_smoothing_enabled(false);
            let _ = c.draw_image_with_html_canvas_element_and_dw_and_dh(canvas, l, t, r - l, b - t);
            c.restore();
        });
    }
}

pub(super) fn set_line_dash(context: &CanvasRenderingContext2d, pattern: &[f64]) {
    let array: js_sys::Array = pattern.iter().map(|&v| JsValue::from_f64(v)).collect();
    // Only a non-finite length can fail; the pattern is then left as it was.
    let _ = context.set_line_dash(&array);
}
