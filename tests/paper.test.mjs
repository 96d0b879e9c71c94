// End to end: "The paper, checked". Every claim the issue names is on the page with its
// verdict; every link opens a demo that shows the state and the value the tour states; the
// tour reads well on a laptop and a phone, prints, and is accessible.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { drawn, open, SHOTS } from './support/browser.mjs';
import { useSession, server, browser } from './support/session.mjs';

useSession();

const REQUIRED = {
  'fig1-zeta-optimum': 'confirmed',
  'sec3-natural-frequency': 'confirmed',
  'sec4-critical-resistance': 'confirmed',
  'fig3-q-factor': 'confirmed',
  'sec5-peak-frequency': 'confirmed',
  'fig4-euler-error': 'differs',
  'fig4-rk4-error': 'differs',
  'fig4-euler-slope': 'differs',
  'sec7-mass-tolerance': 'differs',
};

/** The tour's claims as the page shows them. */
function claims(page) {
  return page.$$eval('[data-claim]', (els) =>
    els.map((e) => ({
      id: e.dataset.claim,
      verdict: e.dataset.verdict,
      computed: e.querySelector('.tour-computed dd').textContent,
      link: e.querySelector('a.tour-link').getAttribute('href'),
      reason: e.querySelector('.tour-verdict').textContent,
    })),
  );
}

/**
 * Resolves once every claim has its verdict: the page's first module links only the demo
 * of the first figure and leaves the other claims pending; the full module checks them.
 */
function checked(page) {
  const done = () => document.querySelector('[data-claim]') && !document.querySelector('[data-verdict="pending"]');
  return page.waitForFunction(done, null, { timeout: 30000 });
}

test('the first module draws the first figure and lists every claim; the full module checks the rest', async () => {
  // The full module held back (its wasm never arrives): the page as its first module shows it.
  const hold = (c) => c.route('**/zeta-app_bg.wasm', () => {});
  const first = await open(browser, `${server.url}?demo=paper`, { before: hold, serviceWorkers: 'block' });
  const { page } = first;
  await page.waitForSelector('[data-claim]');
  assert.equal(await page.evaluate(() => window.zetaDiagnostics.module()), 'first');
  const early = await claims(page);
  const own = early.filter((c) => c.link.startsWith('?demo=quarter-car'));
  const rest = early.filter((c) => !c.link.startsWith('?demo=quarter-car'));
  assert.ok(own.length > 0 && rest.length > 0, `${own.length} checked, ${rest.length} to come`);
  assert.equal(Number(await page.getAttribute('[data-readout="claims"]', 'data-value')), own.length, 'claims checked so far');
  for (const c of own) assert.ok(['confirmed', 'differs'].includes(c.verdict), `${c.id}: ${c.verdict}`);
  for (const c of rest) {
    assert.equal(c.verdict, 'pending', c.id);
    assert.equal(c.computed, '…', c.id);
    assert.match(c.reason, /^Checking… Checked as soon as the whole app has loaded/, c.id);
  }
  const marks = await page.$$eval('[data-provisional]', (els) => els.map((e) => e.dataset.readout ?? e.dataset.plotWrap));
  for (const key of ['claims', 'confirmed', 'differs']) assert.ok(marks.includes(key), `${key} marked: ${marks}`);
  assert.ok(marks.includes('fig2a') && !marks.includes('fig1a'), `thumbnails to come marked: ${marks}`);
  const ink = await page.$eval('canvas[data-plot="fig1a"]', (c) => {
    const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
    let n = 0;
    for (let i = 0; i < d.length; i += 4) if (d[i] !== d[0] || d[i + 1] !== d[1] || d[i + 2] !== d[2]) n++;
    return n;
  });
  assert.ok(ink > 1000, `the first figure is drawn (${ink} px of ink)`);
  assert.deepEqual(first.errors, []);
  await first.context.close();

  // Let through: the full module takes over and checks the rest, in place.
  const { page: full, errors, context } = await open(browser, `${server.url}?demo=paper`);
  await checked(full);
  assert.equal(await full.evaluate(() => window.zetaDiagnostics.module()), 'full');
  const late = await claims(full);
  assert.deepEqual(late.map((c) => c.id), early.map((c) => c.id), 'the same claims, in the same places');
  for (const c of own) assert.deepEqual(late.find((x) => x.id === c.id), c, `${c.id}: unchanged`);
  assert.equal(Number(await full.getAttribute('[data-readout="claims"]', 'data-value')), late.length, 'every claim checked');
  await full.waitForFunction(() => !document.querySelector('[data-provisional]'));
  assert.deepEqual(errors, []);
  await context.close();
});

test('every required claim is on the page with its verdict, and every exhibit has a thumbnail', async () => {
  const { page, errors, context } = await open(browser, `${server.url}?demo=paper`);
  await checked(page);
  const shown = await claims(page);
  for (const [id, verdict] of Object.entries(REQUIRED)) {
    const c = shown.find((x) => x.id === id);
    assert.ok(c, `claim ${id} is on the page`);
    assert.equal(c.verdict, verdict, `${id}: ${c.reason}`);
    assert.ok(c.reason.length > 20, `${id} gives a reason`);
  }
  const exhibits = await page.$$eval('[data-exhibit]', (els) =>
    els.map((e) => ({ id: e.dataset.exhibit, canvas: !!e.querySelector('canvas[data-plot]'), link: !!e.querySelector('a.tour-link') })),
  );
  for (const id of ['fig1a', 'fig1b', 'fig2a', 'fig2b', 'fig3a', 'fig3b', 'fig4a', 'fig4b', 'fig5', 'table1', 'table2', 'table3']) {
    const e = exhibits.find((x) => x.id === id);
    assert.ok(e && e.canvas && e.link, `${id}: thumbnail and link`);
  }
  // Every thumbnail has its text alternative (built when it is drawn: the first frame draws
  // the thumbnails in view, the others follow once the page rests).
  await drawn(page);
  const alts = await page.$$eval('[data-exhibit] canvas[data-plot]', (cs) =>
    cs.map((c) => document.getElementById(c.getAttribute('aria-describedby'))?.textContent ?? ''),
  );
  assert.ok(alts.every((a) => a.length > 10), 'every thumbnail is described');
  await page.screenshot({ path: `${SHOTS}paper-1280.png`, fullPage: false });
  assert.deepEqual(errors, []);
  await context.close();
});

test('every claim link opens its demo showing the value the tour states', async () => {
  const { page, context } = await open(browser, `${server.url}?demo=paper`);
  await checked(page);
  const shown = await claims(page);
  await context.close();
  for (const c of shown) {
    const { page: demo, errors, context: ctx } = await open(browser, `${server.url}${c.link}`);
    const params = new URLSearchParams(c.link);
    for (const [k, v] of params) {
      if (k === 'demo') continue;
      const control = await demo.$(`input[type=number][data-key="${k}"], select[data-key="${k}"]`);
      if (control) {
        const value = await control.inputValue();
        assert.ok(Math.abs(Number(value) - Number(v)) < 1e-9 || value === v, `${c.id}: ${k} = ${value}, link says ${v}`);
      }
    }
    // The computed value is the linked demo's own readout text (or, for the two solver
    // checks, not a readout at all).
    if (!['sec5-peak-frequency', 'fig4-euler-slope'].includes(c.id)) {
      const texts = await demo.$$eval('[data-readout] dd', (dds) => dds.map((d) => d.textContent));
      const parts = c.computed.split(' to ');
      for (const p of parts) assert.ok(texts.includes(p), `${c.id}: the demo shows ${p} (${texts.join(' | ')})`);
    }
    assert.deepEqual(errors, [], c.link);
    await ctx.close();
  }
});

test('on a phone the tour fits the width, and it prints', async () => {
  const { page, errors, context } = await open(browser, `${server.url}?demo=paper`, { viewport: { width: 360, height: 740 } });
  await checked(page);
  const overflow = await page.evaluate(() => document.documentElement.scrollWidth - window.innerWidth);
  assert.ok(overflow <= 1, `no horizontal scroll (${overflow} px)`);
  await page.locator('[data-exhibit="fig4a"]').scrollIntoViewIfNeeded();
  await page.screenshot({ path: `${SHOTS}paper-360.png` });
  await page.emulateMedia({ media: 'print' });
  const pdf = await page.pdf({ format: 'A4' });
  assert.ok(pdf.length > 10000, 'prints');
  assert.deepEqual(errors, []);
  await context.close();
});

test('from the paper, the demo menu opens a demo with its controls and its plot', async () => {
  // The tour hid the stage and the controls on the page's root, and the next demo opened
  // from the menu kept them hidden (until 2026-12-04).
  const { page, errors, context } = await open(browser, `${server.url}?demo=paper`);
  await checked(page);
  await page.selectOption('#demo-select', 'regimes');
  await page.waitForFunction(() => document.querySelector('.workspace')?.dataset.demo === 'regimes' && window.zetaDiagnostics.drawn());
  for (const selector of ['.controls', '.stage-slot canvas[data-plot]', 'input[type=range]']) {
    assert.ok(await page.isVisible(selector), `${selector} is shown`);
  }
  assert.equal(await page.$('.tour'), null);
  assert.deepEqual(errors, []);
  await context.close();
});
