// The shared preamble of the end-to-end tests: one static server for dist/ and one
// headless Chromium per test file, started before the file's tests and closed after them.
// `server` and `browser` are live bindings: read them inside tests, not at import time.
import { before, after } from 'node:test';
import { serve } from './server.mjs';
import { launch } from './browser.mjs';

export let server;
export let browser;

/** Registers the before/after hooks that start and close `server` and `browser`. */
export function useSession() {
  before(async () => {
    server = await serve();
    browser = await launch();
  });
  after(async () => {
    await browser?.close();
    await server?.close();
  });
}
