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

# Release builds: also a "first" module per demo (feature `first`, ZETA_FIRST_DEMO=<id>:
# only that demo linked), which the page starts with for that demo while the full module
# loads behind it (web/main.js). Same crate, same profile and target dir, so only zeta-app
# itself is compiled again. The ids are the registry's lines (crates/app/src/demos/mod.rs);
# a line marked #[first_with("<other>")] links that demo too (ZETA_FIRST_DEMO="<id>
# <other>"); a name the registry lacks fails the build. wasm-opt (below) shrinks each
# module in the background while the next one compiles. ZETA_FIRST_DEMOS="<id> …" builds
# only those (a quicker local build; the others then start from the full module).
src="${TRUNK_SOURCE_DIR:-.}"
opt="$src/node_modules/.bin/wasm-opt"
optimise() { # the final wasm: see the flags' note below
  "$opt" -Os --converge --low-memory-unused --strip-debug --strip-producers \
    --enable-bulk-memory --enable-sign-ext --enable-mutable-globals \
    --enable-nontrapping-float-to-int --enable-reference-types --enable-multivalue \
    "$1" -o "$1.opt" && mv "$1.opt" "$1"
}
pids=()
# A failed step must not leave wasm-opt writing into the folder Trunk is about to replace.
trap '[ ${#pids[@]} -eq 0 ] || kill "${pids[@]}" 2>/dev/null || true' EXIT
if [ "${TRUNK_PROFILE:-}" = "release" ]; then
  if [ ! -x "$opt" ]; then
    echo "post-build: $opt is missing; run scripts/setup.sh" >&2
    exit 1
  fi
  target_dir="${CARGO_TARGET_DIR:-$src/target}"
  optimise "$stage/zeta-app_bg.wasm" &
  pids+=($!)
  # "<id>" per line, or "<id>+<other>" for a line marked #[first_with("<other>")].
  lines="$(perl -ne 'print "$2", ($1 ? "+$1" : ""), "\n" if /^\s*(?:#\[first_with\("([a-z0-9-]+)"\)\]\s*)?"([a-z0-9-]+)", "[^"]*" => /' "$src/crates/app/src/demos/mod.rs")"
  if [ "$(printf '%s\n' "$lines" | grep -c .)" -lt 2 ]; then
    echo "post-build: found no demo ids in the registry" >&2
    exit 1
  fi
  for line in $lines; do
    id="${line%%+*}"
    case " ${ZETA_FIRST_DEMOS:-$id} " in *" $id "*) ;; *) continue ;; esac
    (cd "$src" && ZETA_FIRST_DEMO="${line//+/ }" cargo build --quiet -p zeta-app --release --target wasm32-unknown-unknown --features first)
    wasm-bindgen --target web --no-typescript --out-dir "$stage" --out-name "zeta-first-$id" \
      "$target_dir/wasm32-unknown-unknown/release/zeta_app.wasm"
    optimise "$stage/zeta-first-${id}_bg.wasm" &
    pids+=($!)
  done
  for pid in "${pids[@]}"; do
    wait "$pid" || { echo "post-build: wasm-opt failed" >&2; exit 1; }
  done
fi

# The flags of `optimise`: binaryen's wasm-opt from npm (package-lock.json), not Debian's
# binaryen, whose wasm-opt 108 rewrites the externref table that wasm-bindgen emits into
# one browsers reject at start-up. `-Os --converge` rather than `-Oz`: about 2 KB less
# brotli (what the page downloads), though 7 KB more before compression; -Os gives up less
# speed for size (docs/wasm-size.md). `--low-memory-unused`: addresses below 1024 are never
# used, so constant offsets can be folded into loads and stores (1.0–1.4 KB brotli less a
# module). True of Rust's wasm32 layout: the stack comes first and grows down from 1 MiB
# towards 0 (the data follows it), so only a stack within 1 KiB of overflowing would reach
# them (emscripten passes the same flag for C and C++ whenever its data starts at 1024).
if [ "${TRUNK_PROFILE:-}" = "release" ]; then
  # Trunk's static preloads name the full module: web/preload.js preloads the one module
  # the address starts with instead (the demo's first module on a first visit), so the full
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
# plot (docs/wasm-size.md). preload.js after it has received the demos' list (below).
esbuild="$src/node_modules/.bin/esbuild"
minify() {
  local said
  for f in "$@"; do
    # A warning fails the build: a stray brace in a stylesheet is only a warning, and it
    # silently drops the rule after it (the print rules were lost so once).
    said="$("$esbuild" "$f" --minify --log-level=warning --allow-overwrite --outfile="$f" 2>&1)" &&
      [ -z "$said" ] || {
      printf '%s\npost-build: esbuild did not minify %s cleanly\n' "$said" "$f" >&2
      exit 1
    }
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
# web/preload.js: the demos that have a first module, then (minified in release builds)
# into index.html itself, allowed by its SHA-256 in the page's Content-Security-Policy: as
# a file of its own it cost a round trip before any module was requested.
first_demos="$(cd "$stage" && for f in zeta-first-*_bg.wasm; do
  [ -f "$f" ] || continue # none in a dev build
  printf "'%s'," "$(basename "$f" _bg.wasm | sed 's/^zeta-first-//')"
done)"
perl -pi -e "s#const FIRST_DEMOS = \[\];#const FIRST_DEMOS = [${first_demos%,}];#" "$stage/web/preload.js"
if [ "${TRUNK_PROFILE:-}" = "release" ]; then
  if ! grep -q "const FIRST_DEMOS = \['" "$stage/web/preload.js"; then
    echo "post-build: preload.js did not receive the demos' first modules" >&2
    exit 1
  fi
  minify "$stage/web/preload.js"
fi
PRELOAD="$stage/web/preload.js" perl -0pi -e '
  BEGIN {
    use Digest::SHA qw(sha256_base64);
    open(my $f, "<", $ENV{PRELOAD}) or die "preload.js: $!";
    local $/;
    $js = <$f>;
    $js =~ s/\n+\z//;
    die "preload.js must not contain </script>" if $js =~ m#</script#i;
    $sha = sha256_base64($js);
    $sha .= "=" while length($sha) % 4;
  }
  s#<script src="web/preload\.js"></script>#<script>$js</script># or die "index.html: no preload.js script";
  s#(script-src [^;"]*)#$1 \x27sha256-$sha\x27# or die "index.html: no script-src";
' "$html"
rm "$stage/web/preload.js"

# Version the service worker's cache by the build and list every file it must cache.
build="$(cat "$stage"/zeta-*.wasm "$stage"/zeta-*.js "$stage"/web/* | openssl dgst -sha256 | awk '{print substr($NF, 1, 16)}')"
files="$(cd "$stage" && find . -type f ! -name sw.js | sed 's#^\./##' | sort | awk '{printf ", \x27%s\x27", $0}')"
perl -pi -e "s#__ZETA_BUILD__#$build#; s#const FILES = \['\./'\];#const FILES = ['./'$files];#" "$stage/sw.js"
