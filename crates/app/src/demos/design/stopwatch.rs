//! Wall-clock stopwatch for the compute-time readouts: `performance.now()` in the browser,
//! `Instant` natively. Timing is only reported, never used in any result (the snapshot
//! tests mask it).

/// Started at [`Stopwatch::start`]; read with [`Stopwatch::elapsed_ms`].
pub(crate) struct Stopwatch {
    #[cfg(target_arch = "wasm32")]
    start: f64,
    #[cfg(not(target_arch = "wasm32"))]
    start: std::time::Instant,
}

#[cfg(target_arch = "wasm32")]
#[wasm_bindgen::prelude::wasm_bindgen]
extern "C" {
    /// `performance.now()` of the page or worker (ms); an error where there is none.
    #[wasm_bindgen(catch, js_namespace = performance, js_name = now)]
    fn performance_now() -> Result<f64, wasm_bindgen::JsValue>;
}

/// The browser's clock (ms): `performance.now()`, else `Date.now()`. Bound directly
/// rather than looked up by name on each call (two property reads, a function check and
/// a JavaScript string made for each name): the progressive studies read the clock after
/// every slice to keep within their budgets, and the lookups took 0.1 s of a 12 s profile
/// of design's sliders at 4× CPU slowdown (2026-12-01), a tenth of its map's computing.
#[cfg(target_arch = "wasm32")]
fn browser_now_ms() -> f64 {
    performance_now().unwrap_or_else(|_| js_sys::Date::now())
}

impl Stopwatch {
    /// Starts timing.
    pub(crate) fn start() -> Self {
        Self {
            #[cfg(target_arch = "wasm32")]
            start: browser_now_ms(),
            #[cfg(not(target_arch = "wasm32"))]
            start: std::time::Instant::now(),
        }
    }

    /// Milliseconds since [`Stopwatch::start`] (never negative: the browser clock may fall
    /// back to `Date.now()`, which can step backwards).
    pub(crate) fn elapsed_ms(&self) -> f64 {
        #[cfg(target_arch = "wasm32")]
        {
            (browser_now_ms() - self.start).max(0.0)
        }
        #[cfg(not(target_arch = "wasm32"))]
        {
            self.start.elapsed().as_secs_f64() * 1e3
        }
    }
}
