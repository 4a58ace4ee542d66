#!/usr/bin/env bash
# The main job: identify the paper's Table 1 by Levenberg-Marquardt and write
# the report with its covariance to paper_identification.json.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh > /dev/null
./build/ringid identify --dataset=datasets/paper/table1.json --output=paper_identification.json
echo "report written to paper_identification.json"
