#!/usr/bin/env bash
# Builds the package and the static page (site/) and serves it on 127.0.0.1 (port $PORT, default 8080).
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/build.sh
./scripts/build-site.sh
exec node scripts/serve.mjs "${PORT:-8080}" site
