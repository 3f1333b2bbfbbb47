#!/usr/bin/env python3
"""Compares the figures of two builds of a benchmark program, measured in one run.

    compare_builds.py [--rounds N] [--tolerance 0.05] [--stat median|best] [--raw FILE]
                      BEFORE AFTER [-- ARGS...]

runs BEFORE ARGS and AFTER ARGS in turns (N rounds each, alternating, so that a machine getting
busier or quieter weighs on both alike), takes the median (or, with --stat best, the best value:
the one least disturbed by other work on the machine) of every `figure NAME VALUE UNIT` line per
build, and prints one line per figure:

    figure-ratio NAME BEFORE AFTER RATIO VERDICT

RATIO is AFTER / BEFORE; VERDICT is `worse` when AFTER is worse than BEFORE by more than the
tolerance (lower is better for times, sizes and counts of work; higher for rates: units ending in
`/s`, `per_s` or `fps`, and for speed-ups), else `same` or `better`. A ratio (unit `x`) whose
name does not say which way is better (`speedup`: higher; `busy_over_quiet`, `over_floor`:
lower) gets `differs` instead of `worse`. Exits 1 when a figure is worse, differs or is missing
from one build, so a script can check "within 5 %". --raw writes every run's figures as JSON.
"""
import argparse
import json
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


def higher_is_better(name, unit):
    """True, False, or None where the figure does not say (a ratio of two figures)."""
    if unit.endswith("/s") or unit.endswith("per_s") or unit == "fps":
        return True
    if unit != "x":
        return False
    if "speedup" in name or name.endswith("_over_one") or "_over_one_" in name:
        return True
    if "busy_over_quiet" in name or "over_floor" in name:
        return False
    return None


def best(values, higher):
    return max(values) if higher else min(values)


def main():
    argv = sys.argv[1:]
    extra = []
    if "--" in argv:
        i = argv.index("--")
        argv, extra = argv[:i], argv[i + 1:]
    p = argparse.ArgumentParser()
    p.add_argument("--rounds", type=int, default=3)
    p.add_argument("--tolerance", type=float, default=0.05)
    p.add_argument("--stat", choices=["median", "best"], default="median")
    p.add_argument("--raw")
    p.add_argument("before")
    p.add_argument("after")
    a = p.parse_args(argv)

    runs = {"before": [], "after": []}
    for _ in range(a.rounds):
        runs["before"].append(figures(a.before, extra))
        runs["after"].append(figures(a.after, extra))

    if a.raw:
        with open(a.raw, "w") as f:
            json.dump(runs, f, indent=1)

    def summary(which):
        names = {}
        for r in runs[which]:
            for name, (value, unit) in r.items():
                names.setdefault(name, ([], unit))[0].append(value)
        if a.stat == "median":
            return {n: (statistics.median(v), u) for n, (v, u) in names.items()}
        # a ratio of unknown direction has no best value: its median
        return {n: ((statistics.median(v) if higher_is_better(n, u) is None
                     else best(v, higher_is_better(n, u))), u) for n, (v, u) in names.items()}

    before, after = summary("before"), summary("after")
    failed = False
    for name in sorted(set(before) | set(after)):
        if name not in before or name not in after:
            print(f"figure-ratio {name} missing in {'after' if name in before else 'before'}")
            failed = True
            continue
        (b, unit), (f, _) = before[name], after[name]
        ratio = f / b if b != 0 else (1.0 if f == 0 else float("inf"))
        higher = higher_is_better(name, unit)
        if higher is None:
            verdict = "differs" if abs(ratio - 1) > a.tolerance else "same"
        else:
            change = (ratio - 1) if higher else (1 - ratio)  # > 0: better
            verdict = ("worse" if change < -a.tolerance else
                       "better" if change > a.tolerance else "same")
        failed |= verdict in ("worse", "differs")
        print(f"figure-ratio {name} {b:.6g} {f:.6g} {ratio:.3f} {verdict} ({unit})")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
