#!/usr/bin/env python3
"""Compares the figures of two builds of a benchmark program, measured in one run.

    compare_builds.py [--rounds N] [--tolerance 0.05] BEFORE AFTER [-- ARGS...]

runs BEFORE ARGS and AFTER ARGS in turns (N rounds each, alternating, so that a machine getting
busier or quieter weighs on both alike), takes the median of every `figure NAME VALUE UNIT` line
per build, and prints one line per figure:

    figure-ratio NAME BEFORE AFTER RATIO VERDICT

RATIO is AFTER / BEFORE; VERDICT is `worse` when AFTER is worse than BEFORE by more than the
tolerance (lower is better for times, sizes and counts of work; higher for rates: units ending in
`/s`, `per_s` or `fps`), else `same` or `better`. Exits 1 when a figure is worse or missing from
one build, so a script can check "within 5 %".
"""
import argparse
import statistics
import subprocess
import sys


def figures(binary, args):
    out = subprocess.run([binary, *args], capture_output=True, text=True, check=True).stdout
    result = {}
    for line in out.splitlines():
        w = line.split()
        if len(w) >= 4 and w[0] == "figure":
            try:
                result[w[1]] = (float(w[2]), w[3])
            except ValueError:
                pass
    return result


def higher_is_better(unit):
    return unit.endswith("/s") or unit.endswith("per_s") or unit == "fps" or unit == "x"


def main():
    argv = sys.argv[1:]
    extra = []
    if "--" in argv:
        i = argv.index("--")
        argv, extra = argv[:i], argv[i + 1:]
    p = argparse.ArgumentParser()
    p.add_argument("--rounds", type=int, default=3)
    p.add_argument("--tolerance", type=float, default=0.05)
    p.add_argument("before")
    p.add_argument("after")
    a = p.parse_args(argv)

    runs = {"before": [], "after": []}
    for _ in range(a.rounds):
        runs["before"].append(figures(a.before, extra))
        runs["after"].append(figures(a.after, extra))

    def medians(which):
        names = {}
        for r in runs[which]:
            for name, (value, unit) in r.items():
                names.setdefault(name, ([], unit))[0].append(value)
        return {n: (statistics.median(v), u) for n, (v, u) in names.items()}

    before, after = medians("before"), medians("after")
    failed = False
    for name in sorted(set(before) | set(after)):
        if name not in before or name not in after:
            print(f"figure-ratio {name} missing in {'after' if name in before else 'before'}")
            failed = True
            continue
        (b, unit), (f, _) = before[name], after[name]
        ratio = f / b if b != 0 else (1.0 if f == 0 else float("inf"))
        change = (ratio - 1) if higher_is_better(unit) else (1 - ratio)  # > 0: better
        verdict = "worse" if change < -a.tolerance else "better" if change > a.tolerance else "same"
        failed |= verdict == "worse"
        print(f"figure-ratio {name} {b:.6g} {f:.6g} {ratio:.3f} {verdict} ({unit})")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
