// End to end: the (k, c) design-space demo. The defaults and every preset through the URL
// contract, checked against the readouts and text alternatives recorded by the native
// snapshot tests (no physics recomputed here); every control moved from the keyboard,
// picking designs by clicking the map and the Pareto front, and the sweep's compute time.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { open, caption, readout, canvasFingerprint, drawn, waitForUrlParam, SHOTS, fullShot } from './support/browser.mjs';
import { golden, assertReadoutsMatch, assertFiguresMatch, stateSlug } from './support/golden.mjs';
import { server, browser, useSession } from './support/session.mjs';

useSession();

const DEFAULTS = { m: 300, mu: 40, kt: 200000, metric: 0, band: 5, road: 2, V: 10, k_min: 10000, k_max: 60000, c_min: 500, c_max: 8000, k: 24000, c: 2000, n: 100 };
const PLOTS = ['map', 'pareto', 'response'];

const num = async (page, key) => Number(await readout(page, key));
const query = (values) => Object.entries(values).map(([k, v]) => `${k}=${v}`).join('&');

/** What the page shows whatever the physics: the selection, and the grid it was swept on. */
async function checkEchoes(page, p) {
  // The grid is the full one once the coarse stand-in has been refined (a busy machine can
  // still be showing the coarse sweep here).
  await page.waitForFunction(() => !document.querySelector('[data-provisional]'));
  assert.equal(await num(page, 'k'), p.k);
  assert.equal(await num(page, 'c'), p.c);
  assert.equal(await num(page, 'grid_size'), p.n * p.n);
}


for (const state of golden('design').states) {
  test(`"${state.name}" from the URL: readouts and text alternatives as recorded natively, every plot drawn`, async () => {
    const { page, errors, context } = await open(browser, `${server.url}?demo=design&${state.query}`);
    // The recorded state is the full sweep: wait out the coarse stand-in (the two-DOF comfort
    // cells make a 160 × 160 sweep take a few hundred ms in slices).
    await page.waitForFunction(() => !document.querySelector('[data-provisional]'));
    await assertReadoutsMatch(page, state);
    await assertFiguresMatch(page, state, PLOTS, 3000);
    const [mapInk] = await canvasFingerprint(page, 'map');
    assert.ok(mapInk > 60000, `the heat map fills its plot (${mapInk} px)`);
    await fullShot(page, `${SHOTS}design-${stateSlug(state.name)}-1280.png`);
    assert.deepEqual(errors, []);
    await context.close();
  });
}

/**
 * Everything observable: readouts and the three canvases, once the last input's frame is
 * drawn. The callers wait for the address, written 150 ms after the input: the frame that
 * writes the readouts usually comes first, but not surely on a busy machine (the
 * fingerprints waited for it, the readouts, read first, did not).
 */
async function state(page) {
  await drawn(page);
  const values = await page.$$eval('[data-readout]', (els) => els.map((e) => `${e.dataset.readout}=${e.dataset.value}`).join('&'));
  const prints = [];
  for (const plot of PLOTS) prints.push((await canvasFingerprint(page, plot)).join(':'));
  return { values, prints };
}

const urlValue = (page, key) => page.evaluate((k) => new URLSearchParams(location.search).get(k), key);

test('every slider moves from the keyboard and changes readouts or pixels', async () => {
  const { page, errors, context } = await open(browser, `${server.url}?demo=design&${query(DEFAULTS)}`);
  // key → [expected value after one ArrowRight, the plot that must change (null: none
  // surely does by a pixel), whether the selected design's readouts change (the map's
  // range only moves the map)]
  const sliders = {
    m: [301, 'map', true],
    // The two-DOF car and road behind comfort: the Pareto front and a_w move.
    mu: [41, 'pareto', true],
    // One step of k_t (0.5 %) may move the front by less than a pixel: readouts only.
    kt: [201000, null, true],
    band: [5.5, 'response', true],
    V: [10.5, 'pareto', true],
    k_min: [10500, 'map', false],
    k_max: [60500, 'map', false],
    c_min: [550, 'map', false],
    c_max: [8100, 'map', false],
    k: [24100, 'response', true],
    c: [2010, 'response', true],
    n: [101, 'map', true],
  };
  const p = { ...DEFAULTS };
  for (const [key, [next, plot, moves]] of Object.entries(sliders)) {
    const before = await state(page);
    await page.focus(`#p-${key}`);
    await page.keyboard.press('ArrowRight');
    await waitForUrlParam(page, key, String(next));
    p[key] = next;
    const after = await state(page);
    const i = PLOTS.indexOf(plot);
    if (plot) assert.notEqual(after.prints[i], before.prints[i], `${key}: ${plot} redrawn`);
    if (moves) assert.notEqual(after.values, before.values, `${key}: readouts follow`);
    await checkEchoes(page, p);
  }
  // The choices.
  for (const [key, value, plot] of [
    ['metric', 2, 'map'],
    ['road', 3, 'pareto'],
    ['metric', 3, 'map'],
    ['metric', 1, 'map'],
  ]) {
    const before = await state(page);
    await page.selectOption(`#p-${key}`, String(value));
    await waitForUrlParam(page, key, String(value));
    p[key] = value;
    const after = await state(page);
    const i = PLOTS.indexOf(plot);
    assert.notEqual(after.prints[i], before.prints[i], `${key}=${value}: ${plot} redrawn`);
    await checkEchoes(page, p);
  }
  assert.match(await caption(page, 'map'), /^Peak rebound of the free response from x₀ = 60 mm, in % of x₀, over k/);
  assert.deepEqual(errors, []);
  await context.close();
});

test('clicking the map selects that design; clicking the front selects a front design', async () => {
  const { page, errors, context } = await open(browser, `${server.url}?demo=design`);
  const before = await canvasFingerprint(page, 'response');
  await page.locator('canvas[data-plot="map"]').scrollIntoViewIfNeeded();
  const box = await page.locator('canvas[data-plot="map"]').boundingBox();
  await page.mouse.click(box.x + box.width * 0.35, box.y + box.height * 0.45);
  await page.waitForFunction(() => document.querySelector('[data-readout="k"]').dataset.value !== '24000');
  const k = await num(page, 'k');
  const c = await num(page, 'c');
  assert.ok(k > 10000 && k < 60000 && c > 500 && c < 8000, `picked (${k}, ${c}) inside the map`);
  await waitForUrlParam(page, 'k', String(k));
  assert.equal(await urlValue(page, 'c'), String(c));
  await checkEchoes(page, { ...DEFAULTS, k, c });
  assert.notDeepEqual(await canvasFingerprint(page, 'response'), before);
  // A click on the Pareto plot moves the selection onto the front.
  await page.locator('canvas[data-plot="pareto"]').scrollIntoViewIfNeeded();
  const pbox = await page.locator('canvas[data-plot="pareto"]').boundingBox();
  await page.mouse.click(pbox.x + pbox.width * 0.3, pbox.y + pbox.height * 0.6);
  await page.waitForFunction((kk) => Number(document.querySelector('[data-readout="k"]').dataset.value) !== kk, k);
  const k2 = await num(page, 'k');
  const c2 = await num(page, 'c');
  await checkEchoes(page, { ...DEFAULTS, k: k2, c: c2 });
  // Front designs are cell centres of the 100 × 100 grid.
  const ik = (k2 - 10000) / 500 - 0.5;
  const ic = (c2 - 500) / 75 - 0.5;
  assert.ok(Math.abs(ik - Math.round(ik)) < 1e-6 && Math.abs(ic - Math.round(ic)) < 1e-6, `front design on the grid (${k2}, ${c2})`);
  assert.match(await caption(page, 'pareto'), /^Pareto front of \d+ non-dominated designs/);
  assert.deepEqual(errors, []);
  await context.close();
});

test('the 100 × 100 sweep reruns while the mass moves and reports its compute time', async (t) => {
  const { page, errors, context } = await open(browser, `${server.url}?demo=design`);
  const times = [];
  const frames = [];
  await page.focus('#p-m');
  for (let i = 1; i <= 8; i++) {
    const t0 = await page.evaluate(() => performance.now());
    await page.keyboard.press('ArrowRight');
    await waitForUrlParam(page, 'm', String(300 + i));
    frames.push((await page.evaluate(() => performance.now())) - t0);
    // The full sweep's time: the coarse stand-in shown at once (its one-DOF maps only, the
    // comfort map waiting for a figure that reads it) can take less than the browser's
    // timer resolution.
    await page.waitForFunction(() => !document.querySelector('[data-provisional]'));
    times.push(await num(page, 'compute_time'));
  }
  times.sort((a, b) => a - b);
  const median = times[Math.floor(times.length / 2)];
  t.diagnostic(`sweep compute time in the browser: median ${median.toFixed(2)} ms, all ${times.map((x) => x.toFixed(1)).join(', ')}`);
  // Speed is measured by bench/browser.mjs and bench/lowend.mjs, not asserted here.
  assert.ok(times.every((x) => Number.isFinite(x) && x > 0), `compute times ${times}`);
  // Whole-event timing (sweep + drawing 10 000 cells + the other plots), for the report.
  const ev = await page.evaluate(async () => {
    const range = document.querySelector('#p-m');
    const frame = () => new Promise((r) => requestAnimationFrame(() => r(performance.now())));
    const out = [];
    for (let i = 0; i < 10; i++) {
      await frame();
      let start = 0;
      requestAnimationFrame(() => {
        start = performance.now();
      });
      range.value = String(320 + i);
      range.dispatchEvent(new Event('input', { bubbles: true }));
      out.push((await frame()) - start);
    }
    return out.sort((a, b) => a - b);
  });
  t.diagnostic(`mass slider event (sweep + draw): median ${ev[5].toFixed(1)} ms`);
  await page.setViewportSize({ width: 360, height: 740 });
  await page.waitForTimeout(300);
  await fullShot(page, `${SHOTS}design-360.png`);
  assert.deepEqual(errors, []);
  await context.close();
});
