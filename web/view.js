// The embed view: the view options of the address (`controls=`, `plots=`, `theme=`,
// `predict=`, lecturer presets, …), the animation part of a token, and restoring a view from
// a dropped file or a pasted link. Every page needs this before its first plot; the host-page
// API over postMessage (embed.js), the prediction form (predict.js) and the lecturer styles
// (lecturer.css) load only when the page needs them.
import { fullGlue } from './glue.js';
import { notify } from './ui.js';
import { encodeToken, parsePresets, tokenInText, tokenNotice, viewQuery } from './state.js';
import { t } from './i18n.js';

const THEMES = ['light', 'dark', 'projector'];
export const SPEED_RANGE = [0.1, 10];

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

/**
 * The styles of what the first plot does not need (lecturer.css: projector theme, prediction,
 * fullscreen, share dialog, the tour's handout), loaded once; resolves when they apply (or
 * failed to load, or 3 s passed: the page works unstyled).
 */
export function loadStyles() {
  let link = document.querySelector('link[data-lecturer]'); // web/preload.js may have added it
  if (!link) {
    link = document.createElement('link');
    link.rel = 'stylesheet';
    link.href = new URL('./lecturer.css', import.meta.url).href;
    link.dataset.lecturer = '1';
    document.head.append(link);
  }
  if (link.sheet) return Promise.resolve();
  return new Promise((done) => {
    link.addEventListener('load', done);
    link.addEventListener('error', done);
    setTimeout(done, 3000); // a link that failed before has no event left to send
  });
}

const prediction = { module: null, loading: null };
/** Loads predict.js once (a promise of the module). */
export function loadPrediction() {
  prediction.loading ??= import('./predict.js').then((m) => {
    prediction.module = m;
    return m;
  }).catch((err) => {
    prediction.loading = null;
    throw err;
  });
  return prediction.loading;
}

/** Applies the view options to the built view; returns the plot keys to draw. */
export function applyEmbedView(view, opts) {
  if (opts.predict || opts.presets.length || opts.theme === 'projector' || (opts.embed && opts.fullscreen)) loadStyles();
  // The theme follows the address (web/preload.js decides; a restored token may change it).
  document.dispatchEvent(new Event('zeta:address'));
  const root = document.documentElement;
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
  if (opts.predict) {
    const setup = (m) => m.setupPrediction(view, opts, { post: (msg) => host.post(msg), context: () => host.context() });
    // main.js loads predict.js before the first demo of a `predict=` page opens; a token
    // restored later may still need it.
    if (prediction.module) setup(prediction.module);
    else loadPrediction().then((m) => view.workspace.isConnected && setup(m), (err) => console.warn('Zeta Lab: predict.js:', err && err.message));
  }
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

/** What the page and, once connected, the host know of each other (see connectPage, embed.js). */
export const host = {
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

/** The animation part of a query (`t=`, `play=`, `speed=`). */
export function applyAnimation(h, q) {
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
    let token;
    try {
      token = file.size <= 20e6 ? (await fullGlue()).readStamp(new Uint8Array(await file.arrayBuffer())) : undefined;
    } catch (err) {
      console.warn('Zeta Lab: the dropped file could not be read:', err && err.message);
    }
    if (token) (await import('./embed.js')).applyToken(h, token);
    else notify(document.getElementById('notices'), t('noStamp'), 'warn');
  });
  document.addEventListener('paste', (ev) => {
    const target = ev.target;
    if (target && (target.closest?.('input, textarea, select, [contenteditable]'))) return;
    const text = ev.clipboardData && ev.clipboardData.getData('text');
    const token = text && tokenInText(text);
    if (!token) return;
    ev.preventDefault();
    import('./embed.js').then((m) => m.applyToken(h, token), (err) => console.warn('Zeta Lab: embed.js:', err && err.message));
  });
}

/**
 * Connects the page itself: applies the animation part of the address (`t=`, `play=`,
 * `speed=`), says when a token came from another version, and restores views from dropped
 * files and pasted links. `h`: {set(entries), state(), app, setPlaying, drawTime,
 * requestDraw, openDemo, canOpen, isDark} from main.js. Inside a frame, embed.js's connectHost adds
 * the host-page API.
 */
export function connectPage(h) {
  applyAnimation(h, new URLSearchParams(window.location.search));
  const notices = document.getElementById('notices');
  const note = tokenNotice(h.app.session.spec().params.map((p) => p.key));
  if (note && notices) notify(notices, note, 'warn');
  wireRestore(h);
  host.set = (entries) => h.set(entries);
  host.context = () => ({ demo: h.app.demoId, params: h.state().params, token: currentToken(h) });
}
