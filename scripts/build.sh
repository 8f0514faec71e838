#!/usr/bin/env bash
# Builds the npm package into pkg/: release wasm, wasm-bindgen (--target web), wasm-opt (npm
# binaryen), and pkg/package.json made from pkg.json. Installs missing tools first.
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
