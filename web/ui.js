// Builds a demo's controls, readouts and plot canvases from its Rust declaration, shows or
// hides conditional controls and fills a reference table's live cells (both at the end of
// this file: in the module the first plot needs anyway, each a request fewer before it).
// Every string from outside is inserted with textContent, never as HTML; the only markup
// inserted is the equation's MathML, which comes from the compiled Rust declaration.

import { t } from './i18n.js';

const LOG_STEPS = 1000;

/** A new `tag` element with attributes `attrs` and, if given, `text` as its text content. */
export function el(tag, attrs = {}, text) {
  const node = document.createElement(tag);
  for (const [k, v] of Object.entries(attrs)) node.setAttribute(k, v);
  if (text !== undefined) node.textContent = text;
  return node;
}

/** Slider position for a value (log sliders use 0…LOG_STEPS). */
export function toSlider(param, value) {
  if (param.scale !== 'log') return value;
  const f = Math.log(value / param.min) / Math.log(param.max / param.min);
  return Math.round(Math.min(1, Math.max(0, f)) * LOG_STEPS);
}

/** Value for a slider position. */
export function fromSlider(param, position) {
  if (param.scale !== 'log') return Number(position);
  const f = Number(position) / LOG_STEPS;
  return param.min * Math.pow(param.max / param.min, f);
}

function unitSuffix(unit) {
  return unit ? ` [${unit}]` : '';
}

/** Formats a slider value for the number box: enough digits for the step. */
export function formatValue(param, value) {
  if (param.scale === 'log') return String(Number(value.toPrecision(4)));
  const decimals = Math.max(0, Math.ceil(-Math.log10(param.step) - 1e-9));
  return String(Number(value.toFixed(Math.min(decimals, 12))));
}

function toggleControl(param) {
  const wrap = el('div', { class: 'param param-toggle', 'data-param': param.key });
  const id = `p-${param.key}`;
  const box = el('input', { type: 'checkbox', id, 'data-key': param.key });
  const label = el('label', { for: id }, param.label);
  wrap.append(box, label);
  return { wrap, input: box };
}

function choiceControl(param) {
  const wrap = el('div', { class: 'param', 'data-param': param.key });
  const id = `p-${param.key}`;
  const select = el('select', { id, 'data-key': param.key });
  param.options.forEach((o, i) => select.append(el('option', { value: String(i) }, o.label)));
  wrap.append(el('label', { for: id }, param.label), select);
  return { wrap, input: select };
}

function paramControl(param) {
  const wrap = el('div', { class: 'param', 'data-param': param.key });
  const id = `p-${param.key}`;
  const label = el('label', { for: id });
  label.append(el('span', { class: 'param-name' }, `${param.label} `), el('span', { class: 'symbol' }, param.symbol));
  if (param.unit) label.append(el('span', { class: 'unit' }, ` [${param.unit}]`));
  const range = el('input', {
    type: 'range',
    id,
    'data-key': param.key,
    min: param.scale === 'log' ? 0 : param.min,
    max: param.scale === 'log' ? LOG_STEPS : param.max,
    step: param.scale === 'log' ? 1 : param.step,
  });
  const number = el('input', {
    type: 'number',
    'data-key': param.key,
    min: param.min,
    max: param.max,
    step: param.scale === 'log' ? 'any' : param.step,
    inputmode: 'decimal',
    'aria-label': `${param.label} (${param.symbol})${unitSuffix(param.unit)}, ${t('exactValue')}`,
  });
  wrap.append(label, el('div', { class: 'param-inputs' }, undefined));
  wrap.lastChild.append(range, number);
  return { wrap, range, number };
}

/** The demo's heading: title, equation, and the explanation folded into a disclosure. */
function buildHead(spec) {
  const head = el('section', { class: 'demo-head', 'aria-labelledby': 'demo-title' });
  head.append(el('h1', { id: 'demo-title' }, spec.title));
  // Focusable, so a keyboard can scroll an equation wider than a phone (axe: scrollable-region-focusable).
  const eq = el('div', { class: 'equation', tabindex: '0', role: 'group', 'aria-label': t('equation') });
  eq.innerHTML = spec.equation_mathml; // trusted: compiled into the wasm, never from the URL
  const about = el('details', { class: 'about' });
  about.append(el('summary', {}, t('about')), el('p', { class: 'summary' }, spec.summary));
  // Open where there is room beside the stage; folded on phones and small windows.
  if (window.matchMedia('(min-width: 1000px) and (min-height: 760px)').matches) about.open = true;
  head.append(eq, about);
  return head;
}

/** The parameter form: controls, presets, reset. */
function buildControls(spec) {
  const form = el('form', { class: 'controls', 'aria-label': t('parameters') });
  form.addEventListener('submit', (e) => e.preventDefault());
  const controls = new Map();
  for (const p of spec.params) {
    if (p.kind === 'toggle' || p.kind === 'choice') {
      const c = p.kind === 'toggle' ? toggleControl(p) : choiceControl(p);
      form.append(c.wrap);
      controls.set(p.key, { param: p, input: c.input });
    } else {
      const c = paramControl(p);
      form.append(c.wrap);
      controls.set(p.key, { param: p, range: c.range, number: c.number });
    }
  }
  const reset = el('button', { type: 'button', class: 'reset' }, t('reset'));
  const presets = [];
  if (spec.presets.length) {
    const box = el('div', { class: 'presets', role: 'group', 'aria-label': t('presets') });
    box.append(el('span', { class: 'presets-label' }, t('presets')));
    for (const preset of spec.presets) {
      const b = el('button', { type: 'button', class: 'preset' }, preset.label);
      box.append(b);
      presets.push({ preset, button: b });
    }
    form.append(box);
  }
  const actions = el('div', { class: 'form-actions' });
  actions.append(reset);
  form.append(actions);
  return { form, controls, presets, reset };
}

/** Readouts as a compact strip (scrollable by keyboard when it overflows). */
function buildReadouts(spec) {
  const strip = el('div', { class: 'readout-strip', role: 'region', 'aria-label': t('readouts'), tabindex: '0' });
  const box = el('dl', { class: 'readouts' });
  const readouts = new Map();
  for (const r of spec.readouts) {
    const item = el('div', { class: 'readout', 'data-readout': r.key, 'data-value': '' });
    item.append(el('dt', {}, r.label), el('dd', {}, '—'));
    box.append(item);
    readouts.set(r.key, item);
  }
  strip.append(box);
  return { strip, readouts };
}

/** One plot: canvas with its overlay and read-out tip, caption (its text alternative), exports. */
function buildFigure(p, exports) {
  const fig = el('figure', { class: 'plot', 'data-plot-wrap': p.key });
  // Plots read left to right in every language (as printed maths does): their text is
  // drawn with the canvas's direction, so the stage keeps `ltr` on a right-to-left page.
  const stage = el('div', { class: 'plot-stage', dir: 'ltr' });
  const canvas = el('canvas', { 'data-plot': p.key, role: 'img', 'aria-label': p.title, tabindex: '0' });
  canvas.style.aspectRatio = String(p.aspect);
  const overlay = el('canvas', { class: 'overlay', 'aria-hidden': 'true' });
  const tip = el('div', { class: 'probe', hidden: '' });
  stage.append(canvas, overlay, tip);
  const caption = el('figcaption', { id: `desc-${p.key}` });
  canvas.setAttribute('aria-describedby', caption.id);
  const tools = el('div', { class: 'plot-tools', role: 'group', 'aria-label': t('exportGroup', { plot: p.title }) });
  for (const [format, text] of [['png', 'PNG'], ['svg', 'SVG'], ['csv', 'CSV']]) {
    const b = el('button', { type: 'button', 'data-export': format, 'aria-label': t('download', { plot: p.title, format: text }) }, text);
    tools.append(b);
    exports.push({ key: p.key, format, button: b });
  }
  fig.append(stage, caption, tools);
  return { fig, canvas, overlay, tip, stage, caption };
}

/**
 * Builds the demo. The document order is the reading order on every screen: heading,
 * the plot stage (one plot kept in view, a picker for the others, the readouts), the
 * parameter form, the schematic, the other plots, the reference table. CSS places these
 * in a sticky stage beside (wide) or above (narrow) the controls; see style.css.
 *
 * Returns handles: {controls: Map(key → {param, range, number} | {param, input}),
 * readouts: Map(key → element), canvases: Map(key → canvas), figures: Map(key → figure),
 * stagePlot(key), …}.
 */
export function buildDemo(root, spec) {
  root.replaceChildren();
  root.classList.remove('touring'); // the paper's tour hid the stage and the controls
  const workspace = el('div', { class: 'workspace', 'data-demo': spec.id, 'data-primary': spec.primary_plot });
  const head = buildHead(spec);
  const stageBox = el('section', { class: 'stage', 'aria-label': t('plotInView') });
  const bar = el('div', { class: 'stage-bar' });
  const pickerId = 'plot-picker';
  const picker = el('select', { id: pickerId, class: 'plot-picker' });
  bar.append(el('label', { for: pickerId, class: 'visually-hidden' }, t('plotInView')), picker);
  const { form, controls, presets, reset } = buildControls(spec);
  const { strip, readouts } = buildReadouts(spec);
  const side = el('div', { class: 'side' });
  let animation = null;
  if (spec.schematic) animation = buildAnimation(side);
  const gallery = el('div', { class: 'plots' });

  const canvases = new Map();
  const overlays = new Map();
  const captions = new Map();
  const figures = new Map();
  const exports = [];
  for (const p of spec.plots) {
    const f = buildFigure(p, exports);
    picker.append(el('option', { value: p.key }, p.title));
    gallery.append(f.fig);
    canvases.set(p.key, f.canvas);
    overlays.set(p.key, { overlay: f.overlay, tip: f.tip, stage: f.stage });
    captions.set(p.key, f.caption);
    figures.set(p.key, f.fig);
  }
  const slot = el('div', { class: 'stage-slot' });
  stageBox.append(bar, slot, strip);
  workspace.append(head, stageBox, form, side, gallery);
  root.append(workspace);
  let table = null;
  if (spec.table) table = buildTable(workspace, spec.table);
  const live = el('div', { class: 'visually-hidden', 'aria-live': 'polite', id: 'plot-announcer' });
  root.append(live);

  const view = {
    controls, readouts, canvases, overlays, captions, figures, exports, presets, animation, table,
    live, reset, spec, workspace, stage: stageBox, slot, picker, gallery, staged: null,
    order: spec.plots.map((p) => p.key),
  };
  /** Puts plot `key` on the stage; the one there goes back to its place among the others. */
  view.stagePlot = (key) => {
    if (!figures.has(key)) return;
    view.staged = key;
    workspace.dataset.primaryShown = key;
    picker.value = key;
    slot.replaceChildren(figures.get(key));
    for (const k of view.order) if (k !== key) gallery.append(figures.get(k));
    const choices = [...picker.options].filter((o) => !o.hidden).length;
    stageBox.classList.toggle('single', choices < 2);
    gallery.hidden = [...gallery.children].every((f) => f.hidden);
  };
  picker.addEventListener('change', () => view.stagePlot(picker.value));
  view.stagePlot(spec.primary_plot);
  return view;
}

function buildAnimation(parent) {
  const fig = el('figure', { class: 'schematic' });
  const canvas = el('canvas', { 'data-plot': 'schematic', role: 'img', 'aria-label': t('schematic'), dir: 'ltr' });
  const bar = el('div', { class: 'anim-bar' });
  const play = el('button', { type: 'button', class: 'play', 'aria-pressed': 'false' }, t('play'));
  const scrub = el('input', { type: 'range', min: '0', max: '1000', step: '1', value: '0', 'aria-label': t('animTime') });
  const time = el('output', { class: 'anim-time' }, 't = 0 s');
  const sound = el('button', { type: 'button', class: 'sound', 'aria-pressed': 'false', title: t('soundHint') }, t('soundOff'));
  bar.append(play, scrub, time, sound);
  const caption = el('figcaption', { class: 'visually-hidden' });
  fig.append(canvas, bar, caption);
  parent.append(fig);
  return { canvas, play, scrub, time, caption, sound };
}

function buildTable(root, table) {
  // Focusable, so a keyboard can scroll it sideways on a narrow screen.
  const wrap = el('div', { class: 'table-wrap', role: 'region', 'aria-label': table.caption, tabindex: '0' });
  const t = el('table', { class: 'ref-table' });
  t.append(el('caption', {}, table.caption));
  const head = el('tr');
  for (const c of table.columns) head.append(el('th', { scope: 'col' }, c));
  t.append(el('thead'));
  t.tHead.append(head);
  const body = el('tbody');
  const rows = new Map();
  const live = [];
  for (const [key, cells] of table.rows) {
    const tr = el('tr', { 'data-row': key });
    cells.forEach((c, i) => {
      const m = LIVE.exec(c);
      const cell = el(i === 0 ? 'th' : 'td', i === 0 ? { scope: 'row' } : {}, m ? '—' : c);
      if (m) {
        cell.dataset.liveReadout = m[1];
        live.push({ cell, key: m[1] });
      }
      tr.append(cell);
    });
    body.append(tr);
    rows.set(key, tr);
  }
  t.append(body);
  wrap.append(t);
  root.append(wrap);
  return { wrap, rows, live, readout: table.highlight_readout };
}

/** Highlights the table row whose key is the readout's current value. */
export function highlightRow(table, readouts) {
  if (!table) return;
  const r = readouts.find((x) => x.key === table.readout);
  // The same row as the last frame's (most frames of a drag): nothing to toggle.
  if (table.on === (table.on = r?.data_value)) return;
  for (const [key, tr] of table.rows) {
    const on = r && r.data_value === key;
    tr.classList.toggle('current', on);
    if (on) tr.setAttribute('aria-current', 'true');
    else tr.removeAttribute('aria-current');
  }
}

/** Shows a value on a control (slider and number box, checkbox, or list). */
export function showValue(control, value) {
  if (control.param.kind === 'toggle') {
    control.input.checked = value === 1;
    return;
  }
  if (control.param.kind === 'choice') {
    control.input.value = String(value);
    return;
  }
  // Written only when they differ (a held drag sets the value the slider already shows):
  // setting an input's value, even to the same, has the page style and paint it again.
  const position = String(toSlider(control.param, value));
  if (control.range.value !== position) control.range.value = position;
  const shown = formatValue(control.param, value);
  if (control.number.value !== shown) control.number.value = shown;
  const unit = control.param.unit ? ` ${control.param.unit}` : '';
  setAttr(control.range, 'aria-valuetext', `${control.param.label} ${shown}${unit}`);
}

/** Each readout's value element (its `dd`), found once: a readout is written every frame. */
const valueOf = new WeakMap();

/** Stands for a readout's text in the provisional label's message (a private-use character). */
const TEXT = '\uE000';

/**
 * Writes readouts ([{key, text, data_value}]) into their elements; those in `provisional`
 * get the provisional label ("0.012 (provisional)"), formatted once per call rather than once
 * per readout (each is a call into the module's message formatting, seven a frame while
 * integrators' sliders move). An element in the set `away` (one out of view while a control
 * is held, see main.js observeAway) gets its `data-value` only.
 */
export function showReadouts(elements, readouts, provisional = new Set(), away) {
  const label = provisional.size > 0 ? t('provisional', { value: TEXT }).split(TEXT) : null;
  for (const r of readouts) {
    const item = elements.get(r.key);
    if (!item) continue;
    setAttr(item, 'data-value', r.data_value);
    if (away?.has(item)) continue;
    let dd = valueOf.get(item);
    if (!dd) valueOf.set(item, (dd = item.querySelector('dd')));
    setText(dd, label && provisional.has(r.key) ? label.join(r.text) : r.text);
  }
}

/**
 * Sets a node's text only when it changes: writing even the same text replaces the text
 * node, and the page lays out and paints it again (every frame of a drag, issue 13).
 */
export function setText(node, text) {
  if (node.textContent !== text) node.textContent = text;
}

/** Sets an attribute only when its value changes (see setText). */
export function setAttr(node, name, value) {
  if (node.getAttribute(name) !== value) node.setAttribute(name, value);
}

/** Adds a dismissible notice (plain text). */
export function notify(box, message, kind = 'info') {
  const p = el('p', { class: `notice notice-${kind}` });
  p.append(el('span', {}, message));
  const close = el('button', { type: 'button', class: 'notice-close', 'aria-label': t('dismiss') }, '×');
  close.addEventListener('click', () => p.remove());
  p.append(close);
  box.append(p);
  while (box.children.length > 5) box.firstChild.remove();
}

// Conditional controls: a parameter whose spec carries `visible_when: [key, index]` is shown
// only while the parameter `key` has the value `index` (a choice's option index, or 0/1 for
// a checkbox), e.g. a machine's sliders only while that machine is chosen. Hidden
// controls keep their values. Only controls hidden here are ever shown again here, so the
// embed view's `controls=` choice is left alone.

const MARK = 'conditional';

/** The current value of parameter `key` as the page shows it, or null if it has no control. */
function shownValue(root, key) {
  const input = root.querySelector(`[data-param="${CSS.escape(key)}"] [data-key]`);
  if (!input) return null;
  if (input.type === 'checkbox') return input.checked ? 1 : 0;
  const form = input.closest('.param');
  const number = form && form.querySelector('input[type="number"]');
  return Number(number ? number.value : input.value);
}

/**
 * Shows or hides every control with a `visible_when` condition in `spec` (the demo's spec
 * from `Session.spec()`), reading the controlling values from the page under `root`.
 * Call it after the controls are built and after every update.
 */
export function applyConditions(spec, root = document) {
  for (const param of spec.params) {
    const when = param.visible_when;
    if (!Array.isArray(when) || when.length !== 2) continue;
    const wrap = root.querySelector(`.param[data-param="${CSS.escape(param.key)}"]`);
    if (!wrap) continue;
    const show = shownValue(root, when[0]) === Number(when[1]);
    if (!show && !wrap.hidden) {
      wrap.hidden = true;
      wrap.dataset.hiddenBy = MARK;
    } else if (show && wrap.dataset.hiddenBy === MARK) {
      wrap.hidden = false;
      delete wrap.dataset.hiddenBy;
    }
  }
}

// Live cells of a demo's reference table. A cell whose whole text is `{readout:<key>}`
// (declared in Rust with `live_cell!`, see `Table::live_cells` in crates/app/src/spec.rs)
// shows the current text of readout `<key>`; every other cell stays as declared. The text
// comes from Rust, already formatted and translated: no numbers are computed here.
// buildTable finds the live cells once (marked `data-live-readout="<key>"`, showing "—"
// until the first update), so the declared marker never shows and an update touches only
// them: reading every cell's text back at each slider event cost about 1 ms a frame at 4×
// CPU slowdown (analogy's table).
const LIVE = /^\{readout:([A-Za-z0-9_-]+)\}$/;

/**
 * Fills the live cells of `table` (the view `buildTable` returns: `{ wrap, rows, live:
 * [{ cell, key }] }`, or null) with the texts of `readouts` (`[{ key, text }]`, as
 * `Session.update` returns them). Call after every update. A readout that is missing
 * shows as "—".
 */
export function fillLiveCells(table, readouts) {
  if (!table?.live.length) return;
  const texts = new Map(readouts.map((r) => [r.key, r.text]));
  for (const { cell, key } of table.live) setText(cell, texts.get(key) ?? '—');
}
