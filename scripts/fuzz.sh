#!/usr/bin/env bash
# Builds the libFuzzer targets of tests/fuzz with clang (ASan + UBSan) into
# build-asan/, the build of the sanitized test suite (scripts/sanitized_build.sh),
# and runs each for SECONDS (default 60), one worker per core, from its seed
# corpus: the project's own datasets plus the regression inputs in tests/fuzz/corpus.
# Usage: bash scripts/fuzz.sh [SECONDS [TARGET...]]
#   e.g. bash scripts/fuzz.sh 3600 identify   (an hour on the identify target)
# FUZZ_SANITIZERS=undefined drops ASan for long runs (about 3x the executions;
# memory errors are then caught only as crashes), building into build-fuzz-undefined/.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-60}
shift || true
targets=${*:-dataset dataset3 model identify tir forces uff uff58 obstacle}
sanitizers=${FUZZ_SANITIZERS:-address,undefined}
build=build-asan
[ "$sanitizers" = address,undefined ] || build=build-fuzz-${sanitizers//,/-}
fuzzers=(dataset_fuzzer dataset3_fuzzer model_fuzzer identify_fuzzer tir_fuzzer forces_fuzzer
         uff_fuzzer uff58_fuzzer obstacle_fuzzer)
bash scripts/sanitized_build.sh "$build" "$sanitizers" "${fuzzers[@]}"
export ASAN_OPTIONS=detect_leaks=1
for target in $targets; do
  work=$build/corpus-$target
  mkdir -p "$work"
  cp tests/fuzz/corpus/$target/* "$work"/ 2>/dev/null || true
  [ "$target" = dataset ] && cp datasets/paper/*.json "$work"/
  [ "$target" = tir ] && cp datasets/examples/*.tir "$work"/
  [ "$target" = uff ] && cp datasets/examples/*.uff "$work"/
  [ "$target" = obstacle ] && cp datasets/examples/cleat_spec.json datasets/examples/cross_stitch_lugs.json "$work"/
  echo "fuzzing $target for ${seconds}s" >&2
  # The last status line carries the executions reached over all workers.
  log=$build/fuzz-$target.log
  ./$build/tests/fuzz/${target}_fuzzer "$work" -fork="$(nproc)" -max_total_time="$seconds" \
    -max_len=8192 -timeout=10 -rss_limit_mb=2048 > "$log" 2>&1 || true
  grep -E "^#[0-9]+:|ERROR|SUMMARY|crash-|timeout-|oom-" "$log" | tail -3 || true
  # A finding: libFuzzer says where it wrote the input (in fork mode the
  # crash-*/timeout-*/oom-* file can appear only after the parent returns,
  # so the log, not the directory, is what is read).
  if grep -qE "Test unit written to|^SUMMARY: |ERROR: libFuzzer" "$log" ||
     ls crash-* timeout-* oom-* leak-* > /dev/null 2>&1; then
    echo "fuzz finding in $target (the input is in tests/fuzz/corpus after a fix):" >&2
    grep -E "Test unit written to|^SUMMARY: |runtime error" "$log" | head -5 >&2
    exit 1
  fi
done
