// Builds a demo's controls, readouts and plot canvases from its Rust declaration.
// Every string from outside is inserted with textContent, never as HTML; the only markup
// inserted is the equation's MathML, which comes from the compiled Rust declaration.

const LOG_STEPS = 1000;

function el(tag, attrs = {}, text) {
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
    'aria-label': `${param.label} (${param.symbol})${unitSuffix(param.unit)}, exact value`,
  });
  wrap.append(label, el('div', { class: 'param-inputs' }, undefined));
  wrap.lastChild.append(range, number);
  return { wrap, range, number };
}

/**
 * Builds the demo section. Returns handles: {controls: Map(key → {param, range, number}),
 * readouts: Map(key → element), canvases: Map(key → canvas)}.
 */
export function buildDemo(root, spec) {
  root.replaceChildren();
  const head = el('section', { class: 'demo-head', 'aria-labelledby': 'demo-title' });
  head.append(el('h1', { id: 'demo-title' }, spec.title));
  const eq = el('div', { class: 'equation' });
  eq.innerHTML = spec.equation_mathml; // trusted: compiled into the wasm, never from the URL
  head.append(eq, el('p', { class: 'summary' }, spec.summary));

  const panel = el('div', { class: 'panel' });
  const form = el('form', { class: 'controls', 'aria-label': 'Parameters' });
  form.addEventListener('submit', (e) => e.preventDefault());
  const controls = new Map();
  for (const p of spec.params) {
    const c = paramControl(p);
    form.append(c.wrap);
    controls.set(p.key, { param: p, range: c.range, number: c.number });
  }

  const readoutBox = el('dl', { class: 'readouts', 'aria-label': 'Readouts' });
  const readouts = new Map();
  for (const r of spec.readouts) {
    const item = el('div', { class: 'readout', 'data-readout': r.key, 'data-value': '' });
    item.append(el('dt', {}, r.label), el('dd', {}, '—'));
    readoutBox.append(item);
    readouts.set(r.key, item);
  }
  panel.append(form, readoutBox);

  const plots = el('div', { class: 'plots' });
  const canvases = new Map();
  for (const p of spec.plots) {
    const fig = el('figure', { class: 'plot', 'data-plot-wrap': p.key });
    const canvas = el('canvas', { 'data-plot': p.key, role: 'img', 'aria-label': p.title });
    canvas.style.aspectRatio = String(p.aspect);
    fig.append(canvas);
    plots.append(fig);
    canvases.set(p.key, canvas);
  }
  root.append(head, panel, plots);
  return { controls, readouts, canvases };
}

/** Shows a value on a slider and its number box. */
export function showValue(control, value) {
  control.range.value = String(toSlider(control.param, value));
  control.number.value = formatValue(control.param, value);
  const unit = control.param.unit ? ` ${control.param.unit}` : '';
  control.range.setAttribute('aria-valuetext', `${control.param.label} ${formatValue(control.param, value)}${unit}`);
}

/** Writes readouts ([{key, text, data_value}]) into their elements. */
export function showReadouts(elements, readouts) {
  for (const r of readouts) {
    const item = elements.get(r.key);
    if (!item) continue;
    item.setAttribute('data-value', r.data_value);
    item.querySelector('dd').textContent = r.text;
  }
}

/** Adds a dismissible notice (plain text). */
export function notify(box, message, kind = 'info') {
  const p = el('p', { class: `notice notice-${kind}` });
  p.append(el('span', {}, message));
  const close = el('button', { type: 'button', class: 'notice-close', 'aria-label': 'Dismiss notice' }, '×');
  close.addEventListener('click', () => p.remove());
  p.append(close);
  box.append(p);
  while (box.children.length > 5) box.firstChild.remove();
}
