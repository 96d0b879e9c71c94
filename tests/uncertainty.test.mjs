// End to end: the tolerance demo. The defaults and every preset through the URL contract,
// checked against the readouts and text alternatives recorded by the native snapshot tests
// (no physics or statistics recomputed here), the seed's reproducibility, every control
// moved from the keyboard, and the time of a 100 000-draw run.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { open, caption, readout, canvasFingerprint, drawn, waitForUrlParam, SHOTS, fullShot } from './support/browser.mjs';
import { golden, assertReadoutsMatch, assertFiguresMatch, stateSlug } from './support/golden.mjs';
import { server, browser, useSession } from './support/session.mjs';

useSession();

const PLOTS = ['band', 'zeta_hist', 'hist'];
const num = async (page, key) => Number(await readout(page, key));
const urlValue = (page, key) => page.evaluate((k) => new URLSearchParams(location.search).get(k), key);

for (const state of golden('uncertainty').states) {
  test(`"${state.name}" from the URL: readouts and text alternatives as recorded natively, every plot drawn`, async () => {
    const { page, errors, context } = await open(browser, `${server.url}?demo=uncertainty&${state.query}`);
    // The recorded state is the full run: wait out the coarse one (marked provisional).
    await page.waitForFunction(() => !document.querySelector('[data-provisional]'));
    await assertReadoutsMatch(page, state);
    await assertFiguresMatch(page, state, PLOTS, 3000);
    await fullShot(page, `${SHOTS}uncertainty-${stateSlug(state.name)}-1280.png`);
    assert.deepEqual(errors, []);
    await context.close();
  });
}

test('choosing normal parts redraws the histograms and says so', async () => {
  const { page, errors, context } = await open(browser, `${server.url}?demo=uncertainty&zeta=1&dm=10`);
  const p5 = await readout(page, 'zeta_p5');
  const print = await canvasFingerprint(page, 'zeta_hist');
  assert.match(await caption(page, 'zeta_hist'), /10000 uniform draws/);
  await page.selectOption('#p-dist', '1');
  await waitForUrlParam(page, 'dist', '1');
  assert.match(await caption(page, 'zeta_hist'), /normal \(tolerance = 3σ\) draws/);
  assert.notEqual(await readout(page, 'zeta_p5'), p5);
  assert.notDeepEqual(await canvasFingerprint(page, 'zeta_hist'), print);
  assert.deepEqual(errors, []);
  await context.close();
});

test('the same seed gives the same histogram; another seed a different one', async () => {
  const { page, errors, context } = await open(browser, `${server.url}?demo=uncertainty&system=1&dR=20&dL=20&dC=20`);
  // The full run's numbers, not the coarse run's drawn first (marked provisional). After an
  // input, the frame that marks the coarse run comes first: before it nothing is marked,
  // and a wait for 'nothing provisional' would pass on the old numbers.
  const settled = async (p) => {
    await drawn(p);
    await p.waitForFunction(() => !document.querySelector('[data-provisional]'));
  };
  await settled(page);
  const q5 = await readout(page, 'Q_p5');
  const z95 = await readout(page, 'zeta_p95');
  const y = await readout(page, 'yield');
  const prints = [await canvasFingerprint(page, 'zeta_hist'), await canvasFingerprint(page, 'hist')];
  await page.focus('#p-seed');
  await page.keyboard.press('ArrowRight');
  await waitForUrlParam(page, 'seed', '2');
  await settled(page);
  assert.notEqual(await readout(page, 'Q_p5'), q5, 'another seed, other draws');
  assert.notDeepEqual(await canvasFingerprint(page, 'zeta_hist'), prints[0]);
  await page.keyboard.press('ArrowLeft');
  await waitForUrlParam(page, 'seed', '1');
  await settled(page);
  assert.equal(await readout(page, 'Q_p5'), q5, 'Q_p5 identical after restoring the seed');
  assert.equal(await readout(page, 'zeta_p95'), z95);
  assert.equal(await readout(page, 'yield'), y);
  assert.deepEqual([await canvasFingerprint(page, 'zeta_hist'), await canvasFingerprint(page, 'hist')], prints);
  // The same seed in a fresh page gives the same numbers too.
  const again = await open(browser, `${server.url}?demo=uncertainty&system=1&dR=20&dL=20&dC=20&seed=1`);
  await settled(again.page);
  assert.equal(await readout(again.page, 'Q_p5'), q5);
  await again.context.close();
  assert.deepEqual(errors, []);
  await context.close();
});

/** Everything observable: readouts and the three canvases. */
async function state(page) {
  const values = await page.$$eval('[data-readout]', (els) =>
    els.filter((e) => e.dataset.readout !== 'compute_time').map((e) => `${e.dataset.readout}=${e.dataset.value}`).join('&'));
  const prints = [];
  for (const plot of PLOTS) prints.push((await canvasFingerprint(page, plot)).join(':'));
  return { values, prints };
}

async function nudge(page, key) {
  const old = await urlValue(page, key);
  await page.focus(`#p-${key}`);
  await page.keyboard.press('ArrowRight');
  await page.waitForFunction(([k, v]) => new URLSearchParams(location.search).get(k) !== v, [key, old]);
  // Let the redraw that follows the URL write settle.
  await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
}

test('every control moves from the keyboard; only the chosen system\'s sliders are shown', async () => {
  const { page, errors, context } = await open(browser, `${server.url}?demo=uncertainty&N=2000`);
  // Suspension: its sliders change readouts and the named plot. (m and k only rescale time:
  // at fixed ζ every plot is the same shape on a stretched axis, so only readouts are checked.)
  await page.selectOption('#p-hist', '4');
  await waitForUrlParam(page, 'hist', '4');
  for (const [key, plot, readoutsMove] of [
    ['m', null, true],
    ['k', null, true],
    ['zeta', 'band', true],
    ['dm', 'band', true],
    ['N', 'zeta_hist', true],
    ['seed', 'zeta_hist', true],
    ['zeta_lo', 'zeta_hist', false],
    ['zeta_hi', 'zeta_hist', false],
    ['ts_max', 'hist', false],
  ]) {
    const before = await state(page);
    await nudge(page, key);
    const after = await state(page);
    const i = PLOTS.indexOf(plot);
    if (plot) assert.notEqual(after.prints[i], before.prints[i], `${key}: ${plot} redrawn`);
    if (readoutsMove) assert.notEqual(after.values, before.values, `${key}: readouts follow`);
  }
  // Each system's sliders are shown only while it is chosen (the other's would do nothing).
  const rlc = ['R', 'L', 'C', 'dR', 'dL', 'dC'];
  const suspension = ['m', 'k', 'zeta', 'dm'];
  const shown = (keys) => Promise.all(keys.map((k) => page.isVisible(`#p-${k}`)));
  assert.deepEqual(await shown(rlc), rlc.map(() => false), 'RLC sliders hidden for the suspension');
  // Switch system: now they are shown and count, and the suspension's are hidden.
  await page.selectOption('#p-system', '1');
  await waitForUrlParam(page, 'system', '1');
  await page.waitForFunction(() => !document.querySelector('#p-R').closest('[hidden]'));
  assert.deepEqual(await shown(rlc), rlc.map(() => true), 'RLC sliders shown');
  assert.deepEqual(await shown(suspension), suspension.map(() => false), 'suspension sliders hidden');
  assert.match(await caption(page, 'band'), /suspension sliders are ignored/);
  for (const key of ['R', 'L', 'C', 'dR', 'dL', 'dC']) {
    const before = await state(page);
    await nudge(page, key);
    const after = await state(page);
    assert.notEqual(after.values, before.values, `${key}: readouts follow`);
    assert.notEqual(after.prints[0], before.prints[0], `${key}: band redrawn`);
  }
  // Distribution and the second histogram's quantity.
  for (const [key, value, plot] of [
    ['dist', '1', 'zeta_hist'],
    ['hist', '1', 'hist'],
    ['hist', '3', 'hist'],
    ['hist', '0', 'hist'],
  ]) {
    const before = await state(page);
    await page.selectOption(`#p-${key}`, value);
    await waitForUrlParam(page, key, value);
    await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
    const after = await state(page);
    assert.notEqual(after.prints[PLOTS.indexOf(plot)], before.prints[PLOTS.indexOf(plot)], `${key}=${value}`);
  }
  assert.deepEqual(errors, []);
  await context.close();
});

test('100 000 draws: a coarse run first, then the full run, reported with its compute time', async (t) => {
  const { page, errors, context } = await open(browser, `${server.url}?demo=uncertainty&N=100000&system=1`);
  // The full study arrives in slices after a coarse first answer; wait until nothing is provisional.
  // (After an input: once its frame, which marks the coarse run, is drawn; see above.)
  const settled = async () => {
    await drawn(page);
    await page.waitForFunction(() => !document.querySelector('[data-provisional]'), null, { timeout: 30000 });
  };
  await settled();
  assert.equal(await num(page, 'draws'), 100000);
  const times = [await num(page, 'compute_time')];
  await page.focus('#p-seed');
  for (let i = 2; i <= 4; i++) {
    await page.keyboard.press('ArrowRight');
    await waitForUrlParam(page, 'seed', String(i));
    await settled();
    assert.equal(await num(page, 'draws'), 100000);
    times.push(await num(page, 'compute_time'));
  }
  // Speed is measured by bench/browser.mjs, not asserted here; the numbers are reported.
  assert.ok(times.every((x) => Number.isFinite(x) && x > 0), `compute times ${times}`);
  t.diagnostic(`100 000-draw Monte Carlo in the browser: ${times.map((x) => x.toFixed(0)).join(', ')} ms`);
  await page.setViewportSize({ width: 360, height: 740 });
  await page.waitForTimeout(300);
  await fullShot(page, `${SHOTS}uncertainty-360.png`);
  assert.deepEqual(errors, []);
  await context.close();
});
