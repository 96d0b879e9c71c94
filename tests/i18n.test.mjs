// End to end, languages: ?lang=es (or a Spanish browser) shows the interface, labels,
// readout text and plot descriptions in Spanish with decimal commas, while data-value
// attributes, URL keys and CSV numbers stay machine-readable.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { open, readout, waitForReadout } from './support/browser.mjs';
import { server, browser, useSession } from './support/session.mjs';

useSession();

test('?lang=es translates the page and keeps data-value in SI', async () => {
  const { page, errors, context } = await open(browser, `${server.url}?demo=regimes&zeta=0.25&lang=es`);
  assert.equal(await page.getAttribute('html', 'lang'), 'es');
  assert.equal(await page.textContent('#demo-title'), 'Regímenes de amortiguamiento');
  assert.match(await page.textContent('label[for="p-zeta"]'), /coeficiente de amortiguamiento/);
  assert.equal(await page.textContent('button.reset'), 'Restablecer valores');
  assert.equal(await page.textContent('#share-button'), 'Compartir / Insertar');
  // Readout text is Spanish with a decimal comma; data-value stays English and SI.
  assert.equal(await readout(page, 'regime'), 'underdamped');
  assert.equal(await page.textContent('[data-readout="regime"] dd'), 'subamortiguado');
  assert.match(await page.textContent('[data-readout="wn"] dd'), /^6,000 rad\/s$/);
  assert.equal(Number(await readout(page, 'wn')), 6);
  assert.match(await page.textContent('#desc-response'), /^subamortiguado: .*queda dentro del 5 % del reposo tras \d+,\d+ s/);
  assert.match(await page.textContent('tr.current'), /Subamortiguado/);
  // The language survives slider moves in the URL.
  await page.focus('#p-zeta');
  await page.keyboard.press('ArrowRight');
  await waitForReadout(page, 'zeta', 0.26);
  await page.waitForFunction(() => new URLSearchParams(location.search).get('lang') === 'es');
  assert.deepEqual(errors, []);
  await context.close();
});

test('a Spanish browser gets Spanish; ?lang=en overrides it', async () => {
  const es = await open(browser, `${server.url}?demo=regimes`, { locale: 'es-ES' });
  assert.equal(await es.page.getAttribute('html', 'lang'), 'es');
  assert.equal(await es.page.textContent('button.play'), 'Reproducir');
  await es.context.close();
  const en = await open(browser, `${server.url}?demo=regimes&lang=en`, { locale: 'es-ES' });
  assert.equal(await en.page.textContent('button.play'), 'Play');
  assert.deepEqual([...es.errors, ...en.errors], []);
  await en.context.close();
});

test('notices about bad URL values are translated too', async () => {
  const { page, errors, context } = await open(browser, `${server.url}?demo=regimes&lang=es&zeta=abc&wn=99`);
  const text = await page.textContent('#notices');
  assert.match(text, /no es un número; se usa el valor por defecto/);
  assert.match(text, /coeficiente de amortiguamiento \(zeta\)/);
  assert.match(text, /frecuencia natural \(wn\)/);
  assert.match(text, /está fuera de/);
  assert.deepEqual(errors, []);
  await context.close();
});
