#!/usr/bin/env bash
# The editor's drag frame time in an analysis display against the default isophotes, in one run:
# `patchlab --bench-drag SCENE --display MODE` alternated between "isophotes" and MODE (default
# "mean+isophotes+combs": mean curvature colours with isophote lines and curvature combs),
# ROUNDS times (default 3); the medians of editor_frame_ms_p50 and _p95 are printed as
#   figure editor_frame_ms_p50_isophotes MS ms, editor_frame_ms_p50_MODE MS ms,
#   figure editor_frame_p50_MODE_over_isophotes RATIO x   (and the same for p95)
# with MODE's '+' written '_'. Alternating keeps what else the machine runs in both.
# Usage: bash tests/bench/editor_drag_modes.sh [BUILD_DIR] [ROUNDS] [MODE] [SCENE]
#   SCENE: the default scene unless given. Needs xvfb-run (exit 77 without it).
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
build=${1:-$root/build}
rounds=${2:-3}
mode=${3:-mean+isophotes+combs}
scene=${4:-$root/assets/default.json}
patchlab=$build/app/patchlab
command -v xvfb-run >/dev/null || { echo "editor_drag_modes: xvfb-run is missing" >&2; exit 77; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
unset DISPLAY

median() { sort -g | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }

name=${mode//+/_}
for r in $(seq "$rounds"); do
  for m in isophotes "$mode"; do
    xvfb-run -a -s "-screen 0 1400x900x24" "$patchlab" --bench-drag "$scene" --display "$m" \
      >"$work/${m//+/_}.$r.txt"
  done
done
for p in p50 p95; do
  base=$(cat "$work"/isophotes.*.txt | awk -v f="editor_frame_ms_$p" '$2 == f { print $3 }' | median)
  other=$(cat "$work/$name".*.txt | awk -v f="editor_frame_ms_$p" '$2 == f { print $3 }' | median)
  echo "figure editor_frame_ms_${p}_isophotes $base ms"
  echo "figure editor_frame_ms_${p}_$name $other ms"
  awk -v a="$base" -v b="$other" -v n="editor_frame_${p}_${name}_over_isophotes" \
    'BEGIN { printf "figure %s %.3g x\n", n, b / a }'
done
