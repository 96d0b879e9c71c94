import { languages, t } from './i18n.js';
import { encodeToken, formatPresets, parsePresets, viewQuery } from './state.js';
import { el } from './ui.js';

// The "Share / Embed" dialog: builds the link, the <iframe> snippet and the state token for
// the current view and the chosen options (embed view, sliders shown and locked, plots and
// readouts shown, theme, language, per-slider range and step, fullscreen button, a
// prediction task), with copy buttons and a live preview. Overrides are only written into
// the link: the page that opens it validates them in Rust (crates/app/src/lecturer.rs).

/** The page URL for a demo, its values and the chosen options. */
export function shareUrl(base, demoId, values, opts) {
  const q = new URLSearchParams();
  q.set('demo', demoId);
  for (const [k, v] of values) q.set(k, String(v));
  if (opts.embed) q.set('embed', '1');
  if (opts.controls && opts.controls.length !== opts.allParams.length) q.set('controls', opts.controls.join(','));
  if (opts.lock && opts.lock.length) q.set('lock', opts.lock.join(','));
  if (opts.plots && opts.plots.length !== opts.allPlots.length) q.set('plots', opts.plots.join(','));
  if (opts.autoplay) q.set('autoplay', '1');
  if (opts.theme && opts.theme !== 'auto') q.set('theme', opts.theme);
  if (opts.readouts && opts.allReadouts && opts.readouts.length !== opts.allReadouts.length) q.set('readouts', opts.readouts.join(','));
  if (opts.lang && opts.lang !== 'auto') q.set('lang', opts.lang);
  if (opts.embed && opts.fullscreen === false) q.set('fullscreen', '0');
  if (opts.presets) q.set('presets', opts.presets);
  if (opts.predict) {
    q.set('predict', opts.predict);
    if (opts.tol) q.set('tol', opts.tol);
  }
  for (const [key, lo, hi] of opts.ranges || []) q.set(`range.${key}`, `${lo},${hi}`);
  for (const [key, step] of opts.steps || []) q.set(`step.${key}`, String(step));
  return `${base}?${q.toString()}`;
}

/** The state token of a share URL (the same view, as one value). */
export function shareToken(url, demoId, values) {
  const search = new URL(url).search;
  return encodeToken(viewQuery({ demo: demoId, values, search }));
}

/** The iframe snippet for `url`. */
export function iframeSnippet(url, width, height, title) {
  const esc = (s) => String(s).replace(/&/g, '&amp;').replace(/"/g, '&quot;').replace(/</g, '&lt;');
  return `<iframe src="${esc(url)}" width="${esc(width)}" height="${esc(height)}" title="${esc(title)}" ` +
    `style="border:0;max-width:100%" loading="lazy" allow="fullscreen" ` +
    `sandbox="allow-scripts allow-same-origin allow-downloads"></iframe>`;
}

async function copy(text, button) {
  try {
    await navigator.clipboard.writeText(text);
    button.textContent = t('copied');
  } catch {
    button.textContent = t('copyManual');
  }
  setTimeout(() => { button.textContent = t('copy'); }, 2000);
}

function checkboxList(legend, items, checked, group) {
  const box = el('fieldset', { class: 'share-list' });
  box.append(el('legend', {}, legend));
  const inputs = [];
  for (const [key, label] of items) {
    const id = `share-${group}-${key}`;
    const input = el('input', { type: 'checkbox', id, value: key });
    input.checked = checked(key);
    const lab = el('label', { for: id }, label);
    const row = el('div', {});
    row.append(input, lab);
    box.append(row);
    inputs.push(input);
  }
  return { box, selected: () => inputs.filter((i) => i.checked).map((i) => i.value) };
}

/** Per-slider range and step overrides: a small table of number boxes (empty = declared). */
function rangeTable(spec) {
  const box = el('fieldset', { class: 'share-ranges' });
  box.append(el('legend', {}, t('shareRanges')));
  const table = el('table', {});
  const head = el('tr', {});
  for (const h of [t('shareColSlider'), t('shareColFrom'), t('shareColTo'), t('shareColStep')]) head.append(el('th', { scope: 'col' }, h));
  table.append(head);
  const rows = [];
  for (const p of spec.params.filter((p) => p.kind === 'slider')) {
    const tr = el('tr', {});
    tr.append(el('th', { scope: 'row' }, `${p.label} (${p.key})`));
    const cell = (what, placeholder, label) => {
      const input = el('input', { type: 'number', id: `share-${what}-${p.key}`, placeholder: String(placeholder), step: 'any',
        'aria-label': label });
      const td = el('td', {});
      td.append(input);
      tr.append(td);
      return input;
    };
    rows.push({
      p,
      lo: cell('min', p.min, t('shareRangeFrom', { label: p.label })),
      hi: cell('max', p.max, t('shareRangeTo', { label: p.label })),
      step: cell('step', p.step, t('shareRangeStep', { label: p.label })),
    });
    table.append(tr);
  }
  box.append(table);
  const filled = (input) => input.value.trim() !== '' && Number.isFinite(Number(input.value));
  return {
    box,
    ranges: () => rows.filter((r) => filled(r.lo) || filled(r.hi))
      .map((r) => [r.p.key, filled(r.lo) ? Number(r.lo.value) : r.p.min, filled(r.hi) ? Number(r.hi.value) : r.p.max]),
    steps: () => rows.filter((r) => filled(r.step)).map((r) => [r.p.key, Number(r.step.value)]),
  };
}

/** "Predict, then reveal": which readout to predict, and the tolerance. */
function predictionTask(spec) {
  const box = el('fieldset', { class: 'share-list' });
  box.append(el('legend', {}, t('sharePredictTask')));
  const select = el('select', { id: 'share-predict' });
  select.append(el('option', { value: '' }, t('shareNone')));
  for (const r of spec.readouts) select.append(el('option', { value: r.key }, `${r.label}${r.unit ? ` (${r.unit})` : ''}`));
  const tol = el('input', { type: 'text', id: 'share-tol', value: '10%', size: '6' });
  box.append(el('label', { for: 'share-predict' }, t('sharePredict')), select,
    el('label', { for: 'share-tol' }, t('sharePredictWithin')), tol);
  return { box, readout: () => select.value, tol: () => tol.value.trim() };
}

// Presets authored in this visit, kept while the page is open: set the sliders, open the
// dialog, add; change the sliders, open it again, add another.
let authored = '';

/** Named lecturer presets carried in the link (`presets=`). */
function presetEditor(values) {
  const box = el('fieldset', { class: 'share-list share-presets' });
  box.append(el('legend', {}, t('sharePresets')));
  const name = el('input', { type: 'text', id: 'share-preset-name', maxlength: '40', placeholder: t('sharePresetExample') });
  const add = el('button', { type: 'button', id: 'share-preset-add' }, t('sharePresetAdd'));
  const text = el('input', { type: 'text', id: 'share-presets', value: authored, 'aria-describedby': 'share-presets-help' });
  const help = el('p', { id: 'share-presets-help', class: 'share-help' }, t('sharePresetFormat'));
  add.addEventListener('click', () => {
    const label = name.value.trim() || t('sharePresetDefault', { n: parsePresets(text.value).length + 1 });
    text.value = formatPresets([...parsePresets(text.value), { label, values: values.map(([k, v]) => [k, String(v)]) }]);
    name.value = '';
    text.dispatchEvent(new Event('input', { bubbles: true }));
  });
  const row1 = el('div', {});
  row1.append(el('label', { for: 'share-preset-name' }, t('sharePresetName')), name, add);
  const row2 = el('div', {});
  row2.append(el('label', { for: 'share-presets' }, t('sharePresetList')), text);
  box.append(row1, row2, help);
  return { box, value: () => { authored = text.value.trim(); return formatPresets(parsePresets(authored)); } };
}

/** Opens the dialog for the current state: {demoId, values, spec}. */
export function openShareDialog({ demoId, values, spec }) {
  document.getElementById('share-dialog')?.remove();
  const dialog = el('dialog', { id: 'share-dialog', 'aria-labelledby': 'share-title' });
  dialog.append(el('h2', { id: 'share-title' }, t('shareTitle', { title: spec.title })));
  const base = window.location.origin + window.location.pathname;

  const embed = el('input', { type: 'checkbox', id: 'share-embed' });
  embed.checked = true;
  const autoplay = el('input', { type: 'checkbox', id: 'share-autoplay' });
  const theme = el('select', { id: 'share-theme' });
  for (const [v, label] of [['auto', t('themeAuto')], ['light', t('themeLight')], ['dark', t('themeDark')], ['projector', t('themeProjector')]]) {
    theme.append(el('option', { value: v }, label));
  }
  // The visitor's own language, or one of the real languages (by their own names).
  const lang = el('select', { id: 'share-lang' });
  lang.append(el('option', { value: 'auto' }, t('shareVisitorLanguage')));
  for (const l of languages().filter((x) => !x.pseudo)) lang.append(el('option', { value: l.tag, lang: l.tag }, l.name));
  const fullscreen = el('input', { type: 'checkbox', id: 'share-fullscreen' });
  fullscreen.checked = true;
  const width = el('input', { type: 'number', id: 'share-width', value: '800', min: '320', max: '4000' });
  const height = el('input', { type: 'number', id: 'share-height', value: '720', min: '320', max: '4000' });
  const opts = el('div', { class: 'share-options' });
  const row = (input, text) => {
    const d = el('div', {});
    d.append(input, el('label', { for: input.id }, text));
    return d;
  };
  opts.append(row(embed, t('embedView')), row(autoplay, t('autoplay')), row(fullscreen, t('shareFullscreen')));
  const sizes = el('div', { class: 'share-sizes' });
  sizes.append(el('label', { for: 'share-theme' }, t('theme')), theme, el('label', { for: 'share-lang' }, t('shareLanguage')), lang,
    el('label', { for: 'share-width' }, t('width')), width, el('label', { for: 'share-height' }, t('height')), height);
  opts.append(sizes);
  const params = spec.params.map((p) => [p.key, `${p.label} (${p.key})`]);
  const shown = checkboxList(t('slidersShown'), params, () => true, 'shown');
  const locked = checkboxList(t('slidersLocked'), params, () => false, 'locked');
  const plots = checkboxList(t('plotsShown'), spec.plots.map((p) => [p.key, p.title]), () => true, 'plots');
  const readouts = checkboxList(t('readoutsShown'), spec.readouts.map((r) => [r.key, r.label]), () => true, 'readouts');
  const lists = el('div', { class: 'share-lists' });
  lists.append(shown.box, locked.box, plots.box, readouts.box);
  const ranges = rangeTable(spec);
  const task = predictionTask(spec);
  const presets = presetEditor(values);

  const link = el('input', { type: 'text', readonly: '', id: 'share-link', 'aria-label': t('link') });
  const copyLink = el('button', { type: 'button' }, t('copy'));
  const snippet = el('textarea', { readonly: '', rows: '3', id: 'share-snippet', 'aria-label': t('embedCode') });
  const copySnippet = el('button', { type: 'button' }, t('copy'));
  const preview = el('iframe', { title: t('preview'), sandbox: 'allow-scripts allow-same-origin', class: 'share-preview' });
  const token = el('input', { type: 'text', readonly: '', id: 'share-token', 'aria-label': t('stateToken') });
  const copyToken = el('button', { type: 'button' }, t('copy'));
  const close = el('button', { type: 'button', class: 'share-close' }, t('close'));

  const linkRow = el('div', { class: 'share-row' });
  linkRow.append(el('label', { for: 'share-link' }, t('link')), link, copyLink);
  const snipRow = el('div', { class: 'share-row' });
  snipRow.append(el('label', { for: 'share-snippet' }, t('embedCode')), snippet, copySnippet);
  const tokenRow = el('div', { class: 'share-row' });
  tokenRow.append(el('label', { for: 'share-token' }, t('stateToken')), token, copyToken);
  dialog.append(opts, lists, ranges.box, task.box, presets.box, linkRow, snipRow, tokenRow, preview, close);

  let timer = null;
  const refresh = () => {
    const o = {
      embed: embed.checked,
      autoplay: autoplay.checked,
      theme: theme.value,
      controls: shown.selected(),
      lock: locked.selected(),
      plots: plots.selected(),
      readouts: readouts.selected(),
      lang: lang.value,
      fullscreen: fullscreen.checked,
      ranges: ranges.ranges(),
      steps: ranges.steps(),
      predict: task.readout(),
      tol: task.tol(),
      presets: presets.value(),
      allParams: spec.params,
      allPlots: spec.plots,
      allReadouts: spec.readouts,
    };
    const url = shareUrl(base, demoId, values, o);
    link.value = shareUrl(base, demoId, values, { ...o, embed: false, controls: null, lock: null, plots: null, allParams: [], allPlots: [] });
    token.value = shareToken(url, demoId, values);
    snippet.value = iframeSnippet(url, width.value, height.value, spec.title);
    clearTimeout(timer);
    timer = setTimeout(() => { if (preview.getAttribute('src') !== url) preview.src = url; }, 300);
  };
  dialog.addEventListener('input', refresh);
  dialog.addEventListener('change', refresh);
  copyLink.addEventListener('click', () => copy(link.value, copyLink));
  copySnippet.addEventListener('click', () => copy(snippet.value, copySnippet));
  copyToken.addEventListener('click', () => copy(token.value, copyToken));
  close.addEventListener('click', () => dialog.close());
  dialog.addEventListener('close', () => dialog.remove());
  document.body.append(dialog);
  refresh();
  dialog.showModal();
  return dialog;
}
