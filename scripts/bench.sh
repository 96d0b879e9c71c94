#!/usr/bin/env bash
# Every benchmark: the solver's criterion benches natively, then the release site in headless
# Chromium (per-demo slider-event p50/p95, cold-load time to first plot, bytes shipped).
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$ROOT"
bash scripts/setup.sh
export PATH="$HOME/.cargo/bin:$PATH"
echo "== machine: $(nproc) cores, $(uname -m), $(date -u +%Y-%m-%d)"
cargo bench -p zeta-solver --bench solver -- --warm-up-time 1 --measurement-time 3 2>&1 \
  | grep -E '^[A-Za-z(].*|time:' | grep -vE '^(Benchmarking|Warming|Analyzing|Found|Gnuplot)'
bash scripts/build.sh
node bench/browser.mjs "${1:-300}"
