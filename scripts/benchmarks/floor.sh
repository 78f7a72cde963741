#!/bin/bash
# How much of an RBSM contact-step is YADE's own work: callgrind instructions per contact-step on the settled
# 40 x 40 running-bond wall of scripts/benchmark_contacts.py (exact and frozen kinematics), on its sphere stack,
# and on the wall with the RBSM functors switched off after settling (the "floor": NewtonIntegrator, the
# interaction loop's dispatch, Ig2 returning at once, Law2 making only its four ForceContainer calls, with
# stand-in values). The floor needs a build with scripts/benchmarks/floor_experiment.patch, made here in
# a git worktree of HEAD (never in the plugin). About 4 minutes on 2 cores with a warm ccache (the four scenes
# settle under valgrind), more when the worktree's plugin build starts cold.
#
#   bash scripts/benchmarks/floor.sh            # uses build/ for the plugin as it is
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/../.." && pwd)
WORK=${RBSM_FLOOR_WORK:-/tmp/rbsm-floor}
command -v valgrind > /dev/null || { echo "floor.sh: needs valgrind (apt-get install valgrind)" >&2; exit 1; }
[ -x "$ROOT/build/yade-rbsm" ] || { echo "floor.sh: build the plugin first (bash scripts/build.sh)" >&2; exit 1; }

# the patched build, in a worktree of HEAD
rm -rf "$WORK"; git -C "$ROOT" worktree prune
git -C "$ROOT" worktree add --detach "$WORK/src" HEAD > /dev/null
trap 'git -C "$ROOT" worktree remove --force "$WORK/src" > /dev/null 2>&1 || true' EXIT
git -C "$WORK/src" apply "$ROOT/scripts/benchmarks/floor_experiment.patch"
cmake -S "$WORK/src" -B "$WORK/src/build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DRBSM_BUILD_TESTS=OFF > "$WORK/cmake.log" 2>&1
cmake --build "$WORK/src/build" -j2 --target pkg_rbsm rbsm_overlay > "$WORK/build.log" 2>&1

run() { # run tag mode tree (whose plugin build is used): callgrind of the window, instructions per contact-step (whole step and by part)
	local tag=$1 mode=$2 tree=$3 d="$WORK/$1"
	mkdir -p "$d"
	YADE_PREFIX="$tree/build/yade-prefix" PYTHONPATH="$tree/py:$tree/build/python" \
		valgrind --tool=callgrind --instr-atstart=no --callgrind-out-file="$d/cg.out" \
		/usr/bin/yade -j1 -n -x "$ROOT/scripts/benchmark_contacts.py" --callgrind-window "$mode" > "$d/log" 2>&1
	local f; f=$(ls -S "$d"/cg.out* | head -1)
	callgrind_annotate --inclusive=yes "$f" > "$d/annotate.txt" 2> /dev/null
	/usr/bin/python3 - "$d/annotate.txt" "$d/log" "$tag" <<'PY'
import re, sys
ann, log, tag = sys.argv[1:4]
m = re.search(r"CALLGRIND_WINDOW mode \S+ contacts (\d+) steps (\d+)", open(log).read())
n = int(m.group(1)) * int(m.group(2))
parts = {"step": "PROGRAM TOTALS", "InteractionLoop": "InteractionLoop::action()", "Newton": "NewtonIntegrator::action()",
         "Ig2": "::go(boost::shared_ptr<yade::Shape> const&", "Law2": "::go(boost::shared_ptr<yade::IGeom>&"}
got = {}
for line in open(ann):
    v = re.match(r"\s*([\d,]+) ", line)
    if not v:
        continue
    for k, pat in parts.items():
        if k not in got and pat in line and "thunk" not in line:
            got[k] = int(v.group(1).replace(",", "")) / n
print("| %s | %s | %s |" % (tag, m.group(1), " | ".join("%.0f" % got.get(k, float("nan")) for k in parts)))
PY
}
echo "| scene | contacts | step | InteractionLoop | Newton | Ig2 | Law2 |"
echo "|---|---|---|---|---|---|---|"
run "RBSM exact" exact "$ROOT"
run "RBSM updateTolerance=1e-4" frozen "$ROOT"
run "RBSM floor (functors off)" floor "$WORK/src"
run "YADE spheres" spheres "$ROOT"
echo "(callgrind instructions per contact-step, 20 steps after settling, -j1; $(git -C "$ROOT" rev-parse --short HEAD))"
