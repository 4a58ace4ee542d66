#!/usr/bin/env bash
# Builds TARGETs (all without any) in the configured build directory DIR with
# a line of progress on stderr per step ("ringid build: [12/40] Linking CXX
# executable ringid") and, where the build fails, its messages; nothing on stdout.
# Usage: bash scripts/progress.sh DIR [TARGET...]
set -euo pipefail
build=$1
shift
log=$(mktemp)
trap 'rm -f "$log"' EXIT
start=$SECONDS
targets=()
[ $# -eq 0 ] || targets=(--target "$@")
NINJA_STATUS="[%f/%t] " cmake --build "$build" -j"$(nproc)" "${targets[@]}" > "$log" 2>&1 &
pid=$!
tail -f --pid=$pid -n +1 "$log" 2> /dev/null |
  sed -u -n -E 's|^(\[[0-9]+/[0-9]+\] .*)|ringid build: \1|p' >&2 || true
if ! wait $pid; then
  cat "$log" >&2
  echo "ringid build: failed in $build" >&2
  exit 1
fi
echo "ringid build: $build built in $((SECONDS - start)) s" >&2
