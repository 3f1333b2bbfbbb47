#!/usr/bin/env bash
# Smoke test of editor_drag_busy.sh: one quiet and one busy-core round of the editor's drag
# benchmark on the default scene; every figure the script promises is printed with a positive
# value. The figures themselves are not judged here (timing belongs to the benchmarks).
# Usage: editor_drag_busy_smoke.sh BUILD_DIR. Exit 77 (skipped) without xvfb-run.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
out=$(bash "$here/editor_drag_busy.sh" "$1" 1 default) || exit $?
echo "$out"
for f in editor_frame_ms_p50_default editor_frame_ms_p50_default_busy \
  editor_frame_p50_busy_over_quiet_default editor_frame_ms_p95_default \
  editor_frame_ms_p95_default_busy editor_frame_p95_busy_over_quiet_default; do
  echo "$out" | awk -v f="$f" '$1 == "figure" && $2 == f && $3 + 0 > 0 { found = 1 }
    END { exit !found }' || { echo "editor_drag_busy_smoke: no positive figure $f" >&2; exit 1; }
done
