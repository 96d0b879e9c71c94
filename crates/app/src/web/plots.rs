//! What the page asks of one drawn plot: values under the pointer, a click that picks
//! parameters, the time cursor's pixel, and its exports (CSV, SVG, another canvas).

use super::draw::{device_scale, draw_on};
use super::js_err;
use super::session::Session;
#[cfg(not(feature = "first"))]
use super::to_js;
#[cfg(not(feature = "first"))]
use crate::export;
use wasm_bindgen::prelude::*;
use web_sys::HtmlCanvasElement;

#[wasm_bindgen]
impl Session {
    /// Backend-pixel x of time `t` on plot `key`, if its x axis is time and `t` is in range.
    #[wasm_bindgen(js_name = timeToPixel)]
    pub fn time_to_pixel(&self, key: &str, t: f64) -> Option<f64> {
        let (i, fig) = self.figure(key)?;
        let geo = self.geometry.get(i).copied().flatten()?;
        (fig.x.unit == "s" && t >= fig.x.range.0 && t <= fig.x.range.1)
            .then(|| geo.to_pixel(t, fig.y.range.0).0)
    }

    /// The values under the pointer at backend pixel `(px, py)` of plot `key`:
    /// `{x_text, y_text, points: [{px, py, color, text}]}`, or `undefined` outside the plot.
    /// Not in the first module (feature `first`): a pointer over a plot reads values once the
    /// full module has taken over, about a second after the first plot on a slow line.
    #[cfg(not(feature = "first"))]
    pub fn probe(&mut self, key: &str, px: f64, py: f64) -> Result<JsValue, JsError> {
        let Some(i) = self.drawn_plot(key)? else {
            return Ok(JsValue::UNDEFINED);
        };
        let (Some(fig), Some(geo)) = (self.built(i), self.geometry.get(i).copied().flatten())
        else {
            return Ok(JsValue::UNDEFINED);
        };
        match export::probe(fig, &geo, px, py) {
            Some(p) => to_js(&p),
            None => Ok(JsValue::UNDEFINED),
        }
    }

    /// CSV of plot `key`'s data, with the parameters and units in a header. Not in the
    /// first module (feature `first`), like every export: the page waits for the full one.
    #[cfg(not(feature = "first"))]
    pub fn csv(&mut self, key: &str) -> Result<String, JsError> {
        let i = self.build_plot(key).ok_or_else(|| js_err("no such plot"))?;
        let fig = self.built(i).ok_or_else(|| js_err("no such plot"))?;
        let params: Vec<(&str, f64, &str)> = self
            .params
            .pairs()
            .map(|(k, v)| (k, v, self.spec.param(k).map(|p| p.unit).unwrap_or("")))
            .collect();
        Ok(export::csv(self.spec.id, &params, fig))
    }

    /// SVG document of plot `key` at `w × h` px. Text is measured with `measure`'s 2D
    /// context (any canvas), so export works under a strict Content-Security-Policy. Not in
    /// the first module (feature `first`): the page waits for the full one to export SVG.
    #[cfg(not(feature = "first"))]
    pub fn svg(
        &mut self,
        key: &str,
        w: u32,
        h: u32,
        dark: bool,
        measure: HtmlCanvasElement,
    ) -> Result<String, JsError> {
        let i = self.build_plot(key).ok_or_else(|| js_err("no such plot"))?;
        let fig = self.built(i).ok_or_else(|| js_err("no such plot"))?;
        let mut buf = String::new();
        {
            let size = (w.clamp(16, 8000), h.clamp(16, 8000));
            let svg = plotters::prelude::SVGBackend::with_string(&mut buf, size);
            let backend = crate::canvas::Web::svg(svg, &measure)
                .ok_or_else(|| js_err("no 2D context to measure text"))?;
            let area = plotters::prelude::IntoDrawingArea::into_drawing_area(backend);
            crate::render::render(&area, fig, &super::theme(dark), 1.0).map_err(js_err)?;
        }
        Ok(buf)
    }

    /// Draws plot `key` onto another canvas (e.g. a 2× canvas for PNG export).
    #[wasm_bindgen(js_name = renderTo)]
    pub fn render_to(
        &mut self,
        key: &str,
        canvas: HtmlCanvasElement,
        scale: f64,
        dark: bool,
    ) -> Result<(), JsError> {
        let i = self.build_plot(key).ok_or_else(|| js_err("no such plot"))?;
        let fig = self.built(i).ok_or_else(|| js_err("no such plot"))?;
        let backend = crate::canvas::on(&canvas).ok_or_else(|| js_err("no 2D context"))?;
        let scale = device_scale(scale, 8.0);
        draw_on(backend, fig, dark, scale, None).map(|_| ())
    }

    /// A click at backend pixel `(px, py)` of plot `key`: the demo may choose parameters
    /// from the point (e.g. a design on a map). Returns `[[key, value]]` applied. Not in
    /// the first module (feature `first`), as [`Session::probe`].
    #[cfg(not(feature = "first"))]
    pub fn pick(&mut self, key: &str, px: f64, py: f64) -> Result<JsValue, JsError> {
        let Some(i) = self.drawn_plot(key)? else {
            return to_js(&Vec::<(&str, f64)>::new());
        };
        let Some((x, y)) = self
            .geometry
            .get(i)
            .copied()
            .flatten()
            .and_then(|g| g.to_data(px, py))
        else {
            return to_js(&Vec::<(&str, f64)>::new());
        };
        let plot = self.spec.plots.get(i).map(|p| p.key).unwrap_or("");
        let mut applied = Vec::new();
        for (k, v) in self.demo.pick(plot, x, y) {
            if let Some((v, _)) = self.params.set_raw(&self.spec, k, &format!("{v}")) {
                applied.push((k, v));
            }
        }
        to_js(&applied)
    }
}

impl Session {
    /// Plot `key`'s index, drawn by this session: one on screen that it has not drawn yet
    /// (after a take-over the page shows the first module's drawing until the catch-up
    /// draws it again, the same pixels) is drawn now, from the last update's results, so
    /// that a click or the pointer on it is read against what is seen.
    #[cfg(not(feature = "first"))]
    fn drawn_plot(&mut self, key: &str) -> Result<Option<usize>, JsError> {
        let Some(i) = self.plot_index(key) else {
            return Ok(None);
        };
        let undrawn = self.geometry.get(i).is_some_and(Option::is_none) || self.built(i).is_none();
        if let (true, Some(how)) = (undrawn && self.attached(i), self.last_drawn) {
            self.build(i);
            self.draw_one(i, how)?;
        }
        Ok(Some(i))
    }
}
