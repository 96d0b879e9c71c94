// End to end: the quarter-car demo in headless Chromium, driven through the URL contract,
// the preset buttons and the keyboard. Every expected number comes from the native
// snapshots (crates/app/tests/snapshots/quarter-car.snap); nothing is recomputed here.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { open, caption, readout, canvasFingerprint, drawn, waitForReadout, SHOTS, fullShot } from './support/browser.mjs';
import { golden, goldenState, assertReadoutsMatch } from './support/golden.mjs';
import { waitForChange, assertDrawn, assertKeyboardMove } from './support/page.mjs';
import { server, browser, useSession } from './support/session.mjs';

const ID = 'quarter-car';
const PLOTS = ['response', 'settling', 'sensitivity'];

useSession();

/** The value shown in the number box of parameter `key`. */
async function shown(page, key) {
  return Number(await page.inputValue(`input[type=number][data-key="${key}"]`));
}

test('defaults and every preset show the readouts and captions computed natively', async () => {
  const doc = golden(ID);
  for (const state of doc.states) {
    const { page, errors, context } = await open(browser, `${server.url}?demo=${ID}&${state.query}`);
    await assertReadoutsMatch(page, state);
    for (const [i, p] of doc.spec.plots.entries()) {
      const shown = (await caption(page, p.key)).trim();
      assert.equal(shown, state.figures[i].description, `${state.name}: caption of ${p.key}`);
      const [ink] = await canvasFingerprint(page, p.key);
      assert.ok(ink > 2000, `${state.name}: ${p.key} has ink (${ink} px)`);
    }
    assert.ok((await page.locator('canvas').count()) >= 4, 'three plots and the schematic');
    const slug = state.name.replace(/[^A-Za-z0-9.]+/g, '-');
    await fullShot(page, `${SHOTS}quarter-car-${slug}-1280.png`);
    assert.deepEqual(errors, []);
    await context.close();
  }
});

test('the preset buttons set c and ζ together, as a link to the preset does', async () => {
  const { page, errors, context } = await open(browser, `${server.url}?demo=${ID}`);
  for (const name of ['Performance ζ = 0.7', 'Overdamped ζ = 2']) {
    const state = goldenState(ID, name);
    await page.getByRole('button', { name }).click();
    const zeta = state.readouts.find((r) => r.key === 'zeta').value;
    await waitForReadout(page, 'zeta', Number(zeta));
    await assertReadoutsMatch(page, state);
    // The ζ number box follows the preset.
    assert.ok(Math.abs((await shown(page, 'zeta')) - Number(zeta)) < 1e-9);
  }
  assert.deepEqual(errors, []);
  await context.close();
});

test('URL: c wins over ζ when both are given; ζ alone is used', async () => {
  let { page, errors, context } = await open(browser, `${server.url}?demo=${ID}&zeta=0.9&c=3000`);
  assert.equal(await readout(page, 'c'), '3000');
  assert.notEqual(await readout(page, 'zeta'), '0.9');
  assert.deepEqual(errors, []);
  await context.close();
  ({ page, errors, context } = await open(browser, `${server.url}?demo=${ID}&zeta=0.9`));
  assert.ok(Math.abs(Number(await readout(page, 'zeta')) - 0.9) < 1e-12);
  assert.notEqual(await readout(page, 'c'), String(goldenState(ID).readouts.find((r) => r.key === 'c').value));
  assert.deepEqual(errors, []);
  await context.close();
});

// Each slider: the readouts it drives, and the plots whose pixels must change.
const SLIDERS = [
  ['m', ['wn', 'zeta', 'zeta_lo'], PLOTS],
  ['k', ['wn', 'zeta'], PLOTS],
  ['c', ['zeta', 'settling_time'], PLOTS],
  ['zeta', ['c', 'settling_time'], PLOTS],
  ['x0', [], ['response']], // metrics are relative to x₀: only the curves scale
  ['band', ['settling_time', 'zeta_argmin'], ['response', 'settling']],
  ['dm', ['zeta_lo', 'zeta_hi'], ['sensitivity']],
];

for (const [key, drives, plots] of SLIDERS) {
  test(`the keyboard moves ${key}; readouts, pixels and the URL follow`, async () => {
    // The metrics are relative to x₀: moving it leaves them as they were.
    await assertKeyboardMove(browser, `${server.url}?demo=${ID}`, key, ['PageUp', 'ArrowRight'], {
      drives,
      steady: ['overshoot', 'settling_time'],
      plots,
    });
  });
}

test('moving ζ sets the damper, then moving m keeps the damper and moves ζ', async () => {
  const { page, errors, context } = await open(browser, `${server.url}?demo=${ID}`);
  const c0 = await readout(page, 'c');
  await page.focus('#p-zeta');
  for (let i = 0; i < 4; i++) await page.keyboard.press('ArrowRight');
  await waitForReadout(page, 'zeta', 0.34);
  await waitForChange(page, 'c', c0);
  const c = await readout(page, 'c');
  const zeta = await readout(page, 'zeta');
  await page.focus('#p-m');
  await page.keyboard.press('ArrowRight');
  await waitForChange(page, 'zeta', zeta);
  assert.equal(await readout(page, 'c'), c, 'the damper is unchanged');
  assert.ok(Number(await readout(page, 'zeta')) < Number(zeta), 'a heavier body lowers ζ');
  assert.deepEqual(errors, []);
  await context.close();
});

test('undamped and extreme settings keep a working page', async () => {
  const { page, errors, context } = await open(browser, `${server.url}?demo=${ID}&c=0`);
  assert.equal(await readout(page, 'regime'), 'undamped');
  assert.equal(await readout(page, 'settling_time'), '');
  assert.equal((await page.textContent('[data-readout="settling_time"] dd')).trim(), '—');
  assert.match(await page.textContent('body'), /oscillates forever/);
  await page.focus('#p-c');
  await page.keyboard.press('End');
  await waitForReadout(page, 'c', 20000);
  const zeta = await readout(page, 'zeta');
  await page.focus('#p-m');
  await page.keyboard.press('Home');
  await page.focus('#p-k');
  await page.keyboard.press('Home');
  await waitForChange(page, 'zeta', zeta);
  // ζ changes with m's frame; k's (the second key) may come a frame later: wait for it
  // (zetaDiagnostics.drawn() is false from an input until its frame is drawn) instead
  // of 200 ms.
  await drawn(page);
  assert.equal(await readout(page, 'regime'), 'overdamped');
  await assertDrawn(page, PLOTS, 1000);
  const all = await page.$$eval('[data-readout]', (els) => els.map((e) => e.dataset.value + e.textContent));
  assert.ok(all.every((s) => !/NaN|Infinity/.test(s)), all.join(' | '));
  assert.deepEqual(errors, []);
  await context.close();
});

test('narrow screen (360 × 740)', async () => {
  const { page, errors, context } = await open(browser, `${server.url}?demo=${ID}`, {
    viewport: { width: 360, height: 740 },
  });
  await assertDrawn(page, PLOTS, 1000);
  const overflow = await page.evaluate(() => document.documentElement.scrollWidth - document.documentElement.clientWidth);
  assert.ok(overflow <= 0, `no horizontal scroll (${overflow} px)`);
  await fullShot(page, `${SHOTS}quarter-car-360.png`);
  assert.deepEqual(errors, []);
  await context.close();
});
