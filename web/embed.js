// Embedding: the host-page API over postMessage, exporting stamped files for the host, and
// applying a state token in place. Loaded up front inside a frame (web/main.js); on a page
// of its own, when a file is dropped or a link pasted, and otherwise at idle after the first
// plot. The view options every page needs live in view.js.
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
import { fullGlue, glue } from './glue.js';
import { notify } from './ui.js';
import { decodeToken, loaded, tokenNotice } from './state.js';
import { SPEED_RANGE, applyAnimation, currentToken, embedOptions, host } from './view.js';
import { cancelPendingWrite } from './url.js';
import { t } from './i18n.js';

const MAX_KEYS = 64;

function dataUrl(bytes, mime) {
  let bin = '';
  for (let i = 0; i < bytes.length; i += 0x8000) bin += String.fromCharCode(...bytes.subarray(i, i + 0x8000));
  return `data:${mime};base64,${btoa(bin)}`;
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
  // Another language, or a demo this module cannot open (a demo's first module holds only
  // that demo): the page opens at the token's address, and then says zeta:change.
  if (lang(query) !== lang(window.location.search) || !h.openDemo || (h.canOpen && !h.canOpen(q.get('demo')))) {
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

function contentHeight() {
  const body = document.body;
  return Math.ceil(Math.max(body.scrollHeight, body.getBoundingClientRect().height));
}

/**
 * Inside a frame, speaks the host API (view.js's connectPage has connected the page itself).
 * `handlers`: {set(entries), state() → {demo, params, readouts}} and, when main.js passes
 * them, {app, setPlaying, drawTime, requestDraw, openDemo, isDark}. Returns {notify()}, which
 * main.js calls after each change that was drawn.
 */
export function connectHost(opts, handlers) {
  const h = { isDark: () => false, ...handlers };
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
        const file = await (await import('./download.js')).plotFile(h, plot, format);
        const data = format === 'png' ? dataUrl(file.bytes, file.mime) : new TextDecoder().decode(file.bytes);
        post({ type: 'zeta:file', plot, format, mime: file.mime, data });
      } else if (msg.type === 'zeta:describe') {
        const full = await fullGlue(); // the schema is the full module's
        post({ type: 'zeta:schema', schema: full.describeDemo(h.app.demoId, window.location.search) });
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
