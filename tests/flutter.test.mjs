// End to end: the flutter (Tacoma Narrows) demo in headless Chromium, through the URL
// contract and the keyboard. Expected values come from the closed forms of the model
// θ'' + 2ζ_eff·ω·θ' + ω²·θ = 0, ζ_eff = ζ_s − g·U, recomputed here independently.
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

// The 1940 preset: 0.2 Hz torsion, 0.5 % structural damping, U_crit = 42 mph.
const OMEGA = 2 * Math.PI * 0.2;
const ZETA_S = 0.005;
const U_FAIL = 42 * 0.44704;
const SLOPE = ZETA_S / U_FAIL;
const PLOTS = ['damping', 'locus', 'response'];

/** Closed-form expectations for one wind speed (|ζ_eff| < 1 throughout). */
function expected(u, { omega = OMEGA, zetaS = ZETA_S, slope = SLOPE, theta0Deg = 2 } = {}) {
  const zeta = zetaS - slope * u;
  const sigma = -zeta * omega;
  const wd = omega * Math.sqrt(1 - zeta * zeta);
  const theta0 = (theta0Deg * Math.PI) / 180;
  const tEnd = (60 * 2 * Math.PI) / omega;
  const ampEnd = theta0 * Math.sqrt(1 + (sigma / wd) ** 2) * Math.exp(sigma * tEnd);
  return { zeta, sigma, uCrit: slope > 0 ? zetaS / slope : null, ampEnd };
}

const close = (a, b, rel = 1e-9, abs = 1e-15) => Math.abs(a - b) <= Math.max(abs, rel * Math.abs(b));

function presetQuery(u) {
  return `demo=flutter&U=${u}&zeta_s=${ZETA_S}&omega=${OMEGA}&slope=${SLOPE}&theta0=2`;
}

const PRESETS = [
  ['stable-10', 10, 'underdamped'],
  ['critical', U_FAIL, 'undamped'],
  ['failure-19', 19, 'negatively damped'],
  ['gale-30', 30, 'negatively damped'],
];

for (const [name, u, regime] of PRESETS) {
  test(`preset ${name}: readouts match the closed form, plots drawn, table row highlighted`, async () => {
    const { page, errors, context } = await open(browser, `${server.url}?${presetQuery(u)}`);
    const e = expected(u);
    assert.equal(await readout(page, 'regime'), regime);
    // ζ_eff is evaluated with one fused multiply-add in Rust; allow a few ulps of 0.005.
    assert.ok(close(Number(await readout(page, 'zeta_eff')), e.zeta, 1e-9, 1e-16), 'zeta_eff');
    assert.ok(close(Number(await readout(page, 'U_crit')), e.uCrit, 1e-12), 'U_crit');
    assert.ok(close(Number(await readout(page, 'growth_rate')), e.sigma, 1e-9, 1e-15), 'growth_rate');
    assert.ok(close(Number(await readout(page, 'amplitude_end')), e.ampEnd, 1e-9), 'amplitude_end');
    const doubling = await readout(page, 'doubling_time');
    if (regime === 'negatively damped') {
      assert.ok(close(Number(doubling), Math.LN2 / e.sigma, 1e-6), `doubling ${doubling}`);
    } else {
      assert.equal(doubling, '', 'no doubling time unless the twist grows');
    }
    assert.equal(await page.getAttribute(`tr[data-row="${regime}"]`, 'aria-current'), 'true');
    for (const key of PLOTS) {
      const [ink] = await canvasFingerprint(page, key);
      assert.ok(ink > 2000, `${key} has ink (${ink} px)`);
    }
    const [schematicInk] = await canvasFingerprint(page, 'schematic');
    assert.ok(schematicInk > 500, `schematic drawn (${schematicInk} px)`);
    const caption = await page.textContent('#desc-response');
    assert.match(caption, regime === 'negatively damped' ? /grows by a factor/ : regime === 'undamped' ? /keeps its amplitude/ : /decays to/);
    await page.screenshot({ path: `${SHOTS}flutter-${name}-1280.png`, fullPage: true });
    assert.deepEqual(errors, []);
    await context.close();
  });
}

test('a narrow phone screen still shows every plot', async () => {
  const { page, errors, context } = await open(browser, `${server.url}?${presetQuery(19)}`, {
    viewport: { width: 360, height: 740 },
  });
  for (const key of PLOTS) {
    const [ink] = await canvasFingerprint(page, key);
    assert.ok(ink > 1000, `${key} has ink (${ink} px)`);
  }
  await page.screenshot({ path: `${SHOTS}flutter-360.png`, fullPage: true });
  await page.locator('.plots').screenshot({ path: `${SHOTS}flutter-360-plots.png` });
  assert.deepEqual(errors, []);
  await context.close();
});

/** Fingerprints of every plot. */
async function prints(page) {
  return Promise.all(PLOTS.map((k) => canvasFingerprint(page, k)));
}

/** Presses ArrowRight on slider `key`; waits until readout `watch` changes; returns the new value. */
async function nudge(page, key, watch) {
  const before = await readout(page, watch);
  await page.focus(`#p-${key}`);
  await page.keyboard.press('ArrowRight');
  await page.waitForFunction(
    ([k, v]) => document.querySelector(`[data-readout="${k}"]`).dataset.value !== v,
    [watch, before],
  );
  return Number(await page.inputValue(`#p-${key}`));
}

test('every slider moves readouts and pixels by the keyboard', async () => {
  const { page, errors, context } = await open(browser, `${server.url}?${presetQuery(10)}`);
  const state = { omega: OMEGA, zetaS: ZETA_S, slope: SLOPE, theta0Deg: 2 };
  let u = 10;
  const check = async () => {
    const e = expected(u, state);
    assert.ok(close(Number(await readout(page, 'zeta_eff')), e.zeta, 1e-9, 1e-16), `zeta_eff at U=${u}`);
    assert.ok(close(Number(await readout(page, 'growth_rate')), e.sigma, 1e-9, 1e-15), 'growth_rate');
    assert.ok(close(Number(await readout(page, 'U_crit')), e.uCrit, 1e-12), 'U_crit');
    assert.ok(close(Number(await readout(page, 'amplitude_end')), e.ampEnd, 1e-9), 'amplitude_end');
  };
  for (const [key, watch, apply] of [
    ['U', 'zeta_eff', (v) => { u = v; }],
    ['zeta_s', 'U_crit', (v) => { state.zetaS = v; }],
    ['omega', 'growth_rate', (v) => { state.omega = v; }],
    ['slope', 'U_crit', (v) => { state.slope = v; }],
    ['theta0', 'amplitude_end', (v) => { state.theta0Deg = v; }],
  ]) {
    const before = await prints(page);
    const v = await nudge(page, key, watch);
    apply(v);
    await check();
    const after = await prints(page);
    assert.notDeepEqual(after, before, `${key} changes the plots`);
  }
  // PageUp on U takes big steps; far above U_crit the regime flips and the row follows.
  await page.focus('#p-U');
  await page.keyboard.press('End');
  await waitForReadout(page, 'zeta_eff', expected(40, state).zeta);
  assert.equal(await readout(page, 'regime'), 'negatively damped');
  assert.equal(await page.getAttribute('tr[data-row="negatively damped"]', 'aria-current'), 'true');
  await page.keyboard.press('Home');
  await page.keyboard.press('PageUp');
  const uBig = Number(await page.inputValue('#p-U'));
  assert.ok(uBig > 0, 'PageUp moved the wind speed');
  await waitForReadout(page, 'zeta_eff', expected(uBig, state).zeta);
  assert.deepEqual(errors, []);
  await context.close();
});

test('with no aerodynamic slope there is no critical speed, and the page says so', async () => {
  const { page, errors, context } = await open(browser, `${server.url}?demo=flutter&slope=0&U=40`);
  assert.equal(await readout(page, 'U_crit'), '');
  assert.equal(await readout(page, 'regime'), 'underdamped');
  assert.match(await page.textContent('#desc-damping'), /never crosses zero/);
  assert.deepEqual(errors, []);
  await context.close();
});

test('the animation scrubber twists the deck', async () => {
  const { page, errors, context } = await open(browser, `${server.url}?${presetQuery(30)}`);
  const before = await canvasFingerprint(page, 'schematic');
  const scrub = page.locator('.anim-bar input[type=range]');
  await scrub.focus();
  for (let i = 0; i < 10; i++) await page.keyboard.press('ArrowRight');
  await page.waitForFunction(() => document.querySelector('.anim-time').textContent !== 't = 0.00 s');
  const after = await canvasFingerprint(page, 'schematic');
  assert.notDeepEqual(after, before);
  assert.deepEqual(errors, []);
  await context.close();
});
