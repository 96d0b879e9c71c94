#!/usr/bin/env bash
# Release build of the static site into dist/ (Trunk; its post-build hook runs wasm-opt).
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$ROOT"
export PATH="$HOME/.cargo/bin:$PATH"
trunk build --release --dist dist
wasm="dist/zeta-app_bg.wasm"
printf 'built dist/: wasm %s bytes (gzipped %s), js %s bytes (gzipped %s)\n' \
  "$(wc -c < "$wasm")" "$(gzip -9c "$wasm" | wc -c)" \
  "$(cat dist/zeta-app.js dist/web/*.js | wc -c)" "$(cat dist/zeta-app.js dist/web/*.js | gzip -9c | wc -c)"
