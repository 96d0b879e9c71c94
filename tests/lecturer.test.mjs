// End to end, the lecturer toolkit on two local origins: the static host page of the docs
// (docs/host-example.html, served on one port) embeds the app (served on another) and
// drives it over postMessage — schema, whole state, playback, exports, resize, authoring
// overrides and a keyboard-only prediction — and exported files reopen their view.
import { test, after } from 'node:test';
import assert from 'node:assert/strict';
import { readFile } from 'node:fs/promises';
import { fileURLToPath } from 'node:url';
import { serve } from './support/server.mjs';
import { open, SHOTS } from './support/browser.mjs';
import { typeValue } from './support/page.mjs';
import { useSession, server as app, browser } from './support/session.mjs';

const DOCS = fileURLToPath(new URL('../docs', import.meta.url));
let docs;

useSession({
  setup: async () => {
    docs = await serve({ root: DOCS });
  },
});
after(async () => {
  await docs?.close();
});

/** Opens the docs' host page embedding the app view `q`; returns {page, context, errors, …}. */
async function hostPage(q) {
  const context = await browser.newContext({ viewport: { width: 1280, height: 800 } });
  const page = await context.newPage();
  const errors = [];
  page.on('console', (m) => m.type() === 'error' && errors.push(m.text()));
  page.on('pageerror', (e) => errors.push(String(e)));
  await page.goto(`${docs.url}host-example.html?app=${encodeURIComponent(app.url)}&q=${encodeURIComponent(q)}`);
  await page.waitForFunction(() => window.messages.some((m) => m.type === 'zeta:ready'), null, { timeout: 20000 });
  const frame = page.frames().find((f) => f.url().startsWith(app.url));
  /**
   * Sends `msg` and resolves to the first new message of type `type`. Some answers wait
   * for the full module (350 KB of wasm: zeta:describe, an export) or a reload of the frame
   * (zeta:setState for a demo its first module does not hold): 30 s for a slow CI machine.
   */
  const ask = async (msg, type) => {
    const n = await page.evaluate(() => window.messages.length);
    await page.evaluate((m) => window.send(m), msg);
    await page.waitForFunction(([k, t]) => window.messages.slice(k).some((m) => m.type === t), [n, type], { timeout: 30000 });
    return page.evaluate(([k, t]) => window.messages.slice(k).find((m) => m.type === t), [n, type]);
  };
  return { page, context, errors, frame, ask };
}

function decodeToken(token) {
  assert.match(token, /^1\.[A-Za-z0-9_-]+$/);
  return new URLSearchParams(Buffer.from(token.slice(2), 'base64url').toString('utf8'));
}

/** The tEXt chunks of a PNG as {keyword: text}, checking the signature and chunk layout. */
function pngText(bytes) {
  assert.deepEqual([...bytes.subarray(0, 8)], [0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a]);
  const out = {};
  let at = 8;
  while (at < bytes.length) {
    const len = bytes.readUInt32BE(at);
    const kind = bytes.subarray(at + 4, at + 8).toString('latin1');
    if (kind === 'tEXt') {
      const body = bytes.subarray(at + 8, at + 8 + len);
      const nul = body.indexOf(0);
      out[body.subarray(0, nul).toString('latin1')] = body.subarray(nul + 1).toString('latin1');
    }
    if (kind === 'IEND') break;
    at += 12 + len;
  }
  return out;
}

test('a host on another origin gets the schema, a whole state round trip, playback and resize', async () => {
  const schemaDoc = JSON.parse(await readFile(new URL('../docs/zeta-schema.json', import.meta.url), 'utf8'));
  const h = await hostPage('demo=regimes&zeta=0.2&range.zeta=0,0.5&step.zeta=0.001&theme=projector&plots=response&readouts=regime,zeta');
  try {
    const { schema } = await h.ask({ type: 'zeta:describe' }, 'zeta:schema');
    assert.equal(schema.schema_version, schemaDoc.properties.schema_version.const);
    assert.equal(schema.demo, 'regimes');
    const zeta = schema.parameters.find((p) => p.key === 'zeta');
    assert.deepEqual([zeta.min, zeta.max, zeta.step, zeta.unit], [0, 0.5, 0.001, ''], 'overrides reach the schema');
    assert.equal(schema.parameters.find((p) => p.key === 'wn').unit, 'rad/s');
    assert.deepEqual(schema.plots.map((p) => p.key), ['response', 'poles']);
    assert.ok(schema.readouts.some((r) => r.key === 'wd' && r.unit === 'rad/s'));

    // The overrides narrow the slider, and the Rust parser clamps into the narrowed range.
    const slider = h.frame.locator('input[type=range][data-key="zeta"]');
    assert.deepEqual(await slider.evaluate((e) => [e.min, e.max, e.step]), ['0', '0.5', '0.001']);
    await h.ask({ type: 'zeta:set', params: { zeta: 2 } }, 'zeta:change');
    assert.equal((await h.ask({ type: 'zeta:get' }, 'zeta:state')).params.zeta, 0.5);
    assert.equal(await h.frame.getAttribute('html', 'data-theme'), 'projector');
    assert.equal(await h.frame.locator('[data-readout="wd"]').isHidden(), true, 'readouts= hides the others');

    // Playback: seek, speed, play, pause.
    let pb = await h.ask({ type: 'zeta:seek', t: 1.5 }, 'zeta:playback');
    assert.equal(pb.t, 1.5);
    pb = await h.ask({ type: 'zeta:speed', x: 2 }, 'zeta:playback');
    assert.equal(pb.speed, 2);
    pb = await h.ask({ type: 'zeta:play' }, 'zeta:playback');
    assert.equal(pb.playing, true);
    // Playing until the clock shows a later time than the seek's (300 ms were a frame or two
    // on a busy machine: the clock moves once a frame).
    await h.frame.waitForFunction(() => parseFloat(document.querySelector('.anim-time').textContent.slice(4)) > 1.5);
    pb = await h.ask({ type: 'zeta:pause' }, 'zeta:playback');
    assert.equal(pb.playing, false);
    assert.ok(pb.t > 1.5, `time advanced while playing (${pb.t})`);
    await h.ask({ type: 'zeta:seek', t: 0.75 }, 'zeta:playback');

    // The whole state as one token: read it, set it on a second embed, read it back.
    const { token } = await h.ask({ type: 'zeta:getState' }, 'zeta:stateToken');
    const q = decodeToken(token);
    assert.equal(q.get('demo'), 'regimes');
    assert.equal(q.get('zeta'), '0.5');
    assert.equal(q.get('theme'), 'projector');
    assert.equal(q.get('range.zeta'), '0,0.5');
    assert.equal(q.get('t'), '0.75');
    assert.equal(q.get('play'), '0');
    const other = await hostPage('demo=quarter-car');
    try {
      await other.ask({ type: 'zeta:setState', token }, 'zeta:change');
      const back = await other.ask({ type: 'zeta:getState' }, 'zeta:stateToken');
      assert.equal(back.token, token, 'read back identical');
      const state = await other.ask({ type: 'zeta:get' }, 'zeta:state');
      assert.equal(state.demo, 'regimes');
      assert.equal(state.params.zeta, 0.5);
      assert.equal(await other.frame.locator('figure:has(canvas[data-plot="poles"])').isHidden(), true);
      // A token from an unknown future version is refused, and the host hears why.
      const err = await other.ask({ type: 'zeta:setState', token: '9.abc' }, 'zeta:error');
      assert.match(err.message, /version/);
      assert.deepEqual(other.errors, []);
    } finally {
      await other.context.close();
    }

    // The frame tells the host its height, and the host page follows it.
    const resize = await h.page.evaluate(() => window.messages.filter((m) => m.type === 'zeta:resize').at(-1));
    assert.ok(resize && resize.height > 300, `resize ${resize && resize.height}`);
    const frameHeight = await h.page.evaluate(() => document.getElementById('zeta').getBoundingClientRect().height);
    assert.ok(Math.abs(frameHeight - Math.min(resize.height, 4000)) <= 2, `${frameHeight} vs ${resize.height}`);
    assert.deepEqual(h.errors, []);
  } finally {
    await h.context.close();
  }
});

test('each export parses, carries the state, and reopens its view when dropped on the page', async () => {
  const h = await hostPage('demo=regimes&zeta=0.15&wn=4');
  let files;
  try {
    const { token } = await h.ask({ type: 'zeta:getState' }, 'zeta:stateToken');
    files = {};
    for (const format of ['csv', 'svg', 'png']) {
      const file = await h.ask({ type: 'zeta:export', plot: 'response', format }, 'zeta:file');
      assert.equal(file.plot, 'response');
      assert.equal(file.format, format);
      files[format] = file;
    }
    const csv = files.csv.data.split('\n');
    assert.equal(files.csv.mime, 'text/csv');
    assert.match(csv[0], new RegExp(`^# zeta-state: ${token.replace(/[.]/g, '\\.')} \\(Zeta Lab \\d+\\.\\d+\\.\\d+\\)$`));
    const header = csv.findIndex((l) => !l.startsWith('#'));
    const rows = csv.slice(header + 1).filter(Boolean).map((l) => l.split(',').map(Number));
    assert.ok(rows.length > 50 && rows.every((r) => r.length === rows[0].length && Number.isFinite(r[0])));
    assert.equal(files.svg.mime, 'image/svg+xml');
    assert.match(files.svg.data, /<svg[^>]*>\n<metadata id="zeta-state" data-version="\d+\.\d+\.\d+">([^<]+)<\/metadata>/);
    assert.ok(files.svg.data.includes(`>${token}</metadata>`));
    assert.equal(files.png.mime, 'image/png');
    assert.match(files.png.data, /^data:image\/png;base64,/);
    const png = Buffer.from(files.png.data.split(',')[1], 'base64');
    const text = pngText(png);
    assert.equal(text['zeta-state'], token);
    assert.match(text['zeta-version'], /^\d+\.\d+\.\d+$/);
    files.token = token;
    assert.deepEqual(h.errors, []);
  } finally {
    await h.context.close();
  }

  // Drop each file onto a fresh page at other values: the stamped view comes back.
  const { page, errors, context } = await open(browser, `${app.url}?demo=quarter-car`);
  if (process.env.DEBUG) page.on('console', (m) => console.log('page:', m.text()));
  try {
    for (const [format, name, mime] of [['png', 'a.png', 'image/png'], ['svg', 'a.svg', 'image/svg+xml'], ['csv', 'a.csv', 'text/csv']]) {
      const f = files[format];
      const base64 = format === 'png' ? f.data.split(',')[1] : Buffer.from(f.data, 'utf8').toString('base64');
      await page.evaluate(() => document.querySelector('[data-key="zeta"][type=number]')?.blur());
      await page.goto(`${app.url}?demo=quarter-car`);
      await page.waitForSelector('html[data-ready="true"]');
      await page.evaluate(([b64, n, m]) => {
        const bytes = Uint8Array.from(atob(b64), (c) => c.charCodeAt(0));
        const dt = new DataTransfer();
        dt.items.add(new File([bytes], n, { type: m }));
        document.body.dispatchEvent(new DragEvent('drop', { dataTransfer: dt, bubbles: true, cancelable: true }));
      }, [base64, name, mime]);
      await page.waitForFunction(() => new URLSearchParams(location.search).get('demo') === 'regimes');
      await page.waitForFunction(() => Math.abs(Number(document.querySelector('[data-readout="zeta"]')?.dataset.value) - 0.15) < 1e-12);
      const q = await page.evaluate(() => location.search);
      assert.match(q, /zeta=0\.15/, format);
      assert.match(q, /wn=4/, format);
    }
    assert.deepEqual(errors, []);
  } finally {
    await context.close();
  }
});

test('predict, then reveal: keyboard only, announced, and reported to the host as xAPI', async () => {
  const h = await hostPage('demo=quarter-car&zeta=0.3&predict=overshoot&tol=5%25&controls=zeta');
  try {
    const f = h.frame;
    assert.equal(await f.locator('[data-readout="overshoot"]').isHidden(), true);
    assert.equal(await f.locator('figure:has(canvas[data-plot="response"])').isHidden(), true);
    assert.equal(await f.getAttribute('#plot-announcer', 'aria-live'), 'off', 'plot descriptions are not read out before the reveal');
    const before = await h.page.evaluate(() => window.messages.filter((m) => m.type === 'zeta:resize').length);
    // Keyboard only: Tab from the top of the frame to the prediction box, type, Enter.
    await f.locator('body').evaluate(() => document.activeElement?.blur());
    await h.page.locator('#zeta').focus();
    let focused = '';
    for (let i = 0; i < 30 && focused !== 'zeta-predict-input'; i++) {
      await h.page.keyboard.press('Tab');
      focused = await f.evaluate(() => document.activeElement?.id || '');
    }
    assert.equal(focused, 'zeta-predict-input', 'reachable with Tab');
    await h.page.keyboard.type('abc');
    if (process.env.DEBUG) console.log('typed:', await f.evaluate(() => [document.activeElement.id, document.activeElement.value, document.hasFocus()]));
    await h.page.keyboard.press('Enter');
    await f.waitForFunction(() => /not a number/.test(document.getElementById('zeta-predict-error').textContent));
    assert.equal(await f.getAttribute('#zeta-predict-error', 'role'), 'alert');
    await h.page.keyboard.press('Control+A');
    await h.page.keyboard.type('30');
    await h.page.keyboard.press('Enter');
    await h.page.waitForFunction(() => window.messages.some((m) => m.type === 'zeta:prediction'));
    const msg = await h.page.evaluate(() => window.messages.find((m) => m.type === 'zeta:prediction'));
    const value = Number(await f.getAttribute('[data-readout="overshoot"]', 'data-value'));
    assert.equal(msg.prediction, 30);
    assert.equal(msg.value, value);
    assert.ok(Math.abs(msg.difference - (30 - value)) < 1e-9);
    assert.equal(msg.success, Math.abs(30 - value) <= 0.05 * value);
    assert.equal(msg.params.zeta, 0.3);
    assert.equal(msg.statement.verb.id, 'http://adlnet.gov/expapi/verbs/answered');
    assert.equal(msg.statement.object.definition.interactionType, 'numeric');
    assert.equal(msg.statement.result.response, '30');
    assert.equal(msg.statement.result.success, msg.success);
    assert.equal(msg.statement.actor, undefined, 'the host adds the actor');
    assert.ok(!Number.isNaN(Date.parse(msg.timestamp)));
    // Revealed, announced and focused.
    assert.equal(await f.locator('[data-readout="overshoot"]').isHidden(), false);
    assert.equal(await f.locator('figure:has(canvas[data-plot="response"])').isVisible(), true);
    const result = f.locator('#zeta-predict-result');
    assert.equal(await result.getAttribute('role'), 'status');
    assert.match(await result.textContent(), /You predicted 30 %; the .* is [\d.]+ %/);
    assert.equal(await f.evaluate(() => document.activeElement?.id), 'zeta-predict-result');
    assert.equal(await f.getAttribute('#plot-announcer', 'aria-live'), 'polite');
    // The plots appeared, so the page grew and told the host.
    await h.page.waitForFunction((n) => window.messages.filter((m) => m.type === 'zeta:resize').length > n, before);
    await h.page.screenshot({ path: `${SHOTS}lecturer-host.png` });
    assert.deepEqual(h.errors, []);
  } finally {
    await h.context.close();
  }
});

test('the Share dialog authors ranges, readouts, theme, language, a prediction and the token', async () => {
  const { page, errors, context } = await open(browser, `${app.url}?demo=regimes&zeta=0.1`);
  try {
    await page.click('#share-button');
    await page.waitForSelector('dialog#share-dialog[open]');
    await page.fill('#share-min-zeta', '0');
    await page.fill('#share-max-zeta', '0.2');
    await page.fill('#share-step-zeta', '0.001');
    await page.uncheck('#share-readouts-pole_re');
    await page.selectOption('#share-theme', 'projector');
    await page.selectOption('#share-lang', 'es');
    await page.selectOption('#share-predict', 'wd');
    await page.uncheck('#share-fullscreen');
    await page.fill('#share-preset-name', 'Light damping');
    await page.click('#share-preset-add');
    const link = await page.inputValue('#share-link');
    const snippet = await page.inputValue('#share-snippet');
    const token = await page.inputValue('#share-token');
    for (const part of ['presets=Light+damping%3Awn%3D6%2Czeta%3D0.1%2Cx0%3D0.06%2Cv0%3D0', 'range.zeta=0%2C0.2', 'step.zeta=0.001', 'theme=projector', 'lang=es', 'predict=wd', 'tol=10%25']) {
      assert.ok(link.includes(part), `${part} in ${link}`);
    }
    assert.match(snippet, /embed=1.*fullscreen=0/);
    assert.match(snippet, /readouts=regime%2Cwn%2Czeta%2Cwd%2Cpole_im/);
    const q = decodeToken(token);
    assert.equal(q.get('range.zeta'), '0,0.2');
    assert.equal(q.get('zeta'), '0.1');
    const preview = page.frameLocator('iframe.share-preview');
    await page.waitForFunction(() => (document.querySelector('iframe.share-preview').getAttribute('src') || '').includes('range.zeta'));
    await preview.locator('#zeta-predict-input').waitFor({ timeout: 15000 });
    assert.equal(await preview.locator('input[type=range][data-key="zeta"]').getAttribute('max'), '0.2');
    await page.screenshot({ path: `${SHOTS}lecturer-share-dialog.png`, fullPage: false });
    await page.setViewportSize({ width: 360, height: 740 });
    await page.screenshot({ path: `${SHOTS}lecturer-share-dialog-narrow.png` });
    // Pasting a shared link with a token elsewhere on the page restores that view.
    await page.click('.share-close');
    await page.goto(`${app.url}?demo=rlc`);
    await page.waitForSelector('html[data-ready="true"]');
    await page.evaluate((t) => {
      const dt = new DataTransfer();
      dt.setData('text/plain', `https://example.org/zeta/?state=${t}`);
      document.body.dispatchEvent(new ClipboardEvent('paste', { clipboardData: dt, bubbles: true, cancelable: true }));
    }, token);
    await page.waitForURL(/lang=es/);
    await page.waitForSelector('html[data-ready="true"]');
    assert.equal(await page.getAttribute('input[type=range][data-key="zeta"]', 'max'), '0.2');
    assert.equal(await page.getAttribute('html', 'lang'), 'es');
    // The lecturer's preset came along in the token; it sets values through the Rust parser.
    await typeValue(page, 'zeta', '0.15');
    await page.waitForFunction(() => Math.abs(Number(document.querySelector('[data-readout="zeta"]').dataset.value) - 0.15) < 1e-12);
    await page.click('.lecturer-presets button:has-text("Light damping")');
    await page.waitForFunction(() => Math.abs(Number(document.querySelector('[data-readout="zeta"]').dataset.value) - 0.1) < 1e-12);
    assert.deepEqual(errors, []);
  } finally {
    await context.close();
  }
});

test('an old token opens: missing parameters take defaults with a notice, unknown ones are ignored', async () => {
  const token = `1.${Buffer.from('demo=regimes&zeta=0.4&future_knob=3').toString('base64url')}`;
  const { page, errors, context } = await open(browser, `${app.url}?state=${token}`);
  try {
    assert.ok(Math.abs(Number(await page.getAttribute('[data-readout="zeta"]', 'data-value')) - 0.4) < 1e-12);
    const notice = await page.textContent('#notices');
    assert.match(notice, /wn, x0, v0 are not in it/);
    assert.match(notice, /future_knob is not known here/);
    assert.deepEqual(errors, []);
  } finally {
    await context.close();
  }
});
