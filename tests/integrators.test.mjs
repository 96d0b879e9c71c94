// End to end: the integrators demo in headless Chromium. Readouts and text alternatives are
// checked against the golden snapshots written natively (crates/app/tests/snapshots/), not
// against physics re-implemented here; then every slider, toggle and preset is exercised.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { open as openPage, caption, readout, canvasFingerprint, waitForUrlParam, SHOTS, fullShot } from './support/browser.mjs';
import { golden, goldenState } from './support/golden.mjs';
import { waitForChange } from './support/page.mjs';
import { server, browser, useSession } from './support/session.mjs';

/**
 * A page of the demo once its study is whole: the first module shows a coarse one (marked
 * provisional) until the full module, which computes the full one behind the page, takes
 * over.
 */
async function open(...args) {
  const opened = await openPage(...args);
  await opened.page.waitForFunction(() => !document.querySelector('[data-provisional]'));
  return opened;
}

useSession();

const PLOTS = ['response', 'error', 'convergence', 'work', 'stability'];
const PRESET = 'demo=integrators&zeta=0.05&wn=2&h=0.3';
const LIGHT = 'Lightly damped, h = 0.3 s';

// Numbers are recorded in exponent form to 12 digits; text readouts as they are.
const isNumber = (v) => /^-?\d\.\d+e[-+]?\d+$/.test(v);

// DP45's step-size controller and the fits over errors near the rounding floor depend on
// the last bits of powf, exp and cos, which differ between native code and wasm: those
// readouts agree to 1e-6 relative (far below the 3 digits shown), the rest to 1e-11.
const LOOSE = /^(order_|max_err_dp45$)/;
const tolerance = (key) => (LOOSE.test(key) ? 1e-6 : 1e-11);
const same = (key, shown, recorded) =>
  isNumber(recorded)
    ? Math.abs(Number(shown) - Number(recorded)) <= tolerance(key) * Math.max(1, Math.abs(Number(recorded)))
    : shown === recorded;

/** Every readout on the page equals the recorded one (see `tolerance`). */
async function assertReadoutsMatch(page, state) {
  const shown = new Map(
    await page.$$eval('[data-readout]', (els) => els.map((e) => [e.dataset.readout, e.dataset.value])),
  );
  for (const r of state.readouts) {
    assert.ok(shown.has(r.key), `${state.name}: readout ${r.key} is on the page`);
    assert.ok(same(r.key, shown.get(r.key), r.value), `${state.name}: ${r.key} shows ${shown.get(r.key)}, recorded ${r.value}`);
  }
}

const num = async (page, key) => Number(await readout(page, key));

async function assertInk(page) {
  for (const plot of PLOTS) {
    const [ink] = await canvasFingerprint(page, plot);
    assert.ok(ink > 3000, `${plot} has ink (${ink} px)`);
  }
}

test('defaults and every preset show the readouts and text alternatives computed natively', async () => {
  const { spec, states } = golden('integrators');
  for (const state of states) {
    const { page, errors, context } = await open(browser, `${server.url}?demo=integrators&${state.query}`);
    // The recorded state is the full study: wait out the coarse one (marked provisional).
    await page.waitForFunction(() => !document.querySelector('[data-provisional]'));
    await assertReadoutsMatch(page, state);
    // Drawn first: a plot's figure, and so its caption, comes when the plot is drawn.
    await assertInk(page);
    for (const [i, plot] of spec.plots.entries()) {
      assert.equal(await caption(page, plot.key), state.figures[i].description, `${state.name}: ${plot.key}`);
    }
    assert.deepEqual(errors, []);
    await context.close();
  }
});

test('h = 0.3 s integrates with steps of exactly 0.3 s; the last one ends at T', async () => {
  const { page, errors, context } = await open(browser, `${server.url}?${PRESET}`);
  // 66 steps of 0.3 s reach 19.8 s; a last step of 0.2 s ends the run at T = 20 s.
  assert.equal(await readout(page, 'h_used'), '0.3');
  assert.ok(Math.abs(Number(await readout(page, 'h_last')) - 0.2) < 1e-12);
  assert.match(await caption(page, 'response'), /with h = 300 ms \(67 steps, the last 200 ms to end at T\)/);
  assert.match(await caption(page, 'error'), /\(h = 300 ms\)/);
  // The same from the golden file, which the native tests computed with this h.
  const light = goldenState('integrators', LIGHT);
  assert.equal(light.readouts.find((r) => r.key === 'h_used').value, '3.00000000000e-1');
  await fullShot(page, `${SHOTS}integrators-preset-1280.png`);
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
  // The step used is the slider's value itself (the number box shows 4 digits of it).
  const box = Number(await page.inputValue('input[type=number][data-key="h"]'));
  assert.ok(Math.abs(h - box) <= 1e-3 * box, `h_used ${h} vs the box ${box}`);
  const after = await num(page, 'max_err_rk4');
  assert.ok(after < before, `RK4 error ${after} < ${before}`);
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
  // Steps are exactly h, so a longer run changes the last step (20 s = 66 × 0.3 s + 0.2 s).
  ['T', 'h_last'],
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
    // DP45 has no single h: it is drawn on the work–precision plot, the others on both.
    const other = key === 'dp45' ? 'work' : 'convergence';
    const conv = await canvasFingerprint(page, other);
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
    assert.notDeepEqual(await canvasFingerprint(page, other), conv, `${key} hidden in the ${other} plot`);
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

// Each preset's recorded stability verdicts and DP45 order (blank where stability sets
// its steps), as the page must show them whether opened from the URL or the button.
const PRESETS = [
  ['Euler just stable', 'Euler just stable, h = 0.04 s'],
  ['RK4 beyond its limit', 'RK4 beyond its limit, h = 1.6 s'],
  ['Undamped', 'Undamped, h = 0.1 s'],
  ['Stiff overdamped', 'Stiff overdamped ζ = 2, ωₙ = 20'],
].map(([name, label]) => {
  const state = goldenState('integrators', label);
  const keys = ['stable_euler', 'stable_symplectic_euler', 'stable_heun', 'stable_rk4', 'order_euler', 'order_dp45'];
  const want = Object.fromEntries(state.readouts.filter((r) => keys.includes(r.key)).map((r) => [r.key, r.value]));
  return [name, state.query, want];
});

for (const [name, query, want] of PRESETS) {
  test(`preset "${name}" opens from the URL and from its button`, async () => {
    const { page, errors, context } = await open(browser, `${server.url}?demo=integrators&${query}`);
    for (const [k, v] of Object.entries(want)) assert.ok(same(k, await readout(page, k), v), `${name}: ${k}`);
    await assertInk(page);
    const slug = name.toLowerCase().replace(/[^a-z0-9]+/g, '-');
    await fullShot(page, `${SHOTS}integrators-${slug}-1280.png`);
    // The same preset from its button, starting at the default.
    const other = await open(browser, `${server.url}?demo=integrators`);
    await other.page.getByRole('button', { name: new RegExp(name) }).click();
    for (const [k, v] of Object.entries(want)) {
      await other.page.waitForFunction(
        ([key, val, tol]) => {
          const shown = document.querySelector(`[data-readout="${key}"]`).dataset.value;
          return /^-?\d\.\d+e[-+]?\d+$/.test(val) ? Math.abs(Number(shown) - Number(val)) <= tol * Math.abs(Number(val)) : shown === val;
        },
        [k, v, tolerance(k)],
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
  const state = goldenState('integrators', 'RK4 beyond its limit, h = 1.6 s');
  const g = await num(page, 'growth_rk4');
  assert.ok(g > 1, `RK4 grows by ${g} per step`);
  assert.equal(await readout(page, 'stable_rk4'), 'no');
  // Still a finite number for the error, as recorded natively.
  const err = Number(state.readouts.find((r) => r.key === 'max_err_rk4').value);
  assert.ok(Number.isFinite(err) && Math.abs((await num(page, 'max_err_rk4')) - err) <= 1e-11 * err);
  assert.match(await caption(page, 'response'), /RK4 diverges/);
  assert.deepEqual(errors, []);
  await context.close();
});

test('narrow screen (360 × 740)', async () => {
  const { page, errors, context } = await open(browser, `${server.url}?${PRESET}`, { viewport: { width: 360, height: 740 } });
  await assertInk(page);
  await fullShot(page, `${SHOTS}integrators-preset-360.png`);
  for (const plot of PLOTS) {
    await page.locator(`canvas[data-plot="${plot}"]`).screenshot({ path: `${SHOTS}integrators-360-${plot}.png` });
  }
  assert.deepEqual(errors, []);
  await context.close();
});
