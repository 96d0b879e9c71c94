// The page's side of the study worker (web/study-worker.js, issue 13). A demo with a heavy
// study shows a coarse one at once (marked provisional) and leaves the full one to the
// worker: once the controls rest, the worker gets the open demo's inputs, computes and
// sends the study back, and the session takes it in only if its inputs are still those
// (Session.adoptStudy checks them exactly); the page then draws it. Without a worker
// (none in this browser, or it failed), the full study runs in the page in short slices
// between frames (main.js, scheduleRefine), as it did before. The root element says
// where the last study came from: data-studies="worker" or "page" (diagnostics, tests).

import { currentQuery } from './url.js';

/** How long the controls rest before the worker is given their inputs (ms). */
const REST_MS = 100;

let worker = null;
let failed = false;
let seq = 0;
let timer = 0;
/** The request under way: its seq and the session it is for. */
let asked = null;

/**
 * The open demo has a provisional study (a frame drew a coarse one): hands it to the
 * worker once the controls rest. From main.js: its state `app` and how it draws a frame,
 * refines a study in slices and moves the progress bars.
 */
export function offload(app, requestDraw, scheduleRefine, showStudyProgress) {
  const page = { app, requestDraw, scheduleRefine, showStudyProgress };
  const { session } = app;
  if (failed || typeof Worker !== 'function' || !session.setWorker) return false;
  session.setWorker(true);
  clearTimeout(timer);
  if (asked && worker) {
    // The inputs moved on: the worker drops the study under way at its next slice, so it
    // does not compete with the page's frames for a study that would not be taken.
    worker.postMessage({ seq: ++seq });
    asked = null;
  }
  timer = setTimeout(() => ask(page, session), REST_MS);
  return true;
}

function ask(page, session) {
  timer = 0;
  if (page.app.session !== session) return;
  try {
    worker ??= start(page);
  } catch {
    fallBack(page);
    return;
  }
  const pairs = session.values();
  asked = { seq: ++seq, session };
  worker.postMessage({
    seq,
    id: page.app.demoId,
    query: currentQuery(),
    keys: pairs.map(([k]) => k),
    values: pairs.map(([, v]) => v),
  });
}

function start(page) {
  const w = new Worker(new URL('./study-worker.js', import.meta.url), { type: 'module' });
  w.onmessage = ({ data }) => answer(page, data);
  w.onerror = (ev) => {
    ev.preventDefault();
    console.warn('Zeta Lab: the study worker failed; studies run in the page:', ev.message);
    failed = true;
    worker?.terminate();
    worker = null;
    fallBack(page);
  };
  return w;
}

function answer(page, data) {
  try {
    take(page, data);
  } catch (err) {
    // A failed instance: the page's next call into it reports it and recovers.
    console.warn('Zeta Lab: a study from the worker could not be taken in:', err && err.message);
  }
}

function take(page, data) {
  if (!asked || data.seq !== asked.seq || page.app.session !== asked.session) return; // overtaken
  const { session } = asked;
  if ('done' in data) {
    page.showStudyProgress(data.done);
    return;
  }
  asked = null;
  if (data.error) {
    console.warn('Zeta Lab: the study worker could not compute; studies run in the page:', data.error);
    failed = true;
  }
  if (data.bytes && session.adoptStudy(data.bytes) === 1) {
    document.documentElement.dataset.studies = 'worker';
    page.requestDraw();
    return;
  }
  // Not taken (no newer request waits): the page computes the study itself.
  if (!timer) fallBack(page);
}

/** The open demo's study runs in the page's slices (main.js) instead. */
function fallBack(page) {
  const { session } = page.app;
  document.documentElement.dataset.studies = 'page';
  try {
    session.setWorker(false);
  } catch {
    return; // a failed instance: the page recovers on the next input
  }
  page.scheduleRefine();
}
