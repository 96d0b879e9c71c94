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

test('every required claim is on the page with its verdict, and every exhibit has a thumbnail', async () => {
  const { page, errors, context } = await open(browser, `${server.url}?demo=paper`);
  await page.waitForSelector('[data-claim]');
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
  await page.waitForSelector('[data-claim]');
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
  await page.waitForSelector('[data-claim]');
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
