// End to end: the nonlinear quarter-car demo in headless Chromium. The nonlinear run is RK4
// in Rust; here it is checked against independent bounds (closed-form linear periods, the
// Duffing amplitude–frequency estimate, friction's holding band, an energy bound for the
// bump stops).
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

const PLOTS = ['response', 'phase', 'spring', 'damper'];
const BASE = { m: 300, k: 24000, k3: 0, c_comp: 500, c_reb: 500, friction: 0, gap: 0.06, k_stop: 0, x0: 0.08, v0: 0 };
const PRESETS = {
  linear: {},
  hardening: { k3: 3e6, c_comp: 150, c_reb: 150 },
  softening: { k3: -2e6, c_comp: 150, c_reb: 150 },
  friction: { friction: 300, c_comp: 50, c_reb: 50 },
  'bump-stop': { k_stop: 300000, gap: 0.05, x0: 0, v0: 1.5 },
  asymmetric: { c_comp: 300, c_reb: 1500 },
};

const query = (p) => `demo=nonlinear&${Object.entries(p).map(([k, v]) => `${k}=${v}`).join('&')}`;
const num = async (page, key) => Number(await readout(page, key));

/** Damped period 2π/ω_d of the linear model m·x'' + c̄·x' + k·x = 0 (c̄ the mean rate). */
function linearPeriod(p) {
  const c = (p.c_comp + p.c_reb) / 2;
  const wn = Math.sqrt(p.k / p.m);
  const zeta = c / (2 * Math.sqrt(p.m * p.k));
  return (2 * Math.PI) / (wn * Math.sqrt(1 - zeta * zeta));
}

/** Checks per preset, with the reasoning for each bound. */
const CHECKS = {
  linear: async (page, p) => {
    assert.equal(await readout(page, 'effect'), 'linear');
    // Same model both ways: RK4 with ~700 steps per period matches the closed form.
    assert.ok(Math.abs((await num(page, 'period_ratio')) - 1) < 1e-6);
    assert.ok((await num(page, 'max_deviation')) < 1e-6);
  },
  hardening: async (page, p) => {
    assert.equal(await readout(page, 'effect'), 'hardening spring');
    // Duffing: ω² ≈ ωₙ²(1 + 3k₃A²/4k) at amplitude A, so the period lies between the
    // estimate at the starting amplitude and the small-amplitude (linear) period.
    const duffing = 1 / Math.sqrt(1 + (3 * p.k3 * p.x0 ** 2) / (4 * p.k));
    const r = await num(page, 'period_ratio');
    assert.ok(r > duffing && r < 1, `ratio ${r}, Duffing bound ${duffing}`);
  },
  softening: async (page, p) => {
    assert.equal(await readout(page, 'effect'), 'softening spring');
    const duffing = 1 / Math.sqrt(1 + (3 * p.k3 * p.x0 ** 2) / (4 * p.k));
    const r = await num(page, 'period_ratio');
    assert.ok(r > 1 && r < duffing, `ratio ${r}, Duffing bound ${duffing}`);
  },
  friction: async (page, p) => {
    assert.equal(await readout(page, 'effect'), 'stick-slip');
    // The mass can only stay put where the spring cannot overcome friction: |k·x| ≤ F_c.
    const x = await num(page, 'stick_position');
    assert.ok(Math.abs(x) <= p.friction / p.k + 1e-9, `sticks at ${x}`);
    assert.ok(Math.abs(x) > 1e-4, 'off-centre, not at equilibrium');
  },
  'bump-stop': async (page, p) => {
    assert.equal(await readout(page, 'effect'), 'bump-stop impact');
    // Energy: ½k·x² + ½k_stop·(x − gap)² ≤ ½m·v0² at the largest travel (damping only lowers it).
    const a = p.k + p.k_stop;
    const b = p.k_stop * p.gap;
    const xMax = (b + Math.sqrt(b * b - a * (p.k_stop * p.gap ** 2 - p.m * p.v0 ** 2))) / a;
    const travel = await num(page, 'max_travel');
    assert.ok(travel > p.gap && travel < xMax, `travel ${travel}, gap ${p.gap}, energy bound ${xMax}`);
    assert.ok((await num(page, 'period_ratio')) < 1, 'the stops stiffen the swing');
  },
  asymmetric: async (page, p) => {
    assert.equal(await readout(page, 'effect'), 'asymmetric damper');
    assert.ok(Math.abs((await num(page, 'period_ratio')) - 1) < 0.03);
    assert.ok((await num(page, 'max_deviation')) > 1e-3);
  },
};

for (const [name, changes] of Object.entries(PRESETS)) {
  test(`preset ${name}: readouts within independent bounds, plots drawn, row highlighted`, async () => {
    const p = { ...BASE, ...changes };
    const { page, errors, context } = await open(browser, `${server.url}?${query(p)}`);
    await CHECKS[name](page, p);
    // The linear period is the closed form in every case (zero crossings interpolated on
    // a fine grid: relative error far below 1e-4).
    const tLin = await num(page, 'period_linear');
    assert.ok(Math.abs(tLin - linearPeriod(p)) < 1e-4 * linearPeriod(p), `T_lin ${tLin}`);
    const effect = await readout(page, 'effect');
    assert.equal(await page.getAttribute(`tr[data-row="${effect}"]`, 'aria-current'), 'true');
    for (const key of PLOTS) {
      const [ink] = await canvasFingerprint(page, key);
      assert.ok(ink > 2000, `${key} has ink (${ink} px)`);
    }
    assert.ok((await canvasFingerprint(page, 'schematic'))[0] > 500, 'schematic drawn');
    await page.screenshot({ path: `${SHOTS}nonlinear-${name}-1280.png`, fullPage: true });
    assert.deepEqual(errors, []);
    await context.close();
  });
}

test('a narrow phone screen still shows every plot', async () => {
  const p = { ...BASE, ...PRESETS['bump-stop'] };
  const { page, errors, context } = await open(browser, `${server.url}?${query(p)}`, {
    viewport: { width: 360, height: 740 },
  });
  for (const key of PLOTS) {
    const [ink] = await canvasFingerprint(page, key);
    assert.ok(ink > 1000, `${key} has ink (${ink} px)`);
  }
  await page.screenshot({ path: `${SHOTS}nonlinear-360.png`, fullPage: true });
  await page.locator('.plots').screenshot({ path: `${SHOTS}nonlinear-360-plots.png` });
  assert.deepEqual(errors, []);
  await context.close();
});

test('every slider moves readouts and pixels by the keyboard', async () => {
  const p = { ...BASE, ...PRESETS.hardening };
  const { page, errors, context } = await open(browser, `${server.url}?${query(p)}`);
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
    const old = await readout(page, watch);
    await page.focus(`#p-${key}`);
    await page.keyboard.press('ArrowRight');
    await page.waitForFunction(
      ([k, v]) => document.querySelector(`[data-readout="${k}"]`).dataset.value !== v,
      [watch, old],
    );
    p[key] = Number(await page.inputValue(`#p-${key}`));
    const after = await Promise.all(PLOTS.map((k) => canvasFingerprint(page, k)));
    assert.notDeepEqual(after, before, `${key} changes the plots`);
    const tLin = await num(page, 'period_linear');
    assert.ok(Math.abs(tLin - linearPeriod(p)) < 1e-4 * linearPeriod(p), `T_lin after ${key}: ${tLin}`);
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
  const p = { ...BASE, k: 5000, k3: -4e6, x0: 0.15, v0: 2, c_comp: 0, c_reb: 0 };
  const { page, errors, context } = await open(browser, `${server.url}?${query(p)}`);
  assert.equal(await readout(page, 'effect'), 'escaped');
  assert.match(await page.textContent('#desc-response'), /leaves the plot/);
  assert.deepEqual(errors, []);
  await context.close();
});
