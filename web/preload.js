// The page's decisions from its address, made once, here, in <head> before the first paint
// (a classic script without `async`: it runs before the body is parsed and before
// web/main.js, which reads what it records on <html>):
// - data-theme: the theme= of the address (light, dark or projector), else the system's
//   light or dark, following the system while the page is open. style.css themes by it,
//   main.js draws the plots by it.
// - data-start-module: 'first' (the small module with only the default demo, on the main
//   page) or 'full' (every other demo, and embeds, whose host may open any demo at once).
// It starts the download of that one module, and of what this address needs up front (the
// lecturer styles for the projector theme, the host-page API in an embed, the prediction
// form). A static preload in the HTML could not depend on the address, and would make
// every other demo download both modules. The post-build hook writes the integrity hashes;
// without them (a dev build) no module is preloaded.
// web/state.js expands a `state=` token into the address after this has run; main.js then
// sends 'zeta:address' and the decisions are made again on the expanded address (as when
// a token is restored in place later: the theme follows it).
(() => {
  const HASHES = {
    'zeta-first.js': '__HASH__',
    'zeta-first_bg.wasm': '__HASH__',
    'zeta-app.js': '__HASH__',
    'zeta-app_bg.wasm': '__HASH__',
  };
  const DEFAULT_DEMO = 'regimes';
  const THEMES = ['light', 'dark', 'projector'];
  const root = document.documentElement;
  const here = document.currentScript ? document.currentScript.src : window.location.href;
  const system = window.matchMedia('(prefers-color-scheme: dark)');

  const decide = () => {
    const q = new URLSearchParams(window.location.search);
    const theme = q.get('theme');
    root.dataset.theme = THEMES.includes(theme) ? theme : system.matches ? 'dark' : 'light';
    // Which module starts is decided before the page starts, not again.
    if (root.dataset.ready !== 'true') {
      const demo = q.get('demo');
      const first = (demo === null || demo === DEFAULT_DEMO) && q.get('embed') !== '1';
      root.dataset.startModule = first ? 'first' : 'full';
    }
    return q;
  };

  const link = (attrs) => {
    const el = document.createElement('link');
    Object.assign(el, attrs);
    document.head.append(el);
    return el;
  };

  const q = decide();
  system.addEventListener('change', decide);
  document.addEventListener('zeta:address', decide);

  if (q.get('theme') === 'projector') {
    link({ rel: 'stylesheet', href: new URL('lecturer.css', here).href }).dataset.lecturer = '1';
  }
  if (q.get('embed') === '1') link({ rel: 'modulepreload', href: new URL('embed.js', here).href });
  if (q.has('predict')) link({ rel: 'modulepreload', href: new URL('predict.js', here).href });

  if (q.has('state')) return; // the demo is inside the token: main.js starts its module
  const first = root.dataset.startModule === 'first';
  const files = first ? ['zeta-first.js', 'zeta-first_bg.wasm'] : ['zeta-app.js', 'zeta-app_bg.wasm'];
  for (const file of files) {
    if (!HASHES[file].startsWith('sha384-')) continue;
    const attrs = { crossOrigin: 'anonymous', integrity: HASHES[file], href: `./${file}` };
    if (file.endsWith('.js')) link({ rel: 'modulepreload', ...attrs });
    else link({ rel: 'preload', as: 'fetch', type: 'application/wasm', ...attrs });
  }
})();
