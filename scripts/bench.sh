#!/usr/bin/env bash
# Every benchmark: the solver's criterion benches natively, then the release site in headless
# Chromium (per-demo slider-event p50/p95, cold-load time to first plot, bytes shipped), then
# the same site as a low-end device (4× CPU, phone screen, Slow 4G; bench/lowend.mjs).
# `bash scripts/bench.sh --low-end` runs only the low-end part; `ZETA_RUNS=3` before it
# reports each demo's median of three runs (a single run's p95 moves by several ms).
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/ready.sh"
echo "== machine: $(nproc) cores, $(uname -m), $(date -u +%Y-%m-%d)"
if [ "${1:-}" = "--low-end" ]; then
  bash scripts/build.sh
  node bench/lowend.mjs "${2:-40}"
  exit 0
fi
cargo bench -p zeta-solver --bench solver -- --warm-up-time 1 --measurement-time 3 2>&1 \
  | grep -E '^[A-Za-z(].*|time:' | grep -vE '^(Benchmarking|Warming|Analyzing|Found|Gnuplot)'
bash scripts/build.sh
node bench/browser.mjs "${1:-300}"
node bench/lowend.mjs 40
