#!/usr/bin/env bash
# The campaign benchmark (issue 26): N demo datasets (default 200, made by
# scripts/campaign_demo.sh) diagnosed in one run and in 4 shards, of which
# shard 2 is killed (SIGTERM) mid-way and restarted; merged, the shards' table
# must equal the single run's apart from timings, and the restart must refit
# only what it had not finished. Prints the throughput (datasets per second
# per core) of identify and diagnose on these datasets, and exits 1 when a
# check fails. Usage: bash benchmarks/campaign_resume.sh [N] [DIR]
# (after scripts/build.sh; DIR defaults to a fresh temporary directory).
set -euo pipefail
cd "$(dirname "$0")/.."
n=${1:-200}
dir=${2:-$(mktemp -d)}
ringid=./build/ringid
cores=2  # --jobs=2, one thread each
rm -rf "$dir/datasets" "$dir/truth" "$dir/serial" "$dir/sharded" "$dir/identify"
bash scripts/campaign_demo.sh "$dir" "$n" > /dev/null
flags="--derivatives=analytic --jobs=2 --threads=1"
seconds_of() { python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["seconds"])' "$1"; }

$ringid identify --dataset="$dir/datasets" --output_dir="$dir/identify" $flags > /dev/null || true
$ringid diagnose --dataset="$dir/datasets" --output_dir="$dir/serial" $flags > /dev/null || true
for i in 0 1 3; do
  $ringid diagnose --dataset="$dir/datasets" --output_dir="$dir/sharded" $flags --shard=$i/4 > /dev/null || true
done
reports() { find "$dir/sharded" -maxdepth 1 -name 'case*.json' | wc -l; }
before=$(reports)
$ringid diagnose --dataset="$dir/datasets" --output_dir="$dir/sharded" $flags --shard=2/4 \
  > /dev/null 2>&1 &
pid=$!
while [ "$(reports)" -lt $((before + n / 8)) ] && kill -0 $pid 2> /dev/null; do sleep 0.1; done
kill -TERM $pid
wait $pid || true
finished=$(($(reports) - before))
$ringid diagnose --dataset="$dir/datasets" --output_dir="$dir/sharded" $flags --shard=2/4 > /dev/null || true
$ringid merge --output_dir="$dir/sharded" > /dev/null

python3 - "$dir" "$n" "$finished" "$cores" <<'PY'
import json, sys
d, n, finished, cores = sys.argv[1], int(sys.argv[2]), int(sys.argv[3]), int(sys.argv[4])
def rows(path):
    out = []
    for r in json.load(open(path))["datasets"]:
        out.append({k: v for k, v in r.items() if k not in ("seconds", "report_file", "resumed")})
    return out
serial, merged = rows(f"{d}/serial/campaign.json"), rows(f"{d}/sharded/campaign.json")
shard = json.load(open(f"{d}/sharded/campaign.2-of-4.json"))
shard_size = len(shard["datasets"])
refitted = sum(1 for r in shard["datasets"] if not r.get("resumed"))
ok = serial == merged and shard["resumed"] == finished and refitted == shard_size - finished
for kind in ("identify", "serial"):
    s = json.load(open(f"{d}/{kind}/campaign.json"))["seconds"]
    name = "identify" if kind == "identify" else "diagnose"
    print(f"{name}: {n} datasets in {s:.1f} s on {cores} cores: {n / s / cores:.2f} datasets/s/core")
print(f"shard 2/4: killed after {finished} of {shard_size} reports; the restart kept {shard['resumed']}, refitted {refitted}")
print(f"merged table equals the single run's (timings aside): {'yes' if serial == merged else 'NO'}")
sys.exit(0 if ok else 1)
PY
