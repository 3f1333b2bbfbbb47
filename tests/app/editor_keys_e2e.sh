#!/usr/bin/env bash
# End-to-end keys in the editor's windows under Xvfb, with the mouse and keys only: Esc in F1's
# window closes it and leaves the selection behind it alone; Enter in the Add Vertex tool's typed
# coordinates adds the vertex. The steps and checks are in editor_keys_e2e.py.
# Usage: editor_keys_e2e.sh PATCHLAB_BINARY SOURCE_DIR. Exit 77 (skipped) without the tools.
set -euo pipefail
bin=$1
src=$2
lib=$(cd "$(dirname "$0")" && pwd)/editor_e2e_lib.sh
source "$lib"
e2e_prepare
cp "$src/assets/default.json" "$tmp/scene.json"
e2e_drive keys
