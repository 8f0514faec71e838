#!/usr/bin/env bash
# Benchmarks every method natively and as wasm in Node, 256x256 from the samples (flow animation:
# frames per second at 128x128 and 256x256, wasm in Node):
# texture optimisation with each nearest-neighbour search, graph-cut textures with each placement
# mode, the max-flow solver against the reference, and texture design (scripts/bench-design.mjs:
# layer-based design with QTP against exhaustive search, tileable textures, a brush stroke). The exact search takes minutes on the
# 128x128 sample; choose searches with SEARCHES=patchmatch,kmeans-tree and samples with
# SAMPLES=gravel_128,gravel_64 (the defaults: all three searches, gravel 128 and 64).
set -euo pipefail
cd "$(dirname "$0")/.."
SEARCHES="${SEARCHES:-patchmatch,kmeans-tree,exact}"
SAMPLES="${SAMPLES:-gravel_128,gravel_64}"
./scripts/build.sh >/dev/null
cargo build --release -p texsynth-bench --bins 2>/dev/null
BENCH_SAMPLES="$SAMPLES" ./target/release/bench ${SEARCHES//,/ }
echo
BENCH_SAMPLES="$SAMPLES" ./target/release/bench_graphcut
echo
node scripts/bench.mjs --samples "$SAMPLES" --searches "$SEARCHES"
echo
echo "max-flow on seam graphs, native, against the reference (Dinic) solver:"
cargo test --release --lib -q -- --ignored --nocapture maxflow_timing 2>/dev/null | grep -vE "^(running|test |$)|test result"
echo
node scripts/bench-design.mjs
echo
node scripts/bench-features.mjs
