// Predict, then reveal: with `predict=<readout>` the plots and that readout stay hidden
// until the student types a prediction; the page then reveals the value, says how far off
// the prediction was, and posts an xAPI-shaped statement to the host page:
//
//   {type: 'zeta:prediction', prediction, value, difference, success, tolerance, unit,
//    readout, demo, params, token, timestamp,
//    statement: {verb, object, result, context, timestamp}}     (no actor: the host adds it)
//
// `tol=0.5` is an absolute tolerance in the readout's unit; `tol=5%` is relative to the
// value (default 10 %). The form works with the keyboard alone (type, Enter); the result
// is announced through a polite live region and receives focus.
import { parseNumber } from '../zeta-app.js';
import { LANG } from './i18n.js';

// The box's own words (the readout labels arrive translated from Rust).
const WORDS = {
  en: {
    title: 'Predict first',
    hint: 'The plots and the {label} stay hidden until you predict it. Type your prediction and press Enter.',
    field: 'Your prediction of the {label}{unit}',
    reveal: 'Reveal',
    nan: '“{text}” is not a number. Type a number such as 0.25.',
    undefined: 'The {label} is not defined for these parameters; change them and try again.',
    result: 'You predicted {p}; the {label} is {v}: {how}, {within} the tolerance {tol}.',
    exact: 'exactly right',
    high: '{d} too high',
    low: '{d} too low',
    inside: 'within',
    outside: 'outside',
  },
  es: {
    title: 'Primero, prediga',
    hint: 'Las gráficas y «{label}» quedan ocultas hasta que haga su predicción. Escríbala y pulse Intro.',
    field: 'Su predicción de «{label}»{unit}',
    reveal: 'Mostrar',
    nan: '«{text}» no es un número. Escriba un número como 0.25.',
    undefined: '«{label}» no está definido con estos parámetros; cámbielos y vuelva a intentarlo.',
    result: 'Predijo {p}; «{label}» vale {v}: {how}, {within} de la tolerancia {tol}.',
    exact: 'exacto',
    high: '{d} por encima',
    low: '{d} por debajo',
    inside: 'dentro',
    outside: 'fuera',
  },
};

function w(key, vars = {}) {
  const s = (WORDS[LANG] || WORDS.en)[key] ?? WORDS.en[key];
  return s.replace(/\{(\w+)\}/g, (_, k) => String(vars[k] ?? ''));
}

const VERB = { id: 'http://adlnet.gov/expapi/verbs/answered', display: { 'en-US': 'answered' } };
const INTERACTION = 'http://adlnet.gov/expapi/activities/cmi.interaction';
const EXT = 'urn:zeta-lab:xapi:';
const DEFAULT_TOL = '10%';

function el(tag, attrs = {}, text) {
  const node = document.createElement(tag);
  for (const [k, v] of Object.entries(attrs)) node.setAttribute(k, v);
  if (text !== undefined) node.textContent = text;
  return node;
}

/** `{abs, text}` of a tolerance string around `value`; null when malformed. */
export function tolerance(raw, value) {
  const s = String(raw ?? DEFAULT_TOL).trim();
  const pct = s.endsWith('%');
  const n = parseNumber(pct ? s.slice(0, -1) : s);
  if (n === undefined || n < 0) return null;
  return pct ? { abs: Math.abs(value) * n / 100, text: `±${n} %` } : { abs: n, text: `±${n}` };
}

const show = (v) => new Intl.NumberFormat(LANG, { maximumSignificantDigits: 4, useGrouping: false }).format(v);

/**
 * Hides the plots and readout `opts.predict` of `view` behind a prediction form.
 * `io`: {post(msg), context() → {demo, params, token}}.
 */
export function setupPrediction(view, opts, io) {
  const key = opts.predict;
  const spec = view.spec.readouts.find((r) => r.key === key);
  const item = view.readouts.get(key);
  if (!spec || !item) return;
  const hidden = [];
  const hide = (node) => {
    if (node && !node.hidden) {
      node.hidden = true;
      hidden.push(node);
    }
  };
  for (const canvas of view.canvases.values()) hide(canvas.closest('figure'));
  hide(item);
  // The page announces each plot's description as it changes: mute that until the reveal,
  // so a screen reader does not read out the answer first.
  const live = view.live;
  const liveWas = live ? live.getAttribute('aria-live') : null;
  if (live) live.setAttribute('aria-live', 'off');
  const unit = spec.unit ? ` ${spec.unit}` : '';
  const box = el('section', { class: 'zeta-predict', 'aria-labelledby': 'zeta-predict-title' });
  box.append(el('h2', { id: 'zeta-predict-title' }, w('title')));
  box.append(el('p', { id: 'zeta-predict-hint' }, w('hint', { label: spec.label })));
  // Not a <form> submission: sandboxed frames without allow-forms never fire `submit`.
  const form = el('div', { class: 'zeta-predict-form', role: 'group', 'aria-labelledby': 'zeta-predict-title' });
  const input = el('input', {
    id: 'zeta-predict-input', type: 'text', inputmode: 'decimal', autocomplete: 'off',
    'aria-describedby': 'zeta-predict-hint zeta-predict-error', enterkeyhint: 'done',
  });
  const button = el('button', { type: 'button' }, w('reveal'));
  form.append(el('label', { for: 'zeta-predict-input' }, w('field', { label: spec.label, unit: unit ? ` (${spec.unit})` : '' })), input, button);
  const error = el('p', { id: 'zeta-predict-error', class: 'zeta-predict-error', role: 'alert' });
  const result = el('p', { id: 'zeta-predict-result', class: 'zeta-predict-result', role: 'status', 'aria-live': 'polite', tabindex: '-1' });
  box.append(form, error, result);
  const root = document.getElementById('demo');
  const head = root && root.querySelector('.demo-head');
  if (head) head.after(box);
  else if (root) root.prepend(box);

  input.addEventListener('keydown', (ev) => {
    if (ev.key === 'Enter') {
      ev.preventDefault();
      reveal();
    }
  });
  button.addEventListener('click', () => reveal());
  const reveal = () => {
    if (button.disabled) return;
    const prediction = parseNumber(input.value.replace(',', '.'));
    const value = Number(item.getAttribute('data-value'));
    if (prediction === undefined) {
      error.textContent = w('nan', { text: input.value.slice(0, 40) });
      input.setAttribute('aria-invalid', 'true');
      input.focus();
      return;
    }
    if (item.getAttribute('data-value') === '' || !Number.isFinite(value)) {
      error.textContent = w('undefined', { label: spec.label });
      return;
    }
    error.textContent = '';
    input.removeAttribute('aria-invalid');
    const tol = tolerance(opts.tol, value) || tolerance(DEFAULT_TOL, value);
    const difference = prediction - value;
    const success = Math.abs(difference) <= tol.abs;
    for (const node of hidden) node.hidden = false;
    hidden.length = 0;
    if (live) {
      if (liveWas === null) live.removeAttribute('aria-live');
      else live.setAttribute('aria-live', liveWas);
    }
    input.readOnly = true;
    button.disabled = true;
    const d = `${show(Math.abs(difference))}${unit}`;
    const how = difference === 0 ? w('exact') : w(difference > 0 ? 'high' : 'low', { d });
    result.textContent = w('result', {
      p: `${show(prediction)}${unit}`, label: spec.label, v: `${show(value)}${unit}`, how,
      within: w(success ? 'inside' : 'outside'), tol: `${tol.text}${tol.text.endsWith('%') ? '' : unit}`,
    });
    result.classList.toggle('ok', success);
    result.focus();
    const ctx = io.context();
    const timestamp = new Date().toISOString();
    const activity = `${window.location.origin}${window.location.pathname}?demo=${encodeURIComponent(ctx.demo || '')}#predict-${key}`;
    const statement = {
      verb: VERB,
      object: {
        objectType: 'Activity',
        id: activity,
        definition: {
          type: INTERACTION,
          interactionType: 'numeric',
          name: { 'en-US': `Predict the ${spec.label}` },
          correctResponsesPattern: [`${value - tol.abs}[:]${value + tol.abs}`],
        },
      },
      result: {
        response: String(prediction),
        success,
        extensions: {
          [`${EXT}value`]: value,
          [`${EXT}difference`]: difference,
          [`${EXT}tolerance`]: tol.abs,
          [`${EXT}unit`]: spec.unit,
        },
      },
      context: { extensions: { [`${EXT}params`]: ctx.params || {}, [`${EXT}state`]: ctx.token || '' } },
      timestamp,
    };
    io.post({
      type: 'zeta:prediction', readout: key, unit: spec.unit, prediction, value, difference, success,
      tolerance: tol.abs, demo: ctx.demo, params: ctx.params, token: ctx.token, timestamp, statement,
    });
  };
}
