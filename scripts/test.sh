#!/usr/bin/env bash
# Installs whatever is missing, then runs every check: formatting, lints, native tests,
# docs, wasm tests (browser and Node), the release build of the site, and the end-to-end
# browser tests. Runs them all, then exits non-zero if any failed. The last line is the
# summary: "checks: N passed, N failed".
set -uo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$ROOT"
bash scripts/setup.sh || { echo "setup failed"; echo "checks: 0 passed, 1 failed"; exit 1; }
export PATH="$HOME/.cargo/bin:$PATH"
export CHROMEDRIVER="${CHROMEDRIVER:-/usr/bin/chromedriver}"
export CARGO_TERM_COLOR=never

passed=0
failed=0
failures=()

step() { # step NAME COMMAND...
  local name="$1"
  shift
  printf '\n=== %s\n' "$name"
  local start=$SECONDS
  if "$@"; then
    passed=$((passed + 1))
    printf '=== %s: ok (%ss)\n' "$name" $((SECONDS - start))
  else
    failed=$((failed + 1))
    failures+=("$name")
    printf '=== %s: FAILED (%ss)\n' "$name" $((SECONDS - start))
  fi
}

step "cargo fmt --check" cargo fmt --all -- --check
step "cargo clippy" cargo clippy --workspace --all-targets -- -D warnings
step "cargo clippy (wasm32)" cargo clippy -p zeta-app --target wasm32-unknown-unknown --all-targets -- -D warnings
step "cargo clippy (wasm32, first module)" cargo clippy -p zeta-app --target wasm32-unknown-unknown --all-targets --features first -- -D warnings
step "cargo test" cargo test --workspace
# A first module links only its demo (here the default one; the release build makes one per
# demo): its registry checks, its English messages, its demo tests and its snapshot (the
# same numbers on screen as the full module shows).
step "cargo test (first module)" cargo test -p zeta-app --features first --lib --test snapshots -- demos::tests demos::regimes every_demo i18n::catalogue
step "cargo doc" env RUSTDOCFLAGS="-D warnings" cargo doc --workspace --no-deps
step "wasm-pack test (app, headless Chromium)" wasm-pack test --headless --chrome crates/app
step "wasm-pack test (solver, Node)" wasm-pack test --node crates/solver
step "release build of the site" bash scripts/build.sh
step "end-to-end browser tests" node --test --test-concurrency=1 tests/*.test.mjs

printf '\n'
if ((failed)); then
  printf 'failed: %s\n' "${failures[@]}"
fi
echo "checks: $passed passed, $failed failed"
((failed == 0))
