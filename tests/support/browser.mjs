// Headless Debian Chromium through playwright-core, with every console error and page
// error collected so a test can assert the console stayed clean.
import { chromium } from 'playwright-core';
import { mkdir } from 'node:fs/promises';
import { fileURLToPath } from 'node:url';

const EXECUTABLE = process.env.CHROMIUM || '/usr/bin/chromium';
export const SHOTS = fileURLToPath(new URL('../../target/screenshots/', import.meta.url));

export async function launch(extraArgs = []) {
  await mkdir(SHOTS, { recursive: true });
  return chromium.launch({
    executablePath: EXECUTABLE,
    args: [
      ...extraArgs,
      '--no-sandbox',
      '--disable-gpu',
      '--disable-quic',
      '--no-first-run',
      '--disable-background-networking',
      '--disable-component-update',
      '--disable-sync',
      '--disable-dev-shm-usage',
    ],
  });
}

/**
 * Opens `url` in a fresh context; returns {page, errors, context}. `options` are the
 * context's, but for `before(context)`, which runs before the page is opened (routes).
 */
export async function open(browser, url, options = {}) {
  const { before, ...contextOptions } = options;
  const context = await browser.newContext({ viewport: { width: 1280, height: 800 }, ...contextOptions });
  if (before) await before(context);
  const page = await context.newPage();
  const errors = [];
  page.on('console', (msg) => {
    if (msg.type() === 'error') errors.push(msg.text());
  });
  page.on('pageerror', (err) => errors.push(String(err)));
  page.on('dialog', async (d) => {
    errors.push(`unexpected dialog: ${d.message()}`);
    await d.dismiss();
  });
  await page.goto(url);
  await page.waitForSelector('html[data-ready="true"]', { timeout: 15000 });
  await waitForReadouts(page);
  return { page, errors, context };
}

/**
 * A screenshot of the whole page at `path`, every canvas painted: the page paints a canvas
 * only near the window (content-visibility, style.css), and a full-page capture does not
 * count as the window.
 */
export async function fullShot(page, path) {
  const paint = (on) =>
    page.evaluate(
      (on) =>
        new Promise((done) => {
          for (const c of document.querySelectorAll('canvas')) c.style.contentVisibility = on ? 'visible' : '';
          requestAnimationFrame(() => requestAnimationFrame(done));
        }),
      on,
    );
  await paint(true);
  await page.screenshot({ path, fullPage: true });
  await paint(false);
}

/**
 * Counts what the page behind CDP session `cdp` transfers (encoded bytes, headers
 * included; the caller enables `Network`): `bytes()`, everything so far, and
 * `bytesSentBefore(ms)`, the requests the page made before wall-clock time `ms` (its first
 * plot), so what it fetches right after that is not counted while a poll catches up.
 * The low-end benchmark and the budget test count with it.
 */
export function countBytes(cdp) {
  let bytes = 0;
  const sent = new Map(); // requestId → wall-clock ms when the page asked for it
  const finished = []; // {sentAt, bytes}
  cdp.on('Network.requestWillBeSent', (e) => {
    if (!sent.has(e.requestId)) sent.set(e.requestId, e.wallTime * 1000);
  });
  cdp.on('Network.loadingFinished', (e) => {
    bytes += e.encodedDataLength;
    finished.push({ sentAt: sent.get(e.requestId) ?? -Infinity, bytes: e.encodedDataLength });
  });
  const bytesSentBefore = (ms) => finished.filter((f) => f.sentAt < ms).reduce((n, f) => n + f.bytes, 0);
  return { bytes: () => bytes, bytesSentBefore };
}

/**
 * Inked pixels on plot `key`'s overlay (the time cursor, a crosshair); 0 when it is empty
 * (0 x 0).
 */
export function overlayInk(page, key) {
  return page.evaluate((key) => {
    const c = document.querySelector(`[data-plot-wrap="${key}"] canvas.overlay`);
    if (!c.width) return 0;
    const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
    let n = 0;
    for (let i = 3; i < d.length; i += 4) if (d[i]) n++;
    return n;
  }, key);
}

/** Waits until every readout has been filled in once. */
export async function waitForReadouts(page) {
  await page.waitForFunction(() => {
    const items = [...document.querySelectorAll('[data-readout]')];
    return items.length > 0 && items.every((r) => r.querySelector('dd').textContent !== '—' || r.dataset.value === '');
  });
}

/** A readout's data-value. */
export function readout(page, key) {
  return page.getAttribute(`[data-readout="${key}"]`, 'data-value');
}

/** Resolves when every plot shows the last update (those out of view catch up at rest). */
export function drawn(page) {
  return page.waitForFunction(() => !window.zetaDiagnostics || window.zetaDiagnostics.drawn(), null, { timeout: 5000 });
}

/**
 * Plot `plot`'s caption (its text alternative), once every plot is drawn: a plot's figure,
 * and so its caption, is built when the plot is drawn.
 */
export async function caption(page, plot) {
  await drawn(page);
  return page.textContent(`#desc-${plot}`);
}

/** A cheap fingerprint of a canvas's pixels: [non-background pixel count, checksum]. */
export async function canvasFingerprint(page, plot, { settled = true } = {}) {
  // Plots out of view are drawn once the controls rest (web/main.js observeVisibility);
  // `settled: false` reads the canvas as it is now.
  if (settled) await drawn(page);
  return page.evaluate((key) => {
    const c = document.querySelector(`canvas[data-plot="${key}"]`);
    const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
    let ink = 0;
    let sum = 0;
    for (let i = 0; i < d.length; i += 4) {
      if (d[i] !== d[0] || d[i + 1] !== d[1] || d[i + 2] !== d[2]) ink++;
      sum = (sum * 31 + d[i] + 7 * d[i + 1] + 13 * d[i + 2]) % 1000000007;
    }
    return [ink, sum];
  }, plot);
}

/** Waits until the URL's query has `key` = `value`. */
export async function waitForUrlParam(page, key, value) {
  await page.waitForFunction(
    ([k, v]) => new URLSearchParams(location.search).get(k) === v,
    [key, value],
  );
}

/** Waits until a numeric readout is within 1e-9 (relative) of `value`. */
export async function waitForReadout(page, key, value) {
  await page.waitForFunction(
    ([k, v]) => {
      const el = document.querySelector(`[data-readout="${k}"]`);
      return el && el.dataset.value !== '' && Math.abs(Number(el.dataset.value) - v) <= 1e-9 * Math.max(1, Math.abs(v));
    },
    [key, value],
  );
}
