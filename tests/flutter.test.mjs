// End to end: the flutter (Tacoma Narrows) demo in headless Chromium. The numbers come
// from the native snapshots (crates/app/tests/snapshots/flutter.snap, via golden.mjs);
// here we check that the page shows them, and how it behaves: presets, the regime row,
// every slider and menu, the animation, the narrow screen.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { open, caption, readout, canvasFingerprint, SHOTS, fullShot } from './support/browser.mjs';
import { golden, goldenState, openRecorded } from './support/golden.mjs';
import { nudge, assertDrawn } from './support/page.mjs';
import { server, browser, useSession } from './support/session.mjs';

useSession();

const PLOTS = ['derivative', 'damping', 'locus', 'response'];
const FAILURE_DAY = 'Tacoma 1940, 19 m/s (failure day, ≈ 42 mph)';

for (const state of golden('flutter').states) {
  test(`${state.name}: readouts as computed natively, plots drawn, regime row highlighted`, async () => {
    const { page, errors, context } = await openRecorded(browser, server.url, 'flutter', state, { plots: PLOTS, row: 'regime' });
    // The caption is the one computed natively.
    const response = golden('flutter').spec.plots.findIndex((p) => p.key === 'response');
    assert.equal(await caption(page, 'response'), state.figures[response].description);
    assert.deepEqual(errors, []);
    await context.close();
  });
}

test('failure day: the twist grows to a large amplitude within the plotted minutes', async () => {
  const state = goldenState('flutter', FAILURE_DAY);
  const { page, errors, context } = await open(browser, `${server.url}?demo=flutter&${state.query}`);
  assert.equal(await readout(page, 'regime'), 'negatively damped');
  // From θ₀ = 2° to tens of degrees inside a window of minutes, with degrees on screen.
  assert.ok(Number(await readout(page, 'amplitude_end_deg')) > 20);
  assert.match(await page.textContent('[data-readout="amplitude_end_deg"] dd'), /°/);
  assert.match(await page.textContent('[data-readout="limit_deg"] dd'), /°/);
  assert.ok(Number(await readout(page, 'time_to_large')) < Number(state.time_span[1]));
  assert.match(await caption(page, 'response'), /grows to/);
  // The twist fills more of the right half of the plot than of the left: growth is visible.
  const halves = await page.evaluate(() => {
    const c = document.querySelector('canvas[data-plot="response"]');
    const { width, height } = c;
    const d = c.getContext('2d').getImageData(0, 0, width, height).data;
    const bg = [d[0], d[1], d[2]];
    const count = (x0, x1) => {
      let n = 0;
      for (let y = 0; y < height; y++) {
        for (let x = x0; x < x1; x++) {
          const i = 4 * (y * width + x);
          if (d[i] !== bg[0] || d[i + 1] !== bg[1] || d[i + 2] !== bg[2]) n++;
        }
      }
      return n;
    };
    return [count(Math.round(width * 0.15), Math.round(width * 0.35)), count(Math.round(width * 0.65), Math.round(width * 0.85))];
  });
  assert.ok(halves[1] > 1.5 * halves[0], `ink left ${halves[0]}, right ${halves[1]}`);
  await fullShot(page, `${SHOTS}flutter-failure-day-1280.png`);
  assert.deepEqual(errors, []);
  await context.close();
});

test('a narrow phone screen still shows every plot', async () => {
  const state = goldenState('flutter', FAILURE_DAY);
  const { page, errors, context } = await open(browser, `${server.url}?demo=flutter&${state.query}`, {
    viewport: { width: 360, height: 740 },
  });
  await assertDrawn(page, PLOTS, 1000);
  const overflow = await page.evaluate(() => document.documentElement.scrollWidth - innerWidth);
  assert.ok(overflow <= 0, `no sideways scrolling (${overflow} px)`);
  await fullShot(page, `${SHOTS}flutter-failure-day-360.png`);
  await page.locator('.plots').screenshot({ path: `${SHOTS}flutter-360-plots.png` });
  assert.deepEqual(errors, []);
  await context.close();
});

/** Fingerprints of every plot. */
async function prints(page) {
  return Promise.all(PLOTS.map((k) => canvasFingerprint(page, k)));
}

test('every slider moves readouts and pixels by the keyboard', async () => {
  const { page, errors, context } = await open(browser, `${server.url}?demo=flutter&U=15`);
  for (const [key, watch] of [
    ['U', 'zeta_eff'],
    ['B', 'zeta_eff'],
    ['I', 'zeta_eff'],
    ['f0', 'frequency'],
    ['zeta_s', 'U_crit'],
    ['theta0', 'amplitude_end_deg'],
  ]) {
    const before = await prints(page);
    await nudge(page, key, watch);
    assert.notDeepEqual(await prints(page), before, `${key} changes the plots`);
  }
  await context.close();
  // θ_s and g matter above U_crit and in the simplest picture.
  const second = await open(browser, `${server.url}?demo=flutter&U=25&model=1`);
  for (const [key, watch] of [
    ['theta_s', 'limit_deg'],
    ['slope', 'U_crit'],
  ]) {
    const before = await prints(second.page);
    await nudge(second.page, key, watch);
    assert.notDeepEqual(await prints(second.page), before, `${key} changes the plots`);
  }
  assert.deepEqual([...errors, ...second.errors], []);
  await second.context.close();
});

test('the menus switch the section and the model', async () => {
  const { page, errors, context } = await open(browser, `${server.url}?demo=flutter&U=19`);
  assert.equal(await readout(page, 'regime'), 'negatively damped');
  await page.selectOption('#p-section', '1');
  await page.waitForFunction(() => document.querySelector('[data-readout="regime"]').dataset.value === 'underdamped');
  assert.equal(await readout(page, 'U_crit'), '', 'the streamlined box has no critical speed');
  assert.ok(Number(await readout(page, 'A2')) < 0);
  await page.selectOption('#p-section', '0');
  await page.selectOption('#p-model', '1');
  await page.waitForFunction(() => document.querySelector('[data-readout="A3"]').dataset.value === '0');
  assert.ok(Math.abs(Number(await readout(page, 'U_crit')) - 42 * 0.44704) < 1e-6, 'simplest picture: U_crit at 42 mph');
  assert.deepEqual(errors, []);
  await context.close();
});

test('the animation scrubber twists the deck', async () => {
  const { page, errors, context } = await open(browser, `${server.url}?demo=flutter&U=30`);
  const before = await canvasFingerprint(page, 'schematic');
  const scrub = page.locator('.anim-bar input[type=range]');
  await scrub.focus();
  for (let i = 0; i < 10; i++) await page.keyboard.press('ArrowRight');
  await page.waitForFunction(() => document.querySelector('.anim-time').textContent !== 't = 0.00 s');
  const after = await canvasFingerprint(page, 'schematic');
  assert.notDeepEqual(after, before);
  assert.deepEqual(errors, []);
  await context.close();
});
