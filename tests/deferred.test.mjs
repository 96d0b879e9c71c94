// End to end (issue 13: bytes before the first plot): the modules only a user's action
// needs (share dialog, downloads, sound, the paper's tour, the host-page API, the prediction
// form, the lecturer styles) are not requested before the first plot of the default demo;
// they arrive at idle afterwards, and Share, a download and the sound button work at once.
// And the one theme decision (web/preload.js): system, forced, projector, following the
// system while open, with screenshots of each at a laptop's and a phone's size.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { open, SHOTS } from './support/browser.mjs';
import { server, browser, useSession } from './support/session.mjs';

useSession();

const DEFERRED = ['share.js', 'download.js', 'sound.js', 'tour.js', 'embed.js', 'predict.js', 'lecturer.css'];
const PREFETCHED = DEFERRED.filter((f) => f !== 'predict.js');

/** {file → startTime} of the page's resource requests for `files`, and the first plot's time. */
function timings(page, files) {
  return page.evaluate((names) => {
    const out = {};
    for (const e of performance.getEntriesByType('resource')) {
      const name = new URL(e.name).pathname.split('/').pop();
      if (names.includes(name)) out[name] = Math.min(out[name] ?? Infinity, e.startTime);
    }
    const draw = performance.getEntriesByName('zeta:first-draw')[0];
    return { requested: out, firstDraw: draw ? draw.startTime : null };
  }, files);
}

test('the deferred modules are requested after the first plot, and Share opens at once', async () => {
  const { page, errors, context } = await open(browser, `${server.url}?demo=regimes`, { serviceWorkers: 'block' });
  try {
    assert.equal(await page.getAttribute('html', 'data-start-module'), 'first');
    // Prefetched at idle after the first plot (predict.js only on a predict= page).
    await page.waitForFunction((names) => {
      const got = new Set(performance.getEntriesByType('resource').map((e) => new URL(e.name).pathname.split('/').pop()));
      return names.every((n) => got.has(n));
    }, PREFETCHED, { timeout: 15000 });
    const { requested, firstDraw } = await timings(page, DEFERRED);
    assert.ok(firstDraw !== null, 'first plot drawn');
    for (const file of DEFERRED) {
      if (file in requested) assert.ok(requested[file] > firstDraw, `${file} requested at ${requested[file].toFixed(0)} ms, before the first plot (${firstDraw.toFixed(0)} ms)`);
    }
    assert.ok(!('predict.js' in requested), 'predict.js is loaded only for a predict= page');

    await page.click('#share-button');
    await page.waitForSelector('dialog#share-dialog[open]', { timeout: 2000 });
    await page.keyboard.press('Escape');

    // A download (download.js stamps the view's token into it).
    const [dl] = await Promise.all([
      page.waitForEvent('download', { timeout: 5000 }),
      page.locator('button[data-export="csv"]:visible').first().click(),
    ]);
    assert.ok(dl.suggestedFilename().endsWith('.csv'));

    // Sound (sound.js): the button turns it on and off.
    const sound = page.locator('button.sound').first();
    if (await sound.count()) {
      await sound.click();
      await page.waitForSelector('button.sound[aria-pressed="true"]', { timeout: 2000 });
      await sound.click();
      await page.waitForSelector('button.sound[aria-pressed="false"]', { timeout: 2000 });
    }
    assert.deepEqual(errors, []);
  } finally {
    await context.close();
  }
});

test('the icon is in the page itself (no request before the first plot) and is the manifest\'s icon.svg', async () => {
  const { page, errors, context } = await open(browser, server.url);
  await page.waitForFunction(() => performance.getEntriesByName('zeta:first-draw').length > 0);
  const href = await page.$eval('link[rel=icon]', (l) => l.getAttribute('href'));
  const prefix = 'data:image/svg+xml,';
  assert.ok(href.startsWith(prefix), href.slice(0, 40));
  const file = await (await fetch(new URL('web/icon.svg', server.url))).text();
  // The same drawing: the data URL is the file with its double quotes written as single ones.
  assert.equal(decodeURIComponent(href.slice(prefix.length)), file.trim().replaceAll('"', "'"));
  const requested = await page.evaluate(() => performance.getEntriesByType('resource').map((e) => e.name).filter((n) => n.includes('icon')));
  assert.deepEqual(requested, []);
  assert.deepEqual(errors, []);
  await context.close();
});

test('a module that cannot be downloaded is reported on the page, and the next click fetches it again', async () => {
  let blocked = true;
  const before = (context) => context.route('**/web/share.js', (route) => (blocked ? route.abort('internetdisconnected') : route.continue()));
  const { page, errors, context } = await open(browser, `${server.url}?demo=rlc`, { serviceWorkers: 'block', before });
  try {
    await page.click('#share-button');
    const notice = page.locator('#notices .notice-warn', { hasText: 'share.js' });
    await notice.waitFor({ timeout: 5000 });
    assert.match(await notice.textContent(), /could not be loaded \(share\.js\)\. Check the connection/);
    assert.equal(await page.locator('dialog#share-dialog[open]').count(), 0);
    blocked = false;
    await page.click('#share-button');
    await page.waitForSelector('dialog#share-dialog[open]', { timeout: 5000 });
    // What the failed download logged; nothing else went wrong.
    assert.ok(errors.every((e) => /share\.js|Failed to (load|fetch)|ERR_INTERNET_DISCONNECTED/.test(e)), JSON.stringify(errors));
  } finally {
    await context.close();
  }
});

test('a predict= page loads the prediction form with the page; an embed the host API', async () => {
  const { page, errors, context } = await open(browser, `${server.url}?demo=regimes&predict=regime&embed=1`, { serviceWorkers: 'block' });
  try {
    assert.equal(await page.getAttribute('html', 'data-start-module'), 'first');
    assert.ok(await page.locator('.zeta-predict').count(), 'the prediction form is there when the page is ready');
    const { requested, firstDraw } = await timings(page, ['predict.js', 'embed.js', 'lecturer.css']);
    for (const file of ['predict.js', 'embed.js', 'lecturer.css']) assert.ok(requested[file] < firstDraw, `${file} before the first plot`);
    assert.deepEqual(errors, []);
  } finally {
    await context.close();
  }
});

const bg = (page) => page.evaluate(() => getComputedStyle(document.body).backgroundColor);
const LIGHT = 'rgb(255, 255, 255)';
const DARK = 'rgb(24, 26, 31)';

test('one theme decision: system, forced, projector, and following the system', async () => {
  const cases = [
    { name: 'light', query: '', scheme: 'light', theme: 'light', bg: LIGHT },
    { name: 'dark', query: '', scheme: 'dark', theme: 'dark', bg: DARK },
    { name: 'forced-light', query: '&theme=light', scheme: 'dark', theme: 'light', bg: LIGHT },
    { name: 'forced-dark', query: '&theme=dark', scheme: 'light', theme: 'dark', bg: DARK },
    { name: 'projector', query: '&theme=projector', scheme: 'dark', theme: 'projector', bg: LIGHT },
  ];
  for (const c of cases) {
    for (const [w, h] of [[1280, 800], [360, 740]]) {
      const { page, errors, context } = await open(browser, `${server.url}?demo=regimes${c.query}`, {
        viewport: { width: w, height: h }, colorScheme: c.scheme, serviceWorkers: 'block',
      });
      try {
        assert.equal(await page.getAttribute('html', 'data-theme'), c.theme, c.name);
        assert.equal(await bg(page), c.bg, c.name);
        if (c.name === 'projector') assert.ok(await page.locator('link[data-lecturer]').count(), 'projector styles from <head>');
        await page.screenshot({ path: `${SHOTS}theme-${c.name}-${w}x${h}.png` });
        if (w === 1280 && c.query === '') {
          // The system changes while the page is open: the page and its plots follow.
          const other = c.scheme === 'dark' ? 'light' : 'dark';
          await page.emulateMedia({ colorScheme: other });
          await page.waitForFunction((t) => document.documentElement.dataset.theme === t, other);
          assert.equal(await bg(page), other === 'dark' ? DARK : LIGHT);
        } else if (w === 1280) {
          // A forced theme holds when the system changes. The page hears of the change at
          // its next rendering (a 'change' event: preload.js's listener first, its list being
          // older); wait for that rather than 100 ms, which a slow machine could pass before it.
          await page.evaluate(() => {
            window.__schemeChanged = new Promise((done) => {
              window.matchMedia('(prefers-color-scheme: dark)').addEventListener('change', () => done(), { once: true });
            });
          });
          await page.emulateMedia({ colorScheme: c.scheme === 'dark' ? 'light' : 'dark' });
          await page.evaluate(() => window.__schemeChanged);
          assert.equal(await page.getAttribute('html', 'data-theme'), c.theme, `${c.name} after a system change`);
        }
        assert.deepEqual(errors, []);
      } finally {
        await context.close();
      }
    }
  }
});

test('a state= token that forces a theme is followed once state.js has expanded it', async () => {
  const { page, context } = await open(browser, `${server.url}?demo=regimes&theme=dark`, { colorScheme: 'light', serviceWorkers: 'block' });
  const token = await page.evaluate(() => import('./web/state.js').then((m) => m.encodeToken('demo=regimes&zeta=0.2&theme=dark')));
  await context.close();
  const again = await open(browser, `${server.url}?state=${token}`, { colorScheme: 'light', serviceWorkers: 'block' });
  try {
    assert.equal(await again.page.getAttribute('html', 'data-theme'), 'dark');
    assert.equal(await again.page.getAttribute('html', 'data-start-module'), 'first');
  } finally {
    await again.context.close();
  }
  // <head>'s preload.js reads the token itself (main.js never runs here): the theme and the
  // demo's first module are decided, and that module's download started, before any
  // module script; the address's own keys win over the token's, as in state.js; an
  // unreadable token is dropped (the default demo).
  const cases = [
    [`?state=${token}`, 'dark', 'regimes'],
    [`?state=${await tokenOf('demo=integrators&theme=dark')}&theme=light`, 'light', 'integrators'],
    [`?state=${await tokenOf('demo=design')}&demo=rlc`, 'light', 'rlc'],
    ['?state=1.%%%&demo=flutter', 'light', 'flutter'],
    ['?state=2.ZGVtbz1ybGM', 'light', 'regimes'],
  ];
  for (const [query, theme, demo] of cases) {
    const context = await browser.newContext({ colorScheme: 'light', serviceWorkers: 'block' });
    try {
      await context.route('**/web/main.js', (route) => route.abort());
      const page = await context.newPage();
      await page.goto(`${server.url}${query}`);
      await page.waitForSelector('#loading');
      assert.equal(await page.getAttribute('html', 'data-theme'), theme, query);
      assert.equal(await page.getAttribute('html', 'data-start-demo'), demo, query);
      const preloaded = await page.$$eval('link[rel=preload][as=fetch]', (ls) => ls.map((l) => l.getAttribute('href')));
      assert.deepEqual(preloaded, [`./zeta-first-${demo}_bg.wasm`], query);
    } finally {
      await context.close();
    }
  }
});

/** The state token of `query`, made by the page's own state.js. */
async function tokenOf(query) {
  const { page, context } = await open(browser, `${server.url}?demo=regimes`, { serviceWorkers: 'block' });
  try {
    return await page.evaluate((q) => import('./web/state.js').then((m) => m.encodeToken(q)), query);
  } finally {
    await context.close();
  }
}

test('the theme is on the page before main.js runs (no flash of the wrong theme)', async () => {
  for (const [scheme, query, theme, colour] of [['dark', '', 'dark', DARK], ['light', '&theme=dark', 'dark', DARK], ['dark', '&theme=projector', 'projector', LIGHT]]) {
    const context = await browser.newContext({ viewport: { width: 360, height: 740 }, colorScheme: scheme, serviceWorkers: 'block' });
    try {
      await context.route('**/web/main.js', (route) => route.abort()); // only <head>'s preload.js runs
      const page = await context.newPage();
      await page.goto(`${server.url}?demo=regimes${query}`);
      await page.waitForSelector('#loading');
      assert.equal(await page.getAttribute('html', 'data-theme'), theme);
      assert.equal(await bg(page), colour, `${scheme}${query}`);
    } finally {
      await context.close();
    }
  }
});
