#!/usr/bin/env python3
"""The patchlab module against the C++ loops it wraps, measured in one run (ratios, not times:
the machine may be shared). Prints "figure NAME VALUE UNIT" lines:

  python_eval_msamples_per_s   Scene.evaluate of the GB patch cagd86 (5 sides, degree 5) at
                               1,000,141 samples, from Python: tessellation, evaluation with
                               derivatives, normals and curvatures, finiteness check, arrays
  cpp_eval_msamples_per_s      PatchEvaluator::evaluate_all of the same samples, timed in C++
                               (the loop of patchlab_bench's gb_full_eval figure)
  python_eval_over_cpp         the first over the second (throughput kept from Python)
  python_eval_at_msamples_per_s   PatchSamples.evaluate_at of the same 1,000,141 domain points
                               (new output arrays, filled in parallel; no tessellation)
  python_eval_at_over_cpp      that over evaluate_all, timed alternately again (_2)
  python_eval_into_over_cpp    evaluate_at(uv, out=earlier result): the same points into the
                               arrays of an earlier call, over evaluate_all (_3)
  python_move_ms               PatchSamples.move_control_point of inner point P^1_{2,1} at
                               100,501 samples, from Python, the changed samples returned
  cpp_drag_ms                  PatchEvaluator::move_control_point of the same point, timed in C++
                               (the loop of patchlab_bench's gb_drag_ms_100k figure)
  python_move_over_cpp_drag    the first over the second (cost of a move from Python)
  python_move_run_ms, cpp_drag_run_ms, python_move_over_cpp_drag_run
                               the same in runs of 10 moves back to back (a drag), the two
                               sides alternating run by run

The two sides of each ratio alternate call by call, so both see the same background load; the
figures are medians. The scene keeps its tessellation between evaluations, and the storage of
the results the loop drops (evaluated into again), as any Scene does.
Usage: python_eval_bench.py [--quick] [--cpp-bench BUILD/tests/patchlab_bench]
  --quick      small sizes, a few repeats: proves the script works (figures not meaningful)
  --cpp-bench  also runs `patchlab_bench --only gb` and prints its figures with the ratios of
               the module's to them (python_eval_over_cpp_bench, python_move_over_cpp_bench)
Run with PYTHONPATH=build/python.
"""

import argparse
import pathlib
import statistics
import subprocess
import time

import numpy as np

import patchlab
from patchlab import _timing

CAGD86 = pathlib.Path(__file__).resolve().parents[1] / "data" / "gb" / "cagd86.gbp"


def figure(name, value, unit):
    print(f"figure {name} {value:.6g} {unit}", flush=True)


def time_ms(f):
    a = time.perf_counter()
    f()
    return (time.perf_counter() - a) * 1e3


def against_evaluate_all(name, f, samples, repeats, cpp_name):
    """Msamples/s of f from Python and of evaluate_all in C++, timed alternately (both sides see
    the same background load); prints both and their ratio NAME_over_cpp."""
    python, cpp = [], []
    for _ in range(repeats):
        python.append(time_ms(f))
        cpp += _timing.evaluate_all_ms(samples, 1)
    n = len(samples)
    py_rate = n / (statistics.median(python) * 1e3)
    cpp_rate = n / (statistics.median(cpp) * 1e3)
    figure(f"{name}_msamples_per_s", py_rate, "Msamples/s")
    figure(cpp_name, cpp_rate, "Msamples/s")
    figure(f"{name}_over_cpp", py_rate / cpp_rate, "x")
    return py_rate


def evaluation(scene, density, repeats):
    samples = scene.evaluate(density=density)[0]  # the tessellation is kept by the scene
    figure("python_eval_samples", len(samples), "samples")
    py_rate = against_evaluate_all("python_eval", lambda: scene.evaluate(density=density),
                                   samples, repeats, "cpp_eval_msamples_per_s")
    # The same 1e6 domain points through PatchSamples.evaluate_at: new arrays, no tessellation.
    uv = np.array(samples.params)
    against_evaluate_all("python_eval_at", lambda: samples.evaluate_at(uv), samples, repeats,
                         "cpp_eval_msamples_per_s_2")
    # evaluate_at into the arrays of an earlier result (out=): no allocation, as evaluate_all.
    result = samples.evaluate_at(uv)
    against_evaluate_all("python_eval_into", lambda: samples.evaluate_at(uv, out=result),
                         samples, repeats, "cpp_eval_msamples_per_s_3")
    return py_rate


def drag(scene, density, repeats):
    samples = scene.evaluate(density=density)[0]
    k = _timing.gb_point_index(samples, 1, 2, 1)  # an inner point: it moves most of the patch
    p = np.array(samples.control_points[k])
    samples.move_control_point(k, p)  # builds the influence column, as a drag's start does
    python, cpp = [], []
    for i in range(repeats):  # alternating, one move each
        p[2] += 1e-3 if i % 2 == 0 else -1e-3
        python.append(time_ms(lambda: samples.move_control_point(k, p)))
        cpp += _timing.move_control_point_ms(samples, k, 1, 1e-3 if i % 2 else -1e-3)
    py_ms, cpp_ms = statistics.median(python), statistics.median(cpp)
    figure("python_move_samples", len(samples), "samples")
    figure("python_move_ms", py_ms, "ms")
    figure("cpp_drag_ms", cpp_ms, "ms")
    figure("python_move_over_cpp_drag", py_ms / cpp_ms, "x")
    # A drag: runs of moves back to back (as gb_bench's loop), the two sides alternating by run.
    block, python, cpp = 10, [], []
    for i in range(max(1, repeats // block)):
        for j in range(block):
            p[2] += 1e-3 if j % 2 == 0 else -1e-3
            python.append(time_ms(lambda: samples.move_control_point(k, p)))
        cpp += _timing.move_control_point_ms(samples, k, block)
    py_block, cpp_block = statistics.median(python), statistics.median(cpp)
    figure("python_move_run_ms", py_block, "ms")
    figure("cpp_drag_run_ms", cpp_block, "ms")
    figure("python_move_over_cpp_drag_run", py_block / cpp_block, "x")
    return py_ms


def cpp_bench(binary, py_rate, py_ms):
    out = subprocess.run([binary, "--only", "gb"], capture_output=True, text=True,
                         check=True).stdout
    figures = {}
    for line in out.splitlines():
        parts = line.split()
        if len(parts) == 4 and parts[0] == "figure":
            figures[parts[1]] = float(parts[2])
    rate, ms = figures["gb_full_eval_msamples_per_s"], figures["gb_drag_ms_100k"]
    figure("cpp_bench_gb_full_eval_msamples_per_s", rate, "Msamples/s")
    figure("cpp_bench_gb_drag_ms_100k", ms, "ms")
    figure("python_eval_over_cpp_bench", py_rate / rate, "x")
    figure("python_move_over_cpp_bench", py_ms / ms, "x")


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--quick", action="store_true")
    parser.add_argument("--cpp-bench")
    args = parser.parse_args()
    scene = patchlab.load(CAGD86)
    if args.quick:
        py_rate = evaluation(scene, 60, 2)
        py_ms = drag(scene, 30, 4)
    else:
        py_rate = evaluation(scene, 632, 15)  # 1,000,141 samples
        py_ms = drag(scene, 200, 200)  # 100,501 samples
    if args.cpp_bench:
        cpp_bench(args.cpp_bench, py_rate, py_ms)


if __name__ == "__main__":
    main()
