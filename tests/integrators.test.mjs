// End to end: the integrators demo in headless Chromium. Readouts are checked against an
// independent JavaScript implementation of the exact solution and of forward Euler, Heun
// and RK4 (in this test only), then every slider, toggle and preset is exercised.
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

const PLOTS = ['response', 'error', 'convergence', 'stability'];
const PRESET = 'demo=integrators&zeta=0.05&wn=2&h=0.3';

// ---- Independent reference (underdamped free response, v0 = 0) -------------------------
function exact(zeta, wn, x0, t) {
  const a = zeta * wn;
  const wd = wn * Math.sqrt(1 - zeta * zeta);
  return Math.exp(-a * t) * (x0 * Math.cos(wd * t) + ((a * x0) / wd) * Math.sin(wd * t));
}

const rhs = (zeta, wn) => ([x, v]) => [v, -2 * zeta * wn * v - wn * wn * x];

const STEPPERS = {
  euler: (f, y, h) => {
    const k = f(y);
    return [y[0] + h * k[0], y[1] + h * k[1]];
  },
  heun: (f, y, h) => {
    const k1 = f(y);
    const k2 = f([y[0] + h * k1[0], y[1] + h * k1[1]]);
    return [y[0] + (h / 2) * (k1[0] + k2[0]), y[1] + (h / 2) * (k1[1] + k2[1])];
  },
  rk4: (f, y, h) => {
    const add = (a, b, s) => [a[0] + s * b[0], a[1] + s * b[1]];
    const k1 = f(y);
    const k2 = f(add(y, k1, h / 2));
    const k3 = f(add(y, k2, h / 2));
    const k4 = f(add(y, k3, h));
    return [
      y[0] + (h / 6) * (k1[0] + 2 * k2[0] + 2 * k3[0] + k4[0]),
      y[1] + (h / 6) * (k1[1] + 2 * k2[1] + 2 * k3[1] + k4[1]),
    ];
  },
};

/** max |x_k − x(t_k)| over the grid t_k = k·T/n, n = ⌈T/h⌉. */
function maxError(method, { zeta, wn, x0, T, h }) {
  const n = Math.ceil((T / h) * (1 - 1e-9));
  const dt = T / n;
  const f = rhs(zeta, wn);
  let y = [x0, 0];
  let err = 0;
  for (let k = 1; k <= n; k++) {
    y = STEPPERS[method](f, y, dt);
    err = Math.max(err, Math.abs(y[0] - exact(zeta, wn, x0, k * dt)));
  }
  return { err, dt };
}

/** |R(z)| of a polynomial amplification factor with coefficients c (complex z = [re, im]). */
function ampAbs(coefs, [re, im]) {
  let pr = 0;
  let pi = 0;
  for (let i = coefs.length - 1; i >= 0; i--) {
    const r = pr * re - pi * im + coefs[i];
    pi = pr * im + pi * re;
    pr = r;
  }
  return Math.hypot(pr, pi);
}
const R = { euler: [1, 1], heun: [1, 1, 1 / 2], rk4: [1, 1, 1 / 2, 1 / 6, 1 / 24] };
const hLambda = (zeta, wn, h) => [-zeta * wn * h, wn * Math.sqrt(1 - zeta * zeta) * h];

const num = async (page, key) => Number(await readout(page, key));

async function waitForChange(page, key, old) {
  await page.waitForFunction(
    ([k, v]) => document.querySelector(`[data-readout="${k}"]`).dataset.value !== v,
    [key, old],
  );
}

async function assertInk(page) {
  for (const plot of PLOTS) {
    const [ink] = await canvasFingerprint(page, plot);
    assert.ok(ink > 3000, `${plot} has ink (${ink} px)`);
  }
}

test('preset ζ = 0.05, ωn = 2, h = 0.3 s: stability, errors and orders', async () => {
  const { page, errors, context } = await open(browser, `${server.url}?${PRESET}`);
  const p = { zeta: 0.05, wn: 2, x0: 1, T: 20, h: 0.3 };
  // The step actually used: 67 steps of 20/67 s.
  const hUsed = await num(page, 'h_used');
  assert.ok(Math.abs(hUsed - 20 / 67) < 1e-15, `h_used ${hUsed}`);

  // Stability: Euler needs h ≤ 2ζ/ωn = 0.05 s (|1 + hλ|² ≤ 1 ⇔ h ≤ −2Re λ/|λ|²), so it
  // is unstable here; RK4's |R(hλ)| < 1.
  assert.equal(await readout(page, 'stable_euler'), 'no');
  assert.equal(await readout(page, 'stable_rk4'), 'yes');
  assert.equal(await readout(page, 'stable_heun'), 'yes');
  assert.equal(await readout(page, 'stable_symplectic_euler'), 'yes');
  const z = hLambda(p.zeta, p.wn, hUsed);
  for (const m of ['euler', 'heun', 'rk4']) {
    const g = await num(page, `growth_${m}`);
    const want = ampAbs(R[m], z);
    assert.ok(Math.abs(g - want) < 1e-12, `growth_${m} ${g} vs ${want}`);
  }
  assert.ok((await num(page, 'growth_euler')) > 1.1, 'Euler grows ≈ ×1.14 per step');
  assert.ok((await num(page, 'growth_rk4')) < 1);

  // Max errors against an independent JS run (relative 1e-9: same arithmetic, different
  // evaluation order).
  const errs = {};
  for (const m of ['euler', 'heun', 'rk4']) {
    errs[m] = await num(page, `max_err_${m}`);
    const { err } = maxError(m, p);
    assert.ok(Math.abs(errs[m] - err) <= 1e-9 * err, `max_err_${m} ${errs[m]} vs JS ${err}`);
  }
  assert.ok(errs.rk4 < errs.heun && errs.heun < errs.euler, JSON.stringify(errs));
  assert.ok(errs.euler > 1000, 'forward Euler has diverged to kilometres');
  const dp = await num(page, 'max_err_dp45');
  assert.ok(dp > 0 && dp < 1e-4, `DP45 within its tolerance scale: ${dp}`);
  const steps = await num(page, 'steps_dp45');
  assert.ok(Number.isInteger(steps) && steps > 10 && steps < 1000, `steps_dp45 ${steps}`);

  // Fitted orders (ranges): Euler and symplectic Euler 0.8–1.3, Heun 1.7–2.3, RK4 3.6–4.4,
  // DP45 against its mean step 4–6.5.
  const ranges = {
    order_euler: [0.8, 1.3],
    order_symplectic_euler: [0.8, 1.3],
    order_heun: [1.7, 2.3],
    order_rk4: [3.6, 4.4],
    order_dp45: [4, 6.5],
  };
  for (const [k, [lo, hi]] of Object.entries(ranges)) {
    const o = await num(page, k);
    assert.ok(o >= lo && o <= hi, `${k} = ${o} not in [${lo}, ${hi}]`);
  }
  await assertInk(page);
  // The text alternatives say what the pixels show.
  assert.match(await page.textContent('#desc-response'), /forward Euler diverges \(×1\.139 per step/);
  assert.match(await page.textContent('#desc-stability'), /forward Euler: outside its region/);
  assert.match(await page.textContent('#desc-convergence'), /RK4 fitted slope 4\.0/);
  await page.screenshot({ path: `${SHOTS}integrators-preset-1280.png`, fullPage: true });
  assert.deepEqual(errors, []);
  await context.close();
});

test('shrinking h with the keyboard reduces the RK4 error', async () => {
  const { page, errors, context } = await open(browser, `${server.url}?${PRESET}`);
  const before = await num(page, 'max_err_rk4');
  const conv = await canvasFingerprint(page, 'convergence');
  const resp = await canvasFingerprint(page, 'response');
  const orders = await readout(page, 'order_rk4');
  await page.focus('#p-h');
  await page.keyboard.press('PageDown');
  await waitForChange(page, 'max_err_rk4', String(before));
  const h = await num(page, 'h_used');
  assert.ok(h < 0.29, `h decreased to ${h}`);
  const after = await num(page, 'max_err_rk4');
  assert.ok(after < before, `RK4 error ${after} < ${before}`);
  // Halving-ish h should cut RK4's error by roughly (h ratio)^4.
  const ratio = (0.3 / h) ** 4;
  assert.ok(before / after > ratio / 4, `error ratio ${before / after} vs (h ratio)^4 ${ratio}`);
  // The convergence study does not depend on h: the fitted order stays.
  assert.equal(await readout(page, 'order_rk4'), orders);
  assert.notDeepEqual(await canvasFingerprint(page, 'convergence'), conv, 'current-h line moved');
  assert.notDeepEqual(await canvasFingerprint(page, 'response'), resp);
  // The URL follows (debounced).
  await page.waitForFunction(() => Number(new URLSearchParams(location.search).get('h')) < 0.29);
  // A smaller h still: Euler becomes stable below 2ζ/ωn = 0.05 s.
  for (let i = 0; i < 3; i++) await page.keyboard.press('PageDown');
  await page.waitForFunction(() => Number(document.querySelector('[data-readout="h_used"]').dataset.value) < 0.05);
  assert.equal(await readout(page, 'stable_euler'), 'yes');
  assert.deepEqual(errors, []);
  await context.close();
});

for (const [key, readoutKey] of [
  ['zeta', 'growth_euler'],
  ['wn', 'growth_rk4'],
  ['h', 'h_used'],
  ['T', 'max_err_rk4'],
  ['x0', 'max_err_heun'],
  ['tol', 'steps_dp45'],
]) {
  test(`the keyboard moves the ${key} slider; readouts, URL and pixels follow`, async () => {
    const { page, errors, context } = await open(browser, `${server.url}?${PRESET}`);
    const old = await readout(page, readoutKey);
    const prints = {};
    for (const plot of PLOTS) prints[plot] = await canvasFingerprint(page, plot);
    await page.focus(`#p-${key}`);
    await page.keyboard.press(key === 'tol' ? 'PageUp' : 'ArrowRight');
    await page.keyboard.press('ArrowRight');
    await waitForChange(page, readoutKey, old);
    const url = await page.evaluate(() => location.search);
    await page.waitForFunction((k) => new URLSearchParams(location.search).has(k), key);
    assert.ok(url !== '', 'URL updated');
    let changed = 0;
    for (const plot of PLOTS) {
      if (JSON.stringify(await canvasFingerprint(page, plot)) !== JSON.stringify(prints[plot])) changed++;
    }
    assert.ok(changed >= 1, `${key}: some plot changed`);
    await assertInk(page);
    assert.deepEqual(errors, []);
    await context.close();
  });
}

test('toggles hide curves but readouts are still computed', async () => {
  const { page, errors, context } = await open(browser, `${server.url}?${PRESET}`);
  const readouts = await page.evaluate(() =>
    [...document.querySelectorAll('[data-readout]')].map((r) => [r.dataset.readout, r.dataset.value]),
  );
  for (const key of ['euler', 'symplectic_euler', 'heun', 'rk4', 'dp45']) {
    const before = await canvasFingerprint(page, 'response');
    const conv = await canvasFingerprint(page, 'convergence');
    await page.click(`#p-${key}`);
    await waitForUrlParam(page, key, '0');
    await page.waitForFunction(
      ([b]) => {
        const c = document.querySelector('canvas[data-plot="response"]');
        const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
        let ink = 0;
        for (let i = 0; i < d.length; i += 4) if (d[i] !== d[0] || d[i + 1] !== d[1] || d[i + 2] !== d[2]) ink++;
        return ink !== b;
      },
      [before[0]],
    );
    assert.notDeepEqual(await canvasFingerprint(page, 'convergence'), conv, `${key} hidden in the convergence plot`);
  }
  const after = await page.evaluate(() =>
    [...document.querySelectorAll('[data-readout]')].map((r) => [r.dataset.readout, r.dataset.value]),
  );
  assert.deepEqual(after, readouts);
  // With every method off, the exact curve and the stability plot's hλ remain.
  const [ink] = await canvasFingerprint(page, 'response');
  assert.ok(ink > 2000);
  // Opening with a method off from the URL.
  const second = await open(browser, `${server.url}?${PRESET}&euler=0`);
  assert.equal(await second.page.isChecked('#p-euler'), false);
  assert.equal(await second.page.isChecked('#p-rk4'), true);
  assert.deepEqual(second.errors, []);
  await second.context.close();
  assert.deepEqual(errors, []);
  await context.close();
});

const PRESETS = [
  ['Euler just stable', 'zeta=0.05&wn=2&h=0.04', { stable_euler: 'yes', stable_heun: 'yes', stable_rk4: 'yes' }],
  ['RK4 beyond its limit', 'zeta=0.05&wn=2&h=1.6', { stable_euler: 'no', stable_rk4: 'no' }],
  ['Undamped', 'zeta=0&wn=2&h=0.1', { stable_euler: 'no', stable_heun: 'no', stable_rk4: 'yes', stable_symplectic_euler: 'yes' }],
  ['Stiff overdamped', 'zeta=2&wn=20&h=0.03&T=5', { stable_euler: 'no', stable_rk4: 'yes', order_dp45: '' }],
];

for (const [name, query, want] of PRESETS) {
  test(`preset "${name}" opens from the URL and from its button`, async () => {
    const { page, errors, context } = await open(browser, `${server.url}?demo=integrators&${query}`);
    for (const [k, v] of Object.entries(want)) assert.equal(await readout(page, k), v, `${name}: ${k}`);
    await assertInk(page);
    const slug = name.toLowerCase().replace(/[^a-z0-9]+/g, '-');
    await page.screenshot({ path: `${SHOTS}integrators-${slug}-1280.png`, fullPage: true });
    // The same preset from its button, starting at the default.
    const other = await open(browser, `${server.url}?demo=integrators`);
    await other.page.getByRole('button', { name: new RegExp(name) }).click();
    for (const [k, v] of Object.entries(want)) {
      await other.page.waitForFunction(
        ([key, val]) => document.querySelector(`[data-readout="${key}"]`).dataset.value === val,
        [k, v],
      );
    }
    assert.deepEqual(other.errors, []);
    await other.context.close();
    assert.deepEqual(errors, []);
    await context.close();
  });
}

test('RK4 beyond its limit: the growth factor is reported honestly', async () => {
  const { page, errors, context } = await open(browser, `${server.url}?demo=integrators&zeta=0.05&wn=2&h=1.6`);
  const h = await num(page, 'h_used');
  const g = await num(page, 'growth_rk4');
  assert.ok(Math.abs(g - ampAbs(R.rk4, hLambda(0.05, 2, h))) < 1e-12);
  assert.ok(g > 1);
  // Still a finite number for the error; its JS twin agrees.
  const { err } = maxError('rk4', { zeta: 0.05, wn: 2, x0: 1, T: 20, h: 1.6 });
  assert.ok(Math.abs((await num(page, 'max_err_rk4')) - err) <= 1e-9 * err);
  assert.deepEqual(errors, []);
  await context.close();
});

test('narrow screen (360 × 740)', async () => {
  const { page, errors, context } = await open(browser, `${server.url}?${PRESET}`, { viewport: { width: 360, height: 740 } });
  await assertInk(page);
  await page.screenshot({ path: `${SHOTS}integrators-preset-360.png`, fullPage: true });
  for (const plot of PLOTS) {
    await page.locator(`canvas[data-plot="${plot}"]`).screenshot({ path: `${SHOTS}integrators-360-${plot}.png` });
  }
  assert.deepEqual(errors, []);
  await context.close();
});
