# Issue 21: Kulhawy's stress-based factor of safety of four homogeneous slopes cut into Voronoi blocks, at
# three block sizes and three tessellation seeds, against Bishop and Spencer on the same slope
# (docs/slope_factor_of_safety.md). Each run is `scripts/slope_fs_study.py --mode stress` in its own process
# (two at a time); prints the markdown table and draws docs/slope_stress_fs.png.
#
#   /usr/bin/python3 scripts/slope_stress_fs_table.py [--spacings 1,0.5,0.25] [--seeds 1,2,3] [--jobs 2]
#                                                     [--results R.jsonl] [--save R.jsonl] [--png docs/slope_stress_fs.png]
#
# --results: read the RESULT lines of earlier runs from R.jsonl (one JSON object a line) instead of running;
# --save: write the runs' RESULT objects there (for --results later).
import argparse
import json
import os
import subprocess
import sys
from concurrent.futures import ThreadPoolExecutor

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "scripts"))
from reference_slopes import SLOPES as REFERENCE  # noqa: E402

SLOPES = list(REFERENCE)
LABEL = {name: v[3] for name, v in REFERENCE.items()}


def run(slope, spacing, seed):
    cmd = [os.path.join(ROOT, "build", "yade-rbsm"), "-j1", "-n", "-x", os.path.join(ROOT, "scripts", "slope_fs_study.py"),
           "--slope", slope, "--mode", "stress", "--spacing", str(spacing), "--seed", str(seed)]
    out = subprocess.run(cmd, capture_output=True, text=True, cwd=ROOT).stdout
    lines = [l for l in out.splitlines() if l.startswith("RESULT ")]
    if not lines:
        sys.exit("slope_stress_fs_table.py: %s printed no result:\n%s" % (" ".join(cmd), out[-3000:]))
    return json.loads(lines[0][len("RESULT "):])


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--spacings", default="1,0.5,0.25")
    ap.add_argument("--seeds", default="1,2,3")
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--results", default="")
    ap.add_argument("--save", default="")
    ap.add_argument("--png", default=os.path.join("out", "slope_stress_fs.png"))  # docs/ has the tracked copy
    a = ap.parse_args()
    if a.results:
        rows = [json.loads(l[len("RESULT "):] if l.startswith("RESULT ") else l) for l in open(a.results) if l.strip()]
    else:
        jobs = [(s, float(h), int(k)) for h in a.spacings.split(",") for s in SLOPES for k in a.seeds.split(",")]
        with ThreadPoolExecutor(a.jobs) as ex:
            rows = list(ex.map(lambda j: run(*j), jobs))
        if a.save:
            with open(a.save, "w") as f:
                f.write("".join(json.dumps(r) + "\n" for r in rows))
    if not rows:
        sys.exit("slope_stress_fs_table.py: no results")
    spacings = sorted({r["spacing"] for r in rows}, reverse=True)
    print("| slope (H = 10 m) | Bishop | Spencer | " + " | ".join("H/%g: stress FS (seeds), blocks" % (10 / h) for h in spacings) + " |")
    print("|---" * (3 + len(spacings)) + "|")
    series = {}
    for s in SLOPES:
        mine = [r for r in rows if r["slope"] == s]
        if not mine:
            continue
        b, sp = mine[0]["bishop"], mine[0]["spencer"]
        cells = []
        for h in spacings:
            at = sorted((r for r in mine if r["spacing"] == h), key=lambda r: r["seed"])
            if not at:
                cells.append("")
                continue
            fs = [r["fs"] for r in at]
            dev = [100 * (f / b - 1) for f in fs]
            cells.append("%s (%+.1f…%+.1f %%), %d" % (", ".join("%.3f" % f for f in fs), min(dev), max(dev), at[0]["blocks"]))
            series.setdefault(s, []).append((h, [f / b for f in fs]))
        print("| %s | %.3f | %.3f | %s |" % (LABEL[s], b, sp, " | ".join(cells)))
    if a.png:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, ax = plt.subplots(figsize=(6.4, 4.8))
        for s, pts in series.items():
            xs = [10 / h for h, _ in pts]
            ax.plot(xs, [sum(v) / len(v) for _, v in pts], "o-", label=LABEL[s])
            for x, (_, v) in zip(xs, pts):
                ax.plot([x] * len(v), v, "k.", ms=3)
        ax.axhspan(0.95, 1.05, color="0.9", zorder=0, label="±5 % of Bishop")
        ax.axhline(1.0, color="k", lw=0.8)
        ax.set_xscale("log")
        ax.minorticks_off()
        ax.set_xticks([10, 20, 40])
        ax.set_xticklabels(["H/10", "H/20", "H/40"])
        ax.set_xlabel("block size")
        ax.set_ylabel("stress-based FS / Bishop")
        ax.set_title("Kulhawy's FS from the settled blocks' stresses (mean; dots: seeds)", fontsize=9)
        ax.set_ylim(0.93, 1.07)
        fig.legend(*ax.get_legend_handles_labels(), fontsize=7, loc="lower center", ncol=2, frameon=False)
        fig.subplots_adjust(left=0.13, right=0.97, bottom=0.27, top=0.93)
        os.makedirs(os.path.dirname(os.path.abspath(a.png)), exist_ok=True)
        fig.savefig(a.png, dpi=110)
        print("plot: %s" % a.png)


if __name__ == "__main__":
    main()
