#!/usr/bin/env bash
# Trunk post-build hook (see Trunk.toml), run on the staging folder before it becomes dist/.
# 1. Removes the inline loader script Trunk writes: the page loads the wasm from
#    web/main.js instead, so it runs under a CSP without 'unsafe-inline'.
# 2. Recomputes the preload integrity hashes over the final files.
set -euo pipefail
stage="${TRUNK_STAGING_DIR:?run by trunk}"
html="$stage/index.html"

perl -0pi -e 's#<script type="module">\s*import init[^<]*?TrunkApplicationStarted[^<]*?</script>##s' "$html"
if grep -q 'TrunkApplicationStarted' "$html"; then
  echo "post-build: could not remove Trunk's inline loader" >&2
  exit 1
fi

# wasm-opt is not run: Debian's binaryen (108) rewrites the externref table that
# wasm-bindgen 0.2.130 emits into one the browser rejects at start-up
# ("WebAssembly.Table.set(): Argument 1 is invalid"). rustc's release profile
# (LTO, one codegen unit) already gives ~130 KB gzipped.
for f in zeta-app_bg.wasm zeta-app.js; do
  hash="sha384-$(openssl dgst -sha384 -binary "$stage/$f" | openssl base64 -A)"
  perl -pi -e "s#(href=\"\\./\Q$f\E\"[^>]*?integrity=\")[^\"]*#\${1}$hash#g" "$html"
done

# Version the service worker's cache by the build and list every file it must cache.
build="$(cat "$stage/zeta-app_bg.wasm" "$stage/zeta-app.js" "$stage"/web/* | openssl dgst -sha256 | awk '{print substr($NF, 1, 16)}')"
files="$(cd "$stage" && find . -type f ! -name sw.js | sed 's#^\./##' | sort | awk '{printf ", \x27%s\x27", $0}')"
perl -pi -e "s#__ZETA_BUILD__#$build#; s#const FILES = \['\./'\];#const FILES = ['./'$files];#" "$stage/sw.js"
