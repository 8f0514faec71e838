#!/usr/bin/env bash
# Builds everything and serves the demo page on 127.0.0.1 (port $PORT, default 8080).
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/build.sh
exec node scripts/serve.mjs "${PORT:-8080}"
