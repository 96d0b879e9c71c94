// Browser benchmark: for every demo, the main-thread work of one slider event (input
// handling plus the animation frame that redraws) as p50/p95 over ≥ 300 events, the time
// to the first drawn plot on a cold load, and the bytes shipped. Prints a Markdown table.
// Usage: node bench/browser.mjs [events-per-demo] [demo,demo…]   (after scripts/build.sh)
import { gzipSync } from 'node:zlib';
import { readFileSync, readdirSync } from 'node:fs';
import { join } from 'node:path';
import { serve, DIST } from '../tests/support/server.mjs';
import { launch } from '../tests/support/browser.mjs';
import { quantile, installSlider, fraction } from './slide.mjs';

const EVENTS = Math.max(10, Number(process.argv[2]) || 300);
// Optional second argument: only these demos (comma-separated ids).
const ONLY = process.argv[3] ? new Set(process.argv[3].split(',')) : null;

/** Runs in the page: moves sliders `n` times and times each event's work. */
async function measureInPage([n, fractions]) {
  const ranges = [...document.querySelectorAll('.controls input[type=range]')];
  const times = [];
  for (let i = 0; i < n; i++) times.push(await window.__slideOnce(ranges[i % ranges.length], fractions[i]));
  return times;
}

async function main() {
  const server = await serve();
  const browser = await launch();
  const rows = [];
  try {
    const probe = await browser.newPage();
    await probe.goto(server.url);
    await probe.waitForSelector('html[data-ready="true"]');
    const ids = (await probe.$$eval('#demo-select option', (os) => os.map((o) => o.value))).filter((id) => !ONLY || ONLY.has(id));
    await probe.close();
    for (const id of ids) {
      const context = await browser.newContext({ viewport: { width: 1280, height: 800 } });
      const page = await context.newPage();
      await page.goto(`${server.url}?demo=${id}`);
      await page.waitForSelector('html[data-ready="true"]');
      await page.waitForFunction(() => performance.getEntriesByName('zeta:first-draw').length > 0);
      const firstDraw = await page.evaluate(() => performance.getEntriesByName('zeta:first-draw')[0].startTime);
      await installSlider(page);
      const fractions = Array.from({ length: EVENTS }, (_, i) => fraction(i));
      const times = (await page.evaluate(measureInPage, [EVENTS, fractions])).sort((a, b) => a - b);
      rows.push({ id, n: times.length, p50: quantile(times, 0.5), p95: quantile(times, 0.95), max: times[times.length - 1], firstDraw });
      await context.close();
    }
  } finally {
    await browser.close();
    await server.close();
  }
  // The two heavy computations the issues budget separately, read from the demos' own
  // `compute_time` readouts (measured in wasm around the solver call). Pages that show a
  // coarse study first (issue 13) are read once the full one is shown: its compute time is
  // the sum of its slices.
  const full = (page) => page.waitForFunction(() => !document.querySelector('[data-provisional]'));
  const compute = [];
  {
    const b2 = await launch();
    const srv = await serve();
    try {
      const page = await b2.newPage({ viewport: { width: 1280, height: 800 } });
      const read = () => page.evaluate(() => Number(document.querySelector('[data-readout="compute_time"]').dataset.value));
      await page.goto(`${srv.url}?demo=design&n=100`);
      await page.waitForSelector('html[data-ready="true"]');
      const sweeps = [];
      for (let i = 0; i < 40; i++) {
        const m = 250 + (i % 2 ? 7 : 0) + i;
        await page.fill('input[type=number][data-key="m"]', String(m));
        await page.press('input[type=number][data-key="m"]', 'Enter');
        await page.waitForFunction((mm) => new URLSearchParams(location.search).get('m') === String(mm), m);
        await full(page);
        sweeps.push(await read());
      }
      sweeps.sort((a, b) => a - b);
      compute.push(['design: 100 × 100 (k, c) sweep on a mass change', quantile(sweeps, 0.5), quantile(sweeps, 0.95), '< 16 ms']);
      await page.goto(`${srv.url}?demo=uncertainty&N=100000`);
      await page.waitForSelector('html[data-ready="true"]');
      const runs = [];
      for (let i = 11; i <= 22; i++) {
        await page.fill('input[type=number][data-key="seed"]', String(i));
        await page.press('input[type=number][data-key="seed"]', 'Enter');
        await page.waitForFunction((sd) => new URLSearchParams(location.search).get('seed') === String(sd), i);
        await full(page);
        runs.push(await read());
      }
      runs.sort((a, b) => a - b);
      compute.push(['uncertainty: Monte Carlo, 100 000 draws', quantile(runs, 0.5), quantile(runs, 0.95), '< 200 ms']);
    } finally {
      await b2.close();
      await srv.close();
    }
  }
  const files = ['zeta-app_bg.wasm', 'zeta-app.js', ...readdirSync(join(DIST, 'web')).filter((f) => f.endsWith('.js')).map((f) => `web/${f}`)];
  let wasmRaw = 0, wasmGz = 0, jsRaw = 0, jsGz = 0;
  for (const f of files) {
    const buf = readFileSync(join(DIST, f));
    const gz = gzipSync(buf, { level: 9 }).length;
    if (f.endsWith('.wasm')) { wasmRaw += buf.length; wasmGz += gz; } else { jsRaw += buf.length; jsGz += gz; }
  }
  console.log(`\nSlider events in headless Chromium (${EVENTS} per demo; input handling + the redraw frame):\n`);
  console.log('| demo | events | p50 (ms) | p95 (ms) | max (ms) | first plot, cold load (ms) |');
  console.log('| --- | --- | --- | --- | --- | --- |');
  for (const r of rows) {
    console.log(`| ${r.id} | ${r.n} | ${r.p50.toFixed(2)} | ${r.p95.toFixed(2)} | ${r.max.toFixed(2)} | ${r.firstDraw.toFixed(0)} |`);
  }
  console.log('\nHeavy computations in the browser (compute_time readouts):\n');
  console.log('| computation | p50 (ms) | p95 (ms) | target |');
  console.log('| --- | --- | --- | --- |');
  for (const [name, p50, p95, target] of compute) console.log(`| ${name} | ${p50.toFixed(1)} | ${p95.toFixed(1)} | ${target} |`);
  const kb = (b) => (b / 1024).toFixed(1);
  console.log(`\nBytes: wasm ${kb(wasmRaw)} KiB (${kb(wasmGz)} KiB gzipped), JS ${kb(jsRaw)} KiB (${kb(jsGz)} KiB gzipped), total gzipped ${kb(wasmGz + jsGz)} KiB`);
}

main().catch((e) => {
  console.error(e);
  process.exit(1);
});
