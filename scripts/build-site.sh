#!/usr/bin/env bash
# Writes site/: the demo page, the package it loads and the samples, as plain files that any
# static host serves (no server code). Builds the package first when pkg/ is missing.
#   ./scripts/build-site.sh [OUT_DIR]        (default site/)
set -euo pipefail
source "$(dirname "$0")/lib/ensure.sh"
cd "$ROOT"
out="${1:-site}"
[ -f pkg/texsynth_bg.wasm ] || ./scripts/build.sh
rm -rf "$out"
mkdir -p "$out"
# The page (index.html, scripts, styles, samples) without the package's sources, which pkg/ holds built.
cp -r www/. "$out"/
rm -rf "$out/package"
# The page imports ./pkg/texsynth.js and ./pkg/worker.js: the package as npm ships it.
mkdir -p "$out/pkg"
cp pkg/*.js pkg/*.wasm pkg/package.json "$out/pkg/"
[ -d pkg/threads ] && cp -r pkg/threads "$out/pkg/"
# Cross-origin isolation lets the page's worker run the threaded module; hosts that read a
# _headers file (Netlify, Cloudflare Pages) send these headers, and others need them configured.
cat >"$out/_headers" <<'HEADERS'
/*
  Cross-Origin-Opener-Policy: same-origin
  Cross-Origin-Embedder-Policy: require-corp
HEADERS
echo "build-site: $out/ ($(du -sh "$out" | cut -f1)): serve it with any static server, e.g. node scripts/serve.mjs 8080 $out"
