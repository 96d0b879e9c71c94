// End to end, for lecturers: embedding in sandboxed iframes on another origin, the host
// postMessage API, embed options, the strict CSP, a sub-path deployment, offline reload,
// the share dialog, printing, and screenshots of the embed view.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { createServer } from 'node:http';
import { open, readout, waitForReadout, SHOTS, fullShot } from './support/browser.mjs';
import { serve } from './support/server.mjs';
import { useSession, server as app, browser } from './support/session.mjs';

useSession();

/** A host page on a second origin (another port) embedding two demos. */
async function hostServer(appUrl) {
  const appOrigin = new URL(appUrl).origin;
  const server = createServer((req, res) => {
    const origin = `http://127.0.0.1:${server.address().port}`;
    const src = (q) => `${appUrl}?${q}&embed=1&origin=${encodeURIComponent(origin)}`;
    res.writeHead(200, { 'content-type': 'text/html; charset=utf-8' });
    res.end(`<!doctype html><html><head><title>Course page</title></head><body>
<h1>Week 3: damping</h1>
<iframe id="a" src="${src('demo=regimes&zeta=0.2')}" width="800" height="700" sandbox="allow-scripts allow-same-origin"></iframe>
<iframe id="b" src="${src('demo=regimes&zeta=2&controls=zeta&lock=zeta')}" width="400" height="700" sandbox="allow-scripts allow-same-origin"></iframe>
<script>
  window.messages = [];
  window.addEventListener('message', (ev) => {
    if (ev.origin !== ${JSON.stringify(appOrigin)}) return;
    window.messages.push({ from: ev.source === document.getElementById('a').contentWindow ? 'a' : 'b', data: ev.data });
  });
  window.send = (id, msg) => document.getElementById(id).contentWindow.postMessage(msg, ${JSON.stringify(appOrigin)});
</script></body></html>`);
  });
  await new Promise((ok) => server.listen(0, '127.0.0.1', ok));
  return { url: `http://127.0.0.1:${server.address().port}/`, close: () => new Promise((ok) => server.close(ok)) };
}

test('a host page on another origin drives one sandboxed embed and hears its changes', async () => {
  const host = await hostServer(app.url);
  const context = await browser.newContext();
  const page = await context.newPage();
  const errors = [];
  page.on('console', (m) => m.type() === 'error' && errors.push(m.text()));
  try {
    await page.goto(host.url);
    await page.waitForFunction(() => ['a', 'b'].every((id) => window.messages.some((m) => m.from === id && m.data.type === 'zeta:ready')));
    const ready = await page.evaluate(() => window.messages.find((m) => m.from === 'a').data);
    assert.equal(ready.demo, 'regimes');
    assert.equal(ready.params.zeta, 0.2);
    assert.equal(ready.readouts.regime, 'underdamped');
    // Malformed messages are ignored; a valid one sets ζ through Rust's validation.
    await page.evaluate(() => {
      window.send('a', 'zeta=9');
      window.send('a', { type: 'zeta:set', params: [1, 2] });
      window.send('a', { type: 'zeta:set', params: { zeta: { nested: true } } });
      window.send('a', { type: 'zeta:set', params: { zeta: 1 } });
    });
    await page.waitForFunction(() => window.messages.some((m) => m.from === 'a' && m.data.type === 'zeta:change' && m.data.params.zeta === 1));
    const change = await page.evaluate(() => window.messages.filter((m) => m.from === 'a' && m.data.type === 'zeta:change').at(-1).data);
    assert.equal(change.readouts.regime, 'critically damped');
    // Out-of-range values are clamped exactly like URL values.
    await page.evaluate(() => window.send('a', { type: 'zeta:set', params: { zeta: 1e9 } }));
    await page.waitForFunction(() => window.messages.some((m) => m.data.type === 'zeta:change' && m.data.params.zeta === 3));
    // The other embed did not change.
    await page.evaluate(() => window.send('b', { type: 'zeta:get' }));
    await page.waitForFunction(() => window.messages.some((m) => m.from === 'b' && m.data.type === 'zeta:state'));
    const b = await page.evaluate(() => window.messages.find((m) => m.from === 'b' && m.data.type === 'zeta:state').data);
    assert.equal(b.params.zeta, 2);
    // controls= and lock= in the second frame.
    const frameB = page.frames().find((f) => f.url().includes('zeta=2'));
    assert.equal(await frameB.isHidden('[data-param="wn"]'), true);
    assert.equal(await frameB.isDisabled('#p-zeta'), true);
    assert.equal(await frameB.isHidden('.site-header'), true);
    await fullShot(page, `${SHOTS}embed-host-page.png`);
    assert.deepEqual(errors, []);
  } finally {
    await context.close();
    await host.close();
  }
});

test('a host API that loads after the first plot still says the embed is ready', async () => {
  // On a slow line web/embed.js may arrive after the first frame has been drawn: the
  // embed must still send zeta:ready (once), not only on the next change.
  const host = await hostServer(app.url);
  const context = await browser.newContext();
  const page = await context.newPage();
  await context.route('**/web/embed.js', async (route) => {
    await new Promise((ok) => setTimeout(ok, 2500));
    await route.continue();
  });
  try {
    await page.goto(host.url);
    const frameA = () => page.frames().find((f) => f.url().includes('zeta=0.2'));
    await page.waitForFunction(() => window.messages.some((m) => m.from === 'a' && m.data.type === 'zeta:ready'), null, { timeout: 15000 });
    // The first plot came before the host API did (the delay is what this test is about).
    const drawnAt = await frameA().evaluate(() => performance.getEntriesByName('zeta:first-draw')[0]?.startTime);
    const embedAt = await frameA().evaluate(() => performance.getEntriesByType('resource').find((r) => r.name.endsWith('/web/embed.js'))?.responseEnd);
    assert.ok(drawnAt < embedAt, `first plot at ${drawnAt} ms, host API loaded at ${embedAt} ms`);
    const ready = await page.evaluate(() => window.messages.filter((m) => m.from === 'a' && m.data.type === 'zeta:ready').map((m) => m.data));
    assert.equal(ready.length, 1);
    assert.equal(ready[0].params.zeta, 0.2);
  } finally {
    await context.close();
    await host.close();
  }
});

test('plots= chooses plots; the page runs under the strict CSP with no violations', async () => {
  const context = await browser.newContext({ viewport: { width: 1280, height: 800 } });
  await context.addInitScript(() => {
    window.__csp = [];
    document.addEventListener('securitypolicyviolation', (e) => window.__csp.push(`${e.violatedDirective} ${e.blockedURI}`));
  });
  const page = await context.newPage();
  const errors = [];
  page.on('console', (m) => m.type() === 'error' && errors.push(m.text()));
  await page.goto(`${app.url}?demo=regimes&embed=1&plots=response`);
  await page.waitForSelector('html[data-ready="true"]');
  assert.equal(await page.isHidden('[data-plot-wrap="poles"]'), true);
  assert.equal(await page.isVisible('[data-plot-wrap="response"]'), true);
  const csp = await page.getAttribute('meta[http-equiv="Content-Security-Policy"]', 'content');
  // One inline script, allowed by its hash: web/preload.js, written into the page at build.
  assert.match(csp, /default-src 'self'; script-src 'self' 'wasm-unsafe-eval' 'sha256-[A-Za-z0-9+/]{43}='; style-src 'self'/);
  // Exercise the features that draw, export and build UI.
  await page.focus('#p-zeta');
  await page.keyboard.press('PageUp');
  await page.click('button.play');
  await page.waitForTimeout(200);
  const [dl] = await Promise.all([page.waitForEvent('download'), page.click('[data-plot-wrap="response"] button[data-export="svg"]')]);
  assert.ok(dl.suggestedFilename().endsWith('.svg'));
  assert.deepEqual(await page.evaluate(() => window.__csp), []);
  assert.deepEqual(errors, []);
  await context.close();
});

test('the site works served under a sub-path', async () => {
  const sub = await serve({ base: '/course/demos/' });
  try {
    const { page, errors, context } = await open(browser, `${sub.url}?demo=regimes&zeta=0.5`);
    await waitForReadout(page, 'zeta', 0.5);
    assert.equal(await readout(page, 'regime'), 'underdamped');
    assert.ok(page.url().includes('/course/demos/'));
    assert.deepEqual(errors, []);
    await context.close();
  } finally {
    await sub.close();
  }
});

test('after the first visit the app reloads and works offline', async () => {
  const { page, errors, context } = await open(browser, `${app.url}?demo=regimes&zeta=0.4`);
  await page.evaluate(async () => {
    const reg = await navigator.serviceWorker.ready;
    return reg.active.state;
  });
  await page.reload();
  await page.waitForFunction(() => navigator.serviceWorker.controller !== null);
  await context.setOffline(true);
  await page.reload();
  await page.waitForSelector('html[data-ready="true"]');
  await waitForReadout(page, 'zeta', 0.4);
  await page.focus('#p-zeta');
  await page.keyboard.press('End');
  await waitForReadout(page, 'zeta', 3);
  assert.deepEqual(errors.filter((e) => !/ERR_INTERNET_DISCONNECTED/.test(e)), []);
  await context.close();
});

test('the share dialog builds the link and iframe snippet with a live preview', async () => {
  const { page, errors, context } = await open(browser, `${app.url}?demo=regimes&zeta=0.35`);
  await page.click('#share-button');
  await page.waitForSelector('dialog#share-dialog[open]');
  const link = await page.inputValue('#share-link');
  assert.match(link, /\?demo=regimes&wn=6&zeta=0\.35&x0=0\.06&v0=0$/);
  await page.check('#share-autoplay');
  await page.uncheck('#share-plots-poles');
  await page.check('#share-locked-wn');
  const snippet = await page.inputValue('#share-snippet');
  assert.match(snippet, /^<iframe src="[^"]*embed=1[^"]*lock=wn[^"]*plots=response[^"]*autoplay=1/);
  assert.match(snippet, /sandbox="allow-scripts allow-same-origin allow-downloads"/);
  const preview = page.frameLocator('iframe.share-preview');
  await preview.locator('html[data-ready="true"]').waitFor({ timeout: 15000 });
  await page.waitForFunction(() => (document.querySelector('iframe.share-preview').getAttribute('src') || '').includes('lock=wn'));
  await page.screenshot({ path: `${SHOTS}share-dialog.png` });
  await page.click('.share-close');
  await page.locator('dialog#share-dialog').waitFor({ state: 'detached' });
  assert.deepEqual(errors, []);
  await context.close();
});

test('printing hides the chrome and keeps plots and readouts', async () => {
  const { page, errors, context } = await open(browser, `${app.url}?demo=regimes`);
  await page.emulateMedia({ media: 'print' });
  assert.equal(await page.isHidden('.site-header'), true);
  assert.equal(await page.isHidden('.plot-tools'), true);
  assert.equal(await page.isVisible('canvas[data-plot="response"]'), true);
  assert.equal(await page.isVisible('.readouts'), true);
  assert.deepEqual(errors, []);
  await context.close();
});

for (const [w, h] of [[320, 480], [1280, 800]]) {
  test(`the embed view at ${w} × ${h} fits without horizontal scrolling`, async () => {
    const { page, errors, context } = await open(browser, `${app.url}?demo=regimes&embed=1`, { viewport: { width: w, height: h } });
    const overflow = await page.evaluate(() => document.documentElement.scrollWidth - document.documentElement.clientWidth);
    assert.ok(overflow <= 0, `horizontal overflow ${overflow}px`);
    await fullShot(page, `${SHOTS}embed-${w}x${h}.png`);
    assert.deepEqual(errors, []);
    await context.close();
  });
}
