// The whole view as one value: the state token.
//
//   token = "1." + base64url(UTF-8 query string)      (no padding; URL-safe as it is)
//
// The query string lists, in this order: demo, every parameter of the demo (declaration
// order), the view options that are set (VIEW_KEYS order), the authoring overrides
// (range.<key>, step.<key>, sorted), then the animation: t (seconds), play (1/0) and
// speed (when not 1). Decoding gives that query back; the page then applies it exactly as
// it applies its own URL, so every value still passes through the Rust parser
// (Session.applyQuery): unknown keys are ignored, missing parameters take their defaults
// and a notice says so. A token whose version this page does not know is refused with a
// notice.
//
// Imported first by main.js: a `state=` in the address is expanded into the query before
// any other module reads it (explicit keys in the address win over the token's).

import { t } from './i18n.js';

export const TOKEN_VERSION = '1';
/** View options carried by a token, in token order. */
export const VIEW_KEYS = ['embed', 'controls', 'lock', 'plots', 'readouts', 'theme', 'lang', 'autoplay',
  'fullscreen', 'predict', 'tol', 'presets'];
const ANIM_KEYS = ['t', 'play', 'speed'];
const MAX_TOKEN = 8192;

const MAX_PRESETS = 8;

/**
 * Lecturer presets from `presets=Light:zeta=0.1,wn=4;Heavy:zeta=2`: [{label, values:
 * [[key, text]]}]. Labels are plain text (at most 40 characters); values are passed as text
 * to the Rust parser when the button is pressed. Malformed entries are dropped.
 */
export function parsePresets(text) {
  if (typeof text !== 'string' || !text) return [];
  const out = [];
  for (const part of text.split(';').slice(0, MAX_PRESETS)) {
    const colon = part.lastIndexOf(':');
    if (colon <= 0) continue;
    const label = part.slice(0, colon).trim().slice(0, 40);
    const values = part.slice(colon + 1).split(',')
      .map((kv) => kv.split('='))
      .filter((kv) => kv.length === 2 && /^[A-Za-z0-9_]{1,40}$/.test(kv[0].trim()) && kv[1].trim().length <= 40)
      .map(([k, v]) => [k.trim(), v.trim()]);
    if (label && values.length) out.push({ label, values });
  }
  return out;
}

/** The `presets=` text of [{label, values}] (the inverse of parsePresets). */
export function formatPresets(presets) {
  return presets.map((p) => `${p.label.replace(/[;:]/g, ' ')}:${p.values.map(([k, v]) => `${k}=${v}`).join(',')}`).join(';');
}

/** Whether `key` is an authoring override (`range.zeta`, `step.zeta`). */
export function isOverrideKey(key) {
  return /^(range|step)\.[A-Za-z0-9_]{1,40}$/.test(key);
}

function toBase64Url(bytes) {
  let bin = '';
  for (const b of bytes) bin += String.fromCharCode(b);
  return btoa(bin).replace(/\+/g, '-').replace(/\//g, '_').replace(/=+$/, '');
}

function fromBase64Url(text) {
  const b64 = text.replace(/-/g, '+').replace(/_/g, '/');
  const bin = atob(b64 + '='.repeat((4 - (b64.length % 4)) % 4));
  return Uint8Array.from(bin, (c) => c.charCodeAt(0));
}

/** The token of a query string (without its leading '?'). */
export function encodeToken(query) {
  return `${TOKEN_VERSION}.${toBase64Url(new TextEncoder().encode(query.replace(/^\?/, '')))}`;
}

/** `{query}` from a token, or `{error}` saying why it cannot be read. */
export function decodeToken(token) {
  if (typeof token !== 'string' || token.length > MAX_TOKEN || !/^[A-Za-z0-9_.-]+$/.test(token)) {
    return { get error() { return t('tokenInvalid'); } };
  }
  const dot = token.indexOf('.');
  const version = dot < 0 ? '' : token.slice(0, dot);
  if (version !== TOKEN_VERSION) {
    return { get error() { return t('tokenVersion', { version: version.slice(0, 8) }); } };
  }
  try {
    const query = new TextDecoder('utf-8', { fatal: true }).decode(fromBase64Url(token.slice(dot + 1)));
    return { query };
  } catch {
    return { get error() { return t('tokenDamaged'); } };
  }
}

/**
 * The canonical query of a view: demo, values ([[key, value]] in spec order), the view
 * options and overrides found in `search`, then the animation time, play state and speed.
 */
export function viewQuery({ demo, values, search, time = 0, playing = false, speed = 1 }) {
  const from = new URLSearchParams(search);
  const q = new URLSearchParams();
  q.set('demo', demo);
  for (const [k, v] of values) q.set(k, String(v));
  for (const k of VIEW_KEYS) if (from.has(k)) q.set(k, from.get(k));
  const overrides = [...from.keys()].filter(isOverrideKey).sort();
  for (const k of overrides) q.set(k, from.get(k));
  q.set('t', String(Math.round(Number(time) * 1e4) / 1e4 || 0));
  q.set('play', playing ? '1' : '0');
  if (speed !== 1) q.set('speed', String(speed));
  return q.toString();
}

/** What the last expanded token said: its keys and any notice (read once by embed.js). */
export const loaded = { keys: null, notice: null, version: null };

/**
 * The query after expanding a token: the token's pairs, then every other key of
 * `search` (those win). Returns null when there is no `state=`.
 */
export function expandSearch(search) {
  const url = new URLSearchParams(search);
  const token = url.get('state');
  if (token === null) return null;
  const dec = decodeToken(token.trim());
  url.delete('state');
  if (dec.error) {
    loaded.notice = dec; // its error is read (in the page's language) when shown
    return '?' + url.toString();
  }
  const q = new URLSearchParams(dec.query);
  loaded.keys = new Set(q.keys());
  for (const [k, v] of url) q.set(k, v);
  return '?' + q.toString();
}

/** The notice for a token with missing or unknown keys, given the demo's parameter keys. */
export function tokenNotice(paramKeys) {
  if (loaded.notice) return loaded.notice.error;
  if (!loaded.keys) return null;
  const known = new Set(['demo', 'state', 'origin', ...VIEW_KEYS, ...ANIM_KEYS, ...paramKeys]);
  const missing = paramKeys.filter((k) => !loaded.keys.has(k));
  const unknown = [...loaded.keys].filter((k) => !known.has(k) && !isOverrideKey(k));
  const keys = (list) => list.slice(0, 8).join(', ');
  if (missing.length && unknown.length) {
    return t('tokenOtherVersionBoth', { missing: keys(missing), n: missing.length, unknown: keys(unknown), m: unknown.length });
  }
  if (missing.length) return t('tokenOtherVersionMissing', { missing: keys(missing), n: missing.length });
  if (unknown.length) return t('tokenOtherVersionUnknown', { unknown: keys(unknown), m: unknown.length });
  return null;
}

/** The token inside a pasted link or text (`…?state=1.xxx…` or a bare token), or null. */
export function tokenInText(text) {
  const m = /(?:^|[?&\s])state=([A-Za-z0-9_.-]{3,8192})/.exec(text) || /^\s*(\d+\.[A-Za-z0-9_-]{4,8192})\s*$/.exec(text);
  return m ? m[1] : null;
}

// Expand a token in the address before anything else reads it.
const expanded = expandSearch(window.location.search);
if (expanded !== null) history.replaceState(null, '', expanded + window.location.hash);
