#!/usr/bin/env bash
# Installs whatever is missing, builds, and serves the app at http://127.0.0.1:8080/
# (rebuilding on every change to the sources).
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/ready.sh"
echo "Serving Zeta Lab at http://127.0.0.1:8080/ (Ctrl-C to stop)"
exec trunk serve --release --no-autoreload --address 127.0.0.1 --port 8080 "$@"
