// URL state: the page's query string is the shareable state of the view.
// Values are validated by the Rust side (Session.applyQuery); this module only reads and
// writes the string. Keys that belong to the page rather than to a demo are kept as they are.

const PAGE_KEYS = ['embed', 'controls', 'lock', 'plots', 'autoplay', 'theme', 'lang'];
const WRITE_DELAY_MS = 150;

/** The current query string, including its leading '?'. */
export function currentQuery() {
  return window.location.search;
}

/** The demo id named in the URL, or null. */
export function demoFromUrl() {
  return new URLSearchParams(window.location.search).get('demo');
}

/** The query string for a demo and its values ([[key, value], …]), keeping page keys. */
export function queryFor(demoId, values) {
  const old = new URLSearchParams(window.location.search);
  const q = new URLSearchParams();
  q.set('demo', demoId);
  for (const [key, value] of values) q.set(key, String(value));
  for (const key of PAGE_KEYS) if (old.has(key)) q.set(key, old.get(key));
  return '?' + q.toString();
}

let pending = null;

/** Replaces the URL (no history entry), coalescing bursts of slider moves. */
export function writeState(demoId, values) {
  const query = queryFor(demoId, values);
  if (pending !== null) clearTimeout(pending);
  pending = setTimeout(() => {
    pending = null;
    if (query !== window.location.search) {
      history.replaceState(null, '', query + window.location.hash);
    }
  }, WRITE_DELAY_MS);
}
