// Zeta Lab front end: loads the wasm module, builds the chosen demo from its Rust
// declaration and redraws at most once per animation frame while sliders move.
import init, { Session, demoList, takePanicMessage } from '../zeta-app.js';
import { buildDemo, fromSlider, notify, showReadouts, showValue, formatValue } from './ui.js';
import { currentQuery, demoFromUrl, writeState } from './url.js';

const DEFAULT_DEMO = 'regimes';
const darkQuery = window.matchMedia('(prefers-color-scheme: dark)');

const app = {
  demoId: null,
  session: null,
  view: null,
  framePending: false,
  needsRecovery: false,
  lastSize: new Map(),
  notices: null,
  root: null,
};

function isDark() {
  const forced = new URLSearchParams(window.location.search).get('theme');
  if (forced === 'dark') return true;
  if (forced === 'light') return false;
  return darkQuery.matches;
}

/** Reports an error from a wasm call without breaking the page; the next input recovers. */
function reportFailure(err) {
  const panic = takePanicMessage();
  const text = panic || (err && err.message) || String(err);
  console.warn('Zeta Lab recovered from an error:', text);
  notify(app.notices, `Something went wrong and the demo was restarted: ${text}`, 'error');
  app.needsRecovery = true;
}

function recover() {
  const values = app.session ? safeValues() : [];
  app.session = new Session(app.demoId);
  for (const [k, v] of values) app.session.set(k, String(v));
  attachCanvases();
  app.needsRecovery = false;
}

function safeValues() {
  try {
    return app.session.values();
  } catch {
    return [];
  }
}

function attachCanvases() {
  app.lastSize.clear();
  for (const [key, canvas] of app.view.canvases) app.session.attach(key, canvas);
}

function sizeCanvases() {
  const dpr = window.devicePixelRatio || 1;
  for (const [key, canvas] of app.view.canvases) {
    const w = Math.max(1, Math.round(canvas.clientWidth * dpr));
    const h = Math.max(1, Math.round(canvas.clientHeight * dpr));
    const last = app.lastSize.get(key);
    if (!last || last[0] !== w || last[1] !== h) {
      canvas.width = w;
      canvas.height = h;
      app.lastSize.set(key, [w, h]);
    }
  }
  return dpr;
}

function drawFrame() {
  app.framePending = false;
  try {
    if (app.needsRecovery) recover();
    const dpr = sizeCanvases();
    const readouts = app.session.update(dpr, isDark());
    showReadouts(app.view.readouts, readouts);
  } catch (err) {
    reportFailure(err);
  }
}

/** Schedules one redraw on the next animation frame; bursts of input coalesce. */
function requestDraw() {
  if (app.framePending) return;
  app.framePending = true;
  requestAnimationFrame(drawFrame);
}

function syncUrl() {
  try {
    writeState(app.demoId, app.session.values());
  } catch (err) {
    reportFailure(err);
  }
}

function setParam(control, raw, fromNumberBox) {
  try {
    if (app.needsRecovery) recover();
    const res = app.session.set(control.param.key, raw);
    if (!res) return;
    if (res.notice) notify(app.notices, res.notice.message, 'warn');
    if (fromNumberBox || res.notice) showValue(control, res.value);
    else {
      control.number.value = formatValue(control.param, res.value);
      showValue(control, res.value);
    }
  } catch (err) {
    reportFailure(err);
  }
  requestDraw();
  syncUrl();
}

function wireControls() {
  for (const control of app.view.controls.values()) {
    control.range.addEventListener('input', () => {
      setParam(control, String(fromSlider(control.param, control.range.value)), false);
    });
    control.number.addEventListener('change', () => setParam(control, control.number.value, true));
  }
}

function showAllValues() {
  for (const [key, value] of app.session.values()) {
    const control = app.view.controls.get(key);
    if (control) showValue(control, value);
  }
}

function openDemo(id, query) {
  app.demoId = id;
  app.session = new Session(id);
  const notices = query ? app.session.applyQuery(query) : [];
  const spec = app.session.spec();
  app.view = buildDemo(app.root, spec);
  document.title = `${spec.title} — Zeta Lab`;
  attachCanvases();
  wireControls();
  showAllValues();
  for (const n of notices) notify(app.notices, n.message, 'warn');
  const select = document.getElementById('demo-select');
  if (select) select.value = id;
  requestDraw();
}

function buildMenu(list) {
  const select = document.getElementById('demo-select');
  for (const d of list) {
    const opt = document.createElement('option');
    opt.value = d.id;
    opt.textContent = d.title;
    select.append(opt);
  }
  select.addEventListener('change', () => {
    openDemo(select.value, null);
    syncUrl();
  });
}

function applyForcedTheme() {
  const forced = new URLSearchParams(window.location.search).get('theme');
  if (forced === 'dark' || forced === 'light') document.documentElement.dataset.theme = forced;
}

async function main() {
  applyForcedTheme();
  app.root = document.getElementById('demo');
  app.notices = document.getElementById('notices');
  try {
    await init({ module_or_path: new URL('../zeta-app_bg.wasm', import.meta.url) });
  } catch (err) {
    app.root.replaceChildren();
    const p = document.createElement('p');
    p.className = 'notice notice-error';
    p.textContent = `The solver could not be loaded (${err && err.message ? err.message : err}). This page needs WebAssembly.`;
    app.root.append(p);
    return;
  }
  const list = demoList();
  buildMenu(list);
  const wanted = demoFromUrl();
  const known = list.some((d) => d.id === wanted);
  if (wanted !== null && !known) {
    notify(app.notices, `There is no demo called “${wanted.slice(0, 40)}”; showing ${DEFAULT_DEMO}.`, 'warn');
  }
  openDemo(known ? wanted : DEFAULT_DEMO, known ? currentQuery() : null);
  new ResizeObserver(() => requestDraw()).observe(app.root);
  darkQuery.addEventListener('change', () => requestDraw());
  document.documentElement.dataset.ready = 'true';
}

main();
