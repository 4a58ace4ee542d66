#!/usr/bin/env bash
# Builds ringid and runs the GoogleTest suite through ctest.
set -euo pipefail
cd "$(dirname "$0")/.."
python3 scripts/check_sizes.py  # issue 22: no source over 700 lines, no function over 120
bash scripts/build.sh > /dev/null
cd build && ctest --output-on-failure -j"$(nproc)"
