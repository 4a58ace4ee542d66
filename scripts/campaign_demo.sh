#!/usr/bin/env bash
# Writes N withheld-effect datasets (default 100) into DIR/datasets and their
# truth files into DIR/truth: the six effects of contract section 4 and no
# effect in turn, sized to shift some frequency by 3 % or 5 %, noise 0.25 % /
# 10 % / 0.02, each with its own seed. Usage: bash scripts/campaign_demo.sh DIR [N]
# (after scripts/build.sh). Then, for example:
#   ./build/ringid diagnose --dataset=DIR/datasets --output_dir=DIR/reports --jobs=2
set -euo pipefail
cd "$(dirname "$0")/.."
dir=${1:?usage: campaign_demo.sh DIR [N]}
n=${2:-100}
mkdir -p "$dir/datasets" "$dir/truth"
effects=(none anisotropic_sidewall hub_compliance contact_yaw_stiffness axle_torsion sensor_mass lug_coupling)
for ((i = 0; i < n; ++i)); do
  effect=${effects[i % 7]}
  shift=$([ $(((i / 7) % 2)) = 0 ] && echo 0.03 || echo 0.05)
  name=$(printf "case%03d" "$i")  # the name does not give the effect away
  args=(--parameters=datasets/paper/parameters.json --seed=$((i + 1)) --set=m_a=15
        --output="$dir/datasets/$name.json" --truth="$dir/truth/$name.json")
  [ "$effect" = none ] || args+=(--effects="$effect" --shift="$shift")
  ./build/ringid simulate "${args[@]}" > /dev/null
done
echo "wrote $n datasets to $dir/datasets and their truth to $dir/truth"
