#!/bin/bash
# Configures and builds yade-rbsm in build/ (or $BUILD_DIR): the plugin, the launcher build/yade-rbsm
# and the tests. Incremental: re-running rebuilds only what changed.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BUILD_DIR="${BUILD_DIR:-$ROOT/build}"
JOBS="${JOBS:-$(nproc)}"
cmake -S "$ROOT" -B "$BUILD_DIR" ${CMAKE_ARGS:-}
cmake --build "$BUILD_DIR" -j "$JOBS"
