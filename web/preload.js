// Starts the download of the one module the page will start with (web/main.js decides the
// same way): the small first module for the default demo, the full one otherwise. A static
// preload in the HTML could not depend on the address, and would make every other demo
// download both. The post-build hook writes the integrity hashes; without them (a dev
// build) nothing is preloaded.
(() => {
  const HASHES = {
    'zeta-first.js': '__HASH__',
    'zeta-first_bg.wasm': '__HASH__',
    'zeta-app.js': '__HASH__',
    'zeta-app_bg.wasm': '__HASH__',
  };
  const q = new URLSearchParams(window.location.search);
  if (q.has('state')) return; // the demo is inside the token (web/state.js)
  const demo = q.get('demo');
  const first = (demo === null || demo === 'regimes') && q.get('embed') !== '1';
  const files = first ? ['zeta-first.js', 'zeta-first_bg.wasm'] : ['zeta-app.js', 'zeta-app_bg.wasm'];
  for (const file of files) {
    if (!HASHES[file].startsWith('sha384-')) continue;
    const link = document.createElement('link');
    if (file.endsWith('.js')) {
      link.rel = 'modulepreload';
    } else {
      link.rel = 'preload';
      link.as = 'fetch';
      link.type = 'application/wasm';
    }
    link.crossOrigin = 'anonymous';
    link.integrity = HASHES[file];
    link.href = `./${file}`;
    document.head.append(link);
  }
})();
