//! [`Study`]: a demo's full study computed in the page's worker (issue 13), so that the
//! page's own thread only draws. The worker's instance of the demo is given the page's
//! inputs, starts the same full study the page's instance left pending, computes it and
//! sends what it computed back as bytes, which the page's session takes in
//! ([`Session::adopt_study`](super::Session::adopt_study)) only if they are for its
//! pending study's inputs.

use super::js_err;
use crate::demos::{self, Demo};
use crate::params::resolve_query;
use crate::spec::DemoSpec;
use wasm_bindgen::prelude::*;

/// One demo's instance in the page's worker: it computes full studies, draws nothing.
#[wasm_bindgen]
pub struct Study {
    demo: Box<dyn Demo>,
    spec: DemoSpec,
}

#[wasm_bindgen]
impl Study {
    /// An instance of demo `id` (progressive, as the page's is, so that its inputs start
    /// the same full study); errors for an unknown id.
    #[wasm_bindgen(constructor)]
    pub fn new(id: &str) -> Result<Study, JsError> {
        let mut demo = demos::create(id).ok_or_else(|| js_err("unknown demo"))?;
        demo.set_progressive(true);
        let spec = demo.spec();
        Ok(Study { demo, spec })
    }

    /// Starts the full study for the page's query (`query`: the address's, for a
    /// lecturer's narrowed ranges) and values (`keys[i]` = `values[i]`, as
    /// `Session.values` gives them). Returns whether a full study is pending.
    pub fn start(&mut self, query: &str, keys: Vec<String>, values: Vec<f64>) -> bool {
        let mut spec = self.spec.clone();
        crate::lecturer::narrow(&mut spec, query);
        let (mut params, _) = resolve_query(&spec, query);
        for (key, value) in keys.iter().zip(&values) {
            params.set_raw(&spec, key, &format!("{value}"));
        }
        self.demo.recompute(&params);
        self.demo.advance_study(0.0).is_some()
    }

    /// Computes about `budget_ms` more of the study: the fraction done (1: finished, see
    /// [`Study::result`]), `undefined` when none is pending.
    pub fn advance(&mut self, budget_ms: f64) -> Option<f64> {
        self.demo.advance_study(budget_ms)
    }

    /// The finished study as bytes for the page's session; `undefined` before it is finished.
    pub fn result(&self) -> Option<Vec<u8>> {
        self.demo.export_study()
    }
}
