#!/usr/bin/env bash
# Configures and builds ringid with clang under the sanitizers into a build
# directory, with libFuzzer's coverage instrumentation, so that one build
# serves both the sanitized test suite (scripts/sanitize.sh) and the fuzz
# targets (scripts/fuzz.sh).
# Usage: bash scripts/sanitized_build.sh DIR SANITIZERS [TARGET...]
#   SANITIZERS: address,undefined (the default of both scripts) or e.g. undefined.
set -euo pipefail
cd "$(dirname "$0")/.."
build=$1 sanitizers=$2
shift 2
bash scripts/install_deps.sh clang libclang-rt-14-dev
# Debian's Ceres is a static library built without sanitizers. Eigen drops its
# "glibc malloc is aligned" assumption under ASan, so without this define our
# objects and Ceres' copies of Eigen's inline allocator disagree (a bad free in
# BDCSVD inside ceres::Covariance). glibc and ASan both align malloc to 16.
# Coverage is not traced inside Eigen, Ceres and the standard library
# (tests/fuzz/coverage_ignorelist.txt): their inner loops took 55 % of an
# identify execution. ASan and UBSan still check them.
flags="-fsanitize=fuzzer-no-link,$sanitizers -fno-sanitize-recover=all -fno-omit-frame-pointer"
flags+=" -O1 -DNDEBUG -gline-tables-only -DEIGEN_MALLOC_ALREADY_ALIGNED=1"  # file:line in reports
flags+=" -fsanitize-coverage-ignorelist=$PWD/tests/fuzz/coverage_ignorelist.txt"
# The Python module is left out: an ASan-built extension cannot load into
# Debian's uninstrumented python3 (the ASan runtime must come first); its
# tests run in the optimised suite.
cmake -S . -B "$build" -G Ninja -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=None \
  -DRINGID_BUILD_BENCHMARKS=OFF -DRINGID_BUILD_PYTHON=OFF -DRINGID_BUILD_FUZZERS=ON \
  -DCMAKE_CXX_FLAGS="$flags" -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=$sanitizers" > /dev/null
bash scripts/progress.sh "$build" "$@"
