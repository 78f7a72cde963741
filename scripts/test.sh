#!/bin/bash
# Builds (incrementally) and runs every test through ctest: C++ unit tests, ABI guard tests against
# Debian's yade, YADE tests through the launcher, physics checks, pure-Python tests.
# Extra arguments go to ctest (e.g. -L abi, -R polygon2d, -j 4).
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BUILD_DIR="${BUILD_DIR:-$ROOT/build}"
"$ROOT/scripts/build.sh"
ctest --test-dir "$BUILD_DIR" --output-on-failure -j "${JOBS:-$(nproc)}" "$@"
