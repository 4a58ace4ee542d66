#!/usr/bin/env bash
# Builds ringid and runs the GoogleTest suite through ctest.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh > /dev/null
cd build && ctest --output-on-failure -j"$(nproc)"
