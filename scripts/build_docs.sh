#!/bin/bash
# Builds the manual (Sphinx, HTML) into build/docs/html from docs/: the class reference is generated from
# the built plugin, the verification page from the test results in build/verification (run the tests first
# for its figures). Warnings are errors. Needs scripts/build.sh first (the launcher and the plugin).
#   bash scripts/build_docs.sh
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BUILD_DIR="${BUILD_DIR:-$ROOT/build}"
OUT="$BUILD_DIR/docs"
LAUNCHER="$BUILD_DIR/yade-rbsm"
[ -x "$LAUNCHER" ] || { echo "build_docs.sh: $LAUNCHER is missing: run scripts/build.sh first" >&2; exit 1; }
start=$(date +%s)
rm -rf "$OUT/src" "$OUT/html"
mkdir -p "$OUT/src"
cp -r "$ROOT/docs/." "$OUT/src/"
# The pages include the repository's scripts by their paths in the repository (docs/manual/x.md ->
# ../../scripts): the same relative path from the copy lands on this link.
ln -sfn "$ROOT/scripts" "$OUT/scripts"
SRC="$OUT/src/manual"
cd "$OUT"
/usr/bin/yade -n -x "$ROOT/docs/tools/yade_classes.py" "$OUT/yade_classes.txt" > "$OUT/yade_classes.log" 2>&1 \
  || { cat "$OUT/yade_classes.log" >&2; exit 1; }
"$LAUNCHER" -n -x "$ROOT/docs/tools/class_reference.py" "$OUT/yade_classes.txt" "$SRC/reference/classes.rst" \
  > "$OUT/class_reference.log" 2>&1 || { cat "$OUT/class_reference.log" >&2; exit 1; }
/usr/bin/python3 "$ROOT/docs/tools/verification_page.py" "$BUILD_DIR/verification" "$SRC/verification.md"
RBSM_SOURCE_DIR="$ROOT" "$LAUNCHER" -n -x "$ROOT/docs/tools/sphinx_in_yade.py" -W --keep-going -q -b html \
  -d "$OUT/doctrees" "$SRC" "$OUT/html"
echo "build_docs.sh: the manual is $OUT/html/index.html ($(( $(date +%s) - start )) s)"
