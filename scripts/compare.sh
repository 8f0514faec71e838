#!/usr/bin/env bash
# Speed and quality of every texsynth method side by side with the texture-synthesis crate (the
# peer), on a folder of PNG/JPEG textures: builds the native `compare` binary (bench/) and the wasm
# package, times the methods as wasm in Node, then natively with the peer, scores every output and
# prints the tables. Writes into --out (default results/compare/): results.json, results.tsv,
# contact-sheets/*.png, the prepared exemplars/*.png, plan.json and wasm.json.
#
# With --threads N (N > 1), texsynth runs on N threads (native: the parallel feature on a rayon pool
# of N; wasm: the threaded module, pkg/threads/, on a pool of N) and the peer on N threads too.
#
# Usage: ./scripts/compare.sh [--no-wasm] [--reuse-pkg] [options of `compare --help`]
#   --no-wasm    skip the wasm timings (and the package build)
#   --reuse-pkg  use pkg/ as it is instead of rebuilding it with ./scripts/build.sh
# e.g. ./scripts/compare.sh --dir ~/textures --size 512x512 --seeds 1,2 --methods optimization,peer
set -euo pipefail
source "$(dirname "$0")/lib/ensure.sh"
cd "$ROOT"

wasm=1
build_pkg=1
threads=1
pass=()
prev=""
for arg in "$@"; do
  [ "$prev" = --task ] && [ "$arg" = inpaint ] && wasm=0
  case "$arg" in
    --no-wasm) wasm=0 ;;
    --reuse-pkg) build_pkg=0 ;;
    *) pass+=("$arg") ;;
  esac
  [ "$prev" = --threads ] && threads="$arg"
  prev="$arg"
done

# The bench crate is a workspace member outside default-members: only this builds it (and the peer).
# Above one thread it is built with the parallel feature, in a target dir of its own so the two
# builds do not undo each other.
features=()
if [[ "$threads" =~ ^[0-9]+$ ]] && [ "$threads" -gt 1 ]; then
  features=(--features parallel)
  export CARGO_TARGET_DIR="${CARGO_TARGET_DIR:-$ROOT/target/parallel}"
fi
cargo build --release -p texsynth-bench --bin compare "${features[@]}"
target_dir=$(cargo metadata --format-version 1 --no-deps | node -e \
  'process.stdout.write(JSON.parse(require("fs").readFileSync(0, "utf8")).target_directory)')
bin="$target_dir/release/compare"

# Options are checked (and --help answered) before the slower package build.
for arg in "${pass[@]}"; do
  if [ "$arg" = --help ] || [ "$arg" = -h ]; then
    sed -n '2,12p' "$0" | sed 's/^# \{0,1\}//'
    echo
    exec "$bin" --help
  fi
done

# Writes the prepared exemplars and the plan; prints the plan's path (or refuses bad options).
plan=$("$bin" --prepare-only "${pass[@]}")
wasm_args=()
if [ "$wasm" = 1 ]; then
  if [ "$build_pkg" = 1 ] || [ ! -f pkg/texsynth_bg.wasm ]; then
    # build.sh reads the wasm from ./target, so it must not inherit another target dir.
    env -u CARGO_TARGET_DIR ./scripts/build.sh
  fi
  node scripts/compare_wasm.mjs "$plan"
  wasm_args=(--wasm "$(dirname "$plan")/wasm.json")
fi
COMPARE_COMMAND="./scripts/compare.sh${*:+ $*}" "$bin" "${wasm_args[@]}" "${pass[@]}"
echo "compare.sh: done in ${SECONDS} s"
