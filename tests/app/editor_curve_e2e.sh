#!/usr/bin/env bash
# End-to-end free curve in the real editor under Xvfb, with the mouse and keys only: a B-spline
# made by clicking six points with the New Curve tool, a knot inserted from the right-click menu,
# the curvature graph opened, a point dragged and the scene saved; analyze must list the curve
# with 7 control points and finite figures. The steps and checks are in editor_curve_e2e.py.
# Usage: editor_curve_e2e.sh PATCHLAB_BINARY SOURCE_DIR. Exit 77 (skipped) without the tools.
set -euo pipefail
bin=$1
lib=$(cd "$(dirname "$0")" && pwd)/editor_e2e_lib.sh
source "$lib"
e2e_prepare
e2e_drive curve
