import { t } from './i18n.js';

// The "Share / Embed" dialog: builds the link and the <iframe> snippet for the current
// view and the chosen embed options, with copy buttons and a live preview.

function el(tag, attrs = {}, text) {
  const node = document.createElement(tag);
  for (const [k, v] of Object.entries(attrs)) node.setAttribute(k, v);
  if (text !== undefined) node.textContent = text;
  return node;
}

/** The page URL for a demo, its values and embed options. */
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
  return `${base}?${q.toString()}`;
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
  for (const t of ['auto', 'light', 'dark']) theme.append(el('option', { value: t }, t));
  const width = el('input', { type: 'number', id: 'share-width', value: '800', min: '320', max: '4000' });
  const height = el('input', { type: 'number', id: 'share-height', value: '720', min: '320', max: '4000' });
  const opts = el('div', { class: 'share-options' });
  const row = (input, text) => {
    const d = el('div', {});
    d.append(input, el('label', { for: input.id }, text));
    return d;
  };
  opts.append(row(embed, t('embedView')), row(autoplay, t('autoplay')));
  const sizes = el('div', { class: 'share-sizes' });
  sizes.append(el('label', { for: 'share-theme' }, t('theme')), theme,
    el('label', { for: 'share-width' }, t('width')), width, el('label', { for: 'share-height' }, t('height')), height);
  opts.append(sizes);
  const params = spec.params.map((p) => [p.key, `${p.label} (${p.key})`]);
  const shown = checkboxList(t('slidersShown'), params, () => true, 'shown');
  const locked = checkboxList(t('slidersLocked'), params, () => false, 'locked');
  const plots = checkboxList(t('plotsShown'), spec.plots.map((p) => [p.key, p.title]), () => true, 'plots');
  const lists = el('div', { class: 'share-lists' });
  lists.append(shown.box, locked.box, plots.box);

  const link = el('input', { type: 'text', readonly: '', id: 'share-link', 'aria-label': t('link') });
  const copyLink = el('button', { type: 'button' }, t('copy'));
  const snippet = el('textarea', { readonly: '', rows: '3', id: 'share-snippet', 'aria-label': t('embedCode') });
  const copySnippet = el('button', { type: 'button' }, t('copy'));
  const preview = el('iframe', { title: t('preview'), sandbox: 'allow-scripts allow-same-origin', class: 'share-preview' });
  const close = el('button', { type: 'button', class: 'share-close' }, t('close'));

  const linkRow = el('div', { class: 'share-row' });
  linkRow.append(el('label', { for: 'share-link' }, t('link')), link, copyLink);
  const snipRow = el('div', { class: 'share-row' });
  snipRow.append(el('label', { for: 'share-snippet' }, t('embedCode')), snippet, copySnippet);
  dialog.append(opts, lists, linkRow, snipRow, preview, close);

  let timer = null;
  const refresh = () => {
    const o = {
      embed: embed.checked,
      autoplay: autoplay.checked,
      theme: theme.value,
      controls: shown.selected(),
      lock: locked.selected(),
      plots: plots.selected(),
      allParams: spec.params,
      allPlots: spec.plots,
    };
    const url = shareUrl(base, demoId, values, o);
    link.value = shareUrl(base, demoId, values, { ...o, embed: false, controls: null, lock: null, plots: null, allParams: [], allPlots: [] });
    snippet.value = iframeSnippet(url, width.value, height.value, spec.title);
    clearTimeout(timer);
    timer = setTimeout(() => { if (preview.getAttribute('src') !== url) preview.src = url; }, 300);
  };
  dialog.addEventListener('input', refresh);
  dialog.addEventListener('change', refresh);
  copyLink.addEventListener('click', () => copy(link.value, copyLink));
  copySnippet.addEventListener('click', () => copy(snippet.value, copySnippet));
  close.addEventListener('click', () => dialog.close());
  dialog.addEventListener('close', () => dialog.remove());
  document.body.append(dialog);
  refresh();
  dialog.showModal();
  return dialog;
}
