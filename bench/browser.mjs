// Browser benchmark: for every demo, the main-thread work of one slider event (input
// handling plus the animation frame that redraws) as p50/p95 over ≥ 300 events, and its
// whole frame (with the browser's style, layout and paint after the callbacks), the time
// to the first drawn plot on a cold load, and the bytes shipped. Prints a Markdown table.
// Usage: node bench/browser.mjs [events-per-demo] [demo,demo…]   (after scripts/build.sh)
import { gzipSync } from 'node:zlib';
import { readFileSync, readdirSync } from 'node:fs';
import { join } from 'node:path';
import { DIST } from '../tests/support/server.mjs';
import { quantile, spread, installSlider, fraction, benchArgs, withSite, demoIds, run } from './slide.mjs';

const { events: EVENTS, only: ONLY } = benchArgs(300);

/** Runs in the page: moves sliders `n` times and times each event's work and whole frame. */
async function measureInPage([n, fractions]) {
  const ranges = [...document.querySelectorAll('.controls input[type=range]')];
  const events = [];
  if (!ranges.length) return events; // a demo without sliders (the paper)
  for (let i = 0; i < n; i++) events.push(await window.__slideOnce(ranges[i % ranges.length], fractions[i]));
  return events;
}

/**
 * The `compute_time` readout (ms) of the page at `url` after each value of `values` is typed
 * into parameter `key`'s number box, once the address shows it and any coarse stand-in
 * (issue 13) has given way to the full study; ascending.
 */
async function computeTimes(page, url, key, values) {
  await page.goto(url);
  await page.waitForSelector('html[data-ready="true"]');
  const box = `input[type=number][data-key="${key}"]`;
  const times = [];
  for (const v of values) {
    await page.fill(box, String(v));
    await page.press(box, 'Enter');
    await page.waitForFunction(([k, vv]) => new URLSearchParams(location.search).get(k) === String(vv), [key, v]);
    await page.waitForFunction(() => !document.querySelector('[data-provisional]'));
    times.push(await page.evaluate(() => Number(document.querySelector('[data-readout="compute_time"]').dataset.value)));
  }
  return times.sort((a, b) => a - b);
}

async function main() {
  const rows = [];
  await withSite({}, async (browser, url) => {
    for (const id of await demoIds(browser, url, ONLY)) {
      const context = await browser.newContext({ viewport: { width: 1280, height: 800 } });
      const page = await context.newPage();
      await page.goto(`${url}?demo=${id}`);
      await page.waitForSelector('html[data-ready="true"]');
      await page.waitForFunction(() => performance.getEntriesByName('zeta:first-draw').length > 0);
      const firstDraw = await page.evaluate(() => performance.getEntriesByName('zeta:first-draw')[0].startTime);
      await installSlider(page);
      const fractions = Array.from({ length: EVENTS }, (_, i) => fraction(i));
      const events = await page.evaluate(measureInPage, [EVENTS, fractions]);
      if (!events.length) {
        await context.close();
        continue;
      }
      const script = spread(events.map((e) => e.script));
      const frame = spread(events.map((e) => e.frame));
      rows.push({ id, n: events.length, ...script, frameP50: frame.p50, frameP95: frame.p95, firstDraw });
      await context.close();
    }
  });
  // The two heavy computations the issues budget separately, read from the demos' own
  // `compute_time` readouts (measured in wasm around the solver call). Pages that show a
  // coarse study first (issue 13) are read once the full one is shown: its compute time is
  // the sum of its slices.
  const compute = await withSite({}, async (browser, url) => {
    const page = await browser.newPage({ viewport: { width: 1280, height: 800 } });
    const masses = Array.from({ length: 40 }, (_, i) => 250 + (i % 2 ? 7 : 0) + i);
    const sweeps = await computeTimes(page, `${url}?demo=design&n=100`, 'm', masses);
    const seeds = Array.from({ length: 12 }, (_, i) => 11 + i);
    const runs = await computeTimes(page, `${url}?demo=uncertainty&N=100000`, 'seed', seeds);
    return [
      ['design: 100 × 100 (k, c) sweep on a mass change', quantile(sweeps, 0.5), quantile(sweeps, 0.95), '< 16 ms'],
      ['uncertainty: Monte Carlo, 100 000 draws', quantile(runs, 0.5), quantile(runs, 0.95), '< 200 ms'],
    ];
  });
  const files = ['zeta-app_bg.wasm', 'zeta-app.js', ...readdirSync(join(DIST, 'web')).filter((f) => f.endsWith('.js')).map((f) => `web/${f}`)];
  let wasmRaw = 0, wasmGz = 0, jsRaw = 0, jsGz = 0;
  for (const f of files) {
    const buf = readFileSync(join(DIST, f));
    const gz = gzipSync(buf, { level: 9 }).length;
    if (f.endsWith('.wasm')) { wasmRaw += buf.length; wasmGz += gz; } else { jsRaw += buf.length; jsGz += gz; }
  }
  console.log(`\nSlider events in headless Chromium (${EVENTS} per demo; input handling + the redraw frame's callbacks, then the whole frame with style, layout and paint):\n`);
  console.log('| demo | events | p50 (ms) | p95 (ms) | max (ms) | frame p50 (ms) | frame p95 (ms) | first plot, cold load (ms) |');
  console.log('| --- | --- | --- | --- | --- | --- | --- | --- |');
  for (const r of rows) {
    console.log(`| ${r.id} | ${r.n} | ${r.p50.toFixed(2)} | ${r.p95.toFixed(2)} | ${r.max.toFixed(2)} | ${r.frameP50.toFixed(2)} | ${r.frameP95.toFixed(2)} | ${r.firstDraw.toFixed(0)} |`);
  }
  console.log('\nHeavy computations in the browser (compute_time readouts):\n');
  console.log('| computation | p50 (ms) | p95 (ms) | target |');
  console.log('| --- | --- | --- | --- |');
  for (const [name, p50, p95, target] of compute) console.log(`| ${name} | ${p50.toFixed(1)} | ${p95.toFixed(1)} | ${target} |`);
  const kb = (b) => (b / 1024).toFixed(1);
  console.log(`\nBytes: wasm ${kb(wasmRaw)} KiB (${kb(wasmGz)} KiB gzipped), JS ${kb(jsRaw)} KiB (${kb(jsGz)} KiB gzipped), total gzipped ${kb(wasmGz + jsGz)} KiB`);
}

run(main);
