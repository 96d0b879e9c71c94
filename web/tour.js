// "The paper, checked": lays out the tour that Rust computed (Session.update(...).tour):
// one card per figure or table with its live thumbnail and a link to the state that
// reproduces it, then every claim with the paper's value, the app's value and a verdict.
// Every string is inserted with textContent; links are relative queries built in Rust.

import { t } from './i18n.js';
import { el } from './ui.js';

/** A link that opens `query` (from Rust, always `?demo=…`) on this page. */
function stateLink(query, text) {
  const a = el('a', { class: 'tour-link', href: query.startsWith('?') ? query : `?${query}` }, text);
  return a;
}

function exhibitCard(e, claims) {
  const card = el('article', { class: 'tour-card', 'data-exhibit': e.id, 'aria-labelledby': `tour-${e.id}` });
  card.append(el('h3', { id: `tour-${e.id}` }, e.place), el('p', {}, e.shows));
  // The thumbnail is the plot the page already drew for this exhibit: move it in.
  const plot = document.querySelector(`[data-plot-wrap="${e.id}"]`);
  if (plot) card.append(plot);
  card.append(stateLink(e.link, t('tourOpen')));
  if (claims.length) {
    const list = el('ol', { class: 'tour-claims' });
    for (const c of claims) list.append(claimItem(c));
    card.append(list);
  }
  return card;
}

function claimItem(c) {
  const item = el('li', { class: 'tour-claim', 'data-claim': c.id, 'data-verdict': c.verdict });
  const head = el('p', { class: 'tour-claim-head' });
  head.append(el('span', { class: 'tour-place' }, c.place), ' ', el('span', { class: 'tour-says' }, c.says));
  const values = el('dl', { class: 'tour-values' });
  const pair = (label, value, cls) => {
    const d = el('div', { class: cls });
    d.append(el('dt', {}, label), el('dd', {}, value));
    values.append(d);
  };
  pair(t('tourPaper'), c.claimed, 'tour-claimed');
  pair(t('tourApp'), c.computed, 'tour-computed');
  const verdict = el('p', { class: `tour-verdict verdict-${c.verdict}` });
  const word = c.verdict === 'confirmed' ? t('tourConfirmed') : c.verdict === 'differs' ? t('tourDiffers') : t('tourPending');
  verdict.append(el('strong', {}, word), ' ', c.reason);
  item.append(head, values, verdict, stateLink(c.link, t('tourOpen')));
  return item;
}

/**
 * Builds the tour into `root` once (the paper does not change while the page is open;
 * a language change rebuilds the page); later, the claims the first module left pending
 * get their verdicts (the full module checked them). Returns the section.
 */
export function renderTour(root, tour) {
  let section = root.querySelector('.tour');
  if (section) {
    for (const c of tour.claims) {
      const shown = section.querySelector(`[data-claim="${c.id}"]`);
      if (shown && shown.dataset.verdict !== c.verdict) shown.replaceWith(claimItem(c));
    }
    return section;
  }
  // The tour has no parameters and lays out its own thumbnails: no stage picker, no empty form.
  root.classList.add('touring');
  // The paper's own order: each figure or table, with the claims read beside it.
  section = el('section', { class: 'tour', 'aria-labelledby': 'tour-head' });
  section.append(el('h2', { id: 'tour-head' }, t('tourHead')));
  const ids = new Set(tour.exhibits.map((e) => e.id));
  const cards = el('div', { class: 'tour-cards' });
  for (const e of tour.exhibits) cards.append(exhibitCard(e, tour.claims.filter((c) => c.beside === e.id)));
  section.append(cards);
  const rest = tour.claims.filter((c) => !ids.has(c.beside));
  if (rest.length) {
    const list = el('ol', { class: 'tour-claims tour-rest' });
    for (const c of rest) list.append(claimItem(c));
    section.append(list);
  }
  root.append(section);
  return section;
}
