#!/usr/bin/env bash
# From a fresh Debian 12 machine: installs the packages, builds PatchLab (Release) and runs it on
# the default scene. Extra arguments are passed to patchlab instead of the default.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
[ "${PATCHLAB_SKIP_INSTALL:-0}" = 1 ] || bash .ci/install-deps
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DPATCHLAB_BUILD_TESTS=OFF
cmake --build build --target patchlab
if [ $# -gt 0 ]; then
  exec build/app/patchlab "$@"
fi
exec build/app/patchlab
