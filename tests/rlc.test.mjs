// End to end: the series RLC demo in headless Chromium, driven through the URL contract
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

const L = 0.5;
const C = 0.02;
const V0 = 12;
const PRESETS = [
  ['lossless', 0, 'undamped'],
  ['ringing', 2, 'underdamped'],
  ['underdamped', 5, 'underdamped'],
  ['critical', 10, 'critically damped'],
  ['overdamped', 20, 'overdamped'],
];
const PLOTS = ['current', 'voltage'];

async function num(page, key) {
  const v = await readout(page, key);
  return v === '' || v === null ? NaN : Number(v);
}

async function waitForChange(page, key, old) {
  await page.waitForFunction(
    ([k, o]) => document.querySelector(`[data-readout="${k}"]`).dataset.value !== o,
    [key, old],
  );
}

const rel = (a, b) => Math.abs(a - b) / Math.max(1, Math.abs(b));

/** v_C(t) of L·q'' + R·q' + q/C = 0 from q(0) = C·V0, i(0) = 0 (closed form, any regime). */
function capacitorVoltage(r, l, c, v0, t) {
  const a = r / (2 * l);
  const w2 = 1 / (l * c);
  const d = a * a - w2;
  const e = Math.exp(-a * t);
  if (Math.abs(d) < 1e-12 * w2) return v0 * e * (1 + a * t);
  if (d < 0) {
    const wd = Math.sqrt(-d);
    return v0 * e * (Math.cos(wd * t) + (a / wd) * Math.sin(wd * t));
  }
  const mu = Math.sqrt(d);
  return v0 * e * (Math.cosh(mu * t) + (a / mu) * Math.sinh(mu * t));
}

for (const [name, r, regime] of PRESETS) {
  test(`preset ${name} (R = ${r} Ω) from the URL: readouts match closed forms`, async () => {
    const { page, errors, context } = await open(browser, `${server.url}?demo=rlc&R=${r}&L=${L}&C=${C}&V0=${V0}`);
    // Tolerance 1e-12 relative: the same formulas, evaluated in another order.
    const w0 = 1 / Math.sqrt(L * C); // 10 rad/s
    const zeta = (r / 2) * Math.sqrt(C / L);
    assert.ok(rel(await num(page, 'w0'), w0) < 1e-12);
    assert.ok(rel(await num(page, 'f0'), w0 / (2 * Math.PI)) < 1e-12);
    assert.ok(rel(await num(page, 'alpha'), r / (2 * L)) < 1e-12);
    assert.ok(rel(await num(page, 'zeta'), zeta) < 1e-12);
    assert.ok(rel(await num(page, 'R_crit'), 2 * Math.sqrt(L / C)) < 1e-12);
    assert.equal(await readout(page, 'regime'), regime);
    if (r > 0) {
      assert.ok(rel(await num(page, 'Q'), 1 / (2 * zeta)) < 1e-12);
      assert.ok(rel(await num(page, 'bandwidth'), r / L) < 1e-12);
      // v_C settles: on the 5 % edge at t_s and inside it for 3 s after (1 ms steps).
      const ts = await num(page, 'settling_time');
      assert.ok(Math.abs(Math.abs(capacitorVoltage(r, L, C, V0, ts)) - 0.05 * V0) < 1e-9 * V0, `t_s ${ts}`);
      for (let t = ts + 1e-3; t < ts + 3; t += 1e-3) {
        assert.ok(Math.abs(capacitorVoltage(r, L, C, V0, t)) <= 0.05 * V0 * (1 + 1e-9), `inside after t_s (t = ${t})`);
      }
    } else {
      assert.equal(await readout(page, 'Q'), '', 'Q is infinite without resistance');
      assert.equal(await readout(page, 'settling_time'), '');
    }
    if (zeta < 1) {
      assert.ok(rel(await num(page, 'wd'), w0 * Math.sqrt(1 - zeta * zeta)) < 1e-12);
    } else {
      assert.equal(await readout(page, 'wd'), '');
    }
    for (const plot of PLOTS) {
      const [ink] = await canvasFingerprint(page, plot);
      assert.ok(ink > 2000, `${plot} has ink (${ink} px)`);
    }
    // The text alternatives name the resistance and the regime.
    for (const plot of PLOTS) {
      const text = await page.textContent(`#desc-${plot}`);
      assert.ok(text.startsWith('R = ') && text.includes(regime), `${plot}: ${text}`);
    }
    await page.screenshot({ path: `${SHOTS}rlc-${name}-1280.png`, fullPage: true });
    assert.deepEqual(errors, []);
    await context.close();
  });
}

test('preset buttons switch regimes', async () => {
  const { page, errors, context } = await open(browser, `${server.url}?demo=rlc`);
  await page.getByRole('button', { name: 'Critical, R = 10 Ω' }).click();
  await waitForReadout(page, 'zeta', 1);
  assert.equal(await readout(page, 'regime'), 'critically damped');
  await page.getByRole('button', { name: 'Lossless LC, R = 0' }).click();
  await page.waitForFunction(() => document.querySelector('[data-readout="regime"]').dataset.value === 'undamped');
  assert.deepEqual(errors, []);
  await context.close();
});

// Each slider: the readouts it drives (V0 drives none: every readout is relative).
const SLIDERS = [
  ['R', ['alpha', 'zeta', 'Q', 'bandwidth']],
  ['L', ['w0', 'alpha', 'R_crit']],
  ['C', ['w0', 'zeta', 'R_crit']],
  ['V0', []],
];

for (const [key, readouts] of SLIDERS) {
  test(`the keyboard moves ${key}; readouts and pixels follow`, async () => {
    const { page, errors, context } = await open(browser, `${server.url}?demo=rlc&R=4&L=${L}&C=${C}&V0=${V0}`);
    const before = {};
    for (const r of ['w0', 'alpha', 'zeta', 'Q', 'bandwidth', 'R_crit', 'settling_time']) before[r] = await readout(page, r);
    const pixels = {};
    for (const p of PLOTS) pixels[p] = await canvasFingerprint(page, p);
    await page.focus(`#p-${key}`);
    await page.keyboard.press('ArrowRight');
    await page.keyboard.press('PageUp');
    if (readouts.length) {
      for (const r of readouts) await waitForChange(page, r, before[r]);
    } else {
      await page.waitForFunction(() => Number(new URLSearchParams(location.search).get('V0')) > 12);
      await page.waitForTimeout(100);
      assert.equal(await readout(page, 'settling_time'), before.settling_time);
    }
    for (const p of PLOTS) assert.notDeepEqual(await canvasFingerprint(page, p), pixels[p], `${p} redrawn`);
    // Readouts stay consistent with the values the controls now hold.
    const val = async (k) => Number(await page.inputValue(`input[type=number][data-key="${k}"]`));
    const [R, Lv] = [await val('R'), await val('L')];
    assert.ok(rel(await num(page, 'alpha'), R / (2 * Lv)) < 1e-9);
    assert.deepEqual(errors, []);
    await context.close();
  });
}

test('the C slider is logarithmic and its ends work', async () => {
  const { page, errors, context } = await open(browser, `${server.url}?demo=rlc&R=4&L=${L}&C=${C}`);
  await page.focus('#p-C');
  await page.keyboard.press('End');
  await waitForReadout(page, 'w0', 1 / Math.sqrt(L * 1));
  assert.equal(await readout(page, 'regime'), 'overdamped', 'C = 1 F: R_crit = 2√(L/C) = 1.41 Ω < 4 Ω');
  await page.keyboard.press('Home');
  await waitForReadout(page, 'w0', 1 / Math.sqrt(L * 1e-4));
  assert.equal(await readout(page, 'regime'), 'underdamped', 'C = 0.1 mF: R_crit = 141 Ω > 4 Ω');
  // One arrow step moves C by a constant factor: (1 F / 0.1 mF)^(1/1000).
  await page.keyboard.press('ArrowRight');
  await waitForReadout(page, 'w0', 1 / Math.sqrt(L * 1e-4 * Math.pow(1e4, 1 / 1000)));
  for (const p of PLOTS) assert.ok((await canvasFingerprint(page, p))[0] > 1000);
  assert.deepEqual(errors, []);
  await context.close();
});

test('narrow screen (360 × 740)', async () => {
  const { page, errors, context } = await open(browser, `${server.url}?demo=rlc`, {
    viewport: { width: 360, height: 740 },
  });
  for (const plot of PLOTS) assert.ok((await canvasFingerprint(page, plot))[0] > 1000);
  await page.screenshot({ path: `${SHOTS}rlc-360.png`, fullPage: true });
  assert.deepEqual(errors, []);
  await context.close();
});
