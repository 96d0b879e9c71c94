// End to end: the regimes demo in headless Chromium, driven through the URL contract,
// the keyboard and the mouse.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { open, readout, canvasFingerprint, drawn, waitForUrlParam, waitForReadout, SHOTS, fullShot } from './support/browser.mjs';
import { golden, assertReadoutsMatch } from './support/golden.mjs';
import { assertStillWorks, typeValue } from './support/page.mjs';
import { server, browser, useSession } from './support/session.mjs';

useSession();

test('opens from the URL with its values, readouts and drawn plots', async () => {
  const { page, errors, context } = await open(browser, `${server.url}?demo=regimes&zeta=0.2`);
  assert.ok(Math.abs(Number(await readout(page, 'zeta')) - 0.2) < 1e-12);
  assert.equal(await readout(page, 'regime'), 'underdamped');
  assert.equal(await page.inputValue('#p-zeta'), '0.2');
  const [ink] = await canvasFingerprint(page, 'response');
  assert.ok(ink > 5000, `response plot has ink (${ink} px)`);
  const [poleInk] = await canvasFingerprint(page, 'poles');
  assert.ok(poleInk > 2000, `pole plot has ink (${poleInk} px)`);
  // Canvases are sized for the screen's pixel ratio.
  const sizes = await page.evaluate(() => {
    const c = document.querySelector('canvas[data-plot="response"]');
    return [c.width, Math.round(c.clientWidth * devicePixelRatio)];
  });
  assert.equal(sizes[0], sizes[1]);
  await fullShot(page, `${SHOTS}regimes-1280.png`);
  assert.deepEqual(errors, []);
  await context.close();
});

test('defaults and every preset show the readouts computed natively', async () => {
  for (const state of golden('regimes').states) {
    const { page, errors, context } = await open(browser, `${server.url}?demo=regimes&${state.query}`);
    await assertReadoutsMatch(page, state);
    assert.deepEqual(errors, []);
    await context.close();
  }
});

test('the keyboard moves the ζ slider; readouts, URL and pixels follow', async () => {
  const { page, errors, context } = await open(browser, `${server.url}?demo=regimes&zeta=0.2`);
  const before = await canvasFingerprint(page, 'response');
  await page.focus('#p-zeta');
  for (let i = 0; i < 5; i++) await page.keyboard.press('ArrowRight');
  await waitForReadout(page, 'zeta', 0.25);
  await waitForUrlParam(page, 'zeta', '0.25');
  assert.equal(await page.inputValue('input[type=number][data-key="zeta"]'), '0.25');
  const after = await canvasFingerprint(page, 'response');
  assert.notDeepEqual(after, before);
  // Big steps and ends of the range.
  await page.keyboard.press('End');
  await waitForReadout(page, 'zeta', 3);
  assert.equal(await readout(page, 'regime'), 'overdamped');
  await page.keyboard.press('Home');
  await waitForReadout(page, 'zeta', -0.5);
  assert.equal(await readout(page, 'regime'), 'negatively damped');
  assert.deepEqual(errors, []);
  await context.close();
});

test('a mouse drag on the ζ slider changes readouts, URL and pixels', async () => {
  const { page, errors, context } = await open(browser, `${server.url}?demo=regimes&zeta=0.2`);
  const before = await canvasFingerprint(page, 'poles');
  const box = await page.locator('#p-zeta').boundingBox();
  const y = box.y + box.height / 2;
  await page.mouse.move(box.x + box.width * 0.2, y);
  await page.mouse.down();
  for (let i = 1; i <= 10; i++) await page.mouse.move(box.x + box.width * (0.2 + 0.06 * i), y);
  await page.mouse.up();
  // The drag's last frame drawn: ζ passes 1.5 a few moves before the end, and a value read
  // from an earlier frame is not the one the address gets.
  await drawn(page);
  await page.waitForFunction(() => Number(document.querySelector('[data-readout="zeta"]').dataset.value) > 1.5);
  const zeta = await readout(page, 'zeta');
  await waitForUrlParam(page, 'zeta', zeta);
  assert.equal(await readout(page, 'regime'), 'overdamped');
  assert.equal(await readout(page, 'wd'), '', 'no damped frequency when overdamped');
  assert.notDeepEqual(await canvasFingerprint(page, 'poles'), before);
  assert.deepEqual(errors, []);
  await context.close();
});

test('typing in the number box validates through Rust', async () => {
  const { page, errors, context } = await open(browser, `${server.url}?demo=regimes`);
  await typeValue(page, 'zeta', '1');
  await page.waitForFunction(() => document.querySelector('[data-readout="regime"]').dataset.value === 'critically damped');
  await typeValue(page, 'zeta', '99');
  await waitForReadout(page, 'zeta', 3);
  assert.match(await page.textContent('#notices'), /outside/);
  assert.deepEqual(errors, []);
  await context.close();
});

for (const [name, query] of [
  ['script injection', `zeta=${encodeURIComponent('<script>alert(1)</script>')}`],
  ['a raw script tag', 'zeta=<script>alert(1)</script>'],
  ['a huge number', 'zeta=1e308'],
  ['NaN', 'zeta=NaN'],
]) {
  test(`a hostile URL (${name}) shows a notice and a working page`, async () => {
    const { page, errors, context } = await open(browser, `${server.url}?demo=regimes&${query}&wn=abc&unknown=1`);
    const notices = await page.textContent('#notices');
    assert.match(notices, /damping ratio \(zeta\)/);
    assert.match(notices, /natural frequency \(wn\)/);
    assert.equal(await page.locator('#notices script').count(), 0);
    const zeta = Number(await readout(page, 'zeta'));
    assert.ok(zeta === 0.3 || zeta === 3, `zeta replaced by the default or clamped, got ${zeta}`);
    // The page keeps working.
    await assertStillWorks({ page, errors, context });
  });
}

test('an unknown demo id falls back to the default with a notice', async () => {
  const { page, errors, context } = await open(browser, `${server.url}?demo=%3Cimg%20src=x%3E`);
  assert.match(await page.textContent('#notices'), /no demo called/);
  assert.equal(await page.locator('#notices img').count(), 0);
  assert.equal(await readout(page, 'regime'), 'underdamped');
  assert.deepEqual(errors, []);
  await context.close();
});
