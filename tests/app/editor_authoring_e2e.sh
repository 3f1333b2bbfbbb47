#!/usr/bin/env bash
# End-to-end authoring in the real editor under Xvfb, with the mouse and keys only: from File >
# New, a network of a triangle, a quad and two pentagons is built with the authoring tools, a
# vertex's tangent plane turned by its knob, an edge split, a face deleted and made again, a
# scheme changed from the context menu and the scene saved; analyze must find it G1 with no
# projected vertex, and undo to the empty scene then redo must save the same bytes. The steps
# and checks are in editor_authoring_e2e.py (driven through editor_driver.py).
# Usage: editor_authoring_e2e.sh PATCHLAB_BINARY SOURCE_DIR. Exit 77 (skipped) without the tools.
set -euo pipefail
bin=$1
lib=$(cd "$(dirname "$0")" && pwd)/editor_e2e_lib.sh
source "$lib"
e2e_prepare
e2e_drive authoring
