#!/usr/bin/env bash
# The whole test suite from a fresh Debian 12 machine: installs the packages, builds, runs ctest.
#   bash tests/run.sh             Release build in build/, every test
#   bash tests/run.sh --sanitize  Debug build with AddressSanitizer + UndefinedBehaviorSanitizer
#                                 in build-asan/, every test
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
mode=${1:-release}
[ "${PATCHLAB_SKIP_INSTALL:-0}" = 1 ] || bash .ci/install-deps
# ccache is not a dependency; where a developer has it, rebuilds of unchanged files are cache hits.
launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
if [ "$mode" = "--sanitize" ]; then
  dir=build-asan
  # Debug keeps the asserts; -O1 keeps the sanitized suite fast enough for a 2-core CI, and line
  # tables (-g1) are all a sanitizer's stack needs (full debug information costs a quarter of the
  # build).
  cmake -S . -B "$dir" -G Ninja -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS_DEBUG="-g1 -O1" \
    -DPATCHLAB_SANITIZE=ON "${launcher[@]}"
  # LeakSanitizer reports Mesa's and libgomp's process-lifetime allocations; those are not ours
  # (OpenSubdiv and OpenCASCADE's image libraries still load libgomp).
  export LSAN_OPTIONS="suppressions=$root/tests/lsan.supp:print_suppressions=0"
  export ASAN_OPTIONS="detect_odr_violation=0:strict_string_checks=1"
  export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
else
  dir=build
  cmake -S . -B "$dir" -G Ninja -DCMAKE_BUILD_TYPE=Release "${launcher[@]}"
fi
cmake --build "$dir"
# The core's parallel loops (oneTBB) use the cores this process may run on; a worker the kernel
# deschedules while ctest runs two tests at once holds one small task, so nothing is set here.
unset DISPLAY  # headless tests must not depend on an X server
ctest --test-dir "$dir" --output-on-failure -j2
