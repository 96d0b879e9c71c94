// End to end: the analogy demo (mass–spring–damper and its RLC twin) in headless Chromium,
// driven through the URL contract and the keyboard. The numbers are checked against the
// native snapshots (crates/app/tests/snapshots/analogy.snap), not recomputed here; what is
// checked here is that the page shows them, and that the twins' readouts agree.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { open, readout, canvasFingerprint, waitForUrlParam, SHOTS, fullShot } from './support/browser.mjs';
import { golden, goldenState, assertReadoutsMatch, assertFiguresMatch, waitForReadoutsMatch } from './support/golden.mjs';
import { assertFitsPhone, pressOn, typeValue, waitForChange } from './support/page.mjs';
import { server, browser, useSession } from './support/session.mjs';

useSession();

// The force–voltage analogy with equal numbers: each mechanical readout and its twin.
const TWINS = [
  ['m', 'L'],
  ['c', 'R'],
  ['k', 'elastance'],
  ['compliance', 'C'],
  ['x0', 'q0'],
  ['wn', 'w0'],
];

/** Asserts that every mechanical readout equals its electrical twin (to 1e-12 relative: 1/(1/k) may round). */
async function assertTwinsAgree(page) {
  for (const [mech, elec] of TWINS) {
    const [a, b] = [Number(await readout(page, mech)), Number(await readout(page, elec))];
    assert.ok(Math.abs(a - b) <= 1e-12 * Math.abs(a), `${mech} = ${a}, ${elec} = ${b}`);
  }
}

test('defaults and every preset show the readouts and text alternatives computed natively', async () => {
  for (const state of golden('analogy').states) {
    const { page, errors, context } = await open(browser, `${server.url}?demo=analogy&${state.query}`);
    await assertReadoutsMatch(page, state);
    await assertTwinsAgree(page);
    await assertFiguresMatch(page, state, ['responses', 'energy'], 2000);
    const [ink] = await canvasFingerprint(page, 'schematic');
    assert.ok(ink > 2000, `${state.name}: schematic has ink (${ink} px)`);
    const slug = state.name.split(/[ :(]/)[0].toLowerCase();
    await fullShot(page, `${SHOTS}analogy-${slug}-1280.png`);
    assert.deepEqual(errors, []);
    await context.close();
  }
});

/** The reference table as text: [[cell, …], …] for the body rows. */
function tableCells(page) {
  return page.$$eval('table tbody tr', (trs) => trs.map((tr) => [...tr.cells].map((c) => c.textContent)));
}

/** The live cells: [{row, key, text}]. */
function liveCells(page) {
  return page.$$eval('table [data-live-readout]', (cells) =>
    cells.map((c) => ({ row: c.closest('tr').dataset.row, key: c.dataset.liveReadout, text: c.textContent })),
  );
}

test('the correspondence table shows both machines with their current values', async () => {
  const { page, errors, context } = await open(browser, `${server.url}?demo=analogy`);
  const text = (await tableCells(page)).flat().join('\n');
  for (const want of ['mass m [kg]', 'inductance L [H]', 'resistance R [Ω]', 'spring rate k [N/m]', 'charge q', 'current i']) {
    assert.ok(text.includes(want), `table mentions ${want}`);
  }
  assert.ok(!text.includes('{readout:'), 'no live-cell marker is ever shown');
  // Every live cell shows the text of the readout it names, as the readout panel does.
  const live = await liveCells(page);
  assert.equal(live.length, 18);
  const defaults = goldenState('analogy', 'defaults');
  for (const { row, key, text: shown } of live) {
    const want = defaults.readouts.find((r) => r.key === key);
    assert.ok(want, `${row}: readout ${key} exists`);
    assert.equal(shown, want.text, `${row}: ${key}`);
  }
  const row = (key) => page.$$eval(`tr[data-row="${key}"] td`, (tds) => tds.map((td) => td.textContent));
  assert.deepEqual(await row('inertia'), ['mass m [kg]', '1.000 kg', 'inductance L [H]', '1.000 H']);
  assert.equal(await page.locator('table tbody tr[aria-current]').count(), 0, 'no row is highlighted');
  assert.deepEqual(errors, []);
  await context.close();
});

test('the table follows the sliders and the page language', async () => {
  const { page, errors, context } = await open(browser, `${server.url}?demo=analogy`);
  await page.getByRole('button', { name: /Heavy and soft/ }).click();
  const heavy = goldenState('analogy', 'Heavy and soft: m = 4 kg ↔ L = 4 H, k = 25 N/m ↔ C = 40 mF');
  // The preset's readouts are written on the next animation frame, not by the click.
  await waitForReadoutsMatch(page, heavy);
  await page.waitForFunction(() => document.querySelector('tr[data-row="inertia"] [data-live-readout="L"]').textContent === '4.000 H');
  for (const { key, text } of await liveCells(page)) {
    assert.equal(text, heavy.readouts.find((r) => r.key === key).text, key);
  }
  await context.close();
  const es = await open(browser, `${server.url}?demo=analogy&lang=es`);
  const cells = await liveCells(es.page);
  assert.equal(cells.find((c) => c.key === 'wn').text, '10,00 rad/s', 'Spanish decimal comma');
  assert.ok(!(await tableCells(es.page)).flat().join().includes('{readout:'));
  assert.deepEqual(errors, []);
  assert.deepEqual(es.errors, []);
  await es.context.close();
});

// Each slider: the readouts that must change (on both sides) and a plot whose pixels must.
const SLIDERS = [
  ['m', ['m', 'L', 'wn', 'w0', 'zeta'], 'responses'],
  ['c', ['c', 'R', 'zeta', 'Q'], 'responses'],
  ['k', ['k', 'elastance', 'compliance', 'C', 'wn', 'w0'], 'responses'],
  ['x0', ['x0', 'q0', 'energy'], 'energy'],
];

for (const [key, readouts, plot] of SLIDERS) {
  test(`the keyboard moves ${key}; both machines follow`, async () => {
    const { page, errors, context } = await open(browser, `${server.url}?demo=analogy`);
    const before = {};
    for (const r of readouts) before[r] = await readout(page, r);
    const pixels = await canvasFingerprint(page, plot);
    const table = await liveCells(page);
    await pressOn(page, key, 'ArrowRight', 'PageUp');
    await waitForChange(page, readouts[0], before[readouts[0]]);
    for (const r of readouts) assert.notEqual(await readout(page, r), before[r], `${r} changed`);
    await assertTwinsAgree(page);
    assert.notDeepEqual(await canvasFingerprint(page, plot), pixels, `${plot} redrawn`);
    // The live table moved with the readouts: each cell shows its readout's new text.
    const now = await liveCells(page);
    assert.notDeepEqual(now, table);
    for (const { key: k, text } of now) {
      assert.equal(text, await page.textContent(`[data-readout="${k}"] dd`), `table cell ${k}`);
    }
    assert.deepEqual(errors, []);
    await context.close();
  });
}

test('typing a mass changes the inductance to the same number', async () => {
  const { page, errors, context } = await open(browser, `${server.url}?demo=analogy`);
  await typeValue(page, 'm', '2.5');
  await waitForUrlParam(page, 'm', '2.5');
  await page.waitForFunction(() => document.querySelector('[data-readout="L"]').dataset.value === '2.5');
  await assertTwinsAgree(page);
  assert.deepEqual(errors, []);
  await context.close();
});

test('a phone-sized screen shows both machines', async () => {
  const { page, errors, context } = await open(browser, `${server.url}?demo=analogy`, {
    viewport: { width: 360, height: 740 },
  });
  await assertFitsPhone(page, 'schematic', 'analogy-360.png');
  assert.deepEqual(errors, []);
  await context.close();
});
