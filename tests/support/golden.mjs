// The native snapshot tests (crates/app/tests/snapshots.rs, insta) record every demo's
// readouts at its defaults and presets. The end-to-end tests read those files and check
// that the page shows the same values, instead of recomputing physics in JavaScript.
import { readFileSync } from 'node:fs';
import assert from 'node:assert/strict';
import { open, caption } from './browser.mjs';
import { assertDrawn, assertRowCurrent } from './page.mjs';

const DIR = new URL('../../crates/app/tests/snapshots/', import.meta.url);

/** The recorded document of demo `id`: {id, spec, states: [{name, query, readouts, …}]}. */
export function golden(id) {
  const text = readFileSync(new URL(`${id}.snap`, DIR), 'utf8');
  // An insta file: a `---` header block, then the snapshot body.
  const body = text.split(/^---$/m).slice(2).join('---');
  return JSON.parse(body);
}

/** The recorded state named `name` ('defaults' or a preset's label) of demo `id`. */
export function goldenState(id, name = 'defaults') {
  const state = golden(id).states.find((s) => s.name === name);
  assert.ok(state, `${id}: no recorded state ${name}`);
  return state;
}

/** A recorded state's name as a file-name part: `Laden car 500 kg` → `laden-car-500-kg`. */
export function stateSlug(name) {
  return name.replace(/[^A-Za-z0-9]+/g, '-').replace(/^-|-$/g, '').toLowerCase();
}

/**
 * Asserts that each plot of `plots` (the demo's first figures, in declaration order) has
 * more than `minInk` inked pixels and the text alternative recorded for `state`.
 */
export async function assertFiguresMatch(page, state, plots, minInk) {
  await assertDrawn(page, plots, minInk);
  for (const [i, plot] of plots.entries()) {
    assert.equal(await caption(page, plot), state.figures[i].description, `${state.name}: ${plot} described as recorded`);
  }
}

/**
 * Asserts that every readout on the page equals the recorded one: text readouts exactly,
 * numbers to the 12 significant digits recorded. Readouts that measure time are skipped.
 */
export async function assertReadoutsMatch(page, state) {
  const shown = await page.$$eval('[data-readout]', (els) =>
    els.map((e) => ({ key: e.dataset.readout, value: e.dataset.value })),
  );
  const byKey = new Map(shown.map((r) => [r.key, r.value]));
  for (const r of state.readouts) {
    if ('measured' in r) continue;
    assert.ok(byKey.has(r.key), `${state.name}: readout ${r.key} is on the page`);
    const value = byKey.get(r.key);
    const expected = r.value;
    const n = Number(expected);
    if (expected !== '' && Number.isFinite(n) && /e/.test(expected)) {
      const got = Number(value);
      assert.ok(
        Math.abs(got - n) <= 1e-11 * Math.max(1, Math.abs(n)),
        `${state.name}: ${r.key} shows ${value}, recorded ${expected}`,
      );
    } else {
      assert.equal(value, expected, `${state.name}: ${r.key}`);
    }
  }
}

/**
 * Waits until the page shows the readouts recorded for `state` (compared as
 * `assertReadoutsMatch` compares them), then asserts them with `assertReadoutsMatch`. For a
 * state reached by an action (a preset button, a key): the page applies it and writes the
 * readouts on the next animation frame, and a read before that frame sees the old values
 * ("m shows 1, recorded 4"). If the state never comes, the assertion says what differs.
 */
export async function waitForReadoutsMatch(page, state) {
  const want = state.readouts.filter((r) => !('measured' in r)).map((r) => [r.key, r.value]);
  await page
    .waitForFunction(
      (want) =>
        want.every(([key, expected]) => {
          const el = document.querySelector(`[data-readout="${key}"]`);
          if (!el) return false;
          const n = Number(expected);
          if (expected !== '' && Number.isFinite(n) && /e/.test(expected)) {
            return Math.abs(Number(el.dataset.value) - n) <= 1e-11 * Math.max(1, Math.abs(n));
          }
          return el.dataset.value === expected;
        }),
      want,
    )
    .catch((err) => {
      if (err.name !== 'TimeoutError') throw err;
    });
  await assertReadoutsMatch(page, state);
}

/**
 * Opens demo `id` at recorded `state` (the site served at `url`) and asserts what the page
 * shows: every readout as recorded (`assertReadoutsMatch`), the table row named by readout
 * `row` (if given) marked current, each plot of `plots` and the schematic drawn. Resolves to
 * `open`'s {page, errors, context}.
 */
export async function openRecorded(browser, url, id, state, { plots, row }) {
  const opened = await open(browser, `${url}?demo=${id}&${state.query}`);
  await assertReadoutsMatch(opened.page, state);
  if (row) await assertRowCurrent(opened.page, row);
  await assertDrawn(opened.page, plots, 2000);
  await assertDrawn(opened.page, ['schematic'], 500);
  return opened;
}
