// Embedding: the embed view options (embed, controls, lock, plots) and the host-page API
// over postMessage.
//
// Host → demo:  {type: 'zeta:set', params: {zeta: 0.3, …}}   set parameters (validated in Rust)
//               {type: 'zeta:get'}                            ask for the current state
// Demo → host:  {type: 'zeta:ready', demo, params, readouts}  once, when the demo has drawn
//               {type: 'zeta:change', demo, params, readouts} after every change
// `params` maps keys to numbers; `readouts` maps keys to data-value strings.
// Messages are accepted only from the parent window, and, when the page was given
// `origin=<host origin>`, only from that origin; replies then go to that origin only.
// Anything malformed is ignored.

const MAX_KEYS = 64;

/** Options of the embed view from the query string. */
export function embedOptions(search = window.location.search) {
  const q = new URLSearchParams(search);
  const list = (name) => {
    const v = q.get(name);
    if (v === null) return null;
    return v.split(',').map((s) => s.trim()).filter((s) => /^[A-Za-z0-9_]{1,40}$/.test(s));
  };
  return {
    embed: q.get('embed') === '1',
    controls: list('controls'),
    lock: list('lock'),
    plots: list('plots'),
    origin: q.get('origin'),
  };
}

/** Applies controls=/lock=/plots= to the built view; returns the plot keys to draw. */
export function applyEmbedView(view, opts) {
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
  return shown;
}

/** Connects the host-page API. `handlers`: {set(params), state() → {demo, params, readouts}}. */
export function connectHost(opts, handlers) {
  if (window.parent === window) return { notify() {} };
  const target = opts.origin && /^https?:\/\/[^/]+$/.test(opts.origin) ? opts.origin : '*';
  window.addEventListener('message', (ev) => {
    if (ev.source !== window.parent) return;
    if (target !== '*' && ev.origin !== target) return;
    const msg = ev.data;
    if (!msg || typeof msg !== 'object' || typeof msg.type !== 'string') return;
    if (msg.type === 'zeta:set') {
      const params = msg.params;
      if (!params || typeof params !== 'object' || Array.isArray(params)) return;
      const entries = Object.entries(params).slice(0, MAX_KEYS)
        .filter(([k, v]) => typeof k === 'string' && (typeof v === 'number' || typeof v === 'string'));
      handlers.set(entries.map(([k, v]) => [k, String(v)]));
    } else if (msg.type === 'zeta:get') {
      window.parent.postMessage({ type: 'zeta:state', ...handlers.state() }, target);
    }
  });
  let ready = false;
  return {
    notify() {
      const type = ready ? 'zeta:change' : 'zeta:ready';
      ready = true;
      window.parent.postMessage({ type, ...handlers.state() }, target);
    },
  };
}
