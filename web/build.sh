#!/usr/bin/env bash
# Builds the web workbench into web/pkg/ (serve web/ with any static file server, e.g.
# `python3 -m http.server -d web 8080`, and open http://127.0.0.1:8080).
# The solver runs in a web worker (web/worker.js, which loads the same web/pkg/), so serve over http.
# `?case=fillon-a` opens a shipped case; `?probe` logs frame times to the browser console per job
# (`?probe&sweep` also runs the sweep view's sweep); docs/PERFORMANCE.md has the measured numbers.
#
# `python3 web/size_report.py web/pkg/tiltpad_bg.wasm` says where the bytes go (sections, code by crate).
#
# Needs the wasm target and the wasm-bindgen CLI matching the wasm-bindgen crate (=0.2.130); installs
# them when missing.
set -euo pipefail
cd "$(dirname "$0")/.."
rustup target add wasm32-unknown-unknown
if [[ "$(wasm-bindgen --version 2>/dev/null)" != "wasm-bindgen 0.2.130" ]]; then
  cargo install wasm-bindgen-cli --version 0.2.130
fi
cargo build --profile web --target wasm32-unknown-unknown --bin tiltpad
target_dir="${CARGO_TARGET_DIR:-target}"
wasm="$target_dir/wasm32-unknown-unknown/web/tiltpad.wasm"
# binaryen's wasm-opt (Debian: `apt-get install binaryen`) shrinks the program and drops its symbol names;
# it runs before wasm-bindgen, which must be the last to touch the file (an older wasm-opt run after it breaks
# the table of JavaScript references). Without wasm-opt the page works, only larger.
if command -v wasm-opt >/dev/null; then
  wasm-opt -O2 "$wasm" -o "$target_dir/tiltpad-opt.wasm"
  wasm="$target_dir/tiltpad-opt.wasm"
else
  echo "wasm-opt not found (apt-get install binaryen): the page is built without it, and larger" >&2
fi
wasm-bindgen --target web --no-typescript --out-dir web/pkg "$wasm"
ls -l web/pkg/tiltpad_bg.wasm
echo "built web/pkg/ — serve web/ and open index.html"
