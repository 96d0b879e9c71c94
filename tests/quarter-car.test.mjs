// End to end: the quarter-car demo in headless Chromium, driven through the URL contract
// and the keyboard. Expected values are computed here from closed forms (test-only maths).
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { serve } from './support/server.mjs';
import { launch, open, readout, canvasFingerprint, waitForReadout, SHOTS } from './support/browser.mjs';

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

const M = 300;
const K = 24000;
const CRIT = 2 * Math.sqrt(K * M); // critical damping [N·s/m]
const PRESETS = [
  ['comfort-0.3', 0.3],
  ['comfort-0.4', 0.4],
  ['performance-0.65', 0.65],
  ['performance-0.7', 0.7],
  ['critical', 1],
  ['overdamped', 2],
];
const PLOTS = ['response', 'settling', 'sensitivity'];

async function num(page, key) {
  const v = await readout(page, key);
  return v === '' || v === null ? NaN : Number(v);
}

/** Waits until readout `key` differs from `old` (a data-value string). */
async function waitForChange(page, key, old) {
  await page.waitForFunction(
    ([k, o]) => document.querySelector(`[data-readout="${k}"]`).dataset.value !== o,
    [key, old],
  );
}

/** x(t) of m·x'' + c·x' + k·x = 0 from x(0) = x0, x'(0) = 0 (closed form, any regime). */
function displacement(m, c, k, x0, t) {
  const a = c / (2 * m);
  const w2 = k / m;
  const d = a * a - w2;
  const e = Math.exp(-a * t);
  if (Math.abs(d) < 1e-12 * w2) return x0 * e * (1 + a * t);
  if (d < 0) {
    const wd = Math.sqrt(-d);
    return x0 * e * (Math.cos(wd * t) + (a / wd) * Math.sin(wd * t));
  }
  const mu = Math.sqrt(d);
  return x0 * e * (Math.cosh(mu * t) + (a / mu) * Math.sinh(mu * t));
}

const rel = (a, b) => Math.abs(a - b) / Math.max(1, Math.abs(b));

for (const [name, zeta] of PRESETS) {
  test(`preset ${name} from the URL: readouts match closed forms`, async () => {
    const c = zeta * CRIT;
    const x0 = 0.06;
    const url = `${server.url}?demo=quarter-car&m=${M}&k=${K}&x0=${x0}&zeta=${zeta}&c=${c}`;
    const { page, errors, context } = await open(browser, url);
    const wn = Math.sqrt(K / M);
    // Tolerances: 1e-12 relative for direct formulas (the solver rounds differently).
    assert.ok(rel(await num(page, 'wn'), wn) < 1e-12);
    assert.ok(rel(await num(page, 'fn'), wn / (2 * Math.PI)) < 1e-12);
    assert.ok(rel(await num(page, 'zeta'), zeta) < 1e-12);
    assert.ok(rel(await num(page, 'c'), c) < 1e-12);
    assert.ok(rel(await num(page, 'c_crit'), CRIT) < 1e-12);
    const regime = await readout(page, 'regime');
    if (zeta < 1) {
      assert.equal(regime, 'underdamped');
      const wd = wn * Math.sqrt(1 - zeta * zeta);
      assert.ok(rel(await num(page, 'wd'), wd) < 1e-12);
      // Release from rest: rebound e^{−πζ/√(1−ζ²)} at t = π/ω_d.
      const rebound = 100 * Math.exp((-Math.PI * zeta) / Math.sqrt(1 - zeta * zeta));
      assert.ok(rel(await num(page, 'overshoot'), rebound) < 1e-9, 'overshoot');
      assert.ok(rel(await num(page, 'peak_time'), Math.PI / wd) < 1e-9, 'peak time');
    } else {
      assert.equal(regime, zeta === 1 ? 'critically damped' : 'overdamped');
      assert.equal(await readout(page, 'wd'), '');
      assert.equal(await num(page, 'overshoot'), 0);
      assert.equal(await readout(page, 'peak_time'), '');
    }
    // Settling: on the band edge at t_s, and inside the band for 4 s after it (1 ms steps).
    const ts = await num(page, 'settling_time');
    const h = 0.05 * x0;
    assert.ok(Math.abs(Math.abs(displacement(M, c, K, x0, ts)) - h) < 1e-9 * x0, `x(t_s) on the band, t_s ${ts}`);
    for (let t = ts + 1e-3; t < ts + 4; t += 1e-3) {
      assert.ok(Math.abs(displacement(M, c, K, x0, t)) <= h * (1 + 1e-9), `inside after t_s (t = ${t})`);
    }
    // Fastest ζ for a release from rest into ±5 %: ln 20 / √(π² + ln² 20) (to 1e-6).
    const l = Math.log(20);
    assert.ok(Math.abs((await num(page, 'zeta_argmin')) - l / Math.sqrt(Math.PI ** 2 + l * l)) < 1e-6);
    assert.ok((await num(page, 'settling_min')) <= ts + 1e-12, 'no design settles faster than the optimum');
    // ±10 % mass: ζ ∝ m^−½.
    assert.ok(rel(await num(page, 'zeta_lo'), zeta / Math.sqrt(1.1)) < 1e-12);
    assert.ok(rel(await num(page, 'zeta_hi'), zeta / Math.sqrt(0.9)) < 1e-12);
    for (const plot of PLOTS) {
      const [ink] = await canvasFingerprint(page, plot);
      assert.ok(ink > 2000, `${plot} has ink (${ink} px)`);
    }
    const schematic = await page.locator('canvas').count();
    assert.ok(schematic >= 4, 'three plots and the schematic');
    await page.screenshot({ path: `${SHOTS}quarter-car-${name}-1280.png`, fullPage: true });
    assert.deepEqual(errors, []);
    await context.close();
  });
}

test('the preset buttons set c and ζ together', async () => {
  const { page, errors, context } = await open(browser, `${server.url}?demo=quarter-car`);
  await page.getByRole('button', { name: 'Performance ζ = 0.7' }).click();
  await waitForReadout(page, 'zeta', 0.7);
  assert.ok(rel(await num(page, 'c'), 0.7 * CRIT) < 1e-12);
  assert.equal(Number(await page.inputValue('input[type=number][data-key="zeta"]')), 0.7);
  await page.getByRole('button', { name: 'Overdamped ζ = 2' }).click();
  await waitForReadout(page, 'zeta', 2);
  assert.equal(await readout(page, 'regime'), 'overdamped');
  assert.deepEqual(errors, []);
  await context.close();
});

test('URL: c wins over ζ when both are given; ζ alone is used', async () => {
  let { page, errors, context } = await open(browser, `${server.url}?demo=quarter-car&zeta=0.9&c=3000`);
  assert.equal(await num(page, 'c'), 3000);
  assert.ok(rel(await num(page, 'zeta'), 3000 / CRIT) < 1e-12);
  assert.deepEqual(errors, []);
  await context.close();
  ({ page, errors, context } = await open(browser, `${server.url}?demo=quarter-car&zeta=0.9`));
  assert.ok(rel(await num(page, 'zeta'), 0.9) < 1e-12);
  assert.ok(rel(await num(page, 'c'), 0.9 * CRIT) < 1e-12);
  assert.deepEqual(errors, []);
  await context.close();
});

// Each slider: the readouts it drives, and the plots whose pixels must change.
const SLIDERS = [
  ['m', ['wn', 'zeta', 'zeta_lo'], PLOTS],
  ['k', ['wn', 'zeta'], PLOTS],
  ['c', ['zeta', 'settling_time'], ['response', 'settling', 'sensitivity']],
  ['zeta', ['c', 'settling_time'], ['response', 'settling', 'sensitivity']],
  ['x0', [], ['response']], // metrics are relative to x₀: only the curves scale
  ['band', ['settling_time', 'zeta_argmin'], ['response', 'settling']],
  ['dm', ['zeta_lo', 'zeta_hi'], ['sensitivity']],
];

for (const [key, readouts, plots] of SLIDERS) {
  test(`the keyboard moves ${key}; readouts and pixels follow`, async () => {
    const query = `m=${M}&k=${K}&x0=0.06&zeta=0.3&c=${0.3 * CRIT}`;
    const { page, errors, context } = await open(browser, `${server.url}?demo=quarter-car&${query}`);
    const before = {};
    for (const r of ['wn', 'zeta', 'c', 'settling_time', 'zeta_argmin', 'zeta_lo', 'zeta_hi', 'overshoot']) {
      before[r] = await readout(page, r);
    }
    const pixels = {};
    for (const p of plots) pixels[p] = await canvasFingerprint(page, p);
    await page.focus(`#p-${key}`);
    await page.keyboard.press('PageUp');
    await page.keyboard.press('ArrowRight');
    if (readouts.length) {
      for (const r of readouts) await waitForChange(page, r, before[r]);
    } else {
      await page.waitForFunction(() => Number(new URLSearchParams(location.search).get('x0')) > 0.06);
      await page.waitForTimeout(100);
      for (const r of ['overshoot', 'settling_time']) assert.equal(await readout(page, r), before[r], `${r} is relative to x0`);
    }
    for (const p of plots) {
      assert.notDeepEqual(await canvasFingerprint(page, p), pixels[p], `${p} redrawn after moving ${key}`);
    }
    // The two views of the damper stay consistent: ζ = c / (2√(km)).
    const [m, k, c, z] = [Number(await page.inputValue('input[type=number][data-key="m"]')),
      Number(await page.inputValue('input[type=number][data-key="k"]')), await num(page, 'c'), await num(page, 'zeta')];
    assert.ok(rel(z, c / (2 * Math.sqrt(k * m))) < 1e-12, `ζ ${z} vs c ${c}`);
    assert.deepEqual(errors, []);
    await context.close();
  });
}

test('moving ζ sets the damper, then moving m keeps the damper', async () => {
  const { page, errors, context } = await open(browser, `${server.url}?demo=quarter-car&m=${M}&k=${K}&zeta=0.3&c=${0.3 * CRIT}`);
  await page.focus('#p-zeta');
  for (let i = 0; i < 4; i++) await page.keyboard.press('ArrowRight');
  await waitForReadout(page, 'zeta', 0.34);
  assert.ok(rel(await num(page, 'c'), 0.34 * CRIT) < 1e-12);
  await page.focus('#p-m');
  await page.keyboard.press('ArrowRight');
  await waitForReadout(page, 'zeta', (0.34 * CRIT) / (2 * Math.sqrt(K * 301)));
  assert.ok(rel(await num(page, 'c'), 0.34 * CRIT) < 1e-12, 'the damper is unchanged');
  assert.deepEqual(errors, []);
  await context.close();
});

test('undamped and extreme settings keep a working page', async () => {
  const { page, errors, context } = await open(browser, `${server.url}?demo=quarter-car&c=0`);
  assert.equal(await readout(page, 'regime'), 'undamped');
  assert.equal(await readout(page, 'settling_time'), '');
  assert.match(await page.textContent('body'), /oscillates forever/);
  await page.focus('#p-c');
  await page.keyboard.press('End');
  await waitForReadout(page, 'c', 20000);
  await page.focus('#p-m');
  await page.keyboard.press('Home');
  await page.focus('#p-k');
  await page.keyboard.press('Home');
  await waitForReadout(page, 'zeta', 20000 / (2 * Math.sqrt(100 * 5000)));
  for (const plot of PLOTS) assert.ok((await canvasFingerprint(page, plot))[0] > 1000);
  assert.deepEqual(errors, []);
  await context.close();
});

test('narrow screen (360 × 740)', async () => {
  const { page, errors, context } = await open(browser, `${server.url}?demo=quarter-car`, {
    viewport: { width: 360, height: 740 },
  });
  for (const plot of PLOTS) assert.ok((await canvasFingerprint(page, plot))[0] > 1000);
  const overflow = await page.evaluate(() => document.documentElement.scrollWidth - document.documentElement.clientWidth);
  assert.ok(overflow <= 0, `no horizontal scroll (${overflow} px)`);
  await page.screenshot({ path: `${SHOTS}quarter-car-360.png`, fullPage: true });
  assert.deepEqual(errors, []);
  await context.close();
});
