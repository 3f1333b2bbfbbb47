#!/usr/bin/env bash
# End-to-end: the side panel's tooltips under Xvfb, with the mouse only: the tooltip of a tool
# button opens beside the panel, over the view, and covers none of the panel's text (the tool's
# hint under the buttons). The steps and checks are in editor_tooltip_e2e.py.
# Usage: editor_tooltip_e2e.sh PATCHLAB_BINARY SOURCE_DIR. Exit 77 (skipped) without the tools.
set -euo pipefail
bin=$1
src=$2
lib=$(cd "$(dirname "$0")" && pwd)/editor_e2e_lib.sh
source "$lib"
e2e_prepare
cp "$src/assets/default.json" "$tmp/scene.json"
e2e_drive tooltip
