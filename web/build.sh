#!/usr/bin/env bash
# Builds the web workbench into web/pkg/ (serve web/ with any static file server, e.g.
# `python3 -m http.server -d web 8080`, and open http://127.0.0.1:8080).
# The solver runs in a web worker (web/worker.js, which loads the same web/pkg/), so serve over http.
# `?case=fillon-a` opens a shipped case; `?probe` logs frame times to the browser console per job
# (`?probe&sweep` also runs the sweep view's sweep); docs/PERFORMANCE.md has the measured numbers.
#
# `python3 web/size_report.py target/wasm32-unknown-unknown/release/tiltpad.wasm` says where the bytes go
# (sections, code by crate); it reads the compiler's output, which still has the function names that the
# shipped file leaves out.
#
# Needs the wasm target and the wasm-bindgen CLI matching the wasm-bindgen crate (=0.2.130); installs
# them when missing.
set -euo pipefail
cd "$(dirname "$0")/.."
rustup target add wasm32-unknown-unknown
if [[ "$(wasm-bindgen --version 2>/dev/null)" != "wasm-bindgen 0.2.130" ]]; then
  cargo install wasm-bindgen-cli --version 0.2.130
fi
cargo build --release --target wasm32-unknown-unknown --bin tiltpad
target_dir="${CARGO_TARGET_DIR:-target}"
# The shipped file leaves out the function names (1.9 MB; a panic's message still names the file and line,
# only the browser's stack trace shows function numbers instead of names) and the toolchain's producers
# record. Not passed through binaryen's wasm-opt: it made the page measurably slower to start for 5 % less
# compressed transfer (docs/PERFORMANCE.md, "Web build", "Size and start-up").
wasm-bindgen --target web --no-typescript --remove-name-section --remove-producers-section --out-dir web/pkg \
  "$target_dir/wasm32-unknown-unknown/release/tiltpad.wasm"
ls -l web/pkg/tiltpad_bg.wasm
echo "built web/pkg/ — serve web/ and open index.html"
