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

# Release builds: also the "first" module (feature `first`: only the default demo), which
# the page starts with for that demo while the full module loads behind it (web/main.js).
# Same crate, same profile and target dir, so only zeta-app itself is compiled again.
src="${TRUNK_SOURCE_DIR:-.}"
if [ "${TRUNK_PROFILE:-}" = "release" ]; then
  target_dir="${CARGO_TARGET_DIR:-$src/target}"
  (cd "$src" && cargo build --quiet -p zeta-app --release --target wasm32-unknown-unknown --features first)
  wasm-bindgen --target web --no-typescript --out-dir "$stage" --out-name zeta-first \
    "$target_dir/wasm32-unknown-unknown/release/zeta_app.wasm"
fi

# Release builds: shrink the wasm with binaryen's wasm-opt from npm (package-lock.json).
# Not Debian's binaryen: its wasm-opt 108 rewrites the externref table that wasm-bindgen
# emits into one browsers reject at start-up.
# `-Os --converge` rather than `-Oz`: about 2 KB less brotli (what the page downloads),
# though 7 KB more before compression; -Os gives up less speed for size (docs/wasm-size.md).
opt="$src/node_modules/.bin/wasm-opt"
if [ "${TRUNK_PROFILE:-}" = "release" ]; then
  if [ ! -x "$opt" ]; then
    echo "post-build: $opt is missing; run scripts/setup.sh" >&2
    exit 1
  fi
  for wasm in "$stage/zeta-app_bg.wasm" "$stage/zeta-first_bg.wasm"; do
    "$opt" -Os --converge --strip-debug --strip-producers \
      --enable-bulk-memory --enable-sign-ext --enable-mutable-globals \
      --enable-nontrapping-float-to-int --enable-reference-types --enable-multivalue \
      "$wasm" -o "$wasm.opt"
    mv "$wasm.opt" "$wasm"
  done
  # Trunk's static preloads name the full module: web/preload.js preloads the one module
  # the address starts with instead (the first module for the default demo), so the full
  # module takes no bandwidth from the first plot and other demos do not download both.
  perl -0pi -e 's#<link rel="(?:module)?preload" href="\./zeta-app(?:\.js|_bg\.wasm)"[^>]*>##g' "$html"
  if grep -q 'preload" href="./zeta-app' "$html"; then
    echo "post-build: could not remove Trunk's preloads" >&2
    exit 1
  fi
fi
# Release builds: minify the page's JavaScript and CSS with esbuild from npm
# (package-lock.json), file by file: no bundling, so each module keeps its imports and the
# ones loaded on first use stay separate files. About 11 KB brotli less before the first
# plot (docs/wasm-size.md). Before the hashes below, which are over the final files;
# preload.js, which receives them, after.
esbuild="$src/node_modules/.bin/esbuild"
minify() {
  for f in "$@"; do
    "$esbuild" "$f" --minify --log-level=warning --allow-overwrite --outfile="$f"
  done
}
if [ "${TRUNK_PROFILE:-}" = "release" ]; then
  if [ ! -x "$esbuild" ]; then
    echo "post-build: $esbuild is missing; run scripts/setup.sh" >&2
    exit 1
  fi
  minify "$stage"/zeta-*.js "$stage"/web/*.css
  for f in "$stage"/web/*.js; do
    [ "$(basename "$f")" = preload.js ] || minify "$f"
  done
fi
for f in zeta-app_bg.wasm zeta-app.js zeta-first_bg.wasm zeta-first.js; do
  [ -f "$stage/$f" ] || continue
  hash="sha384-$(openssl dgst -sha384 -binary "$stage/$f" | openssl base64 -A)"
  perl -pi -e "s#(href=\"\\./\Q$f\E\"[^>]*?integrity=\")[^\"]*#\${1}$hash#g" "$html"
  perl -pi -e "s#('\Q$f\E': ')__HASH__#\${1}$hash#" "$stage/web/preload.js"
done

if [ "${TRUNK_PROFILE:-}" = "release" ]; then
  if grep -q "__HASH__" "$stage/web/preload.js"; then
    echo "post-build: preload.js did not receive every integrity hash" >&2
    exit 1
  fi
  minify "$stage/web/preload.js"
fi

# Version the service worker's cache by the build and list every file it must cache.
build="$(cat "$stage"/zeta-*.wasm "$stage"/zeta-*.js "$stage"/web/* | openssl dgst -sha256 | awk '{print substr($NF, 1, 16)}')"
files="$(cd "$stage" && find . -type f ! -name sw.js | sed 's#^\./##' | sort | awk '{printf ", \x27%s\x27", $0}')"
perl -pi -e "s#__ZETA_BUILD__#$build#; s#const FILES = \['\./'\];#const FILES = ['./'$files];#" "$stage/sw.js"
