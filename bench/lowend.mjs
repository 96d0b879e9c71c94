// Low-end benchmark: the school Chromebook and the phone, stood in for as Lighthouse's
// mobile emulation does (DevTools Protocol): CPU slowed 4×, a 360 × 740 window at device
// pixel ratio 2, and for loading "Slow 4G" (150 ms round trip, 1.6 Mbit/s down) with the
// site served brotli-compressed and a cold cache.
// For every demo: every slider scrolled into view and moved EVENTS times (input handler + the frame that redraws)
// as p50/p95, and again with the rest of that frame's main-thread work (style, layout and
// paint after the animation-frame callbacks: a frame keeps 60 fps only if the whole of it
// fits in 16.7 ms), the longest main-thread task seen while sliding, the time to the first plot
// after navigation, the bytes of the requests made before it (not what the page fetches at
// idle just after it), and both again on a second visit (the service worker then answers
// every file but the page). Prints Markdown tables.
// ZETA_RUNS=n measures each demo n times (one after another, n ≥ 1, default 1) and reports
// each column's median over the runs, with the p95's range: on a noisy machine a single
// run's p95 moves by several milliseconds.
// ZETA_ROOT=dir measures the build in dir instead of dist/.
// Usage: node bench/lowend.mjs [events-per-slider] [demo,demo…]   (after scripts/build.sh)
import { resolve } from 'node:path';
import { countBytes } from '../tests/support/browser.mjs';
import { quantile, spread, installSlider, fraction, benchArgs, withSite, demoIds, run } from './slide.mjs';

const { events: EVENTS, only: ONLY } = benchArgs(40);
const CPU_SLOWDOWN = 4;
/** Each slider's moves as one drag (see slideInPage); ZETA_TAPS=1: as separate changes. */
const HOLD = process.env.ZETA_TAPS !== '1';
/** Each slider scrolled into view before it moves (see slideInPage); ZETA_SCROLL=0: not. */
const SCROLL = process.env.ZETA_SCROLL !== '0';
const RUNS = Math.max(1, Math.floor(Number(process.env.ZETA_RUNS)) || 1);
/** ZETA_ROOT=dir serves another build than dist/ (an A/B run of two builds, each copied aside). */
const ROOT = process.env.ZETA_ROOT ? resolve(process.env.ZETA_ROOT) : undefined;
const SLOW_4G = { offline: false, latency: 150, downloadThroughput: (1.6 * 1024 * 1024) / 8, uploadThroughput: (750 * 1024) / 8 };

/**
 * Runs in the page: moves each slider `n` times; per event, handler + redraw frame. With
 * `hold`, each slider's moves are one drag, as a finger or a mouse makes them: the pointer
 * goes down on the slider first and up after (the page holds the axes meanwhile);
 * without, they are separate changes, as a click on the track or a typed value makes them.
 */
async function slideInPage([n, fractions, hold, scroll]) {
  const longest = { ms: 0 };
  const obs = new PerformanceObserver((list) => {
    for (const e of list.getEntries()) longest.ms = Math.max(longest.ms, e.duration);
  });
  obs.observe({ type: 'longtask', buffered: false });
  const ranges = [...document.querySelectorAll('input[type=range][data-key]')].filter((r) => !r.disabled);
  const events = [];
  for (const range of ranges) {
    // As a hand must see the slider it drags: in the middle of what the stage stuck at the
    // window's top leaves (the page's scroll padding), the page given time to see what is
    // in view now. ZETA_SCROLL=0: left where the page opened, as before 2026-12-04 evening
    // (a slider below the window moved).
    if (scroll) {
      range.scrollIntoView({ block: 'center' });
      await new Promise((r) => setTimeout(r, 500));
    }
    if (hold) range.dispatchEvent(new PointerEvent('pointerdown', { bubbles: true }));
    for (let i = 0; i < n; i++) events.push(await window.__slideOnce(range, fractions[i]));
    if (hold) {
      window.dispatchEvent(new PointerEvent('pointerup'));
      // A hand lets go and reaches for the next slider: the axes refit meanwhile.
      await new Promise((r) => setTimeout(r, 500));
    }
  }
  await new Promise((r) => requestAnimationFrame(r));
  obs.disconnect();
  return { events, longest: longest.ms, sliders: ranges.length };
}

async function lowEndPage(browser, { network }) {
  const context = await browser.newContext({ viewport: { width: 360, height: 740 }, deviceScaleFactor: 2, isMobile: true, hasTouch: true });
  const page = await context.newPage();
  const cdp = await context.newCDPSession(page);
  await cdp.send('Emulation.setCPUThrottlingRate', { rate: CPU_SLOWDOWN });
  await cdp.send('Network.enable');
  await cdp.send('Network.setCacheDisabled', { cacheDisabled: true });
  if (network) await cdp.send('Network.emulateNetworkConditions', SLOW_4G);
  return { context, page, cdp, ...countBytes(cdp) };
}

async function main() {
  const rows = [];
  await withSite({ brotli: true, root: ROOT }, async (browser, url) => {
    for (const id of await demoIds(browser, url, ONLY)) {
      const runs = [];
      for (let i = 0; i < RUNS; i++) runs.push(await measure(browser, url, id));
      rows.push(medianRow(id, runs));
    }
  });
  const repeated = RUNS > 1 ? `; each column the median of ${RUNS} runs, p95's range in brackets` : '';
  console.log(`\nLow-end (4× CPU, 360 × 740 at DPR 2; loading on Slow 4G, brotli, cold cache; ${EVENTS} events per slider, ${HOLD ? "each slider one held drag" : "separate changes"}${SCROLL ? ", scrolled into view first" : ", the page left at its top"}${repeated}):\n`);
  console.log('| demo | sliders | events | p50 (ms) | p95 (ms) | with style, layout, paint: p50 (ms) | p95 (ms) | longest task (ms) | longest task from the first plot through the switch to the full module (ms) | first plot (ms) | KB before first plot | second visit: first plot (ms) | second visit: KB |');
  console.log('| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |');
  for (const r of rows) {
    const range = RUNS > 1 ? ` [${r.p95Range.map((v) => v.toFixed(1)).join('–')}]` : '';
    console.log(`| ${r.id} | ${r.sliders} | ${r.n} | ${r.p50.toFixed(1)} | ${r.p95.toFixed(1)}${range} | ${r.frameP50.toFixed(1)} | ${r.frameP95.toFixed(1)} | ${r.longest.toFixed(0)} | ${r.switchTask.toFixed(0)} | ${r.firstPlot.toFixed(0)} | ${(r.bytes / 1000).toFixed(1)} | ${r.secondPlot.toFixed(0)} | ${(r.secondBytes / 1000).toFixed(0)} |`);
  }
}

/** The median of the numbers in `values` (NaN if there are none). */
function median(values) {
  const v = values.filter((x) => !Number.isNaN(x)).sort((a, b) => a - b);
  return v.length ? quantile(v, 0.5) : NaN;
}

/** One row from several runs of a demo: each column's median, and the range of the p95s. */
function medianRow(id, runs) {
  const row = { id, sliders: runs[0].sliders, n: runs[0].n };
  for (const k of ['p50', 'p95', 'frameP50', 'frameP95', 'longest', 'switchTask', 'firstPlot', 'bytes', 'secondPlot', 'secondBytes']) {
    row[k] = median(runs.map((r) => r[k]));
  }
  const p95s = runs.map((r) => r.p95);
  row.p95Range = [Math.min(...p95s), Math.max(...p95s)];
  return row;
}

/** One run for demo `id`: loading (first and second visit), the switch, then sliding. */
async function measure(browser, url, id) {
  // Loading: Slow 4G + 4× CPU, cold cache; bytes counted up to the first plot.
  const load = await lowEndPage(browser, { network: true });
  await load.page.goto(`${url}?demo=${id}`);
  await load.page.waitForFunction(() => performance.getEntriesByName('zeta:first-draw').length > 0, null, { timeout: 60000 });
  const { firstPlot, firstPlotWall } = await load.page.evaluate(() => {
    const ms = performance.getEntriesByName('zeta:first-draw')[0].startTime;
    return { firstPlot: ms, firstPlotWall: performance.timeOrigin + ms };
  });
  const bytes = load.bytesSentBefore(firstPlotWall);
  // Second visit, same network and CPU: from the service worker's cache once it controls
  // the page (the navigation itself still goes to the network first).
  await load.page.evaluate(() => navigator.serviceWorker?.ready);
  const before = load.bytes();
  await load.page.goto(`${url}?demo=${id}`);
  await load.page.waitForFunction(() => performance.getEntriesByName('zeta:first-draw').length > 0, null, { timeout: 60000 });
  const again = await load.page.evaluate(() => ({
    ms: performance.getEntriesByName('zeta:first-draw')[0].startTime,
    controlled: Boolean(navigator.serviceWorker?.controller),
  }));
  const secondPlot = again.controlled ? again.ms : NaN;
  const secondBytes = load.bytes() - before;
  await load.context.close();
  // Sliding: 4× CPU, no network shaping (the page is loaded).
  const slide = await lowEndPage(browser, { network: false });
  await slide.page.goto(`${url}?demo=${id}`);
  await slide.page.waitForSelector('html[data-ready="true"]', { timeout: 60000 });
  await slide.page.waitForFunction(() => performance.getEntriesByName('zeta:first-draw').length > 0, null, { timeout: 60000 });
  // The switch from the demo's first module to the full one (once, after the first
  // plot, while the controls rest): its longest task, then sliding on the full module.
  const switchTask = await slide.page.evaluate(async () => {
    let longest = 0;
    const since = performance.getEntriesByName('zeta:first-draw')[0].startTime;
    // Buffered: from the load on; only the tasks after the first plot count here.
    const obs = new PerformanceObserver((list) => {
      for (const e of list.getEntries()) if (e.startTime > since) longest = Math.max(longest, e.duration);
    });
    obs.observe({ type: 'longtask', buffered: true });
    const deadline = performance.now() + 30000;
    while ((window.zetaDiagnostics.module() !== 'full' || !window.zetaDiagnostics.drawn()) && performance.now() < deadline) {
      await new Promise((r) => setTimeout(r, 50));
    }
    if (window.zetaDiagnostics.module() !== 'full') return NaN; // the switch never came
    await new Promise((r) => setTimeout(r, 500));
    obs.disconnect();
    return longest;
  });
  await installSlider(slide.page);
  const fractions = Array.from({ length: EVENTS }, (_, i) => fraction(i));
  const r = await slide.page.evaluate(slideInPage, [EVENTS, fractions, HOLD, SCROLL]);
  await slide.context.close();
  const script = spread(r.events.map((e) => e.script));
  const frame = spread(r.events.map((e) => e.frame));
  return {
    sliders: r.sliders, n: r.events.length, p50: script.p50, p95: script.p95, frameP50: frame.p50, frameP95: frame.p95,
    longest: r.longest, switchTask, firstPlot, bytes, secondPlot, secondBytes,
  };
}

run(main);
