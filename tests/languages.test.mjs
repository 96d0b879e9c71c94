// End to end, languages (issue 17). The demos and the languages are read from the page
// (its demo menu and the module's language list), so a new demo or a new catalogue is
// tested without touching this file.
//
// - Every demo in every language shows no untranslated message: the module reports, by
//   id, each message it had to show in English (zetaDiagnostics.missingMessages()), after
//   the page opened, a slider moved and the Share dialog opened and closed.
// - Numbers follow the language's CLDR rules (decimal comma in es/fr/pt-BR, point in
//   zh-CN) in readouts and in an exported SVG's ticks; data-value stays locale-free.
// - Language choice: the header menu switches page and demo keeping the values, lang= is
//   kept in the address, the choice is remembered; only that catalogue is downloaded; a
//   failed download leaves the page English with a notice.
// - Pseudo-locales en-XA and ar-XB at 360 × 740 and 1280 × 800: no sideways scroll, no
//   clipped control text, no English that escaped the catalogues (en-XA), the layout
//   mirrored (ar-XB). axe-core finds nothing in fr, zh-CN and ar-XB.
//
// ZETA_DEMOS=regimes,… and ZETA_LANGS=fr,… narrow the run while working on a few.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { createRequire } from 'node:module';
import { readFile } from 'node:fs/promises';
import { serve } from './support/server.mjs';
import { launch, open, SHOTS } from './support/browser.mjs';

const require = createRequire(import.meta.url);
const AXE = require.resolve('axe-core/axe.min.js');

let server;
let browser;
let ids;
let langs;

const only = (name) => (process.env[name] ? new Set(process.env[name].split(',')) : null);

before(async () => {
  server = await serve();
  browser = await launch();
  const { page, context } = await open(browser, `${server.url}?lang=en`);
  ids = await page.$$eval('#demo-select option', (os) => os.map((o) => o.value));
  langs = await page.evaluate(() => window.zetaDiagnostics.languages());
  await context.close();
  const demos = only('ZETA_DEMOS');
  if (demos) ids = ids.filter((id) => demos.has(id));
  const wanted = only('ZETA_LANGS');
  if (wanted) langs = langs.filter((l) => wanted.has(l.tag) || l.pseudo);
});

after(async () => {
  await browser?.close();
  await server?.close();
});

const real = () => langs.filter((l) => !l.pseudo).map((l) => l.tag);

/** Opens `id` in language `tag` on an existing page and waits for the first readouts. */
async function goto(page, query) {
  await page.goto(`${server.url}?${query}`);
  await page.waitForSelector('html[data-ready="true"]', { timeout: 15000 });
  await page.waitForFunction(() => {
    const items = [...document.querySelectorAll('[data-readout]')];
    return items.every((r) => r.querySelector('dd').textContent !== '—' || r.dataset.value === '');
  });
}

/** Moves the first slider one step (if the demo has one) and waits for a redraw. */
async function moveASlider(page) {
  const slider = await page.$('.controls input[type=range]:not([disabled])');
  if (!slider) return;
  const before = await page.$$eval('[data-readout]', (els) => els.map((e) => e.dataset.value).join('|'));
  await slider.focus();
  await page.keyboard.press('ArrowRight');
  await page.waitForFunction(
    (b) => [...document.querySelectorAll('[data-readout]')].map((e) => e.dataset.value).join('|') !== b,
    before,
    { timeout: 5000 },
  ).catch(() => {}); // a slider that changes no readout (only a plot) is fine
  await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
}

test('every demo in every language shows no untranslated message (checked by id)', async () => {
  const failures = [];
  for (const tag of real()) {
    const context = await browser.newContext({ viewport: { width: 1280, height: 800 } });
    const page = await context.newPage();
    const errors = [];
    page.on('pageerror', (e) => errors.push(String(e)));
    for (const id of ids) {
      await goto(page, `demo=${id}&lang=${tag}`);
      assert.equal(await page.getAttribute('html', 'lang'), tag);
      await moveASlider(page);
      await page.click('#share-button');
      await page.waitForSelector('dialog#share-dialog[open]');
      await page.click('#share-dialog .share-close');
      await page.waitForSelector('dialog#share-dialog', { state: 'detached' });
      const missing = await page.evaluate(() => window.zetaDiagnostics.missingMessages());
      if (missing.length) failures.push(`${tag} ${id}: ${missing.length} in English: ${missing.slice(0, 12).join(', ')}`);
    }
    assert.deepEqual(errors, [], tag);
    await context.close();
  }
  assert.equal(failures.length, 0, `${failures.length} problems:\n${failures.join('\n')}`);
});

test('numbers follow the language: readouts, the animation clock and an SVG export', async () => {
  const comma = ['es', 'fr', 'pt-BR'];
  for (const tag of real().filter((l) => l !== 'en')) {
    const { page, errors, context } = await open(browser, `${server.url}?demo=regimes&zeta=0.25&lang=${tag}`, { acceptDownloads: true });
    const sep = comma.includes(tag) ? ',' : '.';
    assert.equal(await page.textContent('[data-readout="wn"] dd'), `6${sep}000 rad/s`, tag);
    assert.equal(await page.getAttribute('[data-readout="wn"]', 'data-value'), '6');
    assert.equal(await page.textContent('.anim-time'), `t = 0${sep}00 s`, tag);
    const [dl] = await Promise.all([
      page.waitForEvent('download'),
      page.click('[data-plot-wrap="response"] button[data-export="svg"]'),
    ]);
    const svg = (await readFile(await dl.path())).toString('utf8');
    const ticks = [...svg.matchAll(/>\s*(-?[0-9]+[.,][0-9]+)\s*</g)].map((m) => m[1]);
    assert.ok(ticks.length >= 2, `${tag}: decimal tick labels in the SVG: ${ticks}`);
    assert.ok(ticks.every((x) => x.includes(sep)), `${tag}: ticks ${ticks.slice(0, 6)}`);
    // The address keeps plain numbers.
    assert.equal(new URL(page.url()).searchParams.get('zeta'), '0.25');
    assert.deepEqual(errors, []);
    await context.close();
  }
});

test('English numbers are written as Intl writes them, without building an Intl.NumberFormat (its first costs ~150 ms at 4× CPU)', async () => {
  // Notes each Intl.NumberFormat the page builds: the time since the first plot, or -1 before it.
  const before = (context) =>
    context.addInitScript(() => {
      const Native = Intl.NumberFormat;
      window.__numberFormats = [];
      Intl.NumberFormat = function (...args) {
        const drawn = performance.getEntriesByName('zeta:first-draw')[0];
        window.__numberFormats.push(drawn ? Math.round(performance.now() - drawn.startTime) : -1);
        return new Native(...args);
      };
      Intl.NumberFormat.prototype = Native.prototype;
    });
  // Quarter-car has an animation clock, written in the first frame.
  const { page, errors, context } = await open(browser, `${server.url}?demo=quarter-car&lang=en`, { before });
  assert.equal(await page.textContent('.anim-time'), 't = 0.00 s');
  const built = await page.evaluate(() => window.__numberFormats);
  assert.deepEqual(built, [], 'Intl.NumberFormat built (ms after the first plot)');
  // The page's English form is Intl's, digit for digit: its rounding of the shortest decimal
  // (1.005 → 1.01), half away from zero, grouping, signs.
  const mismatches = await page.evaluate(async () => {
    const { num } = await import(new URL('web/i18n.js', document.baseURI).href);
    const values = [0, 1, -1, 0.5, 2.5, -2.5, 0.125, -0.125, 1.005, 2.675, 4.35, 0.045, 999.995, 1234.5, -1234.5, 123456789.125, 9.999e20, -0.001, 1e-7, 5e-7, 1 / 3, 2 ** 53 + 2];
    let seed = 7;
    const random = () => ((seed = (seed * 48271) % 2147483647) / 2147483647);
    for (let i = 0; i < 3000; i++) values.push((random() - 0.5) * 10 ** (random() * 14 - 5));
    for (let i = 0; i < 2000; i++) values.push((Math.round(random() * 1e5) / 8) * (random() < 0.5 ? -1 : 1));
    const out = [];
    for (const v of values) {
      for (let d = 0; d <= 6; d++) {
        const want = new Intl.NumberFormat('en', { minimumFractionDigits: d, maximumFractionDigits: d }).format(v);
        if (num(v, d) !== want) out.push(`${v} (${d}): ${num(v, d)} ≠ ${want}`);
      }
    }
    return out;
  });
  assert.deepEqual(mismatches.slice(0, 10), []);
  assert.deepEqual(errors, []);
  await context.close();
});

test('the language menu lists every language by its own name and switches page and demo, keeping the values', async () => {
  const { page, errors, context } = await open(browser, `${server.url}?demo=regimes&zeta=0.25&x0=0.05`, { locale: 'en-GB' });
  const fetched = [];
  page.on('request', (r) => {
    if (r.url().includes('/locales/')) fetched.push(new URL(r.url()).pathname.replace(/^.*\/locales\//, ''));
  });
  const options = await page.$$eval('#lang-select option', (os) => os.map((o) => [o.value, o.textContent]));
  assert.deepEqual(options.map(([v]) => v), real(), 'real languages only, pseudo-locales hidden');
  for (const [v, name] of options) assert.equal(name, langs.find((l) => l.tag === v).name);
  // A text every frame writes with the same arguments (the page keeps the texts it has
  // formatted): it must not stay English after the switch.
  const clock = () => page.getAttribute('.anim-bar input[type=range]', 'aria-valuetext');
  assert.match(await clock(), /^time [\d.]+ seconds$/);
  await page.selectOption('#lang-select', 'fr');
  await page.waitForFunction(() => document.documentElement.lang === 'fr');
  await page.waitForFunction(() => document.querySelector('#share-button').textContent === 'Partager / Intégrer');
  await page.waitForFunction(() => /^temps [\d,]+ secondes$/.test(document.querySelector('.anim-bar input[type=range]').getAttribute('aria-valuetext')));
  assert.equal(await page.inputValue('input[type=number][data-key="zeta"]'), '0.25');
  assert.equal(await page.inputValue('input[type=number][data-key="x0"]'), '0.05');
  assert.equal(new URL(page.url()).searchParams.get('lang'), 'fr');
  assert.deepEqual(fetched, ['fr.ftl'], 'only the chosen catalogue is downloaded');
  // The Share dialog offers every real language for the link.
  await page.click('#share-button');
  // The dialog opens once share.js is in (fetched at idle after the first plot: maybe not yet).
  await page.waitForSelector('dialog#share-dialog[open]');
  const shareLangs = await page.$$eval('#share-lang option', (os) => os.map((o) => o.value));
  assert.deepEqual(shareLangs, ['auto', ...real()]);
  await page.selectOption('#share-lang', 'zh-CN');
  assert.equal(new URL(await page.inputValue('#share-link')).searchParams.get('lang'), 'zh-CN');
  await page.click('#share-dialog .share-close');
  // Remembered: the same visitor coming back without lang= gets French.
  await page.goto(`${server.url}?demo=regimes`);
  await page.waitForSelector('html[data-ready="true"]');
  assert.equal(await page.getAttribute('html', 'lang'), 'fr');
  assert.deepEqual(errors, []);
  await context.close();
  // A browser that prefers Portuguese gets Brazilian Portuguese; lang= overrides it.
  const pt = await open(browser, `${server.url}?demo=regimes`, { locale: 'pt-PT' });
  assert.equal(await pt.page.getAttribute('html', 'lang'), 'pt-BR');
  await pt.context.close();
  const en = await open(browser, `${server.url}?demo=regimes&lang=en`, { locale: 'zh-CN' });
  assert.equal(await en.page.getAttribute('html', 'lang'), 'en');
  assert.equal(await en.page.textContent('button.play'), 'Play');
  await en.context.close();
});

test('a Spanish browser gets the Spanish page; notices about bad URL values are Spanish too', async () => {
  const { page, errors, context } = await open(browser, `${server.url}?demo=regimes&zeta=abc`, { locale: 'es-ES' });
  assert.equal(await page.getAttribute('html', 'lang'), 'es');
  assert.equal(await page.textContent('button.reset'), 'Restablecer valores');
  assert.equal(await page.textContent('#share-button'), 'Compartir / Insertar');
  assert.equal(await page.textContent('button.play'), 'Reproducir');
  assert.equal(await page.getAttribute('[data-readout="regime"]', 'data-value'), 'underdamped');
  assert.match(await page.textContent('#notices'), /no es un número/);
  assert.deepEqual(errors, []);
  await context.close();
});

test('a catalogue that cannot be downloaded leaves the page in English, with a notice', async () => {
  const context = await browser.newContext({ viewport: { width: 1280, height: 800 } });
  const page = await context.newPage();
  const errors = [];
  page.on('pageerror', (e) => errors.push(String(e)));
  await page.route('**/locales/fr.ftl', (route) => route.abort());
  await page.goto(`${server.url}?demo=regimes&lang=fr`);
  await page.waitForSelector('html[data-ready="true"]');
  assert.equal(await page.getAttribute('html', 'lang'), 'en');
  assert.equal(await page.textContent('button.play'), 'Play');
  assert.match(await page.textContent('#notices'), /Français catalogue could not be loaded/);
  assert.ok(Number(await page.getAttribute('[data-readout="wn"]', 'data-value')) > 0);
  assert.deepEqual(errors, []);
  await context.close();
});

test('the service worker keeps the chosen catalogue for an offline visit', async () => {
  const { page, errors, context } = await open(browser, `${server.url}?demo=regimes&lang=fr`);
  await page.evaluate(async () => (await navigator.serviceWorker.ready).active.state);
  await page.reload();
  await page.waitForFunction(() => navigator.serviceWorker.controller !== null);
  await page.waitForSelector('html[data-ready="true"]');
  await context.setOffline(true);
  await page.reload();
  await page.waitForSelector('html[data-ready="true"]');
  assert.equal(await page.getAttribute('html', 'lang'), 'fr');
  assert.equal(await page.textContent('#share-button'), 'Partager / Intégrer');
  assert.equal(await page.textContent('#notices'), '');
  assert.deepEqual(errors, []);
  await context.close();
});

/** Layout problems of the page as it is: sideways scroll and clipped control text. */
function layoutProblems(page) {
  return page.evaluate(() => {
    const out = [];
    const doc = document.documentElement;
    if (doc.scrollWidth > window.innerWidth + 1) out.push(`scrolls sideways: ${doc.scrollWidth} > ${window.innerWidth}`);
    for (const e of document.querySelectorAll('label, button, legend, dt, summary, h1, h2, .presets-label')) {
      if (!e.getClientRects().length || e.closest('[hidden], .visually-hidden, dialog:not([open])')) continue;
      if (e.clientWidth <= 1) continue; // visually hidden (clipped to a pixel on purpose)
      // The phone's compact readout strip shortens long labels with an ellipsis by design
      // (in every language; the full label is in the document for screen readers).
      if (getComputedStyle(e).textOverflow === 'ellipsis' && e.closest('.readout-strip')) continue;
      const style = getComputedStyle(e);
      if (style.overflow === 'visible' && style.textOverflow !== 'ellipsis' && e.scrollWidth <= e.clientWidth + 1) continue;
      if (e.scrollWidth > e.clientWidth + 1) out.push(`clipped: ${e.tagName.toLowerCase()} “${e.textContent.trim().slice(0, 40)}” ${e.scrollWidth} > ${e.clientWidth}`);
    }
    return out;
  });
}

// Plain-ASCII words that may appear outside the pseudo-locale's brackets: the brand, units,
// formats and the parameters' symbols, which stay as declared (`seed`; symbols with a
// subscript such as `k_stop` or `F_static/F_c`, and units with a slash such as `mrad/s`,
// are skipped whole).
const ALLOWED = new Set(['Zeta', 'Lab', 'rad', 'PNG', 'SVG', 'CSV', 'seed']);

/** Visible text of en-XA with a run of 4+ plain ASCII letters outside [brackets]. */
function escapedText(page) {
  return page.evaluate((allowed) => {
    const out = new Set();
    const walker = document.createTreeWalker(document.body, NodeFilter.SHOW_TEXT);
    for (let n = walker.nextNode(); n; n = walker.nextNode()) {
      const host = n.parentElement;
      if (!host || host.closest('script, style, noscript, math, option, textarea, [hidden], [aria-hidden="true"]')) continue;
      if (!host.getClientRects().length) continue;
      const text = n.textContent.replace(/\[[^\]]*\]/g, ' ').replace(/[A-Za-z0-9]*_[A-Za-z0-9_/]*/g, ' ').replace(/[A-Za-zµ·]+\/[A-Za-z0-9µ·²³]+/g, ' ');
      for (const m of text.matchAll(/[A-Za-z]{4,}/g)) if (!allowed.includes(m[0])) out.add(`${m[0]} in “${n.textContent.trim().slice(0, 60)}”`);
    }
    for (const e of document.querySelectorAll('[aria-label], [title], select')) {
      if (e.closest('[hidden]')) continue;
      const label = e.tagName === 'SELECT' ? (e.selectedOptions[0]?.textContent ?? '') : (e.getAttribute('aria-label') || e.getAttribute('title'));
      const text = label.replace(/\[[^\]]*\]/g, ' ').replace(/[A-Za-z0-9]*_[A-Za-z0-9_/]*/g, ' ').replace(/[A-Za-zµ·]+\/[A-Za-z0-9µ·²³]+/g, ' ');
      for (const m of text.matchAll(/[A-Za-z]{4,}/g)) if (!allowed.includes(m[0])) out.add(`${m[0]} in label “${label.slice(0, 60)}”`);
    }
    return [...out];
  }, [...ALLOWED]);
}

const SIZES = [[360, 740], [1280, 800]];
const SHOT_DEMOS = new Set(['regimes', 'quarter-car', 'rlc', 'paper']);

test('pseudo-locales: no sideways scroll, no clipped controls, no escaped English, mirrored right to left', async () => {
  const failures = [];
  for (const tag of ['en-XA', 'ar-XB']) {
    for (const [width, height] of SIZES) {
      const context = await browser.newContext({ viewport: { width, height } });
      const page = await context.newPage();
      const errors = [];
      page.on('pageerror', (e) => errors.push(String(e)));
      for (const id of ids) {
        await goto(page, `demo=${id}&lang=${tag}`);
        const where = `${tag} ${width}px ${id}`;
        for (const p of await layoutProblems(page)) failures.push(`${where}: ${p}`);
        if (tag === 'en-XA') {
          for (const s of await escapedText(page)) failures.push(`${where}: not from a catalogue: ${s}`);
        } else {
          assert.equal(await page.getAttribute('html', 'dir'), 'rtl');
          const mirrored = await page.evaluate(() => {
            const form = document.querySelector('.controls');
            const label = document.querySelector('.param label');
            if (!form || !form.getClientRects().length) return true; // no parameters (the tour)
            const f = form.getBoundingClientRect();
            const stage = document.querySelector('.stage').getBoundingClientRect();
            // Wide: the controls column sits left of the plot stage; narrow: labels start at the right.
            const side = f.top < stage.bottom - 1 ? f.right <= stage.left + 1 : true;
            const l = label && label.firstElementChild ? label.firstElementChild.getBoundingClientRect() : null;
            const start = !l || Math.abs(f.right - l.right) < Math.abs(l.left - f.left);
            return side && start;
          });
          if (!mirrored) failures.push(`${where}: not mirrored`);
        }
        if (SHOT_DEMOS.has(id)) await page.screenshot({ path: `${SHOTS}languages-${tag}-${id}-${width}.png` });
      }
      assert.deepEqual(errors, [], `${tag} ${width}`);
      await context.close();
    }
  }
  // zh-CN screenshots, for the glyphs (the font fallback).
  for (const [width, height] of SIZES) {
    const context = await browser.newContext({ viewport: { width, height } });
    const page = await context.newPage();
    for (const id of ids.filter((d) => SHOT_DEMOS.has(d))) {
      await goto(page, `demo=${id}&lang=zh-CN`);
      for (const p of await layoutProblems(page)) failures.push(`zh-CN ${width}px ${id}: ${p}`);
      await page.screenshot({ path: `${SHOTS}languages-zh-CN-${id}-${width}.png` });
    }
    await context.close();
  }
  assert.equal(failures.length, 0, `${failures.length} problems:\n${failures.join('\n')}`);
});

test('axe-core finds no violations in fr, zh-CN and ar-XB', async () => {
  const failures = [];
  for (const tag of ['fr', 'zh-CN', 'ar-XB'].filter((t) => langs.some((l) => l.tag === t))) {
    for (const id of ids) {
      // axe is injected as a script, which the page's CSP would (rightly) block.
      const { page, errors, context } = await open(browser, `${server.url}?demo=${id}&lang=${tag}`, { bypassCSP: true });
      await page.addScriptTag({ path: AXE });
      const result = await page.evaluate(async () => {
        const r = await window.axe.run(document, { runOnly: { type: 'tag', values: ['wcag2a', 'wcag2aa', 'wcag21a', 'wcag21aa'] } });
        return r.violations.map((v) => `${v.id}: ${v.nodes.slice(0, 3).map((n) => n.target.join(' ')).join(' | ')}`);
      });
      if (result.length) failures.push(`${id} (${tag}): ${result.join('; ')}`);
      assert.deepEqual(errors, [], `${tag} ${id}`);
      await context.close();
    }
  }
  assert.equal(failures.length, 0, `${failures.length} problems:\n${failures.join('\n')}`);
});
