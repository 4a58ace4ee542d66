#!/usr/bin/env bash
# Regenerates docs/figures/*.svg from the paper's data with the tool itself:
# identify on Table 1, then `ringid report --figures_dir`. Needs gnuplot-nox.
# Usage: bash scripts/figures.sh [BUILD_DIR] (default build, after scripts/build.sh)
set -euo pipefail
cd "$(dirname "$0")/.."
ringid=${1:-build}/ringid
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
"$ringid" identify --dataset=datasets/paper/table1.json --output="$tmp/identify.json" > /dev/null
"$ringid" report --input="$tmp/identify.json" --output="$tmp/identify.html" --figures_dir="$tmp" > /dev/null
mkdir -p docs/figures
cp "$tmp/identify-frequencies.svg" docs/figures/
echo "wrote docs/figures/identify-frequencies.svg"
