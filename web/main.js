// Zeta Lab front end: loads the wasm module, builds the chosen demo from its Rust
// declaration, and redraws at most once per animation frame while controls move.
// No physics here: every number comes from the Session (Rust).
// A demo starts from a small "first" module that links only it (issue 13; web/preload.js
// decides); the full module loads after the first plot and takes over between two bursts
// of input.
// Modules needed only on a user's action (share dialog, downloads, sound, the paper's tour,
// the host-page API outside a frame) are not imported here: they load when first used, and
// at idle after the first plot, so a click does not wait on the network (see `later`).
import './state.js'; // first: expands a state= token in the address before anything reads it
import { applyConditions, buildDemo, el, fillLiveCells, fromSlider, notify, showReadouts, showValue, formatValue, highlightRow, setAttr, setText } from './ui.js';
import { cancelPendingWrite, currentQuery, demoFromUrl, queryFor, writeState } from './url.js';
import { applyEmbedView, connectPage, embedOptions, loadPrediction, loadStyles } from './view.js';
import { useFullModuleWith, useGlue } from './glue.js';
import { activeLanguage, adoptInstance, languages, num, remember, requestedLanguages, t, translatePage, useLanguage } from './i18n.js';

const DEFAULT_DEMO = 'regimes';
const ANNOUNCE_DELAY_MS = 1200;
const REFINE_SLICE_MS = 8; // one slice of a pending full study: well inside a frame
const WASM_URL = new URL('../zeta-app_bg.wasm', import.meta.url);
/**
 * The controls rest when none is held and none has moved for a while; three things wait
 * for it, each as long as its own cost to an input it would delay calls for (ms):
 * - `study`: the next slice of a pending full study (while the controls move, the next
 *   event drops the study anyway, and a slice between an input and its frame only delays
 *   the frame);
 * - `offscreen`: plots out of view catch up with the last update, one a frame;
 * - `upgrade`: the full module takes over from the first (a new instance and a redraw).
 */
const REST_MS = { study: 100, offscreen: 200, upgrade: 300 };
/**
 * Within this many screen heights above or below the view, a plot counts as on screen. None:
 * a plot just below the window was drawn with every move of a held slider, a second canvas
 * each frame (at 4× CPU and 360 × 740, about 3 ms of a frame's 16.7); one scrolled into
 * view during a drag is drawn in the next frame, and all are once the controls rest.
 */
const NEAR_SCREEN = 0;
const darkQuery = window.matchMedia('(prefers-color-scheme: dark)');
const root = document.documentElement;
const reducedMotion = window.matchMedia('(prefers-reduced-motion: reduce)');

/** The one app object: all mutable state of the page. */
const app = {
  demoId: null,
  session: null,
  prepared: null, // the session whose static-layer canvases are set up (prepareLayers)
  layerRounds: 0, // keepLayer calls since the last update
  takingOver: null, // the switch to the full module under way for a click or a tap (useFullModule)
  view: null,
  framePending: false,
  needsRecovery: false,
  lastSize: new Map(),
  notices: null,
  root: null,
  timeSpan: null,
  time: 0,
  playing: false,
  lastTick: null,
  announceTimer: null,
  embed: embedOptions(),
  host: { notify() {} },
  changed: true,
  firstDrawn: false,
  /** The sonifier (sound.js), silent until the sound button first loads it. */
  sound: { enabled: false, play() {} },
  dragging: false,
  layoutDirty: true,
  /** A canvas's box may have changed size since sizeCanvases last read them (see there). */
  sizesDirty: true,
  /** Tells of canvas boxes changing size (observeCanvasSizes). */
  canvasSizes: null,
  /** The device pixel ratio sizeCanvases last read the boxes at. */
  sizedFor: 0,
  /** Counts changes of the demo's values from any source (controls, reset, a click on a
   * plot, the host page, a new demo): upgrade.js's computeBehind starts again when it moves. */
  revision: 0,
  /** A relayout is asked for the next frame (requestRelayout). */
  relayoutPending: false,
  /** The glue of the module instance in use: replaced by a fresh instance after a trap. */
  wasm: null,
  /** That instance's wasm exports (its memory). */
  exports: null,
  /** Which module is in use: 'first' (only the demo `firstDemo`) or 'full'. */
  module: 'full',
  /** The one demo the first module links (while `module` is 'first'). */
  firstDemo: null,
  /** The full module loading while the first one is in use: a promise of {glue, exports}. */
  fullLoading: null,
  /** How many times loading it failed (see loadFull). */
  fullFailed: 0,
  /** When the user last touched a control (the full module takes over between bursts). */
  lastInput: 0,
  /** Which canvases are on screen (see observeVisibility); plots off screen wait. */
  visibility: null,
  /** Whether the observer has reported since it began watching (until then readVisibility). */
  visibilityKnown: false,
  schematicVisible: true,
  /** Whether the schematic, or any plot, shows an older frame than the last update's. */
  schematicStale: false,
  staleLeft: false,
  /** The timer that draws everything once the controls rest (scheduleCatchUp). */
  catchUp: null,
  /** The keys of the plots on screen, as observeVisibility sees. */
  onScreen: new Set(),
  /** The full module has just taken over: the catch-up, not a plot coming into view,
   * redraws the plots until none is left (upgrade.js's takeOver). */
  settling: false,
  /** Message ids the first instance showed in English, kept across the switch. */
  missing: [],
  /** How many times the module has been instantiated afresh (cache-busts the glue's URL). */
  instances: 0,
  recovering: null,
};

// What the first module lacks (exports, stamps, the lecturer API) waits for the full one.
useFullModuleWith(useFullModule);

/** The theme web/preload.js resolved from the address and the system (data-theme). */
function isDark() {
  return root.dataset.theme === 'dark';
}

/**
 * The modules loaded on demand, each once: `later('share')` is a promise of `./share.js`.
 * Literal specifiers, so that tools and readers see every module the page can load.
 */
const LATER = {
  share: () => import('./share.js'),
  download: () => import('./download.js'),
  sound: () => import('./sound.js'),
  tour: () => import('./tour.js'),
  embed: () => import('./embed.js'),
  studies: () => import('./studies.js'),
};
const loading = new Map();
function later(name) {
  if (!loading.has(name)) {
    loading.set(name, LATER[name]().catch((err) => {
      loading.delete(name); // the next use tries again
      throw err;
    }));
  }
  return loading.get(name);
}

/**
 * At idle after the first plot: fetches every module a click may need (and the lecturer
 * styles the share dialog uses), so that on a slow line no click waits on the network, and
 * registers the service worker (its install downloads every file of the site).
 */
function prefetchLater() {
  const go = () => {
    for (const name of Object.keys(LATER)) later(name).catch(() => {});
    loadStyles();
    registerServiceWorker();
  };
  if ('requestIdleCallback' in window) requestIdleCallback(go, { timeout: 2000 });
  else setTimeout(go, 200);
}

/**
 * Runs `use(module)` once `later(name)` has the module. A failed call in it is a wasm
 * failure (reportFailure recovers); a module that could not be fetched is not: the page
 * says so, runs `without()`, and the next use fetches it again.
 */
function withModule(name, use, without) {
  later(name).then((m) => {
    try {
      use(m);
    } catch (err) {
      reportFailure(err);
    }
  }, (err) => {
    console.warn(`Zeta Lab: ${name}.js could not be loaded:`, err && err.message);
    notify(app.notices, t('moduleFailed', { text: `${name}.js` }), 'warn');
    without?.();
  });
}

/** Lays out the paper's tour (tour.js) once it is loaded, if the same demo is still open. */
function showTour(tour) {
  const view = app.view;
  // At once, not when tour.js has loaded: the empty stage and form are not painted first.
  app.root.classList.add('touring');
  withModule('tour', (m) => {
    if (app.view === view) m.renderTour(app.root, tour);
  }, () => app.view === view && app.root.classList.remove('touring'));
}

/** Reports an error from a wasm call without breaking the page; the next input recovers. */
function reportFailure(err) {
  app.needsRecovery = true; // first: nothing below may keep the page from recovering
  let panic = null;
  try {
    panic = app.wasm.takePanicMessage();
  } catch {
    // the trapped instance cannot answer; the error itself says enough
  }
  const text = panic || (err && err.message) || String(err);
  console.warn('Zeta Lab recovered from an error:', text);
  notify(app.notices, t('failed', { text }), 'error');
}

/** The values shown in the controls: the page's own copy, usable after a failed call. */
function shownValues() {
  const values = [];
  for (const [key, control] of app.view.controls) {
    const kind = control.param.kind;
    if (kind === 'toggle') values.push([key, control.input.checked ? '1' : '0']);
    else if (kind === 'choice') values.push([key, control.input.value]);
    else values.push([key, control.number.value]);
  }
  return values;
}

/**
 * After a failed call: a fresh module instance (fresh memory, allocator and `RefCell`s;
 * the old one may be poisoned by a trap) and in it a new Session with the values the page
 * shows. Returns a promise; concurrent calls share one recovery.
 */
function recover() {
  app.recovering ??= reinstantiate()
    .then(() => {
      valuesChanged();
      requestDraw();
    })
    .finally(() => {
      app.recovering = null;
    });
  return app.recovering;
}

async function reinstantiate() {
  const values = shownValues();
  app.instances += 1;
  // A new URL is a new ES module record, so the glue instantiates the wasm afresh.
  const glue = await import(`../zeta-app.js?instance=${app.instances}`);
  app.exports = await glue.default({ module_or_path: WASM_URL });
  adoptInstance(glue);
  app.wasm = glue;
  useGlue(glue);
  app.module = 'full';
  app.session = new glue.Session(app.demoId);
  app.session.applyQuery(currentQuery()); // keeps range./step. overrides after a recovery
  for (const [k, v] of values) app.session.set(k, v);
  attachCanvases();
  app.needsRecovery = false;
}

function attachCanvases() {
  app.lastSize.clear();
  observeCanvasSizes();
  for (const key of app.view.shownPlots) app.session.attach(key, app.view.canvases.get(key));
  if (app.view.animation) app.session.attach('schematic', app.view.animation.canvas);
  observeVisibility();
}

/**
 * How long (ms) until the controls have rested for `ms` (see REST_MS): 0 once they have,
 * never less than `ms` while one is held.
 */
function restLeft(ms) {
  if (app.dragging) return ms;
  return Math.max(0, ms - (performance.now() - app.lastInput));
}

/**
 * Only what is on screen is drawn while a control moves:
 * the plots out of view, and the schematic, are drawn from the last update as soon as they
 * come into view, and all of them once the controls have rested (REST_MS.offscreen).
 * Without IntersectionObserver everything counts as on screen and is drawn every time.
 */
function observeVisibility() {
  app.visibility?.disconnect();
  app.schematicVisible = true;
  app.onScreen = new Set(app.view.shownPlots);
  app.visibilityKnown = false;
  if (!('IntersectionObserver' in window)) return;
  const session = app.session;
  app.visibility = new IntersectionObserver(
    (entries) => {
      if (app.session !== session) return;
      app.visibilityKnown = true;
      let stale = false;
      for (const e of entries) {
        const key = e.target.dataset.plot;
        if (key === 'schematic') {
          app.schematicVisible = e.isIntersecting;
          stale ||= e.isIntersecting && app.schematicStale;
        } else {
          if (e.isIntersecting) app.onScreen.add(key);
          else app.onScreen.delete(key);
          try {
            stale = session.setVisible(key, e.isIntersecting) || stale;
          } catch (err) {
            reportFailure(err);
          }
        }
      }
      // Right after the full module took over, the catch-up redraws (one plot a task).
      if (stale && !app.settling) requestAnimationFrame(() => drawStale(false));
    },
    { rootMargin: `${NEAR_SCREEN * 100}% 0px` },
  );
  for (const key of app.view.shownPlots) app.visibility.observe(app.view.canvases.get(key));
  if (app.view.animation) app.visibility.observe(app.view.animation.canvas);
  observeAway();
}

/**
 * While a control is held, texts out of view keep what they show and are written on
 * release (showResults): the readouts scrolled out of the strip (a phone shows two lines of
 * it) and the table below the window. Each text written is laid out and painted again in
 * the frame (analogy's 18 live cells: about 3 ms of a frame at 4× CPU). Their `data-value`
 * stays current; scrolled into view while held, they are written in the next frame.
 */
function observeAway() {
  for (const o of app.awayObservers ?? []) o.disconnect();
  app.away = new Set();
  if (!('IntersectionObserver' in window)) return;
  const watch = (root, targets) => {
    const o = new IntersectionObserver((entries) => {
      for (const e of entries) {
        app.away[e.isIntersecting ? 'delete' : 'add'](e.target);
        if (e.isIntersecting && app.dragging) requestDraw();
      }
    }, { root });
    for (const t of targets) o.observe(t);
    return o;
  };
  const items = [...app.view.readouts.values()];
  app.awayObservers = [watch(items[0]?.closest('.readout-strip'), items)];
  if (app.view.table) app.awayObservers.push(watch(null, [app.view.table.wrap]));
}

/**
 * Which plots are on screen, read from the layout, for a frame drawn before the observer's
 * first report (it reports after the first frame is rendered): the first frame then draws
 * only those, and the catch-up the others once the controls rest. Drawing every plot made
 * integrators' first frame 450 ms at 4× CPU, at 360 × 740, where one plot is in view.
 */
function readVisibility() {
  if (app.visibilityKnown || !app.visibility) return;
  const vh = window.innerHeight;
  const near = (el) => {
    const r = el.getBoundingClientRect();
    return (r.width > 0 || r.height > 0) && r.bottom >= -NEAR_SCREEN * vh && r.top <= (1 + NEAR_SCREEN) * vh;
  };
  for (const key of app.view.shownPlots) {
    const on = near(app.view.canvases.get(key));
    if (on) app.onScreen.add(key);
    else app.onScreen.delete(key);
    app.session.setVisible(key, on);
  }
  if (app.view.animation) app.schematicVisible = near(app.view.animation.canvas);
}

/** Draws the plots (and the schematic) showing an older frame: those on screen, or all. */
function drawStale(all) {
  if (app.needsRecovery || app.framePending) return; // the next frame draws anyway
  try {
    const dpr = window.devicePixelRatio || 1;
    const out = app.session.drawStale(dpr, isDark(), all);
    app.staleLeft = out.left;
    showCaptions(out.descriptions);
    if (app.schematicStale && (all || app.schematicVisible)) drawTime(dpr, true);
    else if (out.descriptions.length && app.view.animation && app.timeSpan) drawCursors(dpr); // the plots just drawn
  } catch (err) {
    reportFailure(err);
  }
}

/**
 * Once everything is drawn and the controls rest, the session sets up the canvases that
 * keep each plot's static layer (once per session), so a first drag does not
 * pay for them.
 */
function prepareLayers() {
  if (app.prepared === app.session) return;
  app.prepared = app.session;
  try {
    app.session.prepareLayers();
  } catch (err) {
    reportFailure(err);
  }
}

/**
 * Once the controls rest, each plot on screen whose canvas does not keep its static layer
 * yet is drawn once more (the same pixels), a plot a task, before what is out of view
 * catches up: a drag's first frame then draws only the data (it drew the whole plot,
 * about twice the time of the drag's other frames at 4x CPU). At most one round per plot
 * after each update. The first module keeps no layers (no keepLayer).
 */
function keepLayer() {
  const session = app.session;
  if (!session?.keepLayer || app.dragging || app.framePending) return false;
  if (app.layerRounds >= app.view.spec.plots.length) return false;
  app.layerRounds += 1;
  try {
    return session.keepLayer(window.devicePixelRatio || 1, isDark());
  } catch (err) {
    reportFailure(err);
    return false;
  }
}

/** keepLayer, a task each (after a frame each), until every plot on screen keeps its layer. */
function keepLayers() {
  setTimeout(() => {
    if (!app.settling && keepLayer()) requestAnimationFrame(keepLayers);
  }, 0);
}

/**
 * Once the controls have rested, everything out of view catches up: one plot a task, so
 * no task grows long. A task of its own, not an animation frame, and the next one after
 * the frame that shows it: that frame then only commits one canvas (a plot's first
 * drawing on the full module and the commit of its canvas were one task of 50-80 ms at 4x
 * CPU; apart, each stays under 50).
 */
function scheduleCatchUp(delay = REST_MS.offscreen) {
  clearTimeout(app.catchUp);
  if (!app.staleLeft && !app.schematicStale) {
    app.settling = false;
    // A task of its own (setting up the layers' canvases is 10-20 ms at 4x CPU), not the
    // animation frame that may have called this.
    setTimeout(() => {
      prepareLayers();
      keepLayers();
    }, 0);
    return;
  }
  app.catchUp = setTimeout(() => {
    const wait = restLeft(REST_MS.offscreen);
    if (wait > 0) {
      scheduleCatchUp(wait);
      return;
    }
    if (!keepLayer()) drawStale(true);
    requestAnimationFrame(() => scheduleCatchUp(0));
  }, delay);
}

/** Whether `canvas` (size key `key`) is not sized to its box at `dpr`; `[w, h]` it needs. */
function misfit(canvas, key, dpr) {
  const w = Math.max(1, Math.round(canvas.clientWidth * dpr));
  const h = Math.max(1, Math.round(canvas.clientHeight * dpr));
  const last = app.lastSize.get(key);
  return !last || last[0] !== w || last[1] !== h ? [w, h] : null;
}

function fit(canvas, key, dpr) {
  const size = misfit(canvas, key, dpr);
  if (size) {
    [canvas.width, canvas.height] = size;
    app.lastSize.set(key, size);
  }
}

/**
 * The page's layout changed (its size, the window's): lays the stage out again, and
 * redraws only if a canvas no longer fits its box (resizing clears it). The observer's
 * first report, just after the first plot, usually changes none: a whole redraw then was
 * 60-150 ms at 4x CPU for nothing.
 */
function requestRelayout() {
  app.layoutDirty = true;
  if (app.relayoutPending) return;
  app.relayoutPending = true;
  requestAnimationFrame(() => {
    app.relayoutPending = false;
    if (app.framePending || !app.session || !app.view) return; // that frame lays out anyway
    if (!app.dragging) layoutStage();
    const dpr = window.devicePixelRatio || 1;
    if (sizedCanvases().some(([canvas, key]) => misfit(canvas, key, dpr))) {
      app.framePending = true;
      drawFrame();
    }
  });
}

/** The least height (px) the staged plot is given while the stage fits the window. */
const MIN_STAGED_PLOT = 200;
/** The smallest a demo's equation is shrunk to fit its box (then it scrolls sideways). */
const EQUATION_MIN_SCALE = 0.6;

/**
 * Shrinks the demo's equation to fit its box, down to EQUATION_MIN_SCALE: five demos'
 * equations were wider than a phone and scrolled sideways (flutter's 440 px in 341 at
 * 360 × 740, in 275 on a phone held sideways). Its width at full size is that of its
 * widest row (MathML is not broken into lines) over its scale.
 */
function fitEquation() {
  const box = app.view.workspace.querySelector('.equation');
  const math = box?.querySelector('math');
  if (!math) return;
  const scale = Number(math.dataset.scale || 1);
  const natural = Math.max(0, ...[...math.children].map((c) => c.getBoundingClientRect().width)) / scale;
  const room = box.clientWidth;
  if (!(natural > 0 && room > 0)) return;
  const fit = room / natural;
  const next = Math.max(EQUATION_MIN_SCALE, Math.min(1, Math.floor(fit * 100) / 100));
  // It grows back only if it would fit more than a step larger: text does not scale exactly
  // with its font, and at some widths each of two sizes asked for the other (universality's
  // equation flickered every frame on a phone).
  if (next === scale || (next > scale && fit < scale + 0.02)) return;
  math.dataset.scale = String(next);
  math.style.fontSize = next === 1 ? '' : `${next * 100}%`;
}

/**
 * Caps the staged plot's height so the whole stage (picker, plot, readouts) fits in the
 * window beside the controls (wide screens) or in the top 45 % above them (narrow), and
 * leaves room below the controls for the stage to stay stuck while the last one is used.
 */
function layoutStage() {
  app.layoutDirty = false;
  const view = app.view;
  const canvas = view.canvases.get(view.staged);
  for (const p of view.spec.plots) {
    const c = view.canvases.get(p.key);
    if (c !== canvas) {
      c.style.maxHeight = '';
      c.style.aspectRatio = String(p.aspect);
    }
  }
  const wide = getComputedStyle(view.workspace).getPropertyValue('--layout').trim() === 'wide';
  if (!canvas) {
    fitEquation();
    markStage(view.stage, wide);
    return;
  }
  const vh = window.innerHeight;
  // On the stage a wide plot may grow taller than its usual shape, up to the room left.
  const aspect = view.spec.plots.find((p) => p.key === view.staged).aspect;
  canvas.style.aspectRatio = String(wide ? Math.min(aspect, 1.5) : aspect);
  fitEquation(); // its read lays the page out once for the reads below (a write: rarely)
  const anchor = wide ? view.workspace : view.stage.previousElementSibling;
  const box = anchor.getBoundingClientRect();
  const top = (wide ? box.top : box.bottom) + window.scrollY;
  const margin = 12;
  let room = wide ? vh - Math.max(top, margin) - margin : Math.min(0.45 * vh, vh - top - margin);
  if (!wide && document.documentElement.dataset.compact === '1') {
    // Compact embed: the page does not scroll, so the stage takes what the form leaves.
    const form = view.workspace.querySelector('.controls');
    room = Math.max(room, vh - top - form.offsetHeight - 3 * margin);
  }
  // What the stage holds beside the plot (its readouts) takes room from it, and gives it
  // back only in another window size: a readout that got shorter (a provisional mark
  // gone, the study done) leaves the plot where it is rather than move the page.
  const size = `${innerWidth}x${vh}`;
  const extra = Math.max(view.stage.offsetHeight - canvas.offsetHeight, view.extraFor === size ? view.extra : 0);
  [view.extra, view.extraFor] = [extra, size];
  let cap = Math.floor(room - extra);
  // A short window beside the controls (a phone held sideways: 360 px, a third of it the
  // site's header) would leave a strip of a plot: it is sized for the stage stuck at the
  // top once the page scrolls to the controls, as it does when one is used.
  if (wide && cap < MIN_STAGED_PLOT) cap = Math.floor(vh - 2 * margin - extra);
  canvas.style.maxHeight = `${Math.max(120, cap)}px`;
  markStage(view.stage, wide);
}

/**
 * The stage's height on the root: the wide layout's room below the controls reads it
 * (style.css); narrow, where the stage sticks over the page's top, it is the page's scroll
 * padding, so a control scrolled to or reached from the keyboard lands below the stage, not
 * under it (WCAG 2.4.11).
 */
function markStage(stage, wide) {
  const root = document.documentElement.style;
  const h = stage.offsetHeight;
  root.setProperty('--stage-h', `${h}px`);
  root.scrollPaddingTop = wide ? '' : `calc(${h}px + 0.5rem)`;
}

function sizeCanvases() {
  // While a control is held the stage holds its layout too, like the axes: a readout that
  // wraps to another line would otherwise resize the plot under the pointer every frame
  // (and a resized canvas is cleared and drawn whole). It is laid out on release.
  if (app.layoutDirty && !app.dragging) layoutStage();
  const dpr = window.devicePixelRatio || 1;
  // Held, the boxes keep their sizes unless an observer says otherwise, and reading them
  // would lay out what the input just changed (the slider, its number) a second time in
  // the frame: the readouts this frame writes need the layout done again anyway.
  if (app.dragging && !app.sizesDirty && app.sizedFor === dpr) return dpr;
  app.sizesDirty = false;
  app.sizedFor = dpr;
  for (const [canvas, key] of sizedCanvases()) fit(canvas, key, dpr);
  return dpr;
}

/** Watches every canvas's box: a change marks the sizes to be read again (sizeCanvases). */
function observeCanvasSizes() {
  app.sizesDirty = true;
  app.canvasSizes?.disconnect();
  app.canvasSizes = new ResizeObserver(() => {
    app.sizesDirty = true;
  });
  for (const [canvas] of sizedCanvases()) app.canvasSizes.observe(canvas);
}

/**
 * Every canvas sized to its box, with its size key: each plot and the schematic. An
 * overlay is sized when something is drawn on it (overlayContext).
 */
function sizedCanvases() {
  const boxes = [...app.view.canvases].map(([key, canvas]) => [canvas, key]);
  if (app.view.animation) boxes.push([app.view.animation.canvas, 'schematic']);
  return boxes;
}

function announce(text) {
  clearTimeout(app.announceTimer);
  app.announceTimer = setTimeout(() => {
    app.view.live.textContent = text;
  }, ANNOUNCE_DELAY_MS);
}

/**
 * Writes each plot's text alternative (`[{key, text}]`) into its caption: an update gives
 * those of the plots it drew (and the primary plot's), drawStale those of the plots it
 * catches up.
 */
function showCaptions(descriptions) {
  for (const d of descriptions) {
    const cap = app.view.captions.get(d.key);
    if (cap) setText(cap, d.text);
  }
}

/** An update's readouts, what reads them (slider descriptions, the table's live cells), its
 * provisional marks and the paper's tour. */
function showResults(out) {
  const away = app.dragging ? app.away : null; // see observeAway
  showReadouts(app.view.readouts, out.readouts, new Set(out.provisional), away);
  markProvisional(out.provisional, out.restarted);
  if (out.tour) showTour(out.tour);
  describeSliders(out.readouts);
  if (away?.has(app.view.table?.wrap)) return;
  highlightRow(app.view.table, out.readouts);
  fillLiveCells(app.view.table, out.readouts);
}

function drawFrame() {
  app.framePending = false;
  if (app.needsRecovery) {
    recover().catch(reportFailure); // draws again when the new instance is ready
    return;
  }
  try {
    const dpr = sizeCanvases();
    readVisibility();
    // A view's first frame computes, fills in the readouts and captions, lays the stage out with them
    // and only then draws: laid out before them, the staged plot was resized a frame later
    // (drawn twice, and the page jumped under the reader).
    const settle = app.view.staged && !app.view.settled;
    if (settle) for (const key of app.view.shownPlots) app.session.setVisible(key, false);
    const out = app.session.update(dpr, isDark());
    app.layerRounds = 0;
    app.settling = false; // this update drew the plots on screen (see upgrade.js, takeOver)
    app.staleLeft = true; // plots out of view were skipped; drawStale(true) says for sure
    showResults(out);
    for (const [key, value] of out.derived) {
      const control = app.view.controls.get(key);
      if (control) showValue(control, value);
    }
    if (out.derived.length) syncUrl();
    applyConditions(app.view.spec, app.root);
    showCaptions(out.descriptions);
    let drawn = out.descriptions;
    if (settle) {
      app.view.settled = app.layoutDirty = true;
      sizeCanvases();
      for (const key of app.view.shownPlots) app.session.setVisible(key, app.onScreen.has(key));
      drawn = app.session.drawStale(dpr, isDark(), false).descriptions;
      showCaptions(drawn);
    }
    // The staged plot's text (an embed's `plots=` may stage another than the primary one).
    const said = drawn.find((d) => d.key === app.view.staged);
    if (said) announce(said.text);
    if (!app.firstDrawn) {
      app.firstDrawn = true;
      performance.mark('zeta:first-draw');
      // After this frame is on screen: the full module (if the first one drew), then at
      // idle what a click may need and the offline cache, so that on a slow line none of
      // them takes bandwidth from another.
      const started = app.module === 'first' ? new Promise((done) => setTimeout(() => startUpgrade().finally(done), 0)) : Promise.resolve();
      started.then(prefetchLater);
    }
    app.timeSpan = out.time_span;
    if (app.timeSpan) app.time = Math.min(Math.max(app.time, app.timeSpan[0]), app.timeSpan[1]);
    drawTime(dpr);
    scheduleCatchUp();
    if (app.changed) {
      app.changed = false;
      app.host.notify();
    }
  } catch (err) {
    reportFailure(err);
  }
}

/** aria-valuetext in words: "damping ratio 0.30, underdamped". */
function describeSliders(readouts) {
  const text = readouts.find((r) => r.data_value !== '' && Number.isNaN(Number(r.data_value)));
  for (const control of app.view.controls.values()) {
    if (!control.range) continue;
    const unit = control.param.unit ? ` ${control.param.unit}` : '';
    const words = `${control.param.label} ${control.number.value}${unit}`;
    setAttr(control.range, 'aria-valuetext', text ? `${words}, ${text.text}` : words);
  }
}

/** The state reported to a host page. */
function hostState() {
  const params = {};
  for (const [k, v] of app.session.values()) params[k] = v;
  const readouts = {};
  for (const [key, item] of app.view.readouts) readouts[key] = item.getAttribute('data-value');
  return { demo: app.demoId, params, readouts };
}

/** What each time plot's overlay shows: the cursor key drawCursors drew last (absent: redraw). */
const cursorDrawn = new WeakMap();

/** Draws the schematic at the current time and the time cursor on every time plot. */
function drawTime(dpr = window.devicePixelRatio || 1, schematic = app.schematicVisible) {
  const anim = app.view.animation;
  if (!anim || !app.timeSpan) return;
  // Off screen, the schematic (and its text) waits until it is in view or the page rests
  // (a moved time or a pause asks for the rest's catch-up here: no update follows them).
  app.schematicStale = !schematic;
  if (schematic) setText(anim.caption, app.session.drawSchematic(app.time, dpr, isDark()));
  else scheduleCatchUp();
  const [t0, t1] = app.timeSpan;
  anim.scrub.value = String(Math.round(((app.time - t0) / (t1 - t0)) * 1000));
  setText(anim.time, `t = ${num(app.time, 2)} s`);
  setAttr(anim.scrub, 'aria-valuetext', t('timeWords', { t: num(app.time, 2) }));
  drawCursors(dpr);
}

/**
 * Draws the time cursor on every time plot drawn from the last update (a plot not drawn
 * yet has no cursor until it is: drawStale calls this again).
 */
function drawCursors(dpr) {
  const t0 = app.timeSpan[0];
  for (const [key, { overlay }] of app.view.overlays) {
    const at = app.session.timeToPixel(key, app.time);
    const x = at === undefined || (app.time === t0 && !app.playing) ? undefined : at;
    // Cleared and drawn only when the cursor moves (or the overlay was resized, the theme
    // changed, or a probe drew on it): clearing every overlay every frame cost a full-size
    // canvas operation per time plot, on screen or not, while a slider moved.
    const plot = app.view.canvases.get(key);
    const drawnKey = `${x}|${plot.width}|${plot.height}|${isDark()}`;
    if (cursorDrawn.get(overlay) === drawnKey) continue;
    cursorDrawn.set(overlay, drawnKey);
    const ctx = overlayContext(key, x !== undefined);
    if (!ctx) continue;
    ctx.strokeStyle = isDark() ? 'rgba(230,233,237,0.8)' : 'rgba(33,37,41,0.7)';
    ctx.lineWidth = Math.max(1, dpr);
    ctx.setLineDash([4 * dpr, 3 * dpr]);
    ctx.beginPath();
    ctx.moveTo(x, 0);
    ctx.lineTo(x, overlay.height);
    ctx.stroke();
  }
}

/**
 * The cleared 2D context of plot `key`'s overlay, sized to the plot's canvas, for drawing
 * on it (`draw`), or `null` after emptying it. An empty overlay is 0 × 0: a canvas of
 * the page's size, even blank, is copied at each commit of a frame (4-5 ms each at 4x CPU
 * in Chromium's software compositing, every canvas on screen at every commit).
 */
function overlayContext(key, draw) {
  const { overlay } = app.view.overlays.get(key);
  const plot = app.view.canvases.get(key);
  const [w, h] = draw ? [plot.width, plot.height] : [0, 0];
  if (overlay.width !== w || overlay.height !== h) {
    [overlay.width, overlay.height] = [w, h]; // cleared by the resize
  } else if (draw) {
    overlay.getContext('2d').clearRect(0, 0, w, h);
  }
  return draw ? overlay.getContext('2d') : null;
}

/** The provisional keys each view last marked (markProvisional), joined. */
const provisionalMarked = new WeakMap();

/**
 * Marks readouts and plots drawn from a coarse study while the full one runs (issue 13);
 * the marks are written when the set changes (each frame of a drag gives the same one).
 * `restarted`: the update started the full study afresh (a redraw goes on with it).
 */
function markProvisional(keys, restarted) {
  if (restarted) showStudyProgress(0, true);
  const joined = keys.join(' ');
  if (provisionalMarked.get(app.view) !== joined) {
    provisionalMarked.set(app.view, joined);
    const now = new Set(keys);
    // The readouts' text says so too (showReadouts).
    for (const [key, item] of app.view.readouts) item.toggleAttribute('data-provisional', now.has(key));
    for (const fig of document.querySelectorAll('[data-plot-wrap]')) {
      const on = now.has(fig.dataset.plotWrap);
      fig.toggleAttribute('data-provisional', on);
      setAttr(fig, 'aria-busy', String(on));
      let bar = fig.querySelector('.study-progress');
      const stage = fig.querySelector('.plot-stage');
      if (on && !bar && stage) {
        bar = el('progress', { class: 'study-progress', max: '100', value: progressValue, 'aria-label': t('studyProgress') });
        stage.append(bar);
      }
      if (bar && on && bar.hidden) setAttr(bar, 'value', progressValue);
      if (bar) bar.hidden = !on;
    }
  }
  if (!keys.length) return;
  // The full module gives a new full study to the worker (studies.js), and only then
  // starts the page's slices (they leave a worker's study alone, and do the rest): else
  // the page began a study the worker would then start again. Without studies.js, the page.
  if (app.module !== 'full') scheduleRefine();
  else withModule('studies', (m) => {
    if (restarted) m.offload(app, requestDraw, scheduleRefine, showStudyProgress);
    scheduleRefine();
  }, scheduleRefine);
}

/** When the study's progress bars were last moved (performance.now()), and to what. */
let progressShown = 0;
let progressValue = '0';

/**
 * Moves the provisional plots' progress bars to `done` (0-1) of the full study, at most
 * every 100 ms (`now`: at once): each move costs a frame's commit.
 */
function showStudyProgress(done, now = false) {
  const t0 = performance.now();
  if (!now && t0 - progressShown < 100) return;
  const value = String(Math.round(Math.min(1, Math.max(0, done)) * 100));
  if (value === progressValue) return; // each frame of a drag starts again from 0
  [progressShown, progressValue] = [t0, value];
  for (const bar of document.querySelectorAll('.study-progress:not([hidden])')) setAttr(bar, 'value', value);
}

/** Runs the pending full study in short slices between frames; redraws when it is done. */
function scheduleRefine() {
  if (app.refineTimer) return;
  const slice = () => {
    app.refineTimer = 0;
    const wait = restLeft(REST_MS.study);
    if (wait > 0 || app.framePending) {
      app.refineTimer = setTimeout(slice, Math.max(wait, 16));
      return;
    }
    const done = app.session.refine(REFINE_SLICE_MS);
    if (done === undefined) return;
    if (done >= 1) requestDraw();
    else {
      showStudyProgress(done);
      app.refineTimer = setTimeout(slice, 0);
    }
  };
  app.refineTimer = setTimeout(slice, 0);
}

/** Schedules one redraw on the next animation frame; bursts of input coalesce. */
function requestDraw() {
  if (app.framePending) return;
  app.framePending = true;
  // Nothing if the frame was drawn at once meanwhile (adopt).
  requestAnimationFrame(() => app.framePending && drawFrame());
}

/**
 * The demo's values changed (a control, reset, a click on a plot, the host page, a new
 * demo, a recovery): the host hears of it after the next frame, and a computation behind
 * the page for the old values starts again (upgrade.js, computeBehind).
 */
function valuesChanged() {
  app.changed = true;
  app.revision += 1;
}

function syncUrl() {
  const { demoId } = app;
  // Read when the write happens, from the session then current (the full module may have
  // replaced it); nothing if another demo has opened meanwhile.
  writeState(demoId, () => {
    if (app.demoId !== demoId) return null;
    try {
      return app.session.values();
    } catch (err) {
      reportFailure(err);
      return null;
    }
  });
}

function setParam(control, raw) {
  app.lastInput = performance.now();
  if (app.needsRecovery) {
    recover().then(() => setParam(control, raw), reportFailure);
    return;
  }
  try {
    const res = app.session.set(control.param.key, raw);
    if (!res) return;
    if (res.notice) notify(app.notices, res.notice.message, 'warn');
    showValue(control, res.value);
  } catch (err) {
    reportFailure(err);
  }
  valuesChanged();
  requestDraw();
  syncUrl();
}

/** Axes hold still while a control is held (pointer or arrow keys); they refit on release. */
function setDragging(on) {
  if (app.dragging === on) return;
  app.dragging = on;
  app.lastInput = performance.now();
  try {
    app.session.setDragging(on);
  } catch (err) {
    reportFailure(err);
  }
  if (!on) easeAxes();
  if (!on && app.layoutDirty) requestDraw();
}

/** After a drag, the axes move to their new ranges over a quarter second (at once when the
 * reader prefers reduced motion). */
function easeAxes() {
  const start = performance.now();
  const session = app.session;
  const step = (now) => {
    if (app.dragging || app.session !== session) return;
    const f = reducedMotion.matches ? 1 : Math.min(1, (now - start) / 250);
    try {
      session.easeAxes(f * f * (3 - 2 * f));
    } catch (err) {
      reportFailure(err);
      return;
    }
    requestDraw();
    if (f < 1) requestAnimationFrame(step);
    // The axes are where they stay: the plots keep their layers a frame after that one,
    // ready for the next drag, before the rest's catch-up.
    else requestAnimationFrame(keepLayers);
  };
  step(start);
}

const STEP_KEYS = new Set(['ArrowLeft', 'ArrowRight', 'ArrowUp', 'ArrowDown', 'PageUp', 'PageDown', 'Home', 'End']);

function wireDrag(range) {
  range.addEventListener('pointerdown', () => setDragging(true));
  // A held arrow key (auto-repeat) is a drag too; a single press rescales at once.
  range.addEventListener('keydown', (ev) => {
    if (ev.repeat && STEP_KEYS.has(ev.key)) setDragging(true);
  });
  range.addEventListener('blur', () => setDragging(false));
}

function wireControls() {
  for (const control of app.view.controls.values()) {
    const kind = control.param.kind;
    if (kind === 'toggle') {
      control.input.addEventListener('change', () => setParam(control, control.input.checked ? '1' : '0'));
    } else if (kind === 'choice') {
      control.input.addEventListener('change', () => setParam(control, control.input.value));
    } else {
      control.range.addEventListener('input', () => {
        const value = fromSlider(control.param, control.range.value);
        control.number.value = formatValue(control.param, value);
        setParam(control, String(value));
      });
      control.number.addEventListener('change', () => setParam(control, control.number.value));
      wireDrag(control.range);
    }
  }
  app.view.picker.addEventListener('change', () => {
    app.layoutDirty = true;
    requestDraw();
  });
  app.view.reset.addEventListener('click', () => {
    app.session.reset();
    showAllValues();
    valuesChanged();
    requestDraw();
    syncUrl();
  });
  for (const { preset, button } of app.view.presets) {
    button.addEventListener('click', () => {
      for (const [key, value] of preset.values) {
        const control = app.view.controls.get(key);
        if (control) setParam(control, String(value));
      }
    });
  }
}

function wireAnimation() {
  const anim = app.view.animation;
  if (!anim) return;
  anim.play.addEventListener('click', () => setPlaying(!app.playing));
  anim.sound.addEventListener('click', () => {
    withModule('sound', ({ createSonifier }) => {
      if (!app.sound.start) app.sound = createSonifier();
      const on = !app.sound.enabled && app.sound.start();
      if (!on) app.sound.stop();
      anim.sound.textContent = on ? t('soundOn') : t('soundOff');
      anim.sound.setAttribute('aria-pressed', String(on));
    });
  });
  anim.scrub.addEventListener('input', () => {
    if (!app.timeSpan) return;
    const [t0, t1] = app.timeSpan;
    app.time = t0 + (Number(anim.scrub.value) / 1000) * (t1 - t0);
    drawTime();
  });
}

function setPlaying(on) {
  const anim = app.view && app.view.animation;
  if (!anim) return;
  app.playing = on;
  anim.play.textContent = on ? t('pause') : t('play');
  anim.play.setAttribute('aria-pressed', String(on));
  if (on) {
    if (app.timeSpan && app.time >= app.timeSpan[1]) app.time = app.timeSpan[0];
    app.lastTick = null;
    requestAnimationFrame(tick);
  } else {
    app.sound.play(null);
  }
}

function tick(now) {
  if (!app.playing || !app.timeSpan) return;
  if (app.lastTick !== null) {
    const dt = Math.min(0.1, (now - app.lastTick) / 1000);
    app.time += dt * (app.speed || 1);
    if (app.time >= app.timeSpan[1]) {
      app.time = app.timeSpan[1];
      setPlaying(false);
    }
  }
  app.lastTick = now;
  try {
    drawTime();
    if (app.sound.enabled) app.sound.play(app.session.sonify(app.time));
  } catch (err) {
    reportFailure(err);
    setPlaying(false);
    return;
  }
  if (app.playing) requestAnimationFrame(tick);
}

/**
 * Takes a probe's crosshair off plot `key`'s overlay: the time cursor is drawn again
 * (drawTime; the crosshair dropped its cursorDrawn), or, without an animation, the overlay
 * is emptied (before, crosshairs piled up there as the pointer moved).
 */
function eraseProbe(key) {
  drawTime();
  if (!app.view.animation || !app.timeSpan) overlayContext(key, false);
}

function wireProbes() {
  for (const [key, canvas] of app.view.canvases) {
    const { overlay, tip, stage } = app.view.overlays.get(key);
    const show = (ev) => {
      if (!app.session.probe) {
        // A first module has no probe. A press or a tap waits for the full module and then
        // shows the values under it (a tap in the first seconds showed nothing); a hover
        // shows them on a move after the full module has taken over.
        if (ev.type === 'pointerdown') {
          useFullModule()
            .then(() => app.session.probe && show(ev))
            .catch(() => {});
        }
        return;
      }
      const dpr = window.devicePixelRatio || 1;
      const rect = canvas.getBoundingClientRect();
      const px = (ev.clientX - rect.left) * dpr;
      const py = (ev.clientY - rect.top) * dpr;
      let probe;
      try {
        probe = app.session.probe(key, px, py);
      } catch (err) {
        reportFailure(err);
        return;
      }
      eraseProbe(key);
      if (!probe) {
        tip.hidden = true;
        return;
      }
      cursorDrawn.delete(overlay); // the crosshair goes with the next drawTime
      if (!overlay.width) overlayContext(key, true); // drawTime left it empty: no cursor
      const ctx = overlay.getContext('2d');
      ctx.save();
      ctx.strokeStyle = isDark() ? 'rgba(230,233,237,0.6)' : 'rgba(33,37,41,0.5)';
      ctx.lineWidth = Math.max(1, dpr);
      ctx.beginPath();
      ctx.moveTo(px, 0);
      ctx.lineTo(px, overlay.height);
      ctx.moveTo(0, py);
      ctx.lineTo(overlay.width, py);
      ctx.stroke();
      for (const p of probe.points) {
        ctx.beginPath();
        ctx.arc(p.px, p.py, 4 * dpr, 0, Math.PI * 2);
        ctx.stroke();
      }
      ctx.restore();
      tip.replaceChildren();
      for (const line of [probe.x_text, ...probe.points.map((p) => p.text)]) {
        const div = document.createElement('div');
        div.textContent = line;
        tip.append(div);
      }
      tip.hidden = false;
      const x = ev.clientX - rect.left;
      const y = ev.clientY - rect.top;
      tip.style.left = `${Math.min(x + 12, stage.clientWidth - tip.offsetWidth - 4)}px`;
      tip.style.top = `${Math.max(4, y - tip.offsetHeight - 12)}px`;
    };
    canvas.addEventListener('click', async (ev) => {
      const dpr = window.devicePixelRatio || 1;
      const rect = canvas.getBoundingClientRect();
      const [px, py] = [(ev.clientX - rect.left) * dpr, (ev.clientY - rect.top) * dpr];
      try {
        // A first module has no pick (see exportPlot): the full one takes over first (and
        // draws, see adopt); if it cannot be loaded, the click does nothing and a later one
        // tries again.
        await useFullModule().catch(() => {});
        if (!app.session.pick) return;
        const applied = app.session.pick(key, px, py);
        if (!applied.length) return;
        for (const [k, v] of applied) {
          const control = app.view.controls.get(k);
          if (control) showValue(control, v);
        }
        valuesChanged();
        requestDraw();
        syncUrl();
      } catch (err) {
        reportFailure(err);
      }
    });
    canvas.addEventListener('pointermove', show);
    canvas.addEventListener('pointerdown', show);
    canvas.addEventListener('pointerleave', (ev) => {
      // A finger "leaves" as it lifts: keep a touch read-out until the next touch.
      if (ev.pointerType !== 'mouse') return;
      tip.hidden = true;
      eraseProbe(key);
    });
  }
}

function wireExports() {
  for (const { key, format, button } of app.view.exports) {
    button.addEventListener('click', () => exportPlot(key, format));
  }
}

/**
 * Downloads plot `key` as `format` (csv, svg or png), stamped (download.js). A first module
 * has no exports (nor the stamp written into each file): the full one takes over first
 * (see fullGlue).
 */
async function exportPlot(key, format) {
  try {
    await useFullModule();
  } catch (err) {
    console.warn(`Zeta Lab: the full module could not be loaded for the ${format} export:`, err && err.message);
    return; // a later click tries again
  }
  withModule('download', (m) => m.downloadPlot({ app, isDark }, key, format).catch(reportFailure));
}

function showAllValues() {
  for (const [key, value] of app.session.values()) {
    const control = app.view.controls.get(key);
    if (control) showValue(control, value);
  }
}

function openDemo(id, query) {
  setPlaying(false);
  app.demoId = id;
  app.session = new app.wasm.Session(id);
  const notices = query ? app.session.applyQuery(query) : [];
  const spec = app.session.spec();
  app.view = buildDemo(app.root, spec);
  app.view.shownPlots = applyEmbedView(app.view, app.embed);
  app.time = 0;
  valuesChanged();
  app.dragging = false;
  app.layoutDirty = true;
  document.title = `${spec.title} — Zeta Lab`;
  attachCanvases();
  wireControls();
  wireAnimation();
  wireProbes();
  wireExports();
  showAllValues();
  applyConditions(spec, app.root);
  for (const n of notices) notify(app.notices, n.message, 'warn');
  const select = document.getElementById('demo-select');
  if (select) select.value = id;
  requestDraw();
  const autoplay = new URLSearchParams(window.location.search).get('autoplay') === '1';
  if (autoplay && !reducedMotion.matches) requestAnimationFrame(() => setPlaying(true));
}

function buildMenu(list) {
  const select = document.getElementById('demo-select');
  select.replaceChildren();
  for (const d of list) {
    const opt = document.createElement('option');
    opt.value = d.id;
    opt.textContent = d.title;
    select.append(opt);
  }
}

function wireMenu() {
  const select = document.getElementById('demo-select');
  select.addEventListener('change', () => {
    if (app.module === 'first' && select.value !== app.demoId) {
      // The first module holds only its own demo: wait for the full one, visibly.
      const note = document.createElement('p');
      note.className = 'notice notice-info';
      note.textContent = t('loading');
      app.notices.append(note);
      app.root.setAttribute('aria-busy', 'true');
      app.root.dataset.loading = 'full';
      loadFull()
        .then((mod) => {
          if (app.module === 'first') adopt(mod, false); // the chosen demo draws
          openDemo(select.value, null);
          syncUrl();
        })
        .catch(reportFailure)
        .finally(() => {
          note.remove();
          app.root.removeAttribute('aria-busy');
          delete app.root.dataset.loading;
        });
      return;
    }
    openDemo(select.value, null);
    syncUrl();
  });
}

/**
 * Instantiates the full module once (a promise of {glue, exports}). After a failure the
 * glue is asked for at a new address, for browsers that remember a failed import.
 */
function loadFull() {
  app.fullLoading ??= (async () => {
    const glue = await import(app.fullFailed ? `../zeta-app.js?try=${app.fullFailed}` : '../zeta-app.js');
    const exports = await glue.default({ module_or_path: WASM_URL });
    return { glue, exports };
  })().catch((err) => {
    app.fullLoading = null;
    app.fullFailed += 1;
    throw err;
  });
  return app.fullLoading;
}

/**
 * After the first plot from the first module: the full module starts downloading at once,
 * while upgrade.js (the switch, see there) loads beside it and then moves the demo to it
 * between two bursts of input. Without upgrade.js (it is asked for again, three times) the
 * menu's switch still works.
 */
function startUpgrade(tries = 0) {
  loadFull().catch(() => {}); // upgrade() reports a failure (its own call tries again if this one already failed)
  return import(tries ? `./upgrade.js?try=${tries}` : './upgrade.js').then(
    (m) => m.upgrade(app, { loadFull, adopt, reportFailure, restLeft, isDark, showStudyProgress, showResults, observeVisibility, scheduleCatchUp, rest: REST_MS.upgrade, slice: REFINE_SLICE_MS }),
    (err) => {
      console.warn('Zeta Lab: upgrade.js could not be loaded:', err && err.message);
      // Asked again (a new address: a failed import is remembered) 2, 4 and 8 s later, while
      // the page is on the first module; a menu choice or a click switches meanwhile.
      if (tries < 3) setTimeout(() => app.module === 'first' && startUpgrade(tries + 1), 2000 << tries);
    },
  );
}

/** Resolves once the open demo runs on the full module (switching to it now if needed). */
function useFullModule() {
  if (app.module !== 'first') return app.takingOver ?? Promise.resolve();
  // One take-over for every caller at once (a tap's read-out and its click's pick): each
  // resolves once the new session has drawn.
  app.takingOver ??= (async () => {
    const mod = await loadFull();
    if (app.module === 'first') adopt(mod);
  })().finally(() => {
    app.takingOver = null;
  });
  return app.takingOver;
}

/**
 * Moves the open demo from the first module's instance to the full module's, and draws it
 * there at once unless `draw` is false (another demo opens next, and draws in its frame):
 * a read-out or a pick in the switch's first frame finds the new session's figures.
 */
function adopt({ glue, exports }, draw = true) {
  const old = app.session;
  try {
    app.missing.push(...app.wasm.takeMissingMessages()); // reported by the diagnostics
  } catch {
    // a failed first instance cannot answer
  }
  // The page's own copy if the first instance failed; else its exact values.
  const values = app.needsRecovery ? shownValues() : old.values().map(([k, v]) => [k, String(v)]);
  adoptInstance(glue);
  app.wasm = glue;
  useGlue(glue);
  app.exports = exports;
  app.module = 'full';
  app.session = new glue.Session(app.demoId);
  app.session.applyQuery(currentQuery());
  for (const [k, v] of values) app.session.set(k, v);
  attachCanvases();
  app.needsRecovery = false;
  try {
    old.free();
  } catch {
    // the first instance is dropped either way
  }
  if (!draw) return requestDraw();
  app.framePending = true;
  drawFrame();
}

/** The language menu: every language by its own name; a pseudo-locale only while active. */
function buildLanguageMenu() {
  const select = document.getElementById('lang-select');
  const current = activeLanguage();
  select.replaceChildren();
  for (const l of languages()) {
    if (l.pseudo && l.tag !== current.tag) continue;
    const opt = document.createElement('option');
    opt.value = l.tag;
    opt.lang = l.pseudo ? 'en' : l.tag;
    opt.textContent = l.name;
    select.append(opt);
  }
  select.value = current.tag;
}

/**
 * Switches the page and the demo to language `tag`, keeping the demo's values: the
 * choice goes into the address (`lang=`) and is remembered for the next visit.
 */
async function switchLanguage(tag) {
  remember(tag);
  const values = app.session ? app.session.values() : [];
  cancelPendingWrite(); // a queued write must not bring back the old lang=
  const q = new URLSearchParams(window.location.search);
  q.set('lang', tag);
  history.replaceState(null, '', `?${q.toString()}${window.location.hash}`);
  const { problem, stale } = await useLanguage(app.wasm, [tag]);
  if (stale) return; // a later choice is being applied
  buildLanguageMenu();
  buildMenu(app.wasm.demoList());
  cancelPendingWrite();
  const query = queryFor(app.demoId, values);
  history.replaceState(null, '', query + window.location.hash);
  openDemo(app.demoId, query);
  if (problem) notify(app.notices, t('catalogueFailed', problem), 'warn');
}

function wireLanguageMenu() {
  const select = document.getElementById('lang-select');
  select.addEventListener('change', () => {
    switchLanguage(select.value).catch(reportFailure);
  });
}

function wireShare() {
  const button = document.getElementById('share-button');
  if (!button) return;
  button.addEventListener('click', () => {
    // Opened styled: its styles load after the first plot (lecturer.css).
    loadStyles().then(() => withModule('share', ({ openShareDialog }) => {
      openShareDialog({ demoId: app.demoId, values: app.session.values(), spec: app.view.spec });
    }));
  });
}

/** Sets parameters from the host page ([[key, text]]), each validated by Rust. */
function setFromHost(entries) {
  for (const [key, raw] of entries) {
    const control = app.view.controls.get(key);
    if (control) setParam(control, raw);
  }
}

/** Space plays or pauses the animation unless a control that uses Space has focus. */
function onKey(ev) {
  if (ev.key !== ' ' || !app.view || !app.view.animation) return;
  const t = ev.target;
  const tag = t && t.tagName;
  if (tag === 'INPUT' || tag === 'SELECT' || tag === 'TEXTAREA' || tag === 'BUTTON' || (t && t.isContentEditable)) return;
  ev.preventDefault();
  setPlaying(!app.playing);
}

async function main() {
  // state.js has expanded a state= token: web/preload.js decides again on the full address
  // (theme, and which module starts), and records it on <html>.
  document.dispatchEvent(new Event('zeta:address'));
  translatePage();
  if (app.embed.embed) root.dataset.embed = '1';
  app.root = document.getElementById('demo');
  app.notices = document.getElementById('notices');
  const wanted = demoFromUrl();
  // Inside a frame the host may talk at once: the host-page API loads beside the wasm. A
  // `predict=` page needs the prediction form before its first demo opens.
  const framed = app.embed.embed || window.parent !== window;
  const hostModule = framed ? later('embed') : null;
  const prediction = app.embed.predict ? loadPrediction() : null;
  // A first module serves its one demo on the main page (web/preload.js decides; a dev
  // build has none and starts with the full module).
  const firstDemo = root.dataset.startModule === 'first' ? root.dataset.startDemo : null;
  try {
    if (firstDemo) {
      try {
        const glue = await import(`../zeta-first-${firstDemo}.js`);
        const wasm = new URL(`../zeta-first-${firstDemo}_bg.wasm`, import.meta.url);
        app.exports = await glue.default({ module_or_path: wasm });
        app.wasm = glue;
        app.module = 'first';
        app.firstDemo = firstDemo;
      } catch (err) {
        console.warn('Zeta Lab: starting with the full module:', err && err.message);
      }
    }
    if (!app.wasm) {
      const { glue, exports } = await loadFull();
      app.wasm = glue;
      app.exports = exports;
      app.module = 'full';
    }
    useGlue(app.wasm);
    // Read-only diagnostics for the soak test and curious lecturers.
    window.zetaDiagnostics = Object.freeze({
      wasmBytes: () => app.exports.memory.buffer.byteLength,
      /** 'first' (the small module that links only the demo the page opened) or 'full'. */
      module: () => app.module,
      /** Whether every canvas shows the last update (or a control is held: then plots off
       * screen wait, see observeVisibility). */
      drawn: () => app.dragging || (!app.framePending && !app.staleLeft && !app.schematicStale),
      /** Message ids shown in English since the last call (the active catalogue lacks them). */
      missingMessages: () => [...new Set([...app.missing.splice(0), ...app.wasm.takeMissingMessages()])],
      language: () => ({ ...activeLanguage() }),
      languages: () => languages().map((l) => ({ ...l })),
    });
  } catch (err) {
    app.root.replaceChildren();
    const p = document.createElement('p');
    p.className = 'notice notice-error';
    p.textContent = t('noWasm', { text: err && err.message ? err.message : err });
    app.root.append(p);
    return;
  }
  if (prediction) await prediction.catch((err) => console.warn('Zeta Lab: predict.js:', err && err.message));
  const { problem } = await useLanguage(app.wasm, requestedLanguages());
  if (problem) notify(app.notices, t('catalogueFailed', problem), 'warn');
  buildLanguageMenu();
  wireLanguageMenu();
  const list = app.wasm.demoList();
  buildMenu(list);
  wireMenu();
  const known = list.some((d) => d.id === wanted);
  if (wanted !== null && !known) {
    notify(app.notices, t('noDemo', { id: wanted.slice(0, 40), fallback: DEFAULT_DEMO }), 'warn');
  }
  openDemo(known ? wanted : DEFAULT_DEMO, known ? currentQuery() : null);
  new ResizeObserver(requestRelayout).observe(app.root);
  // A printout carries the explanation even when it is folded on screen.
  window.addEventListener('beforeprint', () => {
    for (const d of document.querySelectorAll('details')) d.open = true;
  });
  window.addEventListener('resize', requestRelayout);
  for (const type of ['pointerup', 'pointercancel', 'keyup']) window.addEventListener(type, () => setDragging(false));
  darkQuery.addEventListener('change', () => requestDraw());
  document.addEventListener('keydown', onKey);
  wireShare();
  // A demo's first module opens only that demo: embed.js reloads the page for another.
  const canOpen = (id) => app.module !== 'first' || id === app.firstDemo;
  const handlers = { set: setFromHost, state: hostState, app, setPlaying, drawTime, requestDraw, openDemo, canOpen, isDark };
  connectPage(handlers);
  if (hostModule) {
    try {
      app.host = (await hostModule).connectHost(app.embed, handlers);
      // The first frame may have come before the host API: it says it is ready now.
      if (app.firstDrawn && !app.changed) app.host.notify();
    } catch (err) {
      console.warn('Zeta Lab: the host-page API could not be loaded:', err && err.message);
    }
  }
  root.dataset.ready = 'true';
}

/** Offline use after the first visit (not for file:// pages, where it cannot work). */
function registerServiceWorker() {
  if (!('serviceWorker' in navigator) || !window.location.protocol.startsWith('http')) return;
  navigator.serviceWorker.register(new URL('../sw.js', import.meta.url)).catch((err) => {
    console.warn('Offline support unavailable:', err && err.message);
  });
}

main();
