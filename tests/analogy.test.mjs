// End to end: the analogy demo (mass–spring–damper and its RLC twin) in headless Chromium,
// driven through the URL contract and the keyboard. Expected readouts are computed here from
// the force–voltage analogy with identical numbers: L = m, R = c, C = 1/k, q₀ = x₀.
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

// Closed forms (tests only). Relative tolerance: 1e-12 (the circuit's numbers are the
// mechanism's, up to the rounding of 1/(1/k)).
const TOL = 1e-12;
function expected({ m, c, k, x0 }) {
  const zeta = c / (2 * Math.sqrt(m * k));
  const regime = c === 0 ? 'undamped' : Math.abs(zeta - 1) <= 1e-9 ? 'critically damped' : zeta < 1 ? 'underdamped' : 'overdamped';
  return {
    m,
    L: m,
    c,
    R: c,
    k,
    C: 1 / k,
    x0,
    q0: x0,
    wn: Math.sqrt(k / m),
    w0: 1 / Math.sqrt(m * (1 / k)),
    zeta,
    regime,
    Q: c > 0 ? Math.sqrt(m * k) / c : null,
    energy: 0.5 * k * x0 * x0,
  };
}

async function checkReadouts(page, values) {
  for (const [key, v] of Object.entries(expected(values))) {
    const got = await readout(page, key);
    if (v === null) assert.equal(got, '', `${key} undefined`);
    else if (typeof v === 'string') assert.equal(got, v, key);
    else assert.ok(Math.abs(Number(got) - v) <= TOL * Math.max(1, Math.abs(v)), `${key}: got ${got}, want ${v}`);
  }
}

const DEFAULTS = { m: 1, c: 2, k: 100, x0: 0.05 };
const PRESETS = [
  ['lc-tank', { m: 1, c: 0, k: 100 }],
  ['light', { m: 1, c: 1, k: 100 }],
  ['critical', { m: 1, c: 20, k: 100 }],
  ['overdamped', { m: 1, c: 40, k: 100 }],
  ['heavy-soft', { m: 4, c: 2, k: 25 }],
];

for (const [name, preset] of PRESETS) {
  test(`preset ${name} opens from the URL with both machines' readouts and plots`, async () => {
    const values = { ...DEFAULTS, ...preset };
    const query = Object.entries(preset).map(([key, v]) => `${key}=${v}`).join('&');
    const { page, errors, context } = await open(browser, `${server.url}?demo=analogy&${query}`);
    await checkReadouts(page, values);
    for (const plot of ['responses', 'energy', 'schematic']) {
      const [ink] = await canvasFingerprint(page, plot);
      assert.ok(ink > 2000, `${plot} has ink (${ink} px)`);
    }
    // The text alternatives name the regime and say the two machines agree.
    const responses = await page.textContent('#desc-responses');
    assert.ok(responses.startsWith(expected(values).regime), responses);
    assert.match(responses, /coincide/);
    assert.match(await page.textContent('#desc-energy'), /spring.*capacitor/);
    await page.screenshot({ path: `${SHOTS}analogy-${name}-1280.png`, fullPage: true });
    assert.deepEqual(errors, []);
    await context.close();
  });
}

test('the correspondence table lists every quantity with units and highlights none', async () => {
  const { page, errors, context } = await open(browser, `${server.url}?demo=analogy`);
  const rows = await page.$$eval('table tbody tr', (trs) => trs.map((tr) => tr.textContent));
  const text = rows.join('\n');
  for (const want of ['mass m', 'inductance L', 'resistance R', 'spring rate k', 'charge q', 'current i', 'N·s/m', 'Ω', 'H']) {
    assert.ok(text.includes(want), `table mentions ${want}`);
  }
  assert.equal(await page.locator('table tbody tr[aria-current]').count(), 0);
  assert.deepEqual(errors, []);
  await context.close();
});

// Each slider: the readouts that must change (on both sides) and a plot whose pixels must.
const SLIDERS = [
  ['m', ['m', 'L', 'wn', 'w0', 'zeta'], 'responses'],
  ['c', ['c', 'R', 'zeta', 'Q'], 'responses'],
  ['k', ['k', 'C', 'wn', 'w0'], 'responses'],
  ['x0', ['x0', 'q0', 'energy'], 'energy'],
];

for (const [key, readouts, plot] of SLIDERS) {
  test(`the keyboard moves ${key}; both machines follow`, async () => {
    const { page, errors, context } = await open(browser, `${server.url}?demo=analogy`);
    const before = {};
    for (const r of readouts) before[r] = await readout(page, r);
    const pixels = await canvasFingerprint(page, plot);
    await page.focus(`#p-${key}`);
    await page.keyboard.press('ArrowRight');
    await page.keyboard.press('PageUp');
    await page.waitForFunction(
      ([r, v]) => document.querySelector(`[data-readout="${r}"]`).dataset.value !== v,
      [readouts[0], before[readouts[0]]],
    );
    for (const r of readouts) assert.notEqual(await readout(page, r), before[r], `${r} changed`);
    await page.waitForFunction(
      ([k, v]) => {
        const got = new URLSearchParams(location.search).get(k);
        return got !== null && got !== v;
      },
      [key, String(DEFAULTS[key])],
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

test('typing a mass changes the inductance to the same number', async () => {
  const { page, errors, context } = await open(browser, `${server.url}?demo=analogy`);
  await page.fill('input[type=number][data-key="m"]', '2.5');
  await page.press('input[type=number][data-key="m"]', 'Enter');
  await waitForUrlParam(page, 'm', '2.5');
  await checkReadouts(page, { ...DEFAULTS, m: 2.5 });
  assert.deepEqual(errors, []);
  await context.close();
});

test('a phone-sized screen shows both machines', async () => {
  const { page, errors, context } = await open(browser, `${server.url}?demo=analogy`, {
    viewport: { width: 360, height: 740 },
  });
  const [ink] = await canvasFingerprint(page, 'schematic');
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
  await page.screenshot({ path: `${SHOTS}analogy-360.png`, fullPage: true });
  assert.deepEqual(errors, []);
  await context.close();
});
