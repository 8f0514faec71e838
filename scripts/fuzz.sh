#!/usr/bin/env bash
# Runs every cargo-fuzz target (fuzz/fuzz_targets) for SECONDS each (default 60), one after
# another, and prints one line per target: its run time, executions and crashes. Needs a nightly
# toolchain and cargo-fuzz (installed here from crates.io when missing); without nightly it says
# so and exits 0, so that CI can call it unconditionally. A crash leaves its input under
# fuzz/artifacts/TARGET/; copy it to fuzz/regressions/TARGET/ (replayed by every run) and turn it
# into a regression test (a row of tests/node/bad_calls.mjs or a Rust test) before fixing it.
#
# `--smoke` (what ./scripts/test.sh runs): 15 s per target, built without the address sanitizer,
# which halves the cold build (2 min instead of 4 on two cores) and still catches every panic,
# hang and out-of-memory; the full command keeps the sanitizer.
#
# Usage: ./scripts/fuzz.sh [--smoke | SECONDS] [TARGET...]
set -uo pipefail
ROOT="$(cd "$(dirname "$0")/.." && pwd)"
cd "$ROOT"
build_flags=()
if [ "${1:-}" = "--smoke" ]; then
  seconds=15
  build_flags=(--sanitizer none)
else
  seconds="${1:-60}"
fi
shift || true

if ! rustup toolchain list 2>/dev/null | grep -q '^nightly'; then
  echo "fuzz: no nightly toolchain on this machine (rustup toolchain install nightly); skipping"
  exit 0
fi
if ! cargo +nightly fuzz --version >/dev/null 2>&1; then
  echo "fuzz: installing cargo-fuzz"
  cargo install cargo-fuzz || { echo "fuzz: could not install cargo-fuzz; skipping"; exit 0; }
fi

targets=("$@")
[ ${#targets[@]} -gt 0 ] || mapfile -t targets < <(cargo +nightly fuzz list)
failed=0
for target in "${targets[@]}"; do
  mkdir -p "fuzz/corpus/$target"
  log="$(mktemp)"
  # -rss_limit_mb: a session within its 64 MiB budget stays far below; -timeout: one input
  # running longer than 60 s counts as a hang (one input of `options` is a session of up to the
  # 64 MiB budget built and stepped once: measured up to 17.5 s under the sanitizer on a loaded
  # 2-core machine, so 10 s flagged slow inputs that end).
  # New inputs go to the first corpus folder; fuzz/regressions/TARGET holds every crash found so
  # far (kept in git), so that each run starts by replaying them.
  seeds=()
  [ -d "fuzz/regressions/$target" ] && seeds=("$ROOT/fuzz/regressions/$target")
  if cargo +nightly fuzz run "${build_flags[@]}" "$target" "$ROOT/fuzz/corpus/$target" "${seeds[@]}" -- \
       -max_total_time="$seconds" -timeout=60 \
       -rss_limit_mb=2048 -max_len=4096 >"$log" 2>&1; then
    status="0 crashes"
  else
    status="CRASH (see fuzz/artifacts/$target/)"
    failed=1
    tail -40 "$log"
  fi
  runs=$(grep -o 'stat::number_of_executed_units: [0-9]*' "$log" | awk '{print $2}' | tail -1)
  [ -n "$runs" ] || runs=$(grep -oE '^#[0-9]+' "$log" | tail -1 | tr -d '#')
  echo "fuzz: $target ran ${seconds} s, ${runs:-?} executions, $status"
  rm -f "$log"
done
exit $failed
