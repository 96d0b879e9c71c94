// End to end: the features every demo shares — presets, reset, the animated schematic and
// time cursor, the crosshair read-out, exports (PNG, SVG, CSV), and text alternatives —
// exercised on the regimes demo.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFile } from 'node:fs/promises';
import { open, readout, canvasFingerprint, overlayInk, waitForReadout, waitForReadouts } from './support/browser.mjs';
import { typeValue } from './support/page.mjs';
import { server, browser, useSession } from './support/session.mjs';

useSession();

/** How long the full module (350 KB of wasm) may take to load and take over on a slow CI machine. */
const FULL_MODULE_MS = 30000;

/** Resolves after `n` animation frames of the page. */
function frames(page, n) {
  return page.evaluate((n) => new Promise((done) => {
    const step = (left) => (left ? requestAnimationFrame(() => step(left - 1)) : done());
    step(n);
  }), n);
}

test('presets set their values; reset restores the defaults', async () => {
  const { page, errors, context } = await open(browser, `${server.url}?demo=regimes&zeta=0.5&wn=9`);
  await page.click('button.preset:has-text("Critically damped")');
  await page.waitForFunction(() => document.querySelector('[data-readout="regime"]').dataset.value === 'critically damped');
  assert.equal(await page.inputValue('input[type=number][data-key="zeta"]'), '1');
  await page.click('button.reset');
  await waitForReadout(page, 'zeta', 0.3);
  await waitForReadout(page, 'wn', 6);
  await page.waitForFunction(() => new URLSearchParams(location.search).get('wn') === '6');
  assert.deepEqual(errors, []);
  await context.close();
});

test('the highlighted table row follows the regime', async () => {
  const { page, errors, context } = await open(browser, `${server.url}?demo=regimes&zeta=2`);
  assert.equal(await page.getAttribute('tr.current', 'data-row'), 'overdamped');
  await page.focus('#p-zeta');
  await page.keyboard.press('Home');
  await page.waitForFunction(() => document.querySelector('tr.current')?.dataset.row === 'negatively damped');
  assert.equal(await page.locator('tr[aria-current="true"]').count(), 1);
  assert.deepEqual(errors, []);
  await context.close();
});

test('play animates the schematic and the time cursor; Space pauses; the scrubber seeks', async () => {
  const { page, errors, context } = await open(browser, `${server.url}?demo=regimes`);
  const still = await canvasFingerprint(page, 'schematic');
  await page.click('button.play');
  await page.waitForFunction(() => parseFloat(document.querySelector('.anim-time').textContent.slice(4)) > 0.3);
  assert.notDeepEqual(await canvasFingerprint(page, 'schematic'), still);
  // A dashed cursor is drawn on the response plot's overlay.
  const ink = await overlayInk(page, 'response');
  assert.ok(ink > 20, `time cursor drawn (${ink} px)`);
  await page.focus('main');
  await page.keyboard.press('Space');
  assert.equal(await page.getAttribute('button.play', 'aria-pressed'), 'false');
  const t1 = await page.textContent('.anim-time');
  // Still paused after a while and after several animation frames (the clock moves once a
  // frame while playing: on a slow machine 300 ms may hold only a frame or two).
  await page.waitForTimeout(300);
  await frames(page, 10);
  assert.equal(await page.textContent('.anim-time'), t1, 'paused');
  await page.locator('.anim-bar input[type=range]').fill('500');
  // The clock leaves the paused time (it left 0 s while playing: waiting for that proved
  // nothing about the seek).
  await page.waitForFunction((paused) => document.querySelector('.anim-time').textContent !== paused, t1);
  assert.match(await page.getAttribute('.schematic figcaption', 'class'), /visually-hidden/);
  assert.match(await page.textContent('.schematic figcaption'), /displaced/);
  assert.deepEqual(errors, []);
  await context.close();
});

test('hovering a plot shows the values under the pointer', async () => {
  const { page, errors, context } = await open(browser, `${server.url}?demo=regimes`);
  // A hover shows values once the full module has taken over (a first module has no
  // probe: tests/first-module.test.mjs); one move before that showed nothing, at random.
  await page.waitForFunction(() => window.zetaDiagnostics?.module() === 'full', null, { timeout: FULL_MODULE_MS });
  await page.locator('canvas[data-plot="response"]').scrollIntoViewIfNeeded();
  const box = await page.locator('canvas[data-plot="response"]').boundingBox();
  await page.mouse.move(box.x + box.width * 0.5, box.y + box.height * 0.5);
  await page.waitForSelector('[data-plot-wrap="response"] .probe:not([hidden])');
  const text = await page.textContent('[data-plot-wrap="response"] .probe');
  assert.match(text, /time t = [0-9.]+ s/);
  assert.match(text, /x\(t\), underdamped = /);
  assert.deepEqual(errors, []);
  await context.close();
});

test('a crosshair follows the pointer: one at a time, none once it leaves', async () => {
  // design has no animation: before, only drawTime cleared an overlay, so its crosshairs
  // piled up as the pointer moved.
  for (const id of ['design', 'regimes']) {
    const { page, errors, context } = await open(browser, `${server.url}?demo=${id}`);
    await page.waitForFunction(() => window.zetaDiagnostics?.module() === 'full', null, { timeout: FULL_MODULE_MS });
    const plot = page.locator('canvas[data-plot]').first();
    await plot.scrollIntoViewIfNeeded();
    const box = await plot.boundingBox();
    const key = await plot.getAttribute('data-plot');
    const ink = () => overlayInk(page, key);
    const inks = [];
    const tip = `[data-plot-wrap="${key}"] .probe`;
    let shown = null;
    for (const [fx, fy] of [[0.4, 0.4], [0.6, 0.6], [0.5, 0.3]]) {
      await page.mouse.move(box.x + box.width * fx, box.y + box.height * fy);
      // The read-out for this position: after the first move the tip is already visible,
      // and Chromium hands a mouse move to the page with the next animation frame, so
      // "visible" alone let the ink be read before the crosshair moved.
      await page.waitForFunction(
        ([sel, old]) => {
          const t = document.querySelector(sel);
          return !t.hidden && t.textContent !== old;
        },
        [tip, shown],
      );
      shown = await page.textContent(tip);
      inks.push(await ink());
    }
    // One crosshair (two lines across the plot, rings at the curves) each time: about the
    // same ink, never the sum of the earlier ones.
    assert.ok(inks[0] > 100, `${id}: a crosshair is drawn (${inks})`);
    for (const n of inks.slice(1)) assert.ok(Math.abs(n - inks[0]) < 0.5 * inks[0], `${id}: one crosshair at a time (${inks})`);
    await page.mouse.move(2, 2);
    // The pointer's leaving hides the read-out and erases the crosshair in one handler.
    await page.waitForSelector(tip, { state: 'hidden' });
    assert.equal(await ink(), 0, `${id}: no crosshair once the pointer left`);
    assert.deepEqual(errors, []);
    await context.close();
  }
});

test('CSV, SVG and PNG downloads are produced and parse; CSV numbers match the state', async () => {
  const { page, errors, context } = await open(browser, `${server.url}?demo=regimes&zeta=0.25&x0=0.05`);
  const grab = async (format) => {
    const [dl] = await Promise.all([
      page.waitForEvent('download'),
      page.click(`[data-plot-wrap="response"] button[data-export="${format}"]`),
    ]);
    return { name: dl.suggestedFilename(), body: await readFile(await dl.path()) };
  };
  const csv = await grab('csv');
  assert.equal(csv.name, 'zeta-regimes-response.csv');
  const lines = csv.body.toString('utf8').trim().split('\n');
  assert.ok(lines.includes('# zeta = 0.25'));
  assert.ok(lines.includes('# wn = 6 rad/s'));
  const header = lines.find((l) => !l.startsWith('#'));
  assert.match(header, /^time t \[s\],/);
  const rows = lines.slice(lines.indexOf(header) + 1).map((l) => l.split(',').map(Number));
  assert.ok(rows.length >= 500);
  // Header fields may be quoted (they contain commas): split on commas outside quotes.
  const fields = header.match(/("([^"]|"")*"|[^,]*)(,|$)/g).map((f) => f.replace(/,$/, '').replace(/^"|"$/g, ''));
  const xCol = fields.findIndex((h) => h.startsWith('x(t)'));
  assert.ok(xCol > 0, `x(t) column in ${header}`);
  assert.equal(rows[0][0], 0);
  assert.ok(Math.abs(rows[0][xCol] - 0.05) < 1e-12, 'x(0) = x0');
  assert.ok(rows.every((r) => r.every((v) => Number.isFinite(v) || Number.isNaN(v))));
  const svg = await grab('svg');
  assert.match(svg.body.toString('utf8'), /^<svg[\s\S]*time t \[s\][\s\S]*<\/svg>\s*$/);
  const png = await grab('png');
  assert.deepEqual([...png.body.subarray(0, 8)], [137, 80, 78, 71, 13, 10, 26, 10]);
  const width = png.body.readUInt32BE(16);
  const cssWidth = await page.evaluate(() => document.querySelector('canvas[data-plot="response"]').clientWidth);
  assert.equal(width, cssWidth * 2, 'PNG at 2× resolution');
  assert.deepEqual(errors, []);
  await context.close();
});

test('the text alternative changes when the response changes and is announced', async () => {
  const { page, errors, context } = await open(browser, `${server.url}?demo=regimes&zeta=0.1`);
  const first = await page.textContent('#desc-response');
  assert.match(first, /underdamped: swings past equilibrium \d+ times before settling/);
  await typeValue(page, 'zeta', '1.5');
  await page.waitForFunction((f) => document.querySelector('#desc-response').textContent !== f, first);
  assert.match(await page.textContent('#desc-response'), /^overdamped/);
  await page.waitForFunction(() => /^overdamped/.test(document.querySelector('#plot-announcer').textContent));
  assert.equal(await page.getAttribute('canvas[data-plot="response"]', 'aria-describedby'), 'desc-response');
  assert.match(await page.getAttribute('#p-zeta', 'aria-valuetext'), /damping ratio 1\.5, overdamped/);
  assert.deepEqual(errors, []);
  await context.close();
});

test('printed, the page shows every readout and the staged plot at its natural shape', async () => {
  const { page, errors, context } = await open(browser, `${server.url}?demo=integrators`, { viewport: { width: 360, height: 740 } });
  await waitForReadouts(page);
  const strip = () => page.$eval('.readout-strip', (s) => ({ max: getComputedStyle(s).maxHeight, cut: s.scrollHeight > s.clientHeight + 1 }));
  // On the phone's screen the strip shows a few of integrators' 21 readouts and scrolls.
  assert.equal((await strip()).cut, true);
  await page.emulateMedia({ media: 'print' });
  assert.deepEqual(await strip(), { max: 'none', cut: false });
  assert.equal(await page.$eval('.stage canvas[data-plot]', (c) => getComputedStyle(c).aspectRatio), '1.6 / 1');
  assert.deepEqual(errors, []);
  await context.close();
});
