#!/usr/bin/env bash
# Builds ringid with AddressSanitizer and UndefinedBehaviorSanitizer (no
# recovery, leaks detected) into build-asan/ and runs the whole test suite
# there. Any finding fails the run.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install_deps.sh
# Debian's Ceres is a static library built without sanitizers. Eigen drops its
# "glibc malloc is aligned" assumption under ASan, so without this define our
# objects and Ceres' copies of Eigen's inline allocator disagree (a bad free in
# BDCSVD inside ceres::Covariance). glibc and ASan both align malloc to 16.
flags="-fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer -g -O1 -DEIGEN_MALLOC_ALREADY_ALIGNED=1"
cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DRINGID_BUILD_BENCHMARKS=OFF \
  -DCMAKE_CXX_FLAGS="$flags" -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" > /dev/null
cmake --build build-asan -j"$(nproc)"
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1:strict_string_checks=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
# The two longest diagnosis tests (a minute each, ten under the sanitizers)
# run every path again that the shorter diagnosis tests run: left to the
# optimised build, for CI's time.
cd build-asan && ctest --output-on-failure -j"$(nproc)" \
  -E 'QuickValidationSuiteFromScatteredStarts|AnEffectTheDataCannotRejectAgainstTheVerdict'

