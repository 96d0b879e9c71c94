// The page's worker (issue 13): computes a demo's full study (the design sweep, the Monte
// Carlo run, the convergence study) in its own instance of the full module, so that the
// page's thread only draws. In: {seq, id, query, keys, values}, the study for those inputs;
// a newer message (or {seq} alone, sent when the inputs move on) drops an older study
// between two slices. Out, for that seq: {done} (0-1) as it goes, {bytes} when it is done
// (the page's Session.adoptStudy takes them in if its inputs are still those), {none} when
// those inputs need no study, {error}.
import init, { Study } from '../zeta-app.js';

/** How long one slice computes before the worker looks for a newer message (ms). */
const SLICE_MS = 10;
/** How often the page hears how far the study is, after the first slice (ms): its bar moves no faster. */
const TELL_MS = 100;

const ready = init({ module_or_path: new URL('../zeta-app_bg.wasm', import.meta.url) });
/** One instance per demo: its last full study stays there, so the same inputs again cost nothing. */
const studies = new Map();
let latest = 0;

self.onmessage = async ({ data }) => {
  const { seq, id } = data;
  latest = seq;
  if (id === undefined) return; // only a newer seq: the study under way is dropped
  try {
    await ready;
    if (seq !== latest) return;
    if (!studies.has(id)) studies.set(id, new Study(id));
    const study = studies.get(id);
    if (!study.start(data.query, data.keys, Float64Array.from(data.values))) {
      postMessage({ seq, none: true });
      return;
    }
    let told = -Infinity; // the first slice's progress goes at once
    for (;;) {
      const done = study.advance(SLICE_MS);
      if (done === undefined) {
        postMessage({ seq, none: true });
        return;
      }
      if (done >= 1) break;
      if (performance.now() - told >= TELL_MS) {
        told = performance.now();
        postMessage({ seq, done });
      }
      await new Promise((resolve) => setTimeout(resolve, 0));
      if (seq !== latest) return; // the inputs moved on: this study is dropped
    }
    const bytes = study.result();
    postMessage({ seq, bytes }, [bytes.buffer]);
  } catch (err) {
    postMessage({ seq, error: String((err && err.message) || err) });
  }
};
