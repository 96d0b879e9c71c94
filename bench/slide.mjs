// Shared by the browser benchmarks: quantiles, and the in-page timing of one slider event
// (the input handler plus the animation frame that redraws).

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
 * of its span and resolves to the event's main-thread time in ms. Installed as
 * `window.__slideOnce` by `installSlider`.
 */
export async function installSlider(page) {
  await page.evaluate(() => {
    const frame = () => new Promise((r) => requestAnimationFrame(() => r(performance.now())));
    window.__slideOnce = async (range, f) => {
      const min = Number(range.min);
      const max = Number(range.max);
      await frame(); // start from a quiet frame
      // Three callbacks of the same frame, in order: ours (start), the app's redraw, ours (end).
      let before = 0;
      requestAnimationFrame(() => {
        before = performance.now();
      });
      const t0 = performance.now();
      range.value = String(min + f * (max - min));
      range.dispatchEvent(new Event('input', { bubbles: true }));
      const handled = performance.now() - t0;
      const after = await frame();
      return handled + (after - before);
    };
  });
}

/** The i-th of a fixed, spread-out sequence of slider fractions in [0.1, 0.9]. */
export function fraction(i) {
  return 0.1 + 0.8 * (((i * 7919) % 97) / 96);
}
