#!/usr/bin/env bash
# Release build of the static site into dist/ (Trunk; its post-build hook runs wasm-opt).
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$ROOT"
export PATH="$HOME/.cargo/bin:$PATH"
# Panic locations name source files: name them relative to the registry and the project, so
# the wasm a lecturer hosts carries no path of the machine that built it.
cargo_home="${CARGO_HOME:-$HOME/.cargo}"
export RUSTFLAGS="${RUSTFLAGS:-} --remap-path-prefix=$cargo_home/registry/src=registry --remap-path-prefix=$ROOT=."
trunk build --release --dist dist
# No absolute path of this machine in what is shipped.
if grep -rlaF -e "$cargo_home" -e "$ROOT" dist/; then
  echo "build: the files above name a path of this machine" >&2
  exit 1
fi
wasm="dist/zeta-app_bg.wasm"
printf 'built dist/: wasm %s bytes (gzipped %s), js %s bytes (gzipped %s)\n' \
  "$(wc -c < "$wasm")" "$(gzip -9c "$wasm" | wc -c)" \
  "$(cat dist/zeta-app.js dist/web/*.js | wc -c)" "$(cat dist/zeta-app.js dist/web/*.js | gzip -9c | wc -c)"
