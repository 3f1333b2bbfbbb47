#!/usr/bin/env bash
# Builds the libFuzzer targets with clang (build-fuzz/), makes their seed corpora and runs each
# target for a fixed time. Exits non-zero on any finding (crash, sanitizer report, leak, timeout,
# out-of-memory); the reproducer is left in build-fuzz/findings/.
#   bash tests/fuzz/run.sh             60 s per target (CI)
#   bash tests/fuzz/run.sh 1800        a long campaign
#   bash tests/fuzz/run.sh 60 -runs=1000000   extra libFuzzer options for every target
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
cd "$root"
seconds=${1:-60}
shift || true
dir=build-fuzz
# Line tables are all a finding's stack needs; full debug information slows the build.
CC=clang CXX=clang++ cmake -S . -B "$dir" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O2 -gline-tables-only -DNDEBUG" -DPATCHLAB_FUZZ=ON >/dev/null
cmake --build "$dir" --target scene_reader_fuzz gbp_reader_fuzz scene_eval_fuzz cad_writer_fuzz \
  patchlab_fuzz_seeds

# Seeds: the scenes of assets/ and the inputs the library generates (every patch type it writes,
# networks, .gbp files); the evaluation target's inputs start with a density byte.
seeds="$dir/seeds"
rm -rf "$seeds"
mkdir -p "$seeds/scene" "$seeds/gbp" "$seeds/eval" "$seeds/cad"
cp assets/*.json assets/classic/*.json "$seeds/scene/"
"$dir/tests/fuzz/patchlab_fuzz_seeds" "$seeds" >/dev/null
for f in "$seeds"/scene/* "$seeds"/gbp/*; do
  { printf '\003'; cat "$f"; } >"$seeds/eval/$(basename "$f")"
done
# The CAD writer's inputs start with a format byte (even: STEP, odd: IGES): the scenes under
# 2 KB, each as STEP and as IGES. The bigger ones took 120-200 s to export once each under the
# sanitizers, before the first mutation, in a stage of 60 s a target; the round-trip tests export
# every one of them through both formats.
for f in "$seeds"/scene/*; do
  if [ "$(wc -c <"$f")" -lt 2048 ]; then
    { printf '\000'; cat "$f"; } >"$seeds/cad/step-$(basename "$f")"
    { printf '\001'; cat "$f"; } >"$seeds/cad/iges-$(basename "$f")"
  fi
done

mkdir -p "$dir/findings"
export ASAN_OPTIONS="detect_odr_violation=0:allocator_may_return_null=1"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
export LSAN_OPTIONS="suppressions=$root/tests/lsan.supp:print_suppressions=0"
status=0
run() {  # target, seed folder, extra options
  local target=$1 seed=$2
  shift 2
  local corpus="$dir/corpus/$target"
  mkdir -p "$corpus"
  echo "== $target: ${seconds} s"
  if ! "$dir/tests/fuzz/$target" "$corpus" "$seeds/$seed" -max_total_time="$seconds" \
      -rss_limit_mb=2048 -timeout=60 -max_len=8192 -print_final_stats=1 \
      -artifact_prefix="$dir/findings/$target-" "$@" 2>"$dir/$target.log"; then
    status=1
    echo "== $target: FINDING (log: $dir/$target.log)"
    tail -n 40 "$dir/$target.log"
  fi
  grep -E "stat::number_of_executed_units|stat::peak_rss_mb|cov: .*ft:" "$dir/$target.log" |
    tail -n 3
}
run scene_reader_fuzz scene -dict=tests/fuzz/scene.dict "$@"
run gbp_reader_fuzz gbp "$@"
run scene_eval_fuzz eval -dict=tests/fuzz/scene.dict "$@"
run cad_writer_fuzz cad -dict=tests/fuzz/scene.dict "$@"
exit $status
