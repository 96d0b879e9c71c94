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
