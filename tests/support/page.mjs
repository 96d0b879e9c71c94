// Helpers the end-to-end tests share for reading readouts and moving sliders.
import assert from 'node:assert/strict';
import { open, canvasFingerprint, drawn, readout, waitForReadout, SHOTS } from './browser.mjs';

/** Waits until readout `key` differs from `old` (a data-value string). */
export async function waitForChange(page, key, old) {
  await page.waitForFunction(
    ([k, o]) => document.querySelector(`[data-readout="${k}"]`).dataset.value !== o,
    [key, old],
  );
}

/** Every readout's data-value, by key. */
export async function allReadouts(page) {
  return Object.fromEntries(
    await page.$$eval('[data-readout]', (els) => els.map((e) => [e.dataset.readout, e.dataset.value])),
  );
}

/** Readouts equal as texts, or as numbers to 1e-12 (a link carries the shortest decimals). */
export function assertSameReadouts(got, want, what) {
  assert.deepEqual(Object.keys(got), Object.keys(want), what);
  for (const [k, v] of Object.entries(want)) {
    const [a, b] = [Number(got[k]), Number(v)];
    if (v !== '' && Number.isFinite(b)) {
      assert.ok(Math.abs(a - b) <= 1e-12 * Math.max(1, Math.abs(b)), `${what}: ${k} ${got[k]} vs ${v}`);
    } else {
      assert.equal(got[k], v, `${what}: ${k}`);
    }
  }
}

/**
 * Once the address bar has caught up (400 ms), opens its link in a fresh page of the same
 * browser and asserts that page shows the same readouts, with a clean console.
 */
export async function assertLinkReproduces(page, what) {
  await page.waitForTimeout(400);
  const after = await allReadouts(page);
  const link = await page.evaluate(() => location.href);
  const again = await open(page.context().browser(), link);
  assertSameReadouts(await allReadouts(again.page), after, `${what}: the link reproduces the state`);
  assert.deepEqual(again.errors, []);
  await again.context.close();
}

/** Focuses slider `key` and presses `keys` on it in turn (e.g. 'ArrowRight', 'PageUp'). */
export async function pressOn(page, key, ...keys) {
  await page.focus(`#p-${key}`);
  for (const k of keys) await page.keyboard.press(k);
}

/**
 * The page still answers the keyboard: Home on the regimes demo's ζ slider shows ζ = −0.5.
 * Then asserts a clean console and closes the context.
 */
export async function assertStillWorks({ page, errors, context }) {
  await pressOn(page, 'zeta', 'Home');
  await waitForReadout(page, 'zeta', -0.5);
  assert.deepEqual(errors, []);
  await context.close();
}

/** Types `value` into parameter `key`'s number box and presses Enter. */
export async function typeValue(page, key, value) {
  const box = `input[type=number][data-key="${key}"]`;
  await page.fill(box, value);
  await page.press(box, 'Enter');
}

/** Presses ArrowRight on slider `key` and waits until readout `watch` changes. */
export async function nudge(page, key, watch) {
  const old = await readout(page, watch);
  await page.focus(`#p-${key}`);
  await page.keyboard.press('ArrowRight');
  await waitForChange(page, watch, old);
}

/**
 * How far (px) the widest element of the demo sticks out past the right edge of the
 * window; the equation and the tables scroll in their own boxes and are not counted.
 */
export function sidewaysOverflow(page) {
  return page.evaluate(() => {
    let worst = 0;
    for (const e of document.querySelectorAll('#demo *')) {
      if (e.closest('.equation, .table-wrap')) continue;
      worst = Math.max(worst, e.getBoundingClientRect().right - window.innerWidth);
    }
    return worst;
  });
}

/** The pixel fingerprints of `plots`, by plot key (see `canvasFingerprint`). */
export async function fingerprints(page, plots) {
  const out = {};
  for (const p of plots) out[p] = await canvasFingerprint(page, p);
  return out;
}

/** Asserts that every plot of `before` (from `fingerprints`) has been drawn anew since. */
export async function assertRedrawn(page, before, what) {
  for (const [p, pixels] of Object.entries(before)) {
    assert.notDeepEqual(await canvasFingerprint(page, p), pixels, `${p} redrawn ${what}`);
  }
}

/** Asserts that each plot of `plots` has more than `minInk` inked pixels. */
export async function assertDrawn(page, plots, minInk) {
  for (const plot of plots) {
    const [ink] = await canvasFingerprint(page, plot);
    assert.ok(ink > minInk, `${plot} has ink (${ink} px)`);
  }
}

/** Asserts that the table row named by readout `key`'s value is marked as the current one. */
export async function assertRowCurrent(page, key) {
  const row = await readout(page, key);
  assert.equal(await page.getAttribute(`tr[data-row="${row}"]`, 'aria-current'), 'true', `row ${row}`);
}

/**
 * On a phone-sized page: plot `plot` is drawn, nothing of the demo sticks out sideways
 * (the equation and the table scroll in their own boxes); saves screenshot `shot`.
 */
export async function assertFitsPhone(page, plot, shot) {
  await assertDrawn(page, [plot], 1000);
  const overflow = await sidewaysOverflow(page);
  assert.ok(overflow <= 0.5, `nothing wider than the screen (${overflow} px)`);
  await page.screenshot({ path: `${SHOTS}${shot}`, fullPage: true });
}

/**
 * On a fresh page at `url`: presses `keys` on slider `key` and asserts that each readout of
 * `drives` changes or, when it drives none, that each readout of `steady` keeps its value
 * once the address shows the move; that each plot of `plots` is drawn anew; that the page's
 * link reproduces it; and that the console stays clean.
 */
export async function assertKeyboardMove(browser, url, key, keys, { drives, steady = [], plots }) {
  const { page, errors, context } = await open(browser, url);
  const before = await allReadouts(page);
  const pixels = await fingerprints(page, plots);
  const inUrl = () => page.evaluate((k) => new URLSearchParams(location.search).get(k), key);
  const shown = await inUrl();
  await pressOn(page, key, ...keys);
  if (drives.length) {
    for (const r of drives) await waitForChange(page, r, before[r]);
  } else {
    await page.waitForFunction(([k, old]) => new URLSearchParams(location.search).get(k) !== old, [key, shown]);
    // The move's frame drawn (the address is written 150 ms after the keys, the readouts on
    // the next frame: usually before, not surely): a readout read before it is trivially steady.
    await page.waitForTimeout(100);
    await drawn(page);
    for (const r of steady) assert.equal(await readout(page, r), before[r], `${r} does not change with ${key}`);
  }
  await assertRedrawn(page, pixels, `after moving ${key}`);
  await assertLinkReproduces(page, key);
  assert.deepEqual(errors, []);
  await context.close();
}
