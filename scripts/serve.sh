#!/usr/bin/env bash
# Installs whatever is missing, builds, and serves the app at http://127.0.0.1:8080/
# (rebuilding on every change to the sources).
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$ROOT"
bash scripts/setup.sh
export PATH="$HOME/.cargo/bin:$PATH"
echo "Serving Zeta Lab at http://127.0.0.1:8080/ (Ctrl-C to stop)"
exec trunk serve --release --no-autoreload --address 127.0.0.1 --port 8080 "$@"
