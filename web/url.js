// URL state: the page's query string is the shareable state of the view.
// Values are validated by the Rust side (Session.applyQuery); this module only reads and
// writes the string. Keys that belong to the page rather than to a demo are kept as they are,
// and so are the authoring overrides (range.<key>, step.<key>). A `state=` token is expanded
// into these keys by state.js before the page starts.
import { VIEW_KEYS, isOverrideKey } from './state.js';

const PAGE_KEYS = [...VIEW_KEYS, 'origin'];
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
  for (const key of [...old.keys()].filter(isOverrideKey).sort()) q.set(key, old.get(key));
  return '?' + q.toString();
}

let pending = null;

/** Drops a URL write still waiting (a whole new state is about to replace the URL). */
export function cancelPendingWrite() {
  if (pending !== null) clearTimeout(pending);
  pending = null;
}

/**
 * Replaces the URL (no history entry), coalescing bursts of slider moves: `readValues()`
 * ([[key, value], …]) is asked once the burst is over, not on every move; when it gives
 * null (another demo opened meanwhile) the URL stays as it is.
 */
export function writeState(demoId, readValues) {
  if (pending !== null) clearTimeout(pending);
  pending = setTimeout(() => {
    pending = null;
    const values = readValues();
    if (!values) return;
    const query = queryFor(demoId, values);
    if (query !== window.location.search) {
      history.replaceState(null, '', query + window.location.hash);
    }
  }, WRITE_DELAY_MS);
}
