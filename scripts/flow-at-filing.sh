#!/usr/bin/env bash
# What "today's" flow energy was when issue 10 was filed (its point 4 bounds the frames' flow
# energy at 1.5x that), beside the frames of the code checked out now: builds
# examples/flow_frames.rs in a temporary worktree of 69c6703 (the commit the issue was filed
# against) and here, runs both on the issue's three cases (tiles_128 at 256x256, paving_128 and
# gravel_128 at 128x128; vortex of strength 2, 60 frames, the library's defaults) for seeds 1-3,
# and scores every frame with today's metrics (examples/score_frames.rs).
#
# Usage: ./scripts/flow-at-filing.sh [OUT]   (default OUT: results/flow-at-filing; about 5 minutes)
# OUT/then/SAMPLE-sSEED and OUT/now/SAMPLE-sSEED hold frames 1, 30, 36, ..., 60 and flow.tsv.
set -euo pipefail
ROOT="$(cd "$(dirname "$0")/.." && pwd)"
FILED=69c6703
out="$(mkdir -p "${1:-$ROOT/results/flow-at-filing}" && cd "${1:-$ROOT/results/flow-at-filing}" && pwd)"
cases=("tiles_128 256" "paving_128 128" "gravel_128 128")

old="$(mktemp -d)"
trap 'git -C "$ROOT" worktree remove --force "$old" >/dev/null 2>&1 || rm -rf "$old"' EXIT
git -C "$ROOT" worktree add --quiet --detach "$old" "$FILED"
cp "$ROOT/examples/flow_frames.rs" "$old/examples/"
# That commit has no `explore` profile: its release profile without fat LTO is the same thing.
(cd "$old" && CARGO_TARGET_DIR="$old/target" CARGO_PROFILE_RELEASE_LTO=false \
  CARGO_PROFILE_RELEASE_CODEGEN_UNITS=16 cargo build --quiet --release --example flow_frames)
(cd "$ROOT" && cargo build --quiet --profile explore --example flow_frames --example score_frames)
target="$(cd "$ROOT" && cargo metadata --format-version 1 --no-deps | node -e \
  'process.stdout.write(JSON.parse(require("fs").readFileSync(0, "utf8")).target_directory)')"

for c in "${cases[@]}"; do
  set -- $c
  for seed in 1 2 3; do
    "$old/target/release/examples/flow_frames" "$ROOT/www/samples/$1.png" "$2" "$seed" "$out/then/$1-s$seed"
    "$target/explore/examples/flow_frames" "$ROOT/www/samples/$1.png" "$2" "$seed" "$out/now/$1-s$seed"
  done
done
for c in "${cases[@]}"; do
  set -- $c
  echo "== $1 at $2x$2, at $FILED (then) and now"
  "$target/explore/examples/score_frames" "$ROOT/www/samples/$1.png" \
    "$out"/then/"$1"-s{1,2,3} "$out"/now/"$1"-s{1,2,3} | sed "s|$out/||"
done
