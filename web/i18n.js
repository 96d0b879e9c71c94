// The page's language. Every string the page shows is a message of the Fluent catalogues
// (crates/app/locales/<tag>.ftl): the page's own are `page-…` ids, written here as
// `t('camelKey')` (→ `page-camel-key`) so the catalogue tests find them. The wasm module
// holds the catalogues and does the formatting (plurals, argument order); English is
// compiled in and is the fallback for any message a catalogue lacks.
//
// The language: `lang=` in the address, else the visitor's last choice (localStorage),
// else the browser's languages; negotiated in Rust against the list in
// crates/app/src/i18n/locale.rs. Only the active language's catalogue is fetched, once
// the module has started and before the first plot; if that fails the page stays English
// and says so.

const STORE_KEY = 'zeta-lang';

/** The module's exports once started (null before: t() then gives the page's English). */
let wasm = null;

/** The active language: {tag, name, dir, rules, pseudo, file?, loaded}. */
let active = { tag: 'en', name: 'English', dir: 'ltr', rules: 'en', pseudo: false, loaded: true };
/** The fetched catalogues by tag, to load again into a fresh module instance. */
const fetched = new Map();

// Before the module starts only the "cannot load the solver" notice can be shown, and
// after a trap the module may not answer until the page has recovered: these English
// texts (the same as en.ftl's) stand in then.
const BEFORE_START = {
  'page-no-wasm': 'The solver could not be loaded ({ $text }). This page needs WebAssembly.',
  'page-failed': 'Something went wrong and the demo was restarted: { $text }',
};

/** How long a catalogue download may take before the page goes on without it. */
const FETCH_TIMEOUT_MS = 8000;

/** Counts language requests, so that a slow download never overrides a later choice. */
let generation = 0;

/** The message id of the page key `camelKey`: `page-camel-key`. */
function pageId(key) {
  return `page-${key.replace(/[A-Z]/g, (c) => `-${c.toLowerCase()}`)}`;
}

/**
 * The texts `t` formatted since the module instance or the language last changed, by id
 * and arguments: a slider event asks for the same few (a slider's words, the time
 * cursor's) every frame, and each went through the module's formatter (about 0.8 ms a
 * frame at 4× CPU slowdown, rlc). Emptied when it reaches MEMO_SIZE (the time cursor's
 * text changes every frame while the schematic plays).
 */
const memo = new Map();
const MEMO_SIZE = 256;

/** Forgets the formatted texts: the module instance or its language changed. */
function forget() {
  memo.clear();
}

/** The string `key` (a `page-…` message) in the page language, with `vars` as its arguments. */
export function t(key, vars = {}) {
  const id = pageId(key);
  if (wasm) {
    const memoKey = `${id} ${JSON.stringify(vars)}`;
    const known = memo.get(memoKey);
    if (known !== undefined) return known;
    try {
      const text = wasm.message(id, vars);
      if (memo.size >= MEMO_SIZE) memo.clear();
      memo.set(memoKey, text);
      return text;
    } catch {
      // a trapped module instance: fall through to the stand-ins until it is replaced
    }
  }
  const s = BEFORE_START[id] ?? key;
  return s.replace(/\{ \$(\w+) \}/g, (_, k) => String(vars[k] ?? ''));
}

/** Number formats by `locale|digits`: building one costs far more than using it. */
const numberFormats = new Map();

/** `value` with exactly `digits` decimals in the page language's CLDR rules (pseudo-locales:
 * English's). English is written here, as `Intl.NumberFormat('en')` writes it: the page's
 * first `Intl.NumberFormat` loads the locale data, about 150 ms at 4× CPU slowdown, and
 * was built in the first frame of every demo with an animation (its time label). */
export function num(value, digits) {
  const locale = active.rules || 'en';
  if (locale === 'en' && Math.abs(value) < 1e21) return english(value, digits);
  const key = `${locale}|${digits}`;
  let format = numberFormats.get(key);
  if (!format) {
    format = new Intl.NumberFormat(locale, { minimumFractionDigits: digits, maximumFractionDigits: digits });
    numberFormats.set(key, format);
  }
  return format.format(value);
}

/** `value` with `digits` decimals as `Intl.NumberFormat('en')` writes it (|value| < 1e21):
 * Intl rounds the shortest decimal that reads back as the number (1.005 → 1.01, though the
 * double is just under 1.005), half away from zero, and groups the integer digits in
 * threes. (−0 is written 0; Intl writes -0.) */
function english(value, digits) {
  // The shortest decimal that reads back as |value| (what Intl rounds): its digits, and
  // how many of them come before the point.
  const [mantissa, exponent] = Math.abs(value).toExponential().split('e');
  const all = mantissa.replace('.', '');
  const keep = Number(exponent) + 1 + digits;
  let scaled = 0n; // |value| × 10^digits, rounded half away from zero
  if (keep >= 0) {
    scaled = BigInt(all.slice(0, keep).padEnd(keep, '0') || '0');
    if (all[keep] >= '5') scaled += 1n;
  }
  const text = scaled.toString().padStart(digits + 1, '0');
  const whole = text.slice(0, text.length - digits).replace(/\B(?=(\d{3})+$)/g, ',');
  const sign = value < 0 ? '-' : '';
  return digits > 0 ? `${sign}${whole}.${text.slice(text.length - digits)}` : `${sign}${whole}`;
}

/** The locale whose rules format numbers (for Intl elsewhere on the page). */
export function numberLocale() {
  return active.rules || 'en';
}

/** The languages the module offers: [{tag, name, dir, rules, pseudo, file?, loaded}]. */
export function languages() {
  return wasm ? wasm.languages() : [active];
}

/** The active language's entry. */
export function activeLanguage() {
  return active;
}

function remembered() {
  try {
    return window.localStorage.getItem(STORE_KEY);
  } catch {
    return null;
  }
}

/** Remembers the visitor's choice for the next visit (ignored where storage is off). */
export function remember(tag) {
  try {
    window.localStorage.setItem(STORE_KEY, tag);
  } catch {
    // private mode or storage disabled: the choice lasts for this page only
  }
}

/** The requested tags, most wanted first: `lang=`, the remembered choice, the browser's. */
export function requestedLanguages(search = window.location.search) {
  const fromUrl = new URLSearchParams(search).get('lang');
  const list = [fromUrl, remembered(), ...(navigator.languages || [navigator.language])];
  return list.filter((s) => typeof s === 'string' && /^[A-Za-z0-9-]{1,35}$/.test(s));
}

/**
 * Makes the best language for `requested` active (fetching its catalogue if it has one
 * not loaded yet, for at most FETCH_TIMEOUT_MS). Resolves to `{entry, problem, stale}`:
 * `problem` is set when the catalogue could not be fetched or read, and the page is then
 * in English; `stale` when a later request overtook this one (the caller
 * then does nothing more).
 */
export async function useLanguage(module, requested) {
  wasm = module;
  forget();
  const mine = ++generation;
  let entry = wasm.setLanguage(requested.join(','));
  let problem = null;
  if (entry.file && !entry.loaded) {
    try {
      const res = await fetch(new URL(`../${entry.file}`, import.meta.url), {
        signal: AbortSignal.timeout(FETCH_TIMEOUT_MS),
      });
      if (!res.ok) throw new Error(`HTTP ${res.status}`);
      const text = await res.text();
      fetched.set(entry.tag, text);
      const problems = wasm.loadCatalogue(entry.tag, text);
      if (problems.length) console.warn(`Zeta Lab: ${entry.file}:`, problems);
      if (mine !== generation) return { entry: active, problem: null, stale: true };
      entry = wasm.setLanguage(entry.tag); // the same language, now loaded
      forget();
    } catch (err) {
      if (mine !== generation) return { entry: active, problem: null, stale: true };
      problem = { name: entry.name, text: (err && err.message) || String(err) };
      entry = wasm.setLanguage('en'); // as the notice says: the page is in English
      forget();
    }
  }
  active = entry;
  translatePage();
  if (problem) console.warn('Zeta Lab: catalogue not loaded:', problem.text);
  return { entry, problem };
}

/**
 * Gives a new module instance the catalogues fetched so far and the active language,
 * without making it the page's (see adoptInstance). Returns that language's tag.
 */
export function prepareInstance(module) {
  for (const [tag, text] of fetched) module.loadCatalogue(tag, text);
  module.setLanguage(active.tag);
  return active.tag;
}

/**
 * Makes a fresh module instance (after a recovery, or the full module after the first) the
 * page's, in the active language; `prepared`: the tag prepareInstance gave it, if any.
 */
export function adoptInstance(module, prepared = null) {
  wasm = module;
  forget();
  if (prepared !== active.tag) prepareInstance(module);
}

/** Translates the static page (elements carrying data-i18n="key") and sets lang and dir. */
export function translatePage() {
  document.documentElement.lang = active.tag;
  document.documentElement.dir = active.dir === 'rtl' ? 'rtl' : 'ltr';
  if (!wasm) return;
  for (const el of document.querySelectorAll('[data-i18n]')) el.textContent = t(el.dataset.i18n);
  document.querySelector('.site-header nav')?.setAttribute('aria-label', t('demosNav'));
  document.querySelector('.site-header .languages')?.setAttribute('aria-label', t('languageNav'));
}
