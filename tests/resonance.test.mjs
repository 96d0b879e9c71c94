// End to end: the resonance demo (forced harmonic response) in headless Chromium, driven
// through the URL contract, the preset buttons, the keyboard and the magnitude-view list.
// Every expected number comes from the native snapshots
// (crates/app/tests/snapshots/resonance.snap); nothing is recomputed here.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { open, caption, readout, canvasFingerprint, waitForUrlParam, SHOTS, fullShot } from './support/browser.mjs';
import { golden, goldenState, assertReadoutsMatch, waitForReadoutsMatch } from './support/golden.mjs';
import { allReadouts, assertLinkReproduces, assertFitsPhone, pressOn, waitForChange } from './support/page.mjs';
import { server, browser, useSession } from './support/session.mjs';

const ID = 'resonance';

useSession();

/** Undefined readouts show a dash with an empty data-value; none shows NaN or Infinity. */
async function assertNoNonsense(page) {
  const items = await page.$$eval('[data-readout]', (els) =>
    els.map((e) => ({ key: e.dataset.readout, value: e.dataset.value, text: e.querySelector('dd').textContent.trim() })),
  );
  for (const r of items) {
    assert.ok(!/NaN|Infinity/.test(r.value + r.text), `${r.key}: ${r.value} ${r.text}`);
    if (r.value === '') assert.equal(r.text, '—', `${r.key} undefined shows a dash`);
  }
}

test('defaults and every preset show the readouts and captions computed natively', async () => {
  const doc = golden(ID);
  for (const state of doc.states) {
    const { page, errors, context } = await open(browser, `${server.url}?demo=${ID}&${state.query}`);
    await assertReadoutsMatch(page, state);
    await assertNoNonsense(page);
    for (const [i, p] of doc.spec.plots.entries()) {
      const shown = (await caption(page, p.key)).trim();
      assert.equal(shown, state.figures[i].description, `${state.name}: caption of ${p.key}`);
    }
    for (const plot of ['magnitude', 'phase', 'time', 'schematic']) {
      const [ink] = await canvasFingerprint(page, plot);
      assert.ok(ink > 2000, `${state.name}: ${plot} has ink (${ink} px)`);
    }
    const slug = state.name.replace(/[^A-Za-z0-9.]+/g, '-');
    await fullShot(page, `${SHOTS}resonance-${slug}-1280.png`);
    assert.deepEqual(errors, []);
    await context.close();
  }
});

test('at resonance no beat period is shown, and the page says why', async () => {
  const { page, errors, context } = await open(browser, `${server.url}?demo=${ID}&r=1`);
  assert.equal(await readout(page, 'beat_period'), '');
  assert.equal((await page.textContent('[data-readout="beat_period"] dd')).trim(), '—');
  assert.match(await readout(page, 'beats'), /^none \(/);
  assert.match(await caption(page, 'time'), /builds up/);
  assert.deepEqual(errors, []);
  await context.close();
});

test('the preset buttons set the values they name', async () => {
  const { page, errors, context } = await open(browser, `${server.url}?demo=${ID}`);
  const name = 'Beating near resonance, r = 0.9';
  await page.getByRole('button', { name }).click();
  await waitForUrlParam(page, 'zeta', '0.01');
  await waitForUrlParam(page, 'r', '0.9');
  // The address is written 150 ms after the click, the readouts on the next animation
  // frame: usually first, but not on a busy machine.
  await waitForReadoutsMatch(page, goldenState(ID, name));
  assert.equal(await readout(page, 'beats'), 'visible');
  assert.deepEqual(errors, []);
  await context.close();
});

// Each slider: the readouts it drives and the plot whose pixels must change.
const SLIDERS = [
  ['zeta', ['Q', 'peak_gain', 'gain_at_r'], 'magnitude'],
  ['r', ['gain_at_r', 'phase_at_r', 'amplitude'], 'magnitude'],
  ['wn', ['amplitude'], 'time'],
  ['F0', ['amplitude'], 'time'],
];

for (const [key, readouts, plot] of SLIDERS) {
  test(`the keyboard moves ${key}; readouts, URL and pixels follow`, async () => {
    const { page, errors, context } = await open(browser, `${server.url}?demo=${ID}&r=0.95`);
    const before = await allReadouts(page);
    const pixels = await canvasFingerprint(page, plot);
    const start = new URL(page.url()).searchParams.get(key);
    await pressOn(page, key, 'ArrowRight', 'PageUp');
    await waitForChange(page, readouts[0], before[readouts[0]]);
    for (const k of readouts) assert.notEqual(await readout(page, k), before[k], `${k} changed`);
    await page.waitForFunction(
      ([k, v]) => {
        const got = new URLSearchParams(location.search).get(k);
        return got !== null && got !== v;
      },
      [key, start],
    );
    assert.notDeepEqual(await canvasFingerprint(page, plot), pixels, `${plot} redrawn`);
    await assertNoNonsense(page);
    await assertLinkReproduces(page, key);
    assert.deepEqual(errors, []);
    await context.close();
  });
}

test('the magnitude view switches between linear and dB', async () => {
  const { page, errors, context } = await open(browser, `${server.url}?demo=${ID}&zeta=0.05`);
  const linear = await canvasFingerprint(page, 'magnitude');
  const q = await readout(page, 'Q');
  await page.selectOption('#p-view', '1');
  await waitForUrlParam(page, 'view', '1');
  await page.waitForFunction(() => /dB/.test(document.querySelector('figure:has(canvas[data-plot="magnitude"])').textContent));
  assert.notDeepEqual(await canvasFingerprint(page, 'magnitude'), linear);
  assert.equal(await readout(page, 'Q'), q, 'the view changes no readout');
  await fullShot(page, `${SHOTS}resonance-db-1280.png`);
  // And by URL key.
  const again = await open(browser, `${server.url}?demo=${ID}&zeta=0.05&view=db`);
  assert.equal(await again.page.inputValue('#p-view'), '1');
  assert.deepEqual(again.errors, []);
  await again.context.close();
  assert.deepEqual(errors, []);
  await context.close();
});

test('undefined readouts show a dash, never NaN, at the ends of every range', async () => {
  for (const query of ['zeta=2&r=10&wn=20&F0=100', 'zeta=0.01&r=0.1&wn=0.5&F0=0.1', 'zeta=0.5']) {
    const { page, errors, context } = await open(browser, `${server.url}?demo=${ID}&${query}`);
    await assertNoNonsense(page);
    assert.deepEqual(errors, [], query);
    await context.close();
  }
  // A broad peak (ζ = 0.5) has no lower half-power point: no width, and the caption says so.
  const { page, context } = await open(browser, `${server.url}?demo=${ID}&zeta=0.5`);
  assert.equal(await readout(page, 'peak_width'), '');
  assert.match(await caption(page, 'magnitude'), /no lower half-power point/);
  await context.close();
});

test('a phone-sized screen shows the whole demo', async () => {
  const { page, errors, context } = await open(browser, `${server.url}?demo=${ID}&zeta=0.05`, {
    viewport: { width: 360, height: 740 },
  });
  await assertFitsPhone(page, 'magnitude', 'resonance-360.png');
  assert.deepEqual(errors, []);
  await context.close();
});
