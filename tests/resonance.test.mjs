// End to end: the resonance demo (forced harmonic response) in headless Chromium, driven
// through the URL contract, the keyboard and the magnitude-view list. Expected readouts
// are computed here from the closed forms of H(r) = 1/(1 − r² + 2iζr) for a 1 kg mass.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { serve } from './support/server.mjs';
import { launch, open, readout, canvasFingerprint, waitForUrlParam, SHOTS } from './support/browser.mjs';

let server;
let browser;

before(async () => {
  server = await serve();
  browser = await launch();
});

after(async () => {
  await browser?.close();
  await server?.close();
});

// Closed forms (tests only). Relative tolerance for every comparison: 1e-9.
const TOL = 1e-9;
const gain = (r, z) => 1 / Math.hypot(1 - r * r, 2 * z * r);
const phase = (r, z) => -Math.atan2(2 * z * r, 1 - r * r);
function expected({ zeta: z, r, wn, F0 }) {
  const hasPeak = 2 * z * z < 1;
  const s = Math.sqrt(1 - z * z);
  const upper = hasPeak ? Math.sqrt(1 - 2 * z * z + 2 * z * s) : Math.sqrt(1 / (2 * z * z - 1 + Math.hypot(2 * z * z - 1, 1)));
  const lowerSq = 1 - 2 * z * z - 2 * z * s;
  const lower = hasPeak && lowerSq > 0 ? Math.sqrt(lowerSq) : 0;
  const wd = wn * s;
  return {
    peak_gain: hasPeak ? 1 / (2 * z * s) : null,
    peak_ratio: hasPeak ? Math.sqrt(1 - 2 * z * z) : null,
    Q: 1 / (2 * z),
    bandwidth: upper - lower,
    gain_at_r: gain(r, z),
    phase_at_r: phase(r, z),
    amplitude: (gain(r, z) * F0) / (wn * wn), // k = ωn²·m, m = 1 kg
    beat_period: z < 1 ? (2 * Math.PI) / Math.abs(r * wn - wd) : null,
  };
}

async function checkReadouts(page, values) {
  const want = expected(values);
  for (const [key, v] of Object.entries(want)) {
    const got = await readout(page, key);
    if (v === null) {
      assert.equal(got, '', `${key} undefined`);
      const text = await page.textContent(`[data-readout="${key}"] dd`);
      assert.equal(text.trim(), '—', `${key} shown as a dash`);
    } else {
      assert.ok(Math.abs(Number(got) - v) <= TOL * Math.max(1, Math.abs(v)), `${key}: got ${got}, want ${v}`);
    }
  }
}

const DEFAULTS = { zeta: 0.1, r: 1, wn: 6, F0: 10 };
const PRESETS = [
  ['resonance', { zeta: 0.05, r: 1 }],
  ['beating', { zeta: 0.01, r: 0.9 }],
  ['no-peak', { zeta: 0.7072, r: 1 }],
  ['quasi-static', { zeta: 0.1, r: 0.2 }],
  ['isolation', { zeta: 0.1, r: 3 }],
];

for (const [name, preset] of PRESETS) {
  test(`preset ${name} opens from the URL with closed-form readouts and drawn plots`, async () => {
    const values = { ...DEFAULTS, ...preset };
    const query = Object.entries(preset).map(([k, v]) => `${k}=${v}`).join('&');
    const { page, errors, context } = await open(browser, `${server.url}?demo=resonance&${query}`);
    await checkReadouts(page, values);
    for (const plot of ['magnitude', 'phase', 'time', 'schematic']) {
      const [ink] = await canvasFingerprint(page, plot);
      assert.ok(ink > 2000, `${plot} has ink (${ink} px)`);
    }
    // The text alternatives follow the physics of the preset.
    const time = await page.textContent('#desc-time');
    assert.match(time, /steady amplitude/);
    if (name === 'resonance') assert.match(time, /builds up/);
    if (name === 'beating') assert.match(time, /beat with period/);
    const magnitude = await page.textContent('#desc-magnitude');
    assert.match(magnitude, name === 'no-peak' ? /no resonant peak/ : /resonant peak .* at r = /);
    await page.screenshot({ path: `${SHOTS}resonance-${name}-1280.png`, fullPage: true });
    assert.deepEqual(errors, []);
    await context.close();
  });
}

test('the preset buttons set the values they name', async () => {
  const { page, errors, context } = await open(browser, `${server.url}?demo=resonance`);
  await page.getByRole('button', { name: 'Beating near resonance, r = 0.9' }).click();
  await waitForUrlParam(page, 'zeta', '0.01');
  await checkReadouts(page, { ...DEFAULTS, zeta: 0.01, r: 0.9 });
  assert.deepEqual(errors, []);
  await context.close();
});

// Each slider: the readouts it drives and the plot whose pixels must change.
const SLIDERS = [
  ['zeta', ['Q', 'peak_gain', 'gain_at_r'], 'magnitude'],
  ['r', ['gain_at_r', 'phase_at_r', 'amplitude'], 'magnitude'],
  ['wn', ['amplitude', 'beat_period'], 'time'],
  ['F0', ['amplitude'], 'time'],
];

for (const [key, readouts, plot] of SLIDERS) {
  test(`the keyboard moves ${key}; readouts, URL and pixels follow`, async () => {
    const { page, errors, context } = await open(browser, `${server.url}?demo=resonance&r=0.95`);
    const before = {};
    for (const k of readouts) before[k] = await readout(page, k);
    const pixels = await canvasFingerprint(page, plot);
    await page.focus(`#p-${key}`);
    await page.keyboard.press('ArrowRight');
    await page.keyboard.press('PageUp');
    await page.waitForFunction(
      ([k, v]) => document.querySelector(`[data-readout="${k}"]`).dataset.value !== v,
      [readouts[0], before[readouts[0]]],
    );
    for (const k of readouts) assert.notEqual(await readout(page, k), before[k], `${k} changed`);
    // The new value, read back exactly from the URL, gives the same closed-form readouts.
    const start = String({ ...DEFAULTS, r: 0.95 }[key]);
    await page.waitForFunction(
      ([k, v]) => {
        const got = new URLSearchParams(location.search).get(k);
        return got !== null && got !== v;
      },
      [key, start],
    );
    const values = await page.evaluate((keys) => {
      const q = new URLSearchParams(location.search);
      return Object.fromEntries(keys.map((k) => [k, Number(q.get(k))]));
    }, Object.keys(DEFAULTS));
    await checkReadouts(page, values);
    assert.notDeepEqual(await canvasFingerprint(page, plot), pixels, `${plot} redrawn`);
    assert.deepEqual(errors, []);
    await context.close();
  });
}

test('the magnitude view switches between linear and dB', async () => {
  const { page, errors, context } = await open(browser, `${server.url}?demo=resonance&zeta=0.05`);
  const linear = await canvasFingerprint(page, 'magnitude');
  const q = await readout(page, 'Q');
  await page.selectOption('#p-view', '1');
  await waitForUrlParam(page, 'view', '1');
  await page.waitForFunction(() => /dB/.test(document.querySelector('figure:has(canvas[data-plot="magnitude"])').textContent));
  assert.notDeepEqual(await canvasFingerprint(page, 'magnitude'), linear);
  assert.equal(await readout(page, 'Q'), q, 'the view changes no readout');
  await page.screenshot({ path: `${SHOTS}resonance-db-1280.png`, fullPage: true });
  // And by URL key.
  const again = await open(browser, `${server.url}?demo=resonance&zeta=0.05&view=db`);
  assert.equal(await again.page.inputValue('#p-view'), '1');
  assert.deepEqual(again.errors, []);
  await again.context.close();
  assert.deepEqual(errors, []);
  await context.close();
});

test('undefined readouts show a dash, never NaN, at the ends of every range', async () => {
  const { page, errors, context } = await open(browser, `${server.url}?demo=resonance&zeta=2&r=10&wn=20&F0=100`);
  await checkReadouts(page, { zeta: 2, r: 10, wn: 20, F0: 100 });
  const all = await page.$$eval('[data-readout]', (els) => els.map((e) => e.dataset.value + e.textContent));
  assert.ok(all.every((s) => !/NaN|Infinity/.test(s)), all.join(' | '));
  const low = await open(browser, `${server.url}?demo=resonance&zeta=0.01&r=0.1&wn=0.5&F0=0.1`);
  await checkReadouts(low.page, { zeta: 0.01, r: 0.1, wn: 0.5, F0: 0.1 });
  assert.deepEqual(low.errors, []);
  await low.context.close();
  assert.deepEqual(errors, []);
  await context.close();
});

test('a phone-sized screen shows the whole demo', async () => {
  const { page, errors, context } = await open(browser, `${server.url}?demo=resonance&zeta=0.05`, {
    viewport: { width: 360, height: 740 },
  });
  const [ink] = await canvasFingerprint(page, 'magnitude');
  assert.ok(ink > 1000);
  // Nothing of the demo sticks out sideways (the equation and the table scroll in their own boxes).
  const overflow = await page.evaluate(() => {
    let worst = 0;
    for (const e of document.querySelectorAll('#demo *')) {
      if (e.closest('.equation, .table-wrap')) continue;
      worst = Math.max(worst, e.getBoundingClientRect().right - window.innerWidth);
    }
    return worst;
  });
  assert.ok(overflow <= 0.5, `nothing wider than the screen (${overflow} px)`);
  await page.screenshot({ path: `${SHOTS}resonance-360.png`, fullPage: true });
  assert.deepEqual(errors, []);
  await context.close();
});
