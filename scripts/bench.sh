#!/usr/bin/env bash
# Benchmarks texture optimisation natively and as wasm in Node, 256x256 from the samples, for each
# nearest-neighbour search. Prints a table per platform. The exact search takes minutes on the
# 128x128 sample; choose searches with SEARCHES=patchmatch,kmeans-tree and samples with
# SAMPLES=gravel_128,gravel_64 (the defaults: all three searches, gravel 128 and 64).
set -euo pipefail
cd "$(dirname "$0")/.."
SEARCHES="${SEARCHES:-patchmatch,kmeans-tree,exact}"
SAMPLES="${SAMPLES:-gravel_128,gravel_64}"
./scripts/build.sh >/dev/null
cargo build --release --example bench 2>/dev/null
BENCH_SAMPLES="$SAMPLES" ./target/release/examples/bench ${SEARCHES//,/ }
echo
node scripts/bench.mjs --samples "$SAMPLES" --searches "$SEARCHES"
