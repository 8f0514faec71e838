#!/usr/bin/env bash
# Benchmarks every method natively and as wasm in Node, 256x256 from the samples (flow animation:
# frames per second at 128x128 and 256x256, wasm in Node):
# texture optimisation with each nearest-neighbour search, graph-cut textures with each placement
# mode, the max-flow solver against the reference, and texture design (scripts/bench-design.mjs:
# layer-based design with QTP against exhaustive search, tileable textures, a brush stroke). The exact search takes minutes on the
# 128x128 sample; choose searches with SEARCHES=patchmatch,kmeans-tree and samples with
# SAMPLES=gravel_128,gravel_64 (the defaults: all three searches, gravel 128 and 64).
#
# ./scripts/bench.sh --write-docs [options of compare.sh] rewrites docs/benchmarks.md whole (and
# the README's headline rows): the comparison with the peer (./scripts/compare.sh, default: the
# samples at 256x256, seeds 1-3), the same comparison on $THREADS threads on each side (default 2;
# THREADS=1 leaves it out), hole filling against the peer (compare.sh --task inpaint) and the scaling tables (node scripts/bench-scaling.mjs with
# $SCALING_ARGS, default the output sweep to 1024x1024 without the exemplar sweep).
set -euo pipefail
cd "$(dirname "$0")/.."
if [ "${1:-}" = --write-docs ]; then
  shift
  out=results/compare
  dir_args=()
  prev=""
  for arg in "$@"; do
    [ "$prev" = --out ] && out="$arg"
    [ "$prev" = --dir ] && dir_args=(--dir "$arg")
    prev="$arg"
  done
  ./scripts/compare.sh "$@"
  threads_args=()
  if [ "${THREADS:-2}" != 1 ]; then
    ./scripts/compare.sh "$@" --reuse-pkg --threads "${THREADS:-2}" --out "$out-threads"
    threads_args=(--threads "$out-threads/results.json")
  fi
  # Hole filling against the peer, on the same folder (native only).
  ./scripts/compare.sh --task inpaint --seeds 1 "${dir_args[@]}" --out "$out-inpaint"
  scaling="$(mktemp)"
  # shellcheck disable=SC2086
  node scripts/bench-scaling.mjs ${SCALING_ARGS:---outputs 256,512,1024 --exemplars none} | grep -E '^(\||$)' > "$scaling"
  node scripts/write-benchmarks.mjs "$out/results.json" "$scaling" "${threads_args[@]}" --inpaint "$out-inpaint/inpaint.json" \
    --command "./scripts/bench.sh --write-docs $* (THREADS: ${THREADS:-2}, SCALING_ARGS: ${SCALING_ARGS:---outputs 256,512,1024 --exemplars none})"
  rm -f "$scaling"
  exit 0
fi
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
