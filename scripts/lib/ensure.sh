# Installs what the build and the tests need, each only when it is missing. Sourced by the scripts.
# Every step prints one line saying whether it installed or skipped.

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"

ensure_wasm_target() {
  if rustup target list --installed 2>/dev/null | grep -qx wasm32-unknown-unknown; then
    echo "ensure: wasm32-unknown-unknown target present"
  else
    echo "ensure: installing the wasm32-unknown-unknown target"
    rustup target add wasm32-unknown-unknown
  fi
}

# The wasm-bindgen version that Cargo.lock pins (the CLI must match it exactly).
wasm_bindgen_version() {
  awk '/^name = "wasm-bindgen"$/ { getline; gsub(/version = |"/, ""); print; exit }' "$ROOT/Cargo.lock"
}

ensure_wasm_bindgen() {
  [ -f "$ROOT/Cargo.lock" ] || (cd "$ROOT" && cargo generate-lockfile)
  local want have
  want="$(wasm_bindgen_version)"
  # '|| true': under pipefail a missing CLI would end the calling script here.
  have="$( (wasm-bindgen --version 2>/dev/null || true) | awk '{print $2}')"
  if [ "$have" = "$want" ] && command -v wasm-bindgen-test-runner >/dev/null; then
    echo "ensure: wasm-bindgen-cli $want present"
  else
    echo "ensure: installing wasm-bindgen-cli $want (found '${have:-none}'; takes a few minutes)"
    # No --locked: a locked install fails to resolve on these machines (DESIGN.md).
    cargo install wasm-bindgen-cli --version "$want" --force
  fi
}

# The nightly toolchain of the threaded module (std rebuilt with atomics needs -Z build-std),
# named once, as `threads-toolchain` under [package.metadata.texsynth] in Cargo.toml.
THREADS_TOOLCHAIN="$(sed -n 's/^threads-toolchain *= *"\(.*\)"/\1/p' "$ROOT/Cargo.toml")"

# Installs the pinned nightly with rust-src when missing; prints one line and returns 1 when it
# cannot be installed, so that the build ships the single-threaded module alone.
ensure_threads_toolchain() {
  if rustup run "$THREADS_TOOLCHAIN" rustc --version >/dev/null 2>&1 &&
    rustup component list --installed --toolchain "$THREADS_TOOLCHAIN" 2>/dev/null | grep -q '^rust-src'; then
    echo "ensure: $THREADS_TOOLCHAIN with rust-src present"
    return 0
  fi
  echo "ensure: installing $THREADS_TOOLCHAIN with rust-src (the threaded module's toolchain)"
  if rustup toolchain install "$THREADS_TOOLCHAIN" --profile minimal --component rust-src >/dev/null 2>&1; then
    return 0
  fi
  echo "ensure: $THREADS_TOOLCHAIN could not be installed: building the single-threaded module alone"
  return 1
}

ensure_chromium() {
  if [ -x /usr/bin/chromium ] && [ -x /usr/bin/chromedriver ]; then
    echo "ensure: chromium and chromedriver present"
  else
    echo "ensure: installing chromium and chromium-driver (Debian packages)"
    local sudo=""
    [ "$(id -u)" = 0 ] || sudo="sudo"
    $sudo apt-get update -qq
    DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq chromium chromium-driver >/dev/null
  fi
}

ensure_npm_packages() {
  local stamp="$ROOT/node_modules/.package-lock.json"
  if [ -f "$stamp" ] && [ "$stamp" -nt "$ROOT/package-lock.json" ]; then
    echo "ensure: npm packages present"
  else
    echo "ensure: installing npm packages from package-lock.json"
    (cd "$ROOT" && npm ci --no-audit --no-fund --loglevel=error)
  fi
}

ensure_all() {
  ensure_wasm_target
  ensure_wasm_bindgen
  ensure_chromium
  ensure_npm_packages
}
