#!/usr/bin/env bash
# Installs whatever the project needs that is missing, and skips what is already
# present at the right version. Safe to run again: a second run takes seconds.
#
# Everything comes from crates.io, Debian's packages or the npm registry; no step
# downloads a prebuilt binary (see ARCHITECTURE.md, "Toolchain").
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$ROOT"

TRUNK_VERSION="0.21.14"
export PATH="$HOME/.cargo/bin:$PATH"

log() { printf '\033[1;34m[setup]\033[0m %s\n' "$*"; }

have_version() { # have_version CMD WANTED -> true when `CMD --version` mentions WANTED
  command -v "$1" >/dev/null 2>&1 && "$1" --version 2>/dev/null | grep -qF "$2"
}

# The wasm-bindgen CLI must equal the crate version pinned in Cargo.lock.
wasm_bindgen_version() {
  awk '/^name = "wasm-bindgen"$/ { getline; gsub(/version = |"/, ""); print; exit }' Cargo.lock
}

install_apt() {
  local missing=()
  command -v chromium >/dev/null 2>&1 || missing+=(chromium)
  command -v chromedriver >/dev/null 2>&1 || missing+=(chromium-driver)
  command -v gzip >/dev/null 2>&1 || missing+=(gzip)
  # A CJK font, so the Chinese interface shows real glyphs in headless Chromium.
  fc-list :lang=zh 2>/dev/null | grep -q . || missing+=(fonts-wqy-zenhei)
  if ((${#missing[@]})); then
    log "apt-get install ${missing[*]}"
    local sudo=""
    [ "$(id -u)" -eq 0 ] || sudo="sudo"
    $sudo apt-get update -qq
    DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq "${missing[@]}" >/dev/null
  fi
}

install_rust_tools() {
  if ! rustup target list --installed | grep -qx wasm32-unknown-unknown; then
    log "rustup target add wasm32-unknown-unknown"
    rustup target add wasm32-unknown-unknown
  fi
  for comp in rustfmt clippy; do
    rustup component list --installed | grep -q "^$comp" || rustup component add "$comp"
  done
  if [ ! -f Cargo.lock ]; then
    cargo generate-lockfile
  fi
  local wb
  wb="$(wasm_bindgen_version)"
  if ! have_version wasm-bindgen "$wb" || ! have_version wasm-bindgen-test-runner "$wb"; then
    log "cargo install wasm-bindgen-cli $wb (about 3 minutes)"
    # Not --locked: one of its pinned transitive crates is no longer on the registry.
    cargo install --force wasm-bindgen-cli --version "$wb"
  fi
  if ! command -v wasm-pack >/dev/null 2>&1; then
    log "cargo install wasm-pack (about 2 minutes)"
    cargo install --locked wasm-pack
  fi
  if ! have_version trunk "$TRUNK_VERSION"; then
    log "cargo install trunk $TRUNK_VERSION (about 9 minutes)"
    cargo install --locked trunk --version "$TRUNK_VERSION"
  fi
}

install_node_deps() {
  if [ ! -d node_modules/playwright-core ] || [ ! -d node_modules/axe-core ] || [ ! -d node_modules/binaryen ] \
     || [ ! -d node_modules/esbuild ] \
     || [ package-lock.json -nt node_modules/.package-lock.json ]; then
    log "npm ci"
    npm ci --no-audit --no-fund --loglevel=error
  fi
}

install_apt
install_rust_tools
install_node_deps
log "toolchain ready"
