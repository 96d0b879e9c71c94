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
fn browser_now_ms() -> f64 {
    use wasm_bindgen::JsCast;
    let global = js_sys::global();
    js_sys::Reflect::get(&global, &"performance".into())
        .ok()
        .filter(|p| p.is_object())
        .and_then(|perf| {
            let now = js_sys::Reflect::get(&perf, &"now".into()).ok()?;
            let now = now.dyn_into::<js_sys::Function>().ok()?;
            now.call0(&perf).ok()?.as_f64()
        })
        .unwrap_or_else(js_sys::Date::now)
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
