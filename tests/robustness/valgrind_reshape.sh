#!/bin/bash
# Issue 15 under valgrind (ctest robustness.valgrind): the kernel unit tests, then a block reshaped
# while in contact (octagon -> triangle, 300 steps; the old code read the old shape's edges: invalid
# heap reads and an uninitialised value in rbsm::followContact / keepHinted). Any valgrind error fails.
# Usage: valgrind_reshape.sh <rbsm_unit_tests> <yade-rbsm launcher> <overlay prefix> <PYTHONPATH> <yade>
# YADE runs as the launcher would run it, but without the launcher's bash in between (valgrind on
# the dynamic loader under --trace-children reports glibc's own strncmp in is_dst). The same ld.so
# read is reported at YADE's own dlopen for some lengths of the environment (PYTHONPATH, worktree
# path): valgrind.supp suppresses exactly that frame (strncmp called by is_dst), nothing else.
set -euo pipefail
unit="$1" launcher="$2" overlay="$3" pythonpath="$4" yade="$5"
here="$(cd "$(dirname "$0")" && pwd)"
vg=(valgrind --error-exitcode=1 -q --num-callers=30 --suppressions="$here/valgrind.supp")
"${vg[@]}" "$unit" --gtest_brief=1
YADE_RBSM_REFRESH_ONLY=1 "$launcher" # the overlay prefix with this build's plugin
python=$(head -1 "$yade" | sed 's/^#!//')
# Python's own allocator confuses valgrind: malloc instead.
out=$(YADE_PREFIX="$overlay" PYTHONPATH="$pythonpath" PYTHONMALLOC=malloc "${vg[@]}" $python "$yade" -j1 -n -x \
	"$here/scenes/validation_paths.py" '{"case": "reshape_in_contact", "settle": 100, "steps": 200}' 2>&1) || {
	echo "$out" | tail -150
	echo "valgrind found errors (or the scene failed) in the reshaping scene" >&2
	exit 1
}
echo "$out" | grep RBSM_RESULT
echo "$out" | grep -q '"finite": true' || { echo "$out" | tail -50; exit 1; }
