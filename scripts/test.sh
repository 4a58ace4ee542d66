#!/usr/bin/env bash
# Builds ringid and runs the GoogleTest suite through ctest: every test once
# as a user's clone sees it, with no public corpus (scripts/test_without_corpus.sh),
# then the corpus tests on the corpus where it is present (skipped where not).
set -euo pipefail
cd "$(dirname "$0")/.."
python3 scripts/check_sizes.py  # issue 22: no source over 700 lines, no function over 120
bash scripts/build.sh all
bash scripts/test_without_corpus.sh
cd build && ctest -L corpus --output-on-failure -j"$(nproc)"
