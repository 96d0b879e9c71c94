# Sourced by the scripts that build: from the repository root, installs whatever is
# missing (scripts/setup.sh) and puts cargo's tools on PATH. Sets ROOT.
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$ROOT"
bash scripts/setup.sh
export PATH="$HOME/.cargo/bin:$PATH"
