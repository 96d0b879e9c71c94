// End to end: the nonlinear quarter-car demo in headless Chromium. The numbers come from
// the native snapshots (crates/app/tests/snapshots/nonlinear.snap, via golden.mjs), where
// the solver's own tests check them against closed forms; here we check that the page
// shows them and how it behaves: presets, the effect row, every slider, the narrow screen.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { open, caption, readout, canvasFingerprint, SHOTS, fullShot } from './support/browser.mjs';
import { golden, goldenState, openRecorded } from './support/golden.mjs';
import { nudge, assertDrawn } from './support/page.mjs';
import { server, browser, useSession } from './support/session.mjs';

useSession();

const PLOTS = ['response', 'phase', 'spring', 'damper'];

for (const state of golden('nonlinear').states) {
  test(`${state.name}: readouts as computed natively, plots drawn, effect row highlighted`, async () => {
    const { page, errors, context } = await openRecorded(browser, server.url, 'nonlinear', state, { plots: PLOTS, row: 'effect' });
    const slug = state.name.toLowerCase().replace(/[^a-z]+/g, '-');
    await fullShot(page, `${SHOTS}nonlinear-${slug}-1280.png`);
    assert.deepEqual(errors, []);
    await context.close();
  });
}

test('friction holds the mass for good: the stuck position stays within the static band', async () => {
  const state = goldenState('nonlinear', 'Friction stick–slip');
  const { page, errors, context } = await open(browser, `${server.url}?demo=nonlinear&${state.query}`);
  const x = Number(await readout(page, 'stick_position'));
  // Behaviour, not physics: a stuck mass shows a stop marker and a flat end on the plot.
  assert.ok(x !== 0 && Number.isFinite(x));
  assert.match(await caption(page, 'response'), /friction holds the mass at/);
  assert.deepEqual(errors, []);
  await context.close();
});

test('a narrow phone screen still shows every plot', async () => {
  const state = goldenState('nonlinear', 'Bump-stop impact');
  const { page, errors, context } = await open(browser, `${server.url}?demo=nonlinear&${state.query}`, {
    viewport: { width: 360, height: 740 },
  });
  await assertDrawn(page, PLOTS, 1000);
  await fullShot(page, `${SHOTS}nonlinear-360.png`);
  await page.locator('.plots').screenshot({ path: `${SHOTS}nonlinear-360-plots.png` });
  assert.deepEqual(errors, []);
  await context.close();
});

test('every slider moves readouts and pixels by the keyboard', async () => {
  const { page, errors, context } = await open(browser, `${server.url}?demo=nonlinear&${goldenState('nonlinear', 'Hardening spring').query}`);
  // k_stop before gap: the clearance only matters once there are stops.
  for (const [key, watch] of [
    ['m', 'period_linear'],
    ['k', 'period_linear'],
    ['k3', 'max_deviation'],
    ['c_comp', 'max_deviation'],
    ['c_reb', 'max_deviation'],
    ['friction', 'max_deviation'],
    ['k_stop', 'max_deviation'],
    ['gap', 'max_deviation'],
    ['x0', 'max_travel'],
    ['v0', 'max_deviation'],
  ]) {
    const before = await Promise.all(PLOTS.map((k) => canvasFingerprint(page, k)));
    await nudge(page, key, watch);
    const after = await Promise.all(PLOTS.map((k) => canvasFingerprint(page, k)));
    assert.notDeepEqual(after, before, `${key} changes the plots`);
  }
  assert.equal(await readout(page, 'effect'), 'several at once');
  // A big step: PageUp on friction; the mass now sticks.
  await page.focus('#p-friction');
  for (let i = 0; i < 3; i++) await page.keyboard.press('PageUp');
  await page.waitForFunction(() => document.querySelector('[data-readout="stick_position"]').dataset.value !== '');
  assert.deepEqual(errors, []);
  await context.close();
});

test('a softening spring pushed past its limit is cut off, not crashed', async () => {
  const q = 'k=5000&k3=-4000000&x0=0.15&v0=2&c_comp=0&c_reb=0';
  const { page, errors, context } = await open(browser, `${server.url}?demo=nonlinear&${q}`);
  assert.equal(await readout(page, 'effect'), 'escaped');
  assert.match(await caption(page, 'response'), /leaves the plot/);
  assert.deepEqual(errors, []);
  await context.close();
});
