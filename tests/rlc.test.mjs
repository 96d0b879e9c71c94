// End to end: the series RLC demo in headless Chromium, driven through the URL contract,
// the preset buttons and the keyboard. The numbers are checked against the native
// snapshots (crates/app/tests/snapshots/rlc.snap), not recomputed here.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { open, readout, canvasFingerprint, waitForUrlParam, SHOTS, fullShot } from './support/browser.mjs';
import { golden, goldenState, assertReadoutsMatch, assertFiguresMatch } from './support/golden.mjs';
import { assertDrawn, assertKeyboardMove } from './support/page.mjs';
import { server, browser, useSession } from './support/session.mjs';

useSession();

const PLOTS = ['current', 'voltage'];
const READOUTS = ['w0', 'f0', 'alpha', 'zeta', 'Q', 'bandwidth', 'R_crit', 'wd', 'settling_time'];

test('defaults and every preset show the readouts and text alternatives computed natively', async () => {
  for (const state of golden('rlc').states) {
    const { page, errors, context } = await open(browser, `${server.url}?demo=rlc&${state.query}`);
    await assertReadoutsMatch(page, state);
    await assertFiguresMatch(page, state, PLOTS, 2000);
    const slug = state.name.split(',')[0].toLowerCase().replace(/[^a-z]+/g, '-');
    await fullShot(page, `${SHOTS}rlc-${slug}-1280.png`);
    assert.deepEqual(errors, []);
    await context.close();
  }
});

test('the bandwidth readout names the current resonance and its definition', async () => {
  const { page, errors, context } = await open(browser, `${server.url}?demo=rlc`);
  const label = await page.textContent('[data-readout="bandwidth"] dt');
  assert.match(label, /current-resonance half-power bandwidth Δω = R\/L/);
  assert.deepEqual(errors, []);
  await context.close();
});

test('preset buttons switch to the recorded states', async () => {
  const { page, errors, context } = await open(browser, `${server.url}?demo=rlc`);
  for (const name of ['Critical, R = 10 Ω', 'Lossless LC, R = 0']) {
    const state = goldenState('rlc', name);
    const regime = state.readouts.find((r) => r.key === 'regime').value;
    await page.getByRole('button', { name }).click();
    await page.waitForFunction((v) => document.querySelector('[data-readout="regime"]').dataset.value === v, regime);
    await assertReadoutsMatch(page, state);
  }
  assert.deepEqual(errors, []);
  await context.close();
});

// Each slider: the readouts it drives (V0 drives none: every readout is relative to V₀).
const SLIDERS = [
  ['R', ['alpha', 'zeta', 'Q', 'bandwidth']],
  ['L', ['w0', 'alpha', 'R_crit']],
  ['C', ['w0', 'zeta', 'R_crit']],
  ['V0', []],
];

for (const [key, drives] of SLIDERS) {
  test(`the keyboard moves ${key}; readouts, URL and pixels follow`, async () => {
    // No readout depends on V₀: moving it leaves them all as they were.
    await assertKeyboardMove(browser, `${server.url}?demo=rlc`, key, ['ArrowRight', 'PageUp'], { drives, steady: READOUTS, plots: PLOTS });
  });
}

test('the C slider is logarithmic and its ends work', async () => {
  const { page, errors, context } = await open(browser, `${server.url}?demo=rlc&R=4`);
  await page.focus('#p-C');
  await page.keyboard.press('End');
  await waitForUrlParam(page, 'C', '1');
  await page.waitForFunction(() => document.querySelector('[data-readout="regime"]').dataset.value === 'overdamped');
  await page.keyboard.press('Home');
  await waitForUrlParam(page, 'C', '0.0001');
  await page.waitForFunction(() => document.querySelector('[data-readout="regime"]').dataset.value === 'underdamped');
  // One arrow step moves C by a constant factor: (1 F / 0.1 mF)^(1/1000).
  await page.keyboard.press('ArrowRight');
  await page.waitForFunction(() => new URLSearchParams(location.search).get('C') !== '0.0001');
  const c = Number(new URL(page.url()).searchParams.get('C'));
  const want = 1e-4 * Math.pow(1e4, 1 / 1000);
  assert.ok(Math.abs(c - want) <= 1e-6 * want + 1e-6, `C after one step: ${c}, want ≈ ${want}`);
  for (const p of PLOTS) assert.ok((await canvasFingerprint(page, p))[0] > 1000);
  assert.deepEqual(errors, []);
  await context.close();
});

test('the animated loop draws a current arrow while the current flows', async () => {
  const { page, errors, context } = await open(browser, `${server.url}?demo=rlc&R=2`);
  const start = await canvasFingerprint(page, 'schematic');
  await page.$eval('.anim-bar input[type=range]', (e) => {
    e.value = '60';
    e.dispatchEvent(new Event('input', { bubbles: true }));
  });
  await page.waitForFunction(() => document.querySelector('.schematic figcaption').textContent.includes('current -'));
  const flowing = await canvasFingerprint(page, 'schematic');
  assert.ok(flowing[0] > start[0], `the arrow adds ink (${start[0]} → ${flowing[0]} px)`);
  assert.deepEqual(errors, []);
  await context.close();
});

test('narrow screen (360 × 740)', async () => {
  const { page, errors, context } = await open(browser, `${server.url}?demo=rlc`, {
    viewport: { width: 360, height: 740 },
  });
  await assertDrawn(page, PLOTS, 1000);
  await fullShot(page, `${SHOTS}rlc-360.png`);
  assert.deepEqual(errors, []);
  await context.close();
});
