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
import { fullGlue, glue } from './glue.js';
import { numberLocale, t } from './i18n.js';
import { el } from './ui.js';

const VERB = { id: 'http://adlnet.gov/expapi/verbs/answered', display: { 'en-US': 'answered' } };
const INTERACTION = 'http://adlnet.gov/expapi/activities/cmi.interaction';
const EXT = 'urn:zeta-lab:xapi:';
const DEFAULT_TOL = '10%';

/** `{abs, text}` of a tolerance string around `value`; null when malformed. */
export function tolerance(raw, value) {
  const s = String(raw ?? DEFAULT_TOL).trim();
  const pct = s.endsWith('%');
  const n = glue().parseNumber(pct ? s.slice(0, -1) : s);
  if (n === undefined || n < 0) return null;
  return pct ? { abs: Math.abs(value) * n / 100, text: `±${n} %` } : { abs: n, text: `±${n}` };
}

const show = (v) => new Intl.NumberFormat(numberLocale(), { maximumSignificantDigits: 4, useGrouping: false }).format(v);

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
  box.append(el('h2', { id: 'zeta-predict-title' }, t('predictTitle')));
  box.append(el('p', { id: 'zeta-predict-hint' }, t('predictHint', { label: spec.label })));
  // Not a <form> submission: sandboxed frames without allow-forms never fire `submit`.
  const form = el('div', { class: 'zeta-predict-form', role: 'group', 'aria-labelledby': 'zeta-predict-title' });
  const input = el('input', {
    id: 'zeta-predict-input', type: 'text', inputmode: 'decimal', autocomplete: 'off',
    'aria-describedby': 'zeta-predict-hint zeta-predict-error', enterkeyhint: 'done',
  });
  const button = el('button', { type: 'button' }, t('predictReveal'));
  form.append(el('label', { for: 'zeta-predict-input' }, (unit ? t('predictFieldUnit', { label: spec.label, unit: spec.unit }) : t('predictField', { label: spec.label }))), input, button);
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
  let parsing = false;
  const reveal = async () => {
    if (button.disabled || parsing) return;
    // The number parser is the full module's (see fullGlue).
    parsing = true;
    try {
      await fullGlue();
    } catch (err) {
      console.warn('Zeta Lab: the full module could not be loaded:', err && err.message);
      return; // a later click tries again
    } finally {
      parsing = false;
    }
    const prediction = glue().parseNumber(input.value.replace(',', '.'));
    const value = Number(item.getAttribute('data-value'));
    if (prediction === undefined) {
      error.textContent = t('predictNan', { text: input.value.slice(0, 40), example: show(0.25) });
      input.setAttribute('aria-invalid', 'true');
      input.focus();
      return;
    }
    if (item.getAttribute('data-value') === '' || !Number.isFinite(value)) {
      error.textContent = t('predictUndefined', { label: spec.label });
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
    const how = difference === 0 ? t('predictExact') : difference > 0 ? t('predictHigh', { d }) : t('predictLow', { d });
    const words = {
      p: `${show(prediction)}${unit}`, label: spec.label, v: `${show(value)}${unit}`, how,
      tol: `${tol.text}${tol.text.endsWith('%') ? '' : unit}`,
    };
    result.textContent = success ? t('predictResultInside', words) : t('predictResultOutside', words);
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
