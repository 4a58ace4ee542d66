#!/usr/bin/env bash
# Configures ringid (Release, Ninja) into build/ and builds TARGETs, by default
# the tool alone (what scripts/run_paper.sh needs); `all` builds everything,
# the tests, benchmarks and Python module with it (scripts/test.sh). Progress
# goes to stderr, a line per step.
# Usage: bash scripts/build.sh [TARGET...]
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install_deps.sh
# A build/ configured with another generator (make) is configured again.
if [ -f build/CMakeCache.txt ] && ! grep -q '^CMAKE_GENERATOR:INTERNAL=Ninja$' build/CMakeCache.txt; then
  rm -rf build
fi
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release > /dev/null
if [ "${1:-}" = all ]; then
  bash scripts/progress.sh build
else
  bash scripts/progress.sh build "${@:-ringid}"
fi
