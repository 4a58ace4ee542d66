#!/usr/bin/env bash
# The suite as a user's clone runs it, with no public corpus beside it
# (issue 34): RINGID_CORPUS_DIR points at a directory that does not exist.
# Fails if any test fails, if a test not labelled `corpus` skips, or if a
# corpus test does anything but skip; names each test that took over 8 s
# without the label `long` (tests/CMakeLists.txt). Runs on the build of
# scripts/test.sh.
set -euo pipefail
cd "$(dirname "$0")/../build"
export RINGID_CORPUS_DIR="$PWD/no-corpus-here"
[ ! -e "$RINGID_CORPUS_DIR" ] || { echo "test_without_corpus: $RINGID_CORPUS_DIR exists" >&2; exit 1; }
log=$(mktemp)
trap 'rm -f "$log"' EXIT

# ctest lists a skipped test as "N - NAME (Skipped)" under "did not run".
skipped() { grep -E '^\s*[0-9]+ - .* \(Skipped\)$' "$log" | wc -l; }

ctest -LE corpus --output-on-failure -j"$(nproc)" | tee "$log"
if [ "$(skipped)" -ne 0 ]; then
  echo "test_without_corpus: $(skipped) test(s) outside the corpus label skipped" >&2
  exit 1
fi
# "12/451 Test #291: NAME ....   Passed   18.22 sec"
long=$(ctest -L long -N | sed -n -E 's/^ *Test +#[0-9]+: ([^ ]+).*/\1/p')
awk '/ Test +#[0-9]+: .* sec$/ { print $4, $(NF-1) }' "$log" | while read -r name seconds; do
  if awk -v s="$seconds" 'BEGIN { exit !(s > 8) }' && ! grep -qxF "$name" <<< "$long"; then
    echo "test_without_corpus: $name took $seconds s without the label long (tests/CMakeLists.txt)" >&2
  fi
done
corpus=$(ctest -L corpus -N | sed -n 's/^Total Tests: //p')
ctest -L corpus -j"$(nproc)" | tee "$log"
if [ "$corpus" -eq 0 ] || [ "$(skipped)" -ne "$corpus" ]; then
  echo "test_without_corpus: $(skipped) of $corpus corpus tests skipped; all must" >&2
  exit 1
fi
echo "test_without_corpus: every test outside the corpus passed; the $corpus corpus tests skipped"
