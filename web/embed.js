// Embedding: the embed view options and the host-page API over postMessage.
//
// Host → page                                   Page → host
//   {type:'zeta:set', params:{zeta:0.3}}          (then zeta:change)
//   {type:'zeta:get'}                             {type:'zeta:state', demo, params, readouts}
//   {type:'zeta:getState'}                        {type:'zeta:stateToken', token}
//   {type:'zeta:setState', token}                 (applies it, then zeta:change)
//   {type:'zeta:play'} / {type:'zeta:pause'}      (then zeta:playback {playing, t, speed})
//   {type:'zeta:seek', t} / {type:'zeta:speed', x}
//   {type:'zeta:export', plot, format}            {type:'zeta:file', plot, format, mime, data}
//   {type:'zeta:describe'}                        {type:'zeta:schema', schema}
//                                                 {type:'zeta:ready' | 'zeta:change', demo, params, readouts}
//                                                 {type:'zeta:resize', height}
//                                                 {type:'zeta:prediction', statement, …}
//                                                 {type:'zeta:error', request, message}
// Messages are accepted only from the parent window and, when the page was given
// `origin=<host origin>`, only from that origin; every message goes to the parent window
// only, and with `origin=` only to that origin. Anything malformed is ignored.
import { glue } from './glue.js';
import { notify } from './ui.js';
import { decodeToken, encodeToken, loaded, parsePresets, tokenInText, tokenNotice, viewQuery } from './state.js';
import { setupPrediction } from './predict.js';
import { cancelPendingWrite } from './url.js';
import { t } from './i18n.js';

const MAX_KEYS = 64;
const THEMES = ['light', 'dark', 'projector'];
const SPEED_RANGE = [0.1, 10];

/** Options of the embed view from the query string. */
export function embedOptions(search = window.location.search) {
  const q = new URLSearchParams(search);
  const list = (name) => {
    const v = q.get(name);
    if (v === null) return null;
    return v.split(',').map((s) => s.trim()).filter((s) => /^[A-Za-z0-9_]{1,40}$/.test(s));
  };
  const word = (name) => {
    const v = q.get(name);
    return v !== null && /^[A-Za-z0-9_]{1,40}$/.test(v) ? v : null;
  };
  return {
    embed: q.get('embed') === '1',
    controls: list('controls'),
    lock: list('lock'),
    plots: list('plots'),
    readouts: list('readouts'),
    theme: THEMES.includes(q.get('theme')) ? q.get('theme') : null,
    fullscreen: q.get('fullscreen') !== '0',
    predict: word('predict'),
    tol: q.get('tol'),
    presets: parsePresets(q.get('presets')),
    origin: q.get('origin'),
  };
}

let stylesheet = null;
/** The toolkit's own styles (projector theme, prediction, fullscreen), loaded once. */
function loadStyles() {
  if (stylesheet || document.querySelector('link[data-lecturer]')) return;
  stylesheet = document.createElement('link');
  stylesheet.rel = 'stylesheet';
  stylesheet.href = new URL('./lecturer.css', import.meta.url).href;
  stylesheet.dataset.lecturer = '1';
  document.head.append(stylesheet);
}

/** Applies the view options to the built view; returns the plot keys to draw. */
export function applyEmbedView(view, opts) {
  loadStyles();
  const root = document.documentElement;
  if (opts.theme) root.dataset.theme = opts.theme;
  else delete root.dataset.theme;
  if (opts.embed) root.dataset.embed = '1';
  else delete root.dataset.embed;
  for (const [key, control] of view.controls) {
    const wrap = (control.range || control.input).closest('.param');
    if (opts.controls && !opts.controls.includes(key)) wrap.hidden = true;
    if (opts.lock && opts.lock.includes(key)) {
      for (const input of wrap.querySelectorAll('input, select')) {
        input.disabled = true;
        input.setAttribute('aria-disabled', 'true');
      }
      wrap.classList.add('locked');
    }
  }
  if (opts.readouts) {
    for (const [key, item] of view.readouts) if (!opts.readouts.includes(key)) item.hidden = true;
  }
  const shown = [];
  for (const [key, fig] of view.figures) {
    const option = [...view.picker.options].find((o) => o.value === key);
    if (opts.plots && !opts.plots.includes(key)) {
      fig.hidden = true;
      option.hidden = true;
      option.disabled = true;
    } else {
      shown.push(key);
    }
  }
  // The requested plots first, in the order asked: the first on the stage.
  if (opts.plots && shown.length) {
    const asked = opts.plots.filter((k) => shown.includes(k));
    view.order = [...asked, ...view.order.filter((k) => !asked.includes(k))];
    view.stagePlot(asked[0]);
  } else {
    view.stagePlot(view.staged);
  }
  // A lecturer who chose the sliders gets no presets (they would set the others); one who
  // chose the plots too gets a compact view sized to the frame, without the schematic
  // unless it was asked for.
  if (opts.embed && opts.controls) {
    for (const { button } of view.presets) button.closest('.presets').hidden = true;
  }
  if (opts.embed && opts.controls && opts.plots) {
    document.documentElement.dataset.compact = '1';
    if (view.animation && !opts.plots.includes('schematic')) view.animation.canvas.closest('figure').hidden = true;
  }
  if (opts.presets && opts.presets.length) addPresets(view, opts.presets);
  if (opts.embed && opts.fullscreen) addFullscreenButton();
  if (opts.predict) setupPrediction(view, opts, { post: (msg) => host.post(msg), context: () => host.context() });
  return shown;
}

/** The lecturer's presets from the link, as buttons beside the demo's own. */
function addPresets(view, presets) {
  const form = view.reset && view.reset.closest('form');
  if (!form) return;
  const box = document.createElement('div');
  box.className = 'presets lecturer-presets';
  box.setAttribute('role', 'group');
  box.setAttribute('aria-label', t('lecturerPresets'));
  const title = document.createElement('span');
  title.className = 'presets-label';
  title.textContent = t('lecturerPresets');
  box.append(title);
  for (const p of presets) {
    const b = document.createElement('button');
    b.type = 'button';
    b.className = 'preset';
    b.textContent = p.label;
    b.addEventListener('click', () => host.set(p.values.filter(([k]) => view.controls.has(k))));
    box.append(b);
  }
  const actions = form.querySelector('.form-actions');
  if (actions) actions.before(box);
  else form.append(box);
}

function addFullscreenButton() {
  const root = document.getElementById('demo');
  if (!root || !document.fullscreenEnabled) return;
  // Beside the plot's export buttons (no row of its own in a small frame), else in the heading.
  const head = root.querySelector('.stage-bar') || root.querySelector('.demo-head') || root;
  const button = document.createElement('button');
  button.type = 'button';
  button.className = 'zeta-fullscreen';
  const label = () => (document.fullscreenElement ? t('exitFullScreen') : t('fullScreen'));
  button.textContent = label();
  button.setAttribute('aria-pressed', String(Boolean(document.fullscreenElement)));
  button.addEventListener('click', () => {
    const done = document.fullscreenElement ? document.exitFullscreen() : document.documentElement.requestFullscreen();
    Promise.resolve(done).catch(() => {});
  });
  document.addEventListener('fullscreenchange', () => {
    button.textContent = label();
    button.setAttribute('aria-pressed', String(Boolean(document.fullscreenElement)));
  });
  head.prepend(button);
}

/** What the host connection knows of the page once connected (see connectHost). */
const host = {
  post() {},
  set() {},
  context() { return {}; },
};

/** The state token of the view on screen. */
export function currentToken(h) {
  const app = h.app;
  const values = app.session.values();
  return encodeToken(viewQuery({
    demo: app.demoId, values, search: window.location.search,
    time: app.time, playing: app.playing, speed: app.speed || 1,
  }));
}

let tokenProvider = null;
/** The token of the view on screen, or null before the page is connected (for download.js). */
export function tokenNow() {
  try {
    return tokenProvider ? tokenProvider() : null;
  } catch {
    return null;
  }
}

function bytesOf(text) {
  return new TextEncoder().encode(text);
}

function dataUrl(bytes, mime) {
  let bin = '';
  for (let i = 0; i < bytes.length; i += 0x8000) bin += String.fromCharCode(...bytes.subarray(i, i + 0x8000));
  return `data:${mime};base64,${btoa(bin)}`;
}

/** Plot `key` as a stamped file: {mime, bytes}. */
export async function exportPlot(h, key, format) {
  const app = h.app;
  if (!app.view.canvases.has(key)) throw new Error(`no plot “${String(key).slice(0, 40)}”`);
  const token = currentToken(h);
  const canvas = app.view.canvases.get(key);
  const w = canvas.clientWidth || 800;
  const hgt = canvas.clientHeight || 500;
  if (format === 'csv') {
    return { mime: 'text/csv', bytes: glue().stampExport('csv', bytesOf(app.session.csv(key)), token) };
  }
  if (format === 'svg') {
    const svg = app.session.svg(key, w, hgt, h.isDark(), document.createElement('canvas'));
    return { mime: 'image/svg+xml', bytes: glue().stampExport('svg', bytesOf(svg), token) };
  }
  if (format === 'png') {
    const big = document.createElement('canvas');
    big.width = w * 2;
    big.height = hgt * 2;
    app.session.renderTo(key, big, 2, h.isDark());
    const blob = await new Promise((ok) => big.toBlob(ok, 'image/png'));
    if (!blob) throw new Error('the browser could not encode the PNG');
    return { mime: 'image/png', bytes: glue().stampExport('png', new Uint8Array(await blob.arrayBuffer()), token) };
  }
  throw new Error(`unknown format “${String(format).slice(0, 8)}” (png, svg or csv)`);
}

/**
 * Applies a state token in place (a language change reloads the page). Returns false, with
 * a notice, when the token cannot be read.
 */
export function applyToken(h, token) {
  const dec = decodeToken(token);
  const notices = document.getElementById('notices');
  if (dec.error) {
    if (notices) notify(notices, dec.error, 'warn');
    return false;
  }
  const q = new URLSearchParams(dec.query);
  if (!glue().demoList().some((d) => d.id === q.get('demo'))) {
    const error = t('tokenNoDemo', { demo: String(q.get('demo')).slice(0, 40) });
    if (notices) notify(notices, error, 'warn');
    return false;
  }
  const current = new URLSearchParams(window.location.search);
  if (current.has('origin')) q.set('origin', current.get('origin'));
  const query = '?' + q.toString();
  const lang = (s) => new URLSearchParams(s).get('lang') || '';
  if (lang(query) !== lang(window.location.search) || !h.openDemo) {
    try { sessionStorage.setItem('zeta:reloaded', '1'); } catch { /* no storage: the host hears zeta:ready */ }
    window.location.replace(query + window.location.hash);
    return true;
  }
  cancelPendingWrite();
  history.replaceState(null, '', query + window.location.hash);
  loaded.keys = new Set(q.keys());
  loaded.notice = null;
  h.app.embed = embedOptions();
  const wanted = q.get('demo');
  h.openDemo(wanted, query);
  applyAnimation(h, q);
  const note = tokenNotice(h.app.session.spec().params.map((p) => p.key));
  if (note && notices) notify(notices, note, 'warn');
  return true;
}

function applyAnimation(h, q) {
  const app = h.app;
  const speed = Number(q.get('speed'));
  app.speed = Number.isFinite(speed) && speed > 0 ? Math.min(Math.max(speed, SPEED_RANGE[0]), SPEED_RANGE[1]) : 1;
  const t = Number(q.get('t'));
  if (q.has('t') && Number.isFinite(t) && t >= 0) app.time = t;
  if (q.get('play') === '1' && h.setPlaying) h.setPlaying(true);
  else if (h.requestDraw) h.requestDraw();
}

/** Restores the view stamped into a dropped PNG, SVG or CSV, or a pasted link. */
function wireRestore(h) {
  document.addEventListener('dragover', (ev) => {
    if (ev.dataTransfer && [...ev.dataTransfer.types].includes('Files')) ev.preventDefault();
  });
  document.addEventListener('drop', async (ev) => {
    const file = ev.dataTransfer && ev.dataTransfer.files && ev.dataTransfer.files[0];
    if (!file) return;
    ev.preventDefault();
    const token = file.size <= 20e6 ? glue().readStamp(new Uint8Array(await file.arrayBuffer())) : undefined;
    if (token) applyToken(h, token);
    else notify(document.getElementById('notices'), t('noStamp'), 'warn');
  });
  document.addEventListener('paste', (ev) => {
    const target = ev.target;
    if (target && (target.closest?.('input, textarea, select, [contenteditable]'))) return;
    const text = ev.clipboardData && ev.clipboardData.getData('text');
    const token = text && tokenInText(text);
    if (!token) return;
    ev.preventDefault();
    applyToken(h, token);
  });
}

function contentHeight() {
  const body = document.body;
  return Math.ceil(Math.max(body.scrollHeight, body.getBoundingClientRect().height));
}

/**
 * Connects the page: restores from dropped files and pasted links, applies the animation
 * part of a token, and, inside a frame, speaks the host API. `handlers`: {set(entries),
 * state() → {demo, params, readouts}} and, when main.js passes them, {app, setPlaying,
 * drawTime, requestDraw, openDemo, isDark}.
 */
export function connectHost(opts, handlers) {
  const h = { isDark: () => false, ...handlers };
  const notices = document.getElementById('notices');
  if (h.app) {
    tokenProvider = () => currentToken(h);
    applyAnimation(h, new URLSearchParams(window.location.search));
    const note = tokenNotice(h.app.session.spec().params.map((p) => p.key));
    if (note && notices) notify(notices, note, 'warn');
    wireRestore(h);
  }
  host.set = (entries) => h.set(entries);
  host.context = () => (h.app ? { demo: h.app.demoId, params: h.state().params, token: currentToken(h) } : {});
  if (window.parent === window) return { notify() {} };
  const target = opts.origin && /^https?:\/\/[^/]+$/.test(opts.origin) ? opts.origin : '*';
  const post = (msg) => window.parent.postMessage(msg, target);
  host.post = post;
  const fail = (request, err) => post({ type: 'zeta:error', request, message: String(err && err.message ? err.message : err) });
  const playback = () => post({ type: 'zeta:playback', playing: h.app.playing, t: h.app.time, speed: h.app.speed || 1 });
  window.addEventListener('message', async (ev) => {
    if (ev.source !== window.parent) return;
    if (target !== '*' && ev.origin !== target) return;
    const msg = ev.data;
    if (!msg || typeof msg !== 'object' || typeof msg.type !== 'string') return;
    if (msg.type === 'zeta:set') {
      const params = msg.params;
      if (!params || typeof params !== 'object' || Array.isArray(params)) return;
      const entries = Object.entries(params).slice(0, MAX_KEYS)
        .filter(([k, v]) => typeof k === 'string' && (typeof v === 'number' || typeof v === 'string'));
      h.set(entries.map(([k, v]) => [k, String(v)]));
      return;
    }
    if (msg.type === 'zeta:get') {
      post({ type: 'zeta:state', ...h.state() });
      return;
    }
    if (!h.app) return; // The toolkit messages need main.js's hooks.
    try {
      if (msg.type === 'zeta:getState') {
        post({ type: 'zeta:stateToken', token: currentToken(h) });
      } else if (msg.type === 'zeta:setState') {
        if (typeof msg.token !== 'string') return;
        if (!applyToken(h, msg.token)) fail('zeta:setState', decodeToken(msg.token).error || 'unknown demo');
      } else if (msg.type === 'zeta:play' || msg.type === 'zeta:pause') {
        if (!h.app.view.animation || !h.setPlaying) throw new Error('this demo has no animation');
        h.setPlaying(msg.type === 'zeta:play');
        playback();
      } else if (msg.type === 'zeta:seek') {
        const t = Number(msg.t);
        if (typeof msg.t !== 'number' || !Number.isFinite(t)) return;
        const span = h.app.timeSpan;
        h.app.time = span ? Math.min(Math.max(t, span[0]), span[1]) : Math.max(0, t);
        if (h.drawTime) h.drawTime();
        playback();
      } else if (msg.type === 'zeta:speed') {
        const x = Number(msg.x);
        if (typeof msg.x !== 'number' || !Number.isFinite(x) || x <= 0) return;
        h.app.speed = Math.min(Math.max(x, SPEED_RANGE[0]), SPEED_RANGE[1]);
        playback();
      } else if (msg.type === 'zeta:export') {
        const { plot, format } = msg;
        if (typeof plot !== 'string' || typeof format !== 'string') return;
        const file = await exportPlot(h, plot, format);
        const data = format === 'png' ? dataUrl(file.bytes, file.mime) : new TextDecoder().decode(file.bytes);
        post({ type: 'zeta:file', plot, format, mime: file.mime, data });
      } else if (msg.type === 'zeta:describe') {
        post({ type: 'zeta:schema', schema: glue().describeDemo(h.app.demoId, window.location.search) });
      }
    } catch (err) {
      fail(msg.type, err);
    }
  });
  let lastHeight = 0;
  let resizePending = false;
  const sendHeight = () => {
    resizePending = false;
    const height = contentHeight();
    if (Math.abs(height - lastHeight) < 1) return;
    lastHeight = height;
    post({ type: 'zeta:resize', height });
  };
  const ro = new ResizeObserver(() => {
    if (resizePending) return;
    resizePending = true;
    requestAnimationFrame(sendHeight);
  });
  ro.observe(document.body);
  let ready = false;
  try {
    ready = sessionStorage.getItem('zeta:reloaded') === '1';
    sessionStorage.removeItem('zeta:reloaded');
  } catch { /* a sandbox without storage */ }
  return {
    notify() {
      const type = ready ? 'zeta:change' : 'zeta:ready';
      ready = true;
      post({ type, ...h.state() });
    },
  };
}
