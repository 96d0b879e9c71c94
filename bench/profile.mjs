// Profiles one demo's slider events at 4× CPU slowdown (DevTools Protocol `Profiler`) and
// prints the functions with the most self time. Each slider is one held drag (pointer down,
// the moves, pointer up, 500 ms of rest), as bench/lowend.mjs moves it, on the full module.
// Usage, after scripts/build.sh:
//   node bench/profile.mjs <demo> [slider-key] [events]
// ZETA_ROOT=dir profiles the build in dir instead of dist/ (wasm functions keep their names
// in a module optimised without --strip-debug); ZETA_PROFILE_OUT=file.cpuprofile writes the
// whole profile (DevTools opens it) for callers and callees.
import { writeFileSync } from 'node:fs';
import { installSlider, fraction, withSite } from './slide.mjs';

const [id = 'design', key = '', n = '10'] = process.argv.slice(2);
await withSite({ brotli: true, root: process.env.ZETA_ROOT }, async (browser, url) => {
  const context = await browser.newContext({ viewport: { width: 360, height: 740 }, deviceScaleFactor: 2 });
  const page = await context.newPage();
  const cdp = await context.newCDPSession(page);
  await page.goto(`${url}?demo=${id}`);
  await page.waitForSelector('html[data-ready="true"]');
  await page.waitForFunction(() => performance.getEntriesByName('zeta:first-draw').length > 0);
  await page.waitForFunction(() => window.zetaDiagnostics.module() === 'full' && window.zetaDiagnostics.drawn(), null, { timeout: 30000 });
  await installSlider(page);
  await cdp.send('Emulation.setCPUThrottlingRate', { rate: 4 });
  await cdp.send('Profiler.enable');
  await cdp.send('Profiler.setSamplingInterval', { interval: 200 });
  await cdp.send('Profiler.start');
  const times = await page.evaluate(
    async ([key, n, fr]) => {
      const sel = key ? `input[type=range][data-key="${key}"]` : 'input[type=range][data-key]';
      const out = [];
      for (const r of [...document.querySelectorAll(sel)].filter((r) => !r.disabled)) {
        r.dispatchEvent(new PointerEvent('pointerdown', { bubbles: true }));
        for (let i = 0; i < n; i++) out.push([r.dataset.key, Math.round((await window.__slideOnce(r, fr[i])).script)]);
        window.dispatchEvent(new PointerEvent('pointerup'));
        await new Promise((rest) => setTimeout(rest, 500));
      }
      return out;
    },
    [key, Number(n), Array.from({ length: Number(n) }, (_, i) => fraction(i))],
  );
  const { profile } = await cdp.send('Profiler.stop');
  if (process.env.ZETA_PROFILE_OUT) writeFileSync(process.env.ZETA_PROFILE_OUT, JSON.stringify(profile));
  const self = new Map();
  const dt = new Map();
  profile.samples.forEach((id, i) => dt.set(i, profile.timeDeltas[i] || 0));
  const byId = new Map(profile.nodes.map((nd) => [nd.id, nd]));
  profile.samples.forEach((id, i) => {
    const nd = byId.get(id);
    const name = `${nd.callFrame.functionName || '(anon)'} ${nd.callFrame.url.split('/').pop()}`;
    self.set(name, (self.get(name) || 0) + (profile.timeDeltas[i] || 0) / 1000);
  });
  const total = [...self.values()].reduce((a, b) => a + b, 0);
  const perKey = {};
  for (const [k, t] of times) (perKey[k] ||= []).push(t);
  console.log('per slider (ms):', JSON.stringify(perKey));
  console.log(`total sampled ${total.toFixed(0)} ms; top self time:`);
  for (const [name, t] of [...self].sort((a, b) => b[1] - a[1]).slice(0, 25)) console.log(`${t.toFixed(1).padStart(8)} ms  ${name}`);
});
