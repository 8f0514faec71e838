#!/usr/bin/env bash
# Runs every test: native `cargo test`, the package build, wasm-bindgen-test in Node and headless
# Chromium, the package's reliability tests in Node (tests/node: bad-input corpus, leaks,
# determinism), and the browser end-to-end tests (Playwright) plus the npm-pack install test.
# Installs what is missing first. The last line is the summary: "N passed, N failed".
set -uo pipefail
source "$(dirname "$0")/lib/ensure.sh"
cd "$ROOT"
ensure_all || { echo "0 passed, 1 failed"; exit 1; }
timings=("setup $SECONDS s")

LOG="$(mktemp -d)"
failed_stages=()

stage() { # name, command...
  local name="$1"; shift
  local start=$SECONDS
  echo "=== $name: $*"
  if ! "$@" 2>&1 | tee "$LOG/$name.log"; then
    failed_stages+=("$name")
  fi
  timings+=("$name $((SECONDS - start)) s")
}

stage native cargo test --tests --lib
# The crate's documentation builds without a warning, its examples and the README's Rust quick
# start run as doc tests, and every numbered example in examples/ runs on its defaults.
stage doc bash -c 'RUSTDOCFLAGS="-D warnings" cargo doc --no-deps -p texsynth && cargo test --doc -p texsynth --features internals &&
  for e in examples/[0-9]*.rs; do cargo run -q --example "$(basename "$e" .rs)" >/dev/null || { echo "example $e failed"; exit 1; }; done && echo "examples: all ran"'
# The package, and the static page the browser tests open (site/, served as any static host would).
stage build bash -c './scripts/build.sh && ./scripts/build-site.sh'
# The runner gives chromedriver 5 s to start by default: on a loaded 2-core machine it can take
# longer ("driver failed to bind port during startup"), failing the stage before any test runs.
export WASM_BINDGEN_TEST_DRIVER_TIMEOUT=${WASM_BINDGEN_TEST_DRIVER_TIMEOUT:-30}
stage wasm cargo test --target wasm32-unknown-unknown --tests
# The package in Node: the bad-input corpus, the leak test, determinism (tests/node/).
stage node node --test --test-concurrency=1 tests/node/
stage e2e node --test --test-concurrency=1 tests/e2e/
# A short fuzzing smoke run (15 s per cargo-fuzz target); skipped with a message where the machine
# has no nightly toolchain. The long runs are ./scripts/fuzz.sh SECONDS.
stage fuzz ./scripts/fuzz.sh --smoke

# Count what the runners reported: cargo's "test result: ... N passed; M failed" lines and
# node's "# pass N" / "# fail N" lines.
read -r passed failed < <(cat "$LOG"/*.log | awk '
  /^test result: / { for (i = 1; i <= NF; i++) { if ($(i+1) ~ /^passed/) p += $i; if ($(i+1) ~ /^failed/) f += $i } }
  /^# pass [0-9]+$/ { p += $3 }
  /^# fail [0-9]+$/ { f += $3 }
  END { print p + 0, f + 0 }')
rm -rf "$LOG"
# Where the time went (CI has a budget: keep the whole run well under 20 minutes).
echo "stage times: $(IFS=,; echo "${timings[*]}" | sed 's/,/, /g'); total $SECONDS s"
if [ ${#failed_stages[@]} -gt 0 ]; then
  echo "failed stages: ${failed_stages[*]}"
  [ "$failed" -gt 0 ] || failed=${#failed_stages[@]}
fi
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
