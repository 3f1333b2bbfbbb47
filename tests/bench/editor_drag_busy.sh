#!/usr/bin/env bash
# The editor's drag frame times with the machine as it is and with one core held busy by another
# process (`patchlab --bench-drag --busy`), on the default scene and on a 384-face GB cube-sphere:
# runs are alternated, quiet then busy, ROUNDS times (default 2), and the medians of their
# editor_frame_ms_p50 / _p95 are printed as
#   figure editor_frame_ms_p95_SCENE MS ms, editor_frame_ms_p95_SCENE_busy MS ms,
#   editor_frame_p95_busy_over_quiet_SCENE RATIO x   (and the same for p50)
# Usage: bash tests/bench/editor_drag_busy.sh [BUILD_DIR] [ROUNDS] [SCENES]
#   SCENES: "default faces_384" unless given (the smoke test runs "default" only).
# Needs xvfb-run (exit 77 without it, which ctest counts as skipped).
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
build=${1:-$root/build}
rounds=${2:-2}
scenes=${3:-default faces_384}
patchlab=$build/app/patchlab
command -v xvfb-run >/dev/null || { echo "editor_drag_busy: xvfb-run is missing" >&2; exit 77; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$patchlab" sample cube-sphere --cells 8 -o "$work/cube_sphere_384.json" >/dev/null
unset DISPLAY

median() { sort -g | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }

for name in $scenes; do
  case $name in
    default) file=$root/assets/default.json ;;
    faces_384) file=$work/cube_sphere_384.json ;;
    *) echo "editor_drag_busy: unknown scene $name (default, faces_384)" >&2; exit 2 ;;
  esac
  for r in $(seq "$rounds"); do
    for mode in quiet busy; do
      flag=(); [ "$mode" = busy ] && flag=(--busy)
      xvfb-run -a -s "-screen 0 1400x900x24" "$patchlab" --bench-drag "${flag[@]}" "$file" \
        >"$work/$name.$mode.$r.txt"
    done
  done
  for p in p50 p95; do
    q=$(cat "$work/$name".quiet.*.txt | awk -v f="editor_frame_ms_$p" '$2 == f { print $3 }' | median)
    b=$(cat "$work/$name".busy.*.txt | awk -v f="editor_frame_ms_$p" '$2 == f { print $3 }' | median)
    echo "figure editor_frame_ms_${p}_$name $q ms"
    echo "figure editor_frame_ms_${p}_${name}_busy $b ms"
    awk -v q="$q" -v b="$b" -v n="editor_frame_${p}_busy_over_quiet_$name" \
      'BEGIN { printf "figure %s %.3g x\n", n, b / q }'
  done
done
