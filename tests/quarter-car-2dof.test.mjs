// End to end: the two-degree-of-freedom quarter car in headless Chromium. The numbers are
// checked against the native snapshots (crates/app/tests/snapshots/quarter-car-2dof.snap,
// read through tests/support/golden.mjs); the tests here drive the page through the URL,
// the keyboard and the menus and check that readouts, pixels and the animation follow.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { open, readout, canvasFingerprint, SHOTS, fullShot } from './support/browser.mjs';
import { golden, goldenState, openRecorded } from './support/golden.mjs';
import { nudge, assertDrawn } from './support/page.mjs';
import { server, browser, useSession } from './support/session.mjs';

useSession();

const ID = 'quarter-car-2dof';
const PLOTS = ['motion', 'accel', 'frf', 'tyre'];
const url = (query) => `${server.url}?demo=${ID}${query ? `&${query}` : ''}`;
const num = async (page, key) => Number(await readout(page, key));
const recorded = (state, key) => state.readouts.find((r) => r.key === key).value;
const close = (a, b, rel) => Math.abs(a - b) <= rel * Math.abs(b);

for (const state of golden(ID).states) {
  test(`${state.name}: the readouts computed natively, every plot drawn`, async () => {
    const { page, errors, context } = await openRecorded(browser, server.url, ID, state, { plots: PLOTS });
    const shot = state.name.replace(/[^A-Za-z0-9]+/g, '-').toLowerCase();
    await fullShot(page, `${SHOTS}${ID}-${shot}-1280.png`);
    assert.deepEqual(errors, []);
    await context.close();
  });
}

test('the RMS readouts name their window and the lift-off is shown', async () => {
  const bump = goldenState(ID, 'Speed bump 5 cm at 10 m/s');
  const { page, errors, context } = await open(browser, url(bump.query));
  const window = await num(page, 'window');
  assert.equal(window, Number(recorded(bump, 'window')));
  const text = await page.locator('[data-readout="rms_body_accel"]').textContent();
  assert.match(text, /\(0–2\.55 s\)/);
  assert.ok((await num(page, 'lift_off')) > 0, 'the speed bump throws the wheel');
  assert.ok((await num(page, 'airborne_time')) > 0);
  await context.close();
  const wave = await open(browser, url(goldenState(ID, 'Road wave at body bounce').query));
  assert.equal(await readout(wave.page, 'lift_off'), '', 'a gentle wave keeps contact');
  assert.equal(await num(wave.page, 'airborne_time'), 0);
  assert.deepEqual([...errors, ...wave.errors], []);
  await wave.context.close();
});

test('the body bounce and wheel hop resonances are where the FRF says', async () => {
  // Near body bounce the body moves more than the road; near wheel hop it barely moves but
  // the tyre deflection is large. The two frequencies are the recorded defaults.
  const defaults = goldenState(ID);
  const fb = Number(recorded(defaults, 'f_body'));
  const fw = Number(recorded(defaults, 'f_wheel'));
  const { page, errors, context } = await open(browser, url(`road=sine&h=0.01&f_road=${fb.toFixed(2)}`));
  assert.ok((await num(page, 'body_gain')) > 1.5);
  await context.close();
  const second = await open(browser, url(`road=sine&h=0.01&f_road=${fw.toFixed(2)}`));
  assert.ok((await num(second.page, 'body_gain')) < 0.2);
  assert.ok((await num(second.page, 'tyre_gain')) > 1);
  assert.deepEqual([...errors, ...second.errors], []);
  await second.context.close();
});

test('a road class rougher by one doubles every RMS response while the wheel stays on the road', async () => {
  const { page, errors, context } = await open(browser, url('road=random&class=A&V=20&seed=3'));
  const acc = await num(page, 'rms_body_accel');
  const tyre = await num(page, 'rms_tyre_deflection');
  const road = await num(page, 'rms_road');
  const before = await Promise.all(PLOTS.map((k) => canvasFingerprint(page, k)));
  await page.selectOption('#p-class', '1'); // B
  await page.waitForFunction((v) => document.querySelector('[data-readout="rms_body_accel"]').dataset.value !== v, String(acc));
  assert.equal(await num(page, 'airborne_time'), 0);
  assert.ok(close(await num(page, 'rms_body_accel'), 2 * acc, 1e-6));
  assert.ok(close(await num(page, 'rms_tyre_deflection'), 2 * tyre, 1e-6));
  assert.ok(close(await num(page, 'rms_road'), 2 * road, 1e-9));
  const after = await Promise.all(PLOTS.map((k) => canvasFingerprint(page, k)));
  assert.notDeepEqual(after.slice(0, 2), before.slice(0, 2), 'time plots change');
  assert.deepEqual(errors, []);
  await context.close();
});

test('a narrow phone screen still shows every plot', async () => {
  const { page, errors, context } = await open(browser, url(goldenState(ID, 'Speed bump 5 cm at 10 m/s').query), {
    viewport: { width: 360, height: 740 },
  });
  await assertDrawn(page, PLOTS, 1000);
  await fullShot(page, `${SHOTS}${ID}-360.png`);
  await page.locator('.plots').screenshot({ path: `${SHOTS}${ID}-360-plots.png` });
  assert.deepEqual(errors, []);
  await context.close();
});

test('every slider and choice moves readouts and pixels', async () => {
  const { page, errors, context } = await open(browser, url(goldenState(ID, 'Speed bump 5 cm at 10 m/s').query));
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
    await nudge(page, key, watch);
    const after = await Promise.all(PLOTS.map((k) => canvasFingerprint(page, k)));
    assert.notDeepEqual(after, before, `${key} changes the plots`);
    assert.ok((await num(page, 'rms_body_accel')) > 0 && (await num(page, 'window')) > 0);
  }
  // Road choice: sine, then its frequency slider (logarithmic).
  await page.selectOption('#p-road', '2');
  await page.waitForFunction(() => document.querySelector('[data-readout="body_gain"]').dataset.value !== '');
  const beforeSine = await canvasFingerprint(page, 'frf');
  await nudge(page, 'f_road', 'body_gain');
  // One arrow step can move the marker by less than a pixel on a narrow plot: take a big step.
  const f = await page.evaluate(() => new URLSearchParams(location.search).get('f_road'));
  await page.focus('#p-f_road');
  await page.keyboard.press('PageUp');
  await page.waitForFunction((v) => new URLSearchParams(location.search).get('f_road') !== v, f);
  await page.waitForTimeout(100);
  assert.notDeepEqual(await canvasFingerprint(page, 'frf'), beforeSine, 'the road marker moves');
  // Random road: class and seed.
  await page.selectOption('#p-road', '3');
  await page.waitForFunction(() => document.querySelector('[data-readout="rms_road"]').dataset.value !== '');
  const roadC = await num(page, 'rms_road');
  const beforeSeed = await canvasFingerprint(page, 'motion');
  await nudge(page, 'seed', 'rms_body_accel');
  assert.notDeepEqual(await canvasFingerprint(page, 'motion'), beforeSeed, 'a new seed, a new road');
  // Class A has a sixteenth of class C's spectrum: a quarter of its RMS height.
  await page.selectOption('#p-class', '0');
  await page.waitForFunction((v) => Math.abs(Number(document.querySelector('[data-readout="rms_road"]').dataset.value) - v) < 1e-12 * v, roadC / 4);
  assert.deepEqual(errors, []);
  await context.close();
});

test('the animation scrubber moves the car', async () => {
  const { page, errors, context } = await open(browser, url(goldenState(ID, 'Speed bump 5 cm at 10 m/s').query));
  const before = await canvasFingerprint(page, 'schematic');
  await page.locator('.anim-bar input[type=range]').focus();
  for (let i = 0; i < 30; i++) await page.keyboard.press('ArrowRight');
  await page.waitForFunction(() => document.querySelector('.anim-time').textContent !== 't = 0.00 s');
  assert.notDeepEqual(await canvasFingerprint(page, 'schematic'), before);
  assert.deepEqual(errors, []);
  await context.close();
});
