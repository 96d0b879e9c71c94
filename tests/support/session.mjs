// The shared preamble of the end-to-end tests: one static server for dist/ and one
// headless Chromium per test file, started before the file's tests and closed after them.
// `server` and `browser` are live bindings: read them inside tests, not at import time.
import { before, after } from 'node:test';
import { serve } from './server.mjs';
import { launch, open } from './browser.mjs';

export let server;
export let browser;

/**
 * Registers the before/after hooks that start and close `server` and `browser`.
 * `launchArgs` are extra Chromium flags; `setup` runs once both are up, in the same hook
 * (a second top-level `before` is not ordered after this one by Node 20's runner).
 */
export function useSession({ launchArgs = [], setup } = {}) {
  before(async () => {
    server = await serve();
    browser = await launch(launchArgs);
    await setup?.();
  });
  after(async () => {
    await browser?.close();
    await server?.close();
  });
}

/** The demo ids in the page's menu, in menu order (call it inside a hook or test). */
export async function demoIds() {
  const { page, context } = await open(browser, server.url);
  const ids = await page.$$eval('#demo-select option', (os) => os.map((o) => o.value));
  await context.close();
  return ids;
}
