// End to end: the universality demo (one equation, many machines) in headless Chromium.
// Readouts are checked against the native snapshots (golden), "match" against the CSV the
// page exports, and the conditional controls (`applyConditions`, web/ui.js) on the real page.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFile } from 'node:fs/promises';
import { open, readout, canvasFingerprint, waitForUrlParam, SHOTS, fullShot } from './support/browser.mjs';
import { golden, goldenState, assertReadoutsMatch } from './support/golden.mjs';
import { server, browser, useSession } from './support/session.mjs';

useSession();

const ID = 'universality';

/**
 * Applies `applyConditions` (web/ui.js) to the page with the recorded spec, as main.js does after
 * every update once it is hooked in (calling it again is harmless: it is idempotent).
 */
async function applyConditions(page) {
  const spec = golden(ID).spec;
  await page.evaluate(async (s) => {
    const { applyConditions: apply } = await import(new URL('web/ui.js', document.baseURI).href);
    apply(s, document);
  }, spec);
}

/** Keys of the parameter controls the visitor can see. */
function visibleParams(page) {
  return page.$$eval('.controls .param', (els) => els.filter((e) => !e.hidden && e.offsetParent !== null).map((e) => e.dataset.param));
}

/** The CSV of plot `key` as {header fields, rows of numbers}. */
async function csv(page, key) {
  const [dl] = await Promise.all([
    page.waitForEvent('download'),
    page.click(`[data-plot-wrap="${key}"] button[data-export="csv"]`),
  ]);
  const lines = (await readFile(await dl.path())).toString('utf8').trim().split('\n');
  const header = lines.find((l) => !l.startsWith('#'));
  const fields = header.match(/("([^"]|"")*"|[^,]*)(,|$)/g).map((f) => f.replace(/,$/, '').replace(/^"|"$/g, ''));
  const rows = lines.slice(lines.indexOf(header) + 1).map((l) => l.split(',').map(Number));
  return { fields, rows };
}

test('defaults and every preset show the readouts computed natively', async () => {
  for (const state of golden(ID).states) {
    const { page, errors, context } = await open(browser, `${server.url}?demo=${ID}&${state.query}`);
    await assertReadoutsMatch(page, state);
    assert.deepEqual(errors, []);
    await context.close();
  }
});

test('"match" tunes B to A: sliders move, readouts agree and the normalised curves coincide', async () => {
  const { page, errors, context } = await open(browser, `${server.url}?demo=${ID}`);
  await assertReadoutsMatch(page, goldenState(ID));
  assert.notEqual(await readout(page, 'zeta_B'), await readout(page, 'zeta_A'));
  const before = await csv(page, 'normalised');
  const colA = before.fields.findIndex((f) => f.startsWith('A:'));
  const colB = before.fields.findIndex((f) => f.startsWith('B:'));
  assert.ok(colA > 0 && colB > 0, `A and B columns in ${before.fields}`);
  const apart = Math.max(...before.rows.map((r) => Math.abs(r[colA] - r[colB])));
  assert.ok(apart > 0.1, `unmatched curves differ (${apart})`);
  const pixels = await canvasFingerprint(page, 'normalised');

  await page.check('#p-match');
  await page.waitForFunction(() => document.querySelector('[data-readout="match"]').dataset.value.startsWith('on'));
  const recorded = goldenState(ID, 'Mass–spring and RLC circuit, matched');
  await assertReadoutsMatch(page, recorded);
  for (const q of ['wn', 'zeta']) {
    const [a, b] = [Number(await readout(page, `${q}_A`)), Number(await readout(page, `${q}_B`))];
    assert.ok(Math.abs(a - b) <= 1e-12 * a, `${q}: A ${a}, B ${b}`);
  }
  // The tuned sliders show the derived values, and the URL follows.
  for (const [key, value] of recorded.derived) {
    const shown = Number(await page.inputValue(`input[type=number][data-key="${key}"]`));
    assert.ok(Math.abs(shown - Number(value)) <= 1e-3 * Number(value), `${key} shows ${shown}, want ${value}`);
  }
  await waitForUrlParam(page, 'match', '1');
  const after = await csv(page, 'normalised');
  const gap = Math.max(...after.rows.map((r) => Math.abs(r[colA] - r[colB])));
  assert.ok(gap <= 1e-12, `matched curves coincide (largest difference ${gap})`);
  const realtime = await csv(page, 'realtime');
  const rA = realtime.fields.findIndex((f) => f.startsWith('A:'));
  const rB = realtime.fields.findIndex((f) => f.startsWith('B:'));
  assert.ok(Math.max(...realtime.rows.map((r) => Math.abs(r[rA] - r[rB]))) <= 1e-12, 'and in real time');
  assert.notDeepEqual(await canvasFingerprint(page, 'normalised'), pixels);
  assert.deepEqual(errors, []);
  await context.close();
});

test('only the chosen machines\' sliders are shown once conditions apply', async () => {
  const { page, errors, context } = await open(browser, `${server.url}?demo=${ID}`);
  await applyConditions(page);
  assert.deepEqual(await visibleParams(page), ['A', 'A_m', 'A_c', 'A_k', 'B', 'B_L', 'B_R', 'B_C', 'match']);
  await page.selectOption('#p-A', { label: 'two-capacity thermal system' });
  await page.waitForFunction(() => document.querySelector('[data-readout="regime_A"]').dataset.value === 'overdamped');
  await applyConditions(page);
  const shown = await visibleParams(page);
  assert.deepEqual(shown.slice(0, 5), ['A', 'A_C1', 'A_R1', 'A_C2', 'A_R2']);
  assert.ok(!shown.includes('A_m'));
  assert.ok(Number(await readout(page, 'zeta_A')) > 1, 'the thermal system is overdamped');
  assert.deepEqual(errors, []);
  await context.close();
});

test('screenshots at 1280×800 and 360×740', async () => {
  for (const [w, h, query, name] of [
    [1280, 800, 'A=u-tube&B=storey&match=1', ''],
    [360, 740, 'A=u-tube&B=storey&match=1', ''],
    [1280, 800, 'A=servo&B=thermal&match=1', '-thermal'],
  ]) {
    const { page, errors, context } = await open(browser, `${server.url}?demo=${ID}&${query}`, {
      viewport: { width: w, height: h },
    });
    const [ink] = await canvasFingerprint(page, 'normalised');
    assert.ok(ink > 3000, `normalised plot has ink (${ink} px)`);
    await applyConditions(page);
    await fullShot(page, `${SHOTS}universality-${w}${name}.png`);
    assert.deepEqual(errors, []);
    await context.close();
  }
});
