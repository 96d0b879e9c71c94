// Shared by the browser benchmarks: the command line, the served site with its browser and
// the demos to measure, quantiles, and the in-page timing of one slider event (the input
// handler plus the animation frame that redraws).
import { serve } from '../tests/support/server.mjs';
import { launch } from '../tests/support/browser.mjs';

/**
 * The benchmark's command line `[events] [demo,demo…]`: the number of events (at least 10,
 * `fallback` when not given) and the set of demo ids to measure (null: every demo).
 */
export function benchArgs(fallback) {
  const events = Math.max(10, Number(process.argv[2]) || fallback);
  const only = process.argv[3] ? new Set(process.argv[3].split(',')) : null;
  return { events, only };
}

/**
 * Serves the built site (`serveOptions`, see tests/support/server.mjs), launches Chromium,
 * and resolves to what `body(browser, url)` resolves to; closes both afterwards.
 */
export async function withSite(serveOptions, body) {
  const server = await serve(serveOptions);
  const browser = await launch();
  try {
    return await body(browser, server.url);
  } finally {
    await browser.close();
    await server.close();
  }
}

/** The ids of the demos in the page's picker at `url`, only those in `only` if it is a set. */
export async function demoIds(browser, url, only) {
  const probe = await browser.newPage();
  await probe.goto(url);
  await probe.waitForSelector('html[data-ready="true"]');
  const ids = await probe.$$eval('#demo-select option', (os) => os.map((o) => o.value));
  await probe.close();
  return ids.filter((id) => !only || only.has(id));
}

/** Runs `main`; on failure prints the error and exits with status 1. */
export function run(main) {
  main().catch((e) => {
    console.error(e);
    process.exit(1);
  });
}

/** The median, 95th percentile and largest of `values` (any order; not changed). */
export function spread(values) {
  const sorted = [...values].sort((a, b) => a - b);
  return { p50: quantile(sorted, 0.5), p95: quantile(sorted, 0.95), max: sorted[sorted.length - 1] };
}

/** The `q` quantile of an ascending array, linearly interpolated. */
export function quantile(sorted, q) {
  if (!sorted.length) return NaN;
  const i = (sorted.length - 1) * q;
  const lo = Math.floor(i);
  const hi = Math.ceil(i);
  return sorted[lo] + (sorted[hi] - sorted[lo]) * (i - lo);
}

/**
 * Source of a function to run in the page (`page.evaluate`): moves `range` to fraction `f`
 * of its span and resolves to the event's main-thread time in ms, `{script, frame}`:
 * `script` the input handler and the redrawing frame's animation-frame callbacks, `frame`
 * that and the rest of the frame's main-thread work after the callbacks (style, layout,
 * paint, and any task the page queued before the frame ended; a frame is on time when the
 * whole of it fits in 16.7 ms). Installed as `window.__slideOnce` by `installSlider`.
 */
export async function installSlider(page) {
  await page.evaluate(() => {
    // When each frame's first animation-frame callback began, by the frame's timestamp:
    // every callback, the app's included, goes through this wrapper from now on.
    const raf = window.requestAnimationFrame.bind(window);
    const firstCallback = new Map();
    window.requestAnimationFrame = (cb) =>
      raf((ts) => {
        if (!firstCallback.has(ts)) firstCallback.set(ts, performance.now());
        cb(ts);
      });
    const frame = () => new Promise((r) => requestAnimationFrame((ts) => r(ts)));
    // When the current task ends: a message posted in a frame's callbacks is handled after
    // the frame's style, layout and paint, which run in the same task after them.
    const taskEnd = () => new Promise((r) => {
      const channel = new MessageChannel();
      channel.port1.onmessage = () => r(performance.now());
      channel.port2.postMessage(0);
    });
    window.__slideOnce = async (range, f) => {
      const min = Number(range.min);
      const max = Number(range.max);
      await frame(); // start from a quiet frame
      firstCallback.clear();
      const t0 = performance.now();
      range.value = String(min + f * (max - min));
      range.dispatchEvent(new Event('input', { bubbles: true }));
      const handled = performance.now() - t0;
      // The frame that redraws: from its first callback to ours, registered after the
      // app's redraw. From its first callback, not from one of ours registered before the
      // input: an app that asked for the frame earlier (a study finishing, a plot scrolled
      // into view) has its callback run before any of ours.
      const ts = await frame();
      const start = firstCallback.get(ts);
      const script = handled + (performance.now() - start);
      return { script, frame: handled + ((await taskEnd()) - start) };
    };
  });
}

/** The i-th of a fixed, spread-out sequence of slider fractions in [0.1, 0.9]. */
export function fraction(i) {
  return 0.1 + 0.8 * (((i * 7919) % 97) / 96);
}
