"""Writes the manual's verification page from the figures the tests recorded (tests/support/verification.py):
one JSON file per case in build/verification. A case whose test did not run in this build says so.
    python3 docs/tools/verification_page.py <build/verification> <out.md>"""
import glob
import json
import os
import sys

HEAD = """# Verification

Every closed-form and published case the tests check, with the figure measured **in the last test run of
this build** (the tests write them; this page is generated from them, so it cannot drift from the code).
The difference is (measured − reference) / reference; the tolerance is the one the test asserts.

"""


def fmt(x):
    return f"{x:.6g}" if isinstance(x, (int, float)) else str(x)


def main(src, out):
    cases = []
    for path in sorted(glob.glob(os.path.join(src, "*.json"))):
        with open(path) as f:
            cases.append(json.load(f))
    lines = [HEAD]
    if not cases:
        lines.append("No test results in this build yet: run `bash scripts/test.sh`, then `bash scripts/build_docs.sh`.\n")
    groups = {}
    for c in cases:
        groups.setdefault(c.get("group", "Other"), []).append(c)
    for group in sorted(groups):
        lines += [f"## {group}\n", "| case | reference | measured | difference | tolerance | test |",
                  "| --- | --- | --- | --- | --- | --- |"]
        for c in sorted(groups[group], key=lambda c: c["case"]):
            ref, got = c["reference"], c["measured"]
            diff = f"{100 * (got / ref - 1):+.2f} %" if isinstance(ref, (int, float)) and ref else "\u2014"
            unit = f" {c['unit']}" if c.get("unit") else ""
            tol = f"{100 * c['rtol']:g} %" if c.get("rtol") is not None else c.get("tolerance", "\u2014")
            lines.append(f"| {c['case']} | {fmt(ref)}{unit} ({c['source']}) | {fmt(got)}{unit} | {diff} | {tol} | "
                         f"`{c['test']}` |")
        lines.append("")
    stamp = sorted({c.get("commit", "?") for c in cases})
    if cases:
        lines.append(f"Recorded on commit {', '.join(stamp)}.\n")
    with open(out, "w") as f:
        f.write("\n".join(lines))


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
