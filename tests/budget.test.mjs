// Issue 13's download budget, enforced: a demo's page transfers at most 200 KB before its
// first plot (brotli, as a static host serves it, headers included; cold cache), counted as
// bench/lowend.mjs counts it (countBytes), without its network and CPU throttling. The README's low-end
// table reports the same bytes; integrators has the least room.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { serve } from './support/server.mjs';
import { countBytes, launch } from './support/browser.mjs';

/** Bytes (1 KB = 1000 B) a page may transfer before its first plot. */
const BUDGET = 200_000;

let server;
let browser;
before(async () => {
  server = await serve({ brotli: true });
  browser = await launch();
});
after(async () => {
  await browser?.close();
  await server?.close();
});

/** Bytes of what the page at `url` requested before its first plot. */
async function bytesBeforeFirstPlot(url) {
  const context = await browser.newContext({ viewport: { width: 360, height: 740 }, deviceScaleFactor: 2, isMobile: true, hasTouch: true });
  const page = await context.newPage();
  const cdp = await context.newCDPSession(page);
  await cdp.send('Network.enable');
  await cdp.send('Network.setCacheDisabled', { cacheDisabled: true });
  const counted = countBytes(cdp);
  await page.goto(url);
  await page.waitForFunction(() => performance.getEntriesByName('zeta:first-draw').length > 0, null, { timeout: 30000 });
  const wall = await page.evaluate(() => performance.timeOrigin + performance.getEntriesByName('zeta:first-draw')[0].startTime);
  // Let the responses of requests made before the plot finish being counted.
  await page.waitForLoadState('networkidle');
  const bytes = counted.bytesSentBefore(wall);
  await context.close();
  return bytes;
}

test('every demo transfers at most 200 KB (brotli) before its first plot', async () => {
  const probe = await browser.newPage();
  await probe.goto(server.url);
  const ids = await probe.$$eval('#demo-select option', (os) => os.map((o) => o.value));
  await probe.close();
  assert.ok(ids.length >= 12, `the demos: ${ids}`);
  const over = [];
  const seen = {};
  for (const id of ids) {
    const bytes = await bytesBeforeFirstPlot(`${server.url}?demo=${id}`);
    seen[id] = (bytes / 1000).toFixed(1);
    // More than a first module's page could need means the count itself broke.
    assert.ok(bytes > 100_000, `${id}: ${bytes} B counted`);
    if (bytes > BUDGET) over.push(`${id} ${(bytes / 1000).toFixed(1)} KB`);
  }
  assert.deepEqual(over, [], `over the 200 KB budget before the first plot: ${over.join(', ')} (all: ${JSON.stringify(seen)})`);
});
