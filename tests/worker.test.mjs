// End to end, issue 13: the heavy studies (the design sweep, the Monte Carlo run, the
// convergence study) run in the page's worker (web/study-worker.js), off the page's
// thread. What the page shows from the worker's study is what it shows when it computes
// the study itself (the worker cannot be loaded): the same readouts, to the last digit,
// and for the sweep and the Monte Carlo run the numbers the solver computes natively (the
// recorded snapshots; the integrators' are checked against them in integrators.test.mjs).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { open } from './support/browser.mjs';
import { goldenState, assertReadoutsMatch } from './support/golden.mjs';
import { useSession, server, browser } from './support/session.mjs';

useSession();

/** Each demo with a heavy study, and a preset (recorded in its snapshot) that starts one. */
const CASES = [
  ['design', 'Laden car 500 kg, same parts', true],
  ['uncertainty', 'RLC 20 % parts', true],
  ['integrators', 'Stiff overdamped ζ = 2, ωₙ = 20', false],
];

/** No worker script: the page has to compute its studies itself. */
const noWorker = (c) => c.route('**/study-worker.js', (route) => route.fulfill({ status: 404, body: '' }));

/**
 * Opens `demo`, waits for the full module (a first module's study is finished behind the
 * page by the full one before it takes over), clicks `preset` and waits for the full
 * study; resolves to {page, errors, context, worker, shown}: shown, every readout but the
 * compute time.
 */
async function study(demo, preset, options = {}) {
  const opened = await open(browser, `${server.url}?demo=${demo}`, options);
  const { page } = opened;
  await page.waitForFunction(() => window.zetaDiagnostics?.module() === 'full', null, { timeout: 20000 });
  const worker = options.before ? null : page.waitForEvent('worker');
  await page.locator('button.preset', { hasText: preset }).click();
  await page.waitForFunction(() => document.documentElement.dataset.studies);
  await page.waitForFunction(() => !document.querySelector('[data-provisional]'));
  const shown = await page.$$eval('[data-readout]', (els) =>
    els.filter((e) => e.dataset.readout !== 'compute_time').map((e) => [e.dataset.readout, e.dataset.value]),
  );
  return { ...opened, worker, shown };
}

for (const [demo, preset, recorded] of CASES) {
  test(`${demo}: the full study comes from the worker, the same as computed in the page`, async () => {
    const off = await study(demo, preset);
    assert.match((await off.worker).url(), /study-worker\.js$/);
    assert.equal(await off.page.getAttribute('html', 'data-studies'), 'worker');
    if (recorded) await assertReadoutsMatch(off.page, goldenState(demo, preset));

    const on = await study(demo, preset, { before: noWorker });
    assert.equal(await on.page.getAttribute('html', 'data-studies'), 'page');
    assert.deepEqual(off.shown, on.shown);
    assert.ok(on.shown.length > 5, `${demo}: readouts compared`);
    assert.deepEqual(off.errors, []);
    // A worker that cannot be loaded is a warning, never an error the page shows.
    assert.deepEqual(on.errors.filter((e) => !/study-worker/.test(e)), []);
    await off.context.close();
    await on.context.close();
  });
}
