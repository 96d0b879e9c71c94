// End to end: the two-degree-of-freedom quarter car in headless Chromium. Natural
// frequencies, static deflection, frequency responses and the random road's RMS height are
// recomputed here from their closed forms; the RK4 runs are checked through linearity.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { serve } from './support/server.mjs';
import { launch, open, readout, canvasFingerprint, SHOTS } from './support/browser.mjs';

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

const PLOTS = ['motion', 'accel', 'frf', 'tyre'];
const CAR = { ms: 300, mu: 40, ks: 24000, kt: 200000, cs: 1500 };
const PRESETS = {
  bump: { road: 'bump', h: 0.05, L: 0.5, V: 10 },
  step: { road: 'step', h: 0.05 },
  'sine-body': { road: 'sine', h: 0.02, f_road: 1.25 },
  'sine-wheel': { road: 'sine', h: 0.005, f_road: 11.5 },
  'random-C': { road: 'random', class: 'C', V: 20, seed: 1 },
  'random-D-soft': { road: 'random', class: 'D', V: 20, cs: 500, seed: 1 },
};

const query = (p) => `demo=quarter-car-2dof&${Object.entries(p).map(([k, v]) => `${k}=${v}`).join('&')}`;
const num = async (page, key) => Number(await readout(page, key));
const close = (a, b, rel) => Math.abs(a - b) <= rel * Math.abs(b);

/** Undamped natural frequencies [Hz]: roots of m_s·m_u·λ² − (k_s·m_u + (k_s + k_t)·m_s)·λ + k_s·k_t. */
function naturalHz(p) {
  const a = p.ms * p.mu;
  const b = p.ks * p.mu + (p.ks + p.kt) * p.ms;
  const c = p.ks * p.kt;
  const d = Math.sqrt(b * b - 4 * a * c);
  return [(b - d) / (2 * a), (b + d) / (2 * a)].map((l) => Math.sqrt(l) / (2 * Math.PI));
}

/** |Z_s/U| and |(Z_u − U)/U| at f [Hz] from the 2×2 complex system (tyre undamped). */
function frf(p, f) {
  const w = 2 * Math.PI * f;
  const mul = ([a, b], [c, d]) => [a * c - b * d, a * d + b * c];
  const div = ([a, b], [c, d]) => { const q = c * c + d * d; return [(a * c + b * d) / q, (b * c - a * d) / q]; };
  const s = [p.ks, w * p.cs];
  const t = [p.kt, 0];
  const a11 = [s[0] - w * w * p.ms, s[1]];
  const a22 = [s[0] + t[0] - w * w * p.mu, s[1]];
  const ss = mul(s, s);
  const a = mul(a11, a22);
  const det = [a[0] - ss[0], a[1] - ss[1]];
  const zs = div(mul(s, t), det);
  const zu = div(mul(a11, t), det);
  return { body: Math.hypot(...zs), tyre: Math.hypot(zu[0] - 1, zu[1]) };
}

/** RMS height of the 64-term ISO 8608 road over the demo's band (midpoint rule of ∫G_d dn). */
function roadRms(cls, V) {
  const g0 = 16e-6 * 4 ** 'ABCDEFGH'.indexOf(cls);
  const nMin = Math.min(Math.max(0.5 / V, 0.011), 1);
  const nMax = Math.min(Math.max(20 / V, 2 * nMin), 2.83);
  const dn = (nMax - nMin) / 64;
  let v = 0;
  for (let i = 0; i < 64; i++) {
    const n = nMin + (i + 0.5) * dn;
    v += g0 * (0.1 / n) ** 2 * dn;
  }
  return Math.sqrt(v);
}

async function checkCommon(page, p) {
  const [fb, fw] = naturalHz(p);
  assert.ok(close(await num(page, 'f_body'), fb, 1e-12), 'f_body');
  assert.ok(close(await num(page, 'f_wheel'), fw, 1e-12), 'f_wheel');
  assert.ok(close(await num(page, 'static_tyre_deflection'), ((p.ms + p.mu) * 9.80665) / p.kt, 1e-12));
  assert.ok((await num(page, 'rms_body_accel')) > 0);
  assert.ok((await num(page, 'rms_tyre_deflection')) > 0);
}

for (const [name, changes] of Object.entries(PRESETS)) {
  test(`preset ${name}: closed-form readouts, all plots drawn`, async () => {
    const p = { ...CAR, ...changes };
    const { page, errors, context } = await open(browser, `${server.url}?${query(p)}`);
    await checkCommon(page, p);
    if (p.road === 'sine') {
      const g = frf(p, p.f_road);
      assert.ok(close(await num(page, 'body_gain'), g.body, 1e-9), 'body_gain');
      assert.ok(close(await num(page, 'tyre_gain'), g.tyre, 1e-9), 'tyre_gain');
    } else {
      assert.equal(await readout(page, 'body_gain'), '');
    }
    if (p.road === 'random') {
      assert.ok(close(await num(page, 'rms_road'), roadRms(p.class, p.V), 1e-9), 'rms_road');
    } else {
      assert.equal(await readout(page, 'rms_road'), '');
    }
    for (const key of PLOTS) {
      const [ink] = await canvasFingerprint(page, key);
      assert.ok(ink > 2000, `${key} has ink (${ink} px)`);
    }
    assert.ok((await canvasFingerprint(page, 'schematic'))[0] > 500, 'schematic drawn');
    await page.screenshot({ path: `${SHOTS}quarter-car-2dof-${name}-1280.png`, fullPage: true });
    assert.deepEqual(errors, []);
    await context.close();
  });
}

test('the body bounce and wheel hop resonances are where the FRF says', async () => {
  // Near body bounce the body moves more than the road; near wheel hop it barely moves but
  // the tyre deflection is large.
  const p = { ...CAR, road: 'sine', h: 0.01 };
  const [fb, fw] = naturalHz(p);
  const { page, errors, context } = await open(browser, `${server.url}?${query({ ...p, f_road: fb.toFixed(2) })}`);
  assert.ok((await num(page, 'body_gain')) > 1.5);
  await context.close();
  const second = await open(browser, `${server.url}?${query({ ...p, f_road: fw.toFixed(2) })}`);
  assert.ok((await num(second.page, 'body_gain')) < 0.2);
  assert.ok((await num(second.page, 'tyre_gain')) > 1);
  assert.deepEqual([...errors, ...second.errors], []);
  await second.context.close();
});

test('a road class rougher by one doubles every RMS response (linearity)', async () => {
  const p = { ...CAR, road: 'random', class: 'C', V: 20, seed: 3 };
  const { page, errors, context } = await open(browser, `${server.url}?${query(p)}`);
  const acc = await num(page, 'rms_body_accel');
  const tyre = await num(page, 'rms_tyre_deflection');
  const before = await Promise.all(PLOTS.map((k) => canvasFingerprint(page, k)));
  await page.selectOption('#p-class', '3'); // D
  await page.waitForFunction((v) => document.querySelector('[data-readout="rms_body_accel"]').dataset.value !== v, String(acc));
  assert.ok(close(await num(page, 'rms_body_accel'), 2 * acc, 1e-6));
  assert.ok(close(await num(page, 'rms_tyre_deflection'), 2 * tyre, 1e-6));
  assert.ok(close(await num(page, 'rms_road'), roadRms('D', 20), 1e-9));
  const after = await Promise.all(PLOTS.map((k) => canvasFingerprint(page, k)));
  assert.notDeepEqual(after.slice(0, 2), before.slice(0, 2), 'time plots change');
  assert.deepEqual(errors, []);
  await context.close();
});

test('a narrow phone screen still shows every plot', async () => {
  const p = { ...CAR, ...PRESETS.bump };
  const { page, errors, context } = await open(browser, `${server.url}?${query(p)}`, {
    viewport: { width: 360, height: 740 },
  });
  for (const key of PLOTS) {
    const [ink] = await canvasFingerprint(page, key);
    assert.ok(ink > 1000, `${key} has ink (${ink} px)`);
  }
  await page.screenshot({ path: `${SHOTS}quarter-car-2dof-360.png`, fullPage: true });
  await page.locator('.plots').screenshot({ path: `${SHOTS}quarter-car-2dof-360-plots.png` });
  assert.deepEqual(errors, []);
  await context.close();
});

/** ArrowRight on a slider; waits for readout `watch` to change; returns the new value. */
async function nudge(page, key, watch) {
  const old = await readout(page, watch);
  await page.focus(`#p-${key}`);
  await page.keyboard.press('ArrowRight');
  await page.waitForFunction(
    ([k, v]) => document.querySelector(`[data-readout="${k}"]`).dataset.value !== v,
    [watch, old],
  );
  return Number(await page.inputValue(`input[type=number][data-key="${key}"]`));
}

test('every slider and choice moves readouts and pixels', async () => {
  const p = { ...CAR, ...PRESETS.bump };
  const { page, errors, context } = await open(browser, `${server.url}?${query(p)}`);
  const steps = [
    ['ms', 'f_body'],
    ['mu', 'f_wheel'],
    ['ks', 'f_body'],
    ['kt', 'f_wheel'],
    ['cs', 'rms_body_accel'],
    ['h', 'rms_body_accel'],
    ['L', 'rms_body_accel'],
    ['V', 'rms_body_accel'],
  ];
  for (const [key, watch] of steps) {
    const before = await Promise.all(PLOTS.map((k) => canvasFingerprint(page, k)));
    p[key] = await nudge(page, key, watch);
    const after = await Promise.all(PLOTS.map((k) => canvasFingerprint(page, k)));
    assert.notDeepEqual(after, before, `${key} changes the plots`);
    await checkCommon(page, p);
  }
  // Road choice: sine, then its frequency slider (logarithmic).
  await page.selectOption('#p-road', '2');
  await page.waitForFunction(() => document.querySelector('[data-readout="body_gain"]').dataset.value !== '');
  const beforeSine = await canvasFingerprint(page, 'frf');
  await nudge(page, 'f_road', 'body_gain');
  // The number box rounds a log slider's value to 4 digits; the URL carries it exactly.
  await page.waitForFunction(() => !['1.2', null].includes(new URLSearchParams(location.search).get('f_road')));
  p.f_road = Number(await page.evaluate(() => new URLSearchParams(location.search).get('f_road')));
  assert.ok(close(await num(page, 'body_gain'), frf(p, p.f_road).body, 1e-9), `body_gain at ${p.f_road} Hz`);
  // One arrow step can move the marker by less than a pixel on a narrow plot: take a big step.
  await page.focus('#p-f_road');
  await page.keyboard.press('PageUp');
  await page.waitForFunction((f) => new URLSearchParams(location.search).get('f_road') !== String(f), p.f_road);
  await page.waitForTimeout(100);
  assert.notDeepEqual(await canvasFingerprint(page, 'frf'), beforeSine, 'the road marker moves');
  p.f_road = Number(await page.evaluate(() => new URLSearchParams(location.search).get('f_road')));
  // Random road: class and seed.
  await page.selectOption('#p-road', '3');
  await page.waitForFunction(() => document.querySelector('[data-readout="rms_road"]').dataset.value !== '');
  assert.ok(close(await num(page, 'rms_road'), roadRms('C', p.V), 1e-9));
  const beforeSeed = await canvasFingerprint(page, 'motion');
  await nudge(page, 'seed', 'rms_body_accel');
  assert.notDeepEqual(await canvasFingerprint(page, 'motion'), beforeSeed, 'a new seed, a new road');
  await page.selectOption('#p-class', '0');
  await page.waitForFunction((v) => Math.abs(Number(document.querySelector('[data-readout="rms_road"]').dataset.value) - v) < 1e-12 * v, roadRms('A', p.V));
  assert.deepEqual(errors, []);
  await context.close();
});

test('the animation scrubber moves the car', async () => {
  const p = { ...CAR, ...PRESETS.bump };
  const { page, errors, context } = await open(browser, `${server.url}?${query(p)}`);
  const before = await canvasFingerprint(page, 'schematic');
  await page.locator('.anim-bar input[type=range]').focus();
  for (let i = 0; i < 30; i++) await page.keyboard.press('ArrowRight');
  await page.waitForFunction(() => document.querySelector('.anim-time').textContent !== 't = 0.00 s');
  assert.notDeepEqual(await canvasFingerprint(page, 'schematic'), before);
  assert.deepEqual(errors, []);
  await context.close();
});
