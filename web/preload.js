// The page's decisions from its address, made once, here, in <head> before the first paint
// (a classic script without `async`: it runs before the body is parsed and before
// web/main.js, which reads what it records on <html>). The post-build hook writes it into
// index.html itself, allowed by its hash in the page's Content-Security-Policy: as a file
// it cost a round trip before any module was requested.
// - data-theme: the theme= of the address (light, dark or projector), else the system's
//   light or dark, following the system while the page is open. style.css themes by it,
//   main.js draws the plots by it.
// - data-start-module: 'first' (a small module that links only the demo the address opens,
//   on a first visit, embedded or not: a host that opens another demo at once reloads the
//   frame at its address, see embed.js applyToken) or 'full' (a page the service worker
//   serves, which has the full module in its cache; an address naming no demo that has a
//   first module; a dev build, which has none); data-start-demo: the demo of that first
//   module.
// It starts the download of that one module, and of what this address needs up front (the
// lecturer styles for the projector theme, the host-page API in an embed, the prediction
// form). A static preload in the HTML could not depend on the address, and would make
// every other demo download two modules.
// A `state=` token (web/state.js: "1." + base64url of a query) is read here too, with the
// address's own keys winning as there, so a shared link starts its demo's module as early
// as a plain address does. state.js expands it into the address after this has run;
// main.js then sends 'zeta:address' and the decisions are made again on the expanded
// address (as when a token is restored in place later: the theme follows it).
(() => {
  // The demos that have a first module (zeta-first-<demo>.js, zeta-first-<demo>_bg.wasm),
  // written by the post-build hook; none in a dev build.
  const FIRST_DEMOS = [];
  const DEFAULT_DEMO = 'regimes';
  const THEMES = ['light', 'dark', 'projector'];
  const root = document.documentElement;
  const system = window.matchMedia('(prefers-color-scheme: dark)');

  /** The address's query, a version-1 `state=` token expanded (an unreadable one dropped). */
  const address = () => {
    const q = new URLSearchParams(window.location.search);
    const token = q.get('state');
    if (token === null) return q;
    q.delete('state');
    try {
      const [, data] = /^\s*1\.([A-Za-z0-9_-]+)\s*$/.exec(token) ?? [];
      if (!data) return q;
      const bin = atob(data.replace(/-/g, '+').replace(/_/g, '/'));
      const text = new TextDecoder('utf-8', { fatal: true }).decode(Uint8Array.from(bin, (c) => c.charCodeAt(0)));
      const expanded = new URLSearchParams(text);
      for (const [k, v] of q) expanded.set(k, v);
      return expanded;
    } catch {
      return q;
    }
  };

  const decide = () => {
    const q = address();
    const theme = q.get('theme');
    root.dataset.theme = THEMES.includes(theme) ? theme : system.matches ? 'dark' : 'light';
    // Which module starts is decided before the page starts, not again.
    if (root.dataset.ready !== 'true') {
      const demo = q.get('demo') ?? DEFAULT_DEMO;
      const cached = 'serviceWorker' in navigator && navigator.serviceWorker.controller !== null;
      const first = FIRST_DEMOS.includes(demo) && !cached;
      root.dataset.startModule = first ? 'first' : 'full';
      if (first) root.dataset.startDemo = demo;
      else delete root.dataset.startDemo;
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
    link({ rel: 'stylesheet', href: 'web/lecturer.css' }).dataset.lecturer = '1';
  }
  if (q.get('embed') === '1') link({ rel: 'modulepreload', href: 'web/embed.js' });
  if (q.has('predict')) link({ rel: 'modulepreload', href: 'web/predict.js' });

  const name = root.dataset.startModule === 'first' ? `zeta-first-${root.dataset.startDemo}` : 'zeta-app';
  link({ rel: 'modulepreload', crossOrigin: 'anonymous', href: `./${name}.js` });
  link({ rel: 'preload', as: 'fetch', type: 'application/wasm', crossOrigin: 'anonymous', href: `./${name}_bg.wasm` });
})();
