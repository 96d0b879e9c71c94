// End to end, accessibility: axe-core finds no WCAG 2.1 A/AA violations on any demo in
// light and dark themes; a keyboard-only session completes a task in every demo (change a
// parameter, play, export) with focus moving in a logical order; the phone layout has no
// horizontal scroll. Screenshots land in target/screenshots/.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { createRequire } from 'node:module';
import { open, SHOTS, fullShot, drawn } from './support/browser.mjs';
import { useSession, server, browser, demoIds } from './support/session.mjs';

const require = createRequire(import.meta.url);
const AXE = require.resolve('axe-core/axe.min.js');

let ids;

useSession({
  setup: async () => {
    ids = await demoIds();
  },
});

test('axe-core finds no violations on any demo, light and dark', async () => {
  const failures = [];
  for (const id of ids) {
    for (const scheme of ['light', 'dark']) {
      // axe is injected as a script, which the page's CSP would (rightly) block.
      const { page, errors, context } = await open(browser, `${server.url}?demo=${id}`, { colorScheme: scheme, bypassCSP: true });
      await page.addScriptTag({ path: AXE });
      const result = await page.evaluate(async () => {
        const r = await window.axe.run(document, { runOnly: { type: 'tag', values: ['wcag2a', 'wcag2aa', 'wcag21a', 'wcag21aa'] } });
        return r.violations.map((v) => `${v.id}: ${v.nodes.slice(0, 3).map((n) => n.target.join(' ')).join(' | ')}`);
      });
      if (result.length) failures.push(`${id} (${scheme}): ${result.join('; ')}`);
      assert.deepEqual(errors, []);
      await context.close();
    }
  }
  assert.deepEqual(failures, []);
});

test('keyboard only: change a parameter, play and export in every demo, in a logical focus order', async () => {
  for (const id of ids) {
    const { page, errors, context } = await open(browser, `${server.url}?demo=${id}`);
    // Walk the whole tab order once: every control is reachable, in document order, no traps.
    const order = [];
    await page.focus('body');
    for (let i = 0; i < 200; i++) {
      await page.keyboard.press('Tab');
      const info = await page.evaluate(() => {
        const el = document.activeElement;
        const all = [...document.querySelectorAll('*')];
        return { index: all.indexOf(el), tag: el.tagName, key: el.dataset.key || el.dataset.export || el.className || el.id };
      });
      if (order.length && info.index <= order[order.length - 1].index) break; // wrapped around
      order.push(info);
    }
    assert.ok(order.length >= 5, `${id}: tab order reaches the controls`);
    assert.ok(order.some((o) => o.key === 'png'), `${id}: export buttons are reachable by Tab`);
    const slider = await page.$('.controls input[type=range]:not([disabled])');
    if (slider) {
      const firstSlider = order.find((o) => o.tag === 'INPUT' && o.key && !['share-button'].includes(o.key));
      assert.ok(firstSlider, `${id}: a parameter control is reachable by Tab`);
      // Change the first slider with the keyboard.
      const before = await page.$$eval('[data-readout]', (els) => els.map((e) => e.dataset.value).join('|'));
      await slider.focus();
      await page.keyboard.press('PageUp');
      await page.keyboard.press('ArrowRight');
      await page.waitForFunction((b) => [...document.querySelectorAll('[data-readout]')].map((e) => e.dataset.value).join('|') !== b, before);
    } else {
      // A page without parameters (the paper's tour): its links are reachable instead.
      assert.ok(order.some((o) => o.tag === 'A' && String(o.key).includes('tour-link')), `${id}: the tour's links are reachable by Tab`);
    }
    // Play with Space (from outside a text control), if the demo animates.
    if (await page.$('button.play')) {
      await page.focus('button.play');
      await page.keyboard.press('Space');
      await page.waitForFunction(() => document.querySelector('button.play').getAttribute('aria-pressed') === 'true');
      await page.keyboard.press('Space');
    }
    // Export with Enter.
    await page.focus('button[data-export="csv"]');
    const [dl] = await Promise.all([page.waitForEvent('download'), page.keyboard.press('Enter')]);
    assert.match(dl.suggestedFilename(), new RegExp(`^zeta-${id}-.*\\.csv$`));
    // Focus is visible: the focused element has an outline.
    const outline = await page.evaluate(() => getComputedStyle(document.activeElement).outlineStyle);
    assert.notEqual(outline, 'none', `${id}: visible focus`);
    assert.deepEqual(errors, []);
    await context.close();
  }
});

for (const scheme of ['light', 'dark']) {
  test(`phone (360 × 740) and laptop (1280 × 800) layouts, ${scheme}: no horizontal scroll`, async () => {
    for (const id of ids) {
      for (const [w, h] of [[360, 740], [1280, 800]]) {
        const { page, errors, context } = await open(browser, `${server.url}?demo=${id}`, { viewport: { width: w, height: h }, colorScheme: scheme });
        const overflow = await page.evaluate(() => document.documentElement.scrollWidth - document.documentElement.clientWidth);
        assert.ok(overflow <= 0, `${id} at ${w}px (${scheme}): horizontal overflow ${overflow}px`);
        await fullShot(page, `${SHOTS}${id}-${w}x${h}-${scheme}.png`);
        assert.deepEqual(errors, []);
        await context.close();
      }
    }
  });
}

test('reduced motion: autoplay=1 does not start the animation', async () => {
  const { page, errors, context } = await open(browser, `${server.url}?demo=regimes&autoplay=1`, { reducedMotion: 'reduce' });
  await page.waitForTimeout(400);
  assert.equal(await page.getAttribute('button.play', 'aria-pressed'), 'false');
  await context.close();
  const normal = await open(browser, `${server.url}?demo=regimes&autoplay=1`);
  await normal.page.waitForFunction(() => document.querySelector('button.play').getAttribute('aria-pressed') === 'true');
  assert.deepEqual([...errors, ...normal.errors], []);
  await normal.context.close();
});

test('touch: a tap on a plot shows the values under the finger; sliders move by touch', async () => {
  const { page, errors, context } = await open(browser, `${server.url}?demo=regimes`, { hasTouch: true, isMobile: true, viewport: { width: 360, height: 740 } });
  const plot = page.locator('canvas[data-plot="response"]');
  await plot.scrollIntoViewIfNeeded();
  // A plot just scrolled to is drawn once the page has seen it come into view (and just
  // after the full module took over, once the catch-up has redrawn it): tap what is shown.
  await drawn(page);
  const box = await plot.boundingBox();
  await page.touchscreen.tap(box.x + box.width * 0.5, box.y + box.height * 0.5);
  await page.waitForSelector('[data-plot-wrap="response"] .probe:not([hidden])');
  assert.match(await page.textContent('[data-plot-wrap="response"] .probe'), /time t = /);
  const slider = page.locator('#p-zeta');
  await slider.scrollIntoViewIfNeeded();
  const s = await slider.boundingBox();
  await page.touchscreen.tap(s.x + s.width * 0.9, s.y + s.height / 2);
  await page.waitForFunction(() => Number(document.querySelector('[data-readout="zeta"]').dataset.value) > 2);
  assert.deepEqual(errors, []);
  await context.close();
});

test('phone: a control reached with Shift+Tab lands below the stage stuck at the top, not under it (WCAG 2.4.11)', async () => {
  const { page, errors, context } = await open(browser, `${server.url}?demo=integrators`, { viewport: { width: 360, height: 740 } });
  await drawn(page);
  // From the second slider's number box, with the first slider scrolled above the window,
  // back through the second slider and the first one's number box to the first slider: each
  // is scrolled to as it takes the focus.
  await page.focus('input[type=number][data-key="wn"]');
  await page.evaluate(() => window.scrollBy(0, document.querySelector('input[type=range][data-key="zeta"]').getBoundingClientRect().bottom + 40));
  const seen = [];
  for (let i = 0; i < 3; i++) {
    await page.keyboard.press('Shift+Tab');
    seen.push(await page.evaluate(() => {
      const el = document.activeElement;
      const r = el.getBoundingClientRect();
      const stage = document.querySelector('.stage').getBoundingClientRect();
      const hit = document.elementFromPoint(r.left + r.width / 2, r.top + r.height / 2);
      const label = document.querySelector(`label[for="${el.id}"]`);
      const clear = r.top >= stage.bottom - 0.5 && r.bottom <= window.innerHeight + 0.5 && (hit === el || el.contains(hit) || label?.contains(hit));
      return `${el.dataset.key}(${el.type}) ${clear ? 'clear' : `covered: top ${Math.round(r.top)}, stage ends ${Math.round(stage.bottom)}`}`;
    }));
  }
  assert.deepEqual(seen, ['wn(range) clear', 'zeta(number) clear', 'zeta(range) clear']);
  assert.deepEqual(errors, []);
  await context.close();
});
