#!/usr/bin/env bash
# Builds the npm package into pkg/: release wasm, wasm-bindgen (--target web), wasm-opt (npm
# binaryen), and pkg/package.json made from pkg.json. Installs missing tools first.
# With the pinned nightly (scripts/lib/ensure.sh) it also builds the threaded module into
# pkg/threads/ (the `parallel` feature, shared memory, std rebuilt with atomics); TEXSYNTH_THREADS=0
# skips it, and so does a machine where the nightly cannot be installed.
set -euo pipefail
source "$(dirname "$0")/lib/ensure.sh"
cd "$ROOT"
ensure_wasm_target
ensure_wasm_bindgen
ensure_npm_packages

cargo build --release --target wasm32-unknown-unknown --lib
rm -rf pkg
wasm-bindgen --target web --out-dir pkg target/wasm32-unknown-unknown/release/texsynth.wasm
# Features rustc enables by default for wasm32 plus simd128 (from .cargo/config.toml).
node_modules/.bin/wasm-opt -O3 \
  --enable-simd --enable-bulk-memory --enable-nontrapping-float-to-int --enable-sign-ext \
  --enable-mutable-globals --enable-reference-types --enable-multivalue \
  pkg/texsynth_bg.wasm -o pkg/texsynth_bg.wasm
threads=0
if [ "${TEXSYNTH_THREADS:-}" != 0 ] && ensure_threads_toolchain; then
  # The target's rustflags in .cargo/config.toml give way to RUSTFLAGS, so simd128 is repeated.
  RUSTFLAGS="-C target-feature=+atomics,+bulk-memory,+mutable-globals,+simd128 \
-C link-arg=--shared-memory -C link-arg=--import-memory -C link-arg=--max-memory=4294967296 \
-C link-arg=--export=__wasm_init_tls -C link-arg=--export=__tls_size \
-C link-arg=--export=__tls_align -C link-arg=--export=__tls_base" \
    cargo "+$THREADS_TOOLCHAIN" build -Z build-std=std,panic_abort --release \
    --target wasm32-unknown-unknown --lib --features parallel --target-dir target/threads
  wasm-bindgen --target web --out-dir pkg/threads target/threads/wasm32-unknown-unknown/release/texsynth.wasm
  node_modules/.bin/wasm-opt -O3 \
    --enable-simd --enable-bulk-memory --enable-nontrapping-float-to-int --enable-sign-ext \
    --enable-mutable-globals --enable-reference-types --enable-multivalue --enable-threads \
    pkg/threads/texsynth_bg.wasm -o pkg/threads/texsynth_bg.wasm
  threads=1
fi
node scripts/make-package-json.mjs
# The option and event declarations, from the bindings' tables.
node scripts/make-typings.mjs pkg
# The hand-written entry points, types, worker wrapper and CLI (www/package/) beside the generated files.
cp www/package/*.js www/package/*.d.ts pkg/
chmod +x pkg/cli.js
# The package's own README (the npm page, from README.md) and the licences.
node scripts/make-package-readme.mjs pkg
cp LICENSE-MIT LICENSE-APACHE pkg/
raw=$(stat -c %s pkg/texsynth_bg.wasm)
gz=$(gzip -9 -c pkg/texsynth_bg.wasm | wc -c)
echo "build: pkg/texsynth_bg.wasm is $raw bytes ($gz gzipped)"
if [ "$threads" = 1 ]; then
  raw=$(stat -c %s pkg/threads/texsynth_bg.wasm)
  gz=$(gzip -9 -c pkg/threads/texsynth_bg.wasm | wc -c)
  echo "build: pkg/threads/texsynth_bg.wasm is $raw bytes ($gz gzipped)"
else
  rm -f pkg/threads.js pkg/threads-worker.js
fi
