#!/usr/bin/env bash
# End-to-end interior control in the real editor under Xvfb, with the mouse and keys only: a copy
# of the default scene (a Gregory quad and a GB pentagon) is opened, the pentagon selected, its
# degree raised to 5 with the face panel's button, its central point and one inner-row free point
# dragged, the scene saved; analyze must report degree 5, two offsets and every shared edge below
# 1e-6 degrees. The steps and checks are in editor_interior_e2e.py.
# Usage: editor_interior_e2e.sh PATCHLAB_BINARY SOURCE_DIR. Exit 77 (skipped) without the tools.
set -euo pipefail
bin=$1
src=$2
lib=$(cd "$(dirname "$0")" && pwd)/editor_e2e_lib.sh
source "$lib"
e2e_prepare
cp "$src/assets/default.json" "$tmp/pentagon.json"
e2e_drive interior
