#!/usr/bin/env bash
# Issue 13: whole-process `ringid identify --starts=1` on Table 1 against
# SciPy's least_squares doing the same fit (benchmarks/scipy_identify.py), in
# one run on one machine. Prints a table of medians and the ratios.
#
# Usage: bash benchmarks/compare_scipy.sh
#   RINGID_FLAGS="--derivatives=analytic"  extra ringid flags; if the binary
#                                          rejects them, the run falls back to
#                                          none and says so
#   RUNS=5                                 timed runs of each command (median)
#   SCIPY_METHODS="trf dogbox"             least_squares methods to time; trf is
#                                          the one issue 13 names
#   DATASET=datasets/paper/table1.json
#   SKIP_BUILD=1                           use the existing build/ringid
set -euo pipefail
cd "$(dirname "$0")/.."
runs=${RUNS:-5}
dataset=${DATASET:-datasets/paper/table1.json}
methods=${SCIPY_METHODS:-trf dogbox}
flags=${RINGID_FLAGS:-}

# Debian's python3-numpy and python3-scipy install for /usr/bin/python3,
# which need not be the python3 first on PATH.
bash scripts/install_deps.sh python3-numpy python3-scipy
python=/usr/bin/python3
[ -x "$python" ] || python=python3
"$python" -c "import numpy, scipy" || { echo "compare_scipy: $python has no numpy/scipy" >&2; exit 1; }

[ "${SKIP_BUILD:-0}" = 1 ] || bash scripts/build.sh
ringid=./build/ringid

# The model and the residuals must be ringid's before any time means anything.
"$python" benchmarks/scipy_identify.py --check-predict datasets/paper/parameters.json \
  --ringid="$ringid" > /dev/null
echo "check: the SciPy model reproduces ringid predict to 1e-9 (frequencies, damping ratios)" >&2

# Does the binary take RINGID_FLAGS?
note=""
if [ -n "$flags" ]; then
  # shellcheck disable=SC2086  # flags are words
  if ! "$ringid" identify --dataset="$dataset" --starts=1 $flags > /dev/null 2> /tmp/compare_scipy.$$.err; then
    if "$ringid" identify --dataset="$dataset" --starts=1 > /dev/null 2>&1; then
      note="ringid rejected '$flags' ($(head -1 /tmp/compare_scipy.$$.err)); timed without it"
      flags=""
    else
      cat /tmp/compare_scipy.$$.err >&2
      rm -f /tmp/compare_scipy.$$.err
      exit 1
    fi
  fi
  rm -f /tmp/compare_scipy.$$.err
fi

RUNS=$runs DATASET=$dataset METHODS=$methods FLAGS=$flags NOTE=$note RINGID=$ringid \
  PYTHON=$python "$python" - <<'EOF'
import json, os, re, shlex, statistics, subprocess, sys, time

runs = int(os.environ["RUNS"])
dataset, ringid, python = os.environ["DATASET"], os.environ["RINGID"], os.environ["PYTHON"]
flags = shlex.split(os.environ["FLAGS"])


def timed(cmd):
    """Wall time of the whole process (fork, exec, start-up, work, exit)."""
    t0 = time.perf_counter()
    done = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    seconds = time.perf_counter() - t0
    if done.returncode != 0:
        sys.exit("compare_scipy: %s failed (%d): %s" % (" ".join(cmd), done.returncode, done.stderr))
    return seconds, done.stdout


def median_of(cmd, parse):
    timed(cmd)  # warm the file cache; not counted
    walls, inner = [], []
    for _ in range(runs):
        wall, out = timed(cmd)
        walls.append(wall)
        inner.append(parse(out))
    return statistics.median(walls), inner


def parse_ringid(out):
    # BriefReport: "... converged, cost C, N model evaluations in 1 start(s), T ms"
    m = re.search(r"\): (converged|not converged|FAILED), cost (\S+), (\d+) model evaluations"
                  r" in \d+ start\(s\), (\S+) ms", out)
    return {"converged": m.group(1) == "converged", "cost": float(m.group(2)),
            "solutions": int(m.group(3)), "inner": float(m.group(4)) / 1e3,
            "iterations": "-"}


def parse_scipy(out):
    d = json.loads(out)
    return {"converged": d["converged"], "cost": d["cost"], "solutions": d["model_solutions"],
            "inner": d["fit_seconds"], "iterations": "%d nfev" % d["nfev"]}


rows = []
cmd = [ringid, "identify", "--dataset=" + dataset, "--starts=1"] + flags
wall, inner = median_of(cmd, parse_ringid)
rows.append(("ringid " + (" ".join(flags) or "(numeric derivatives)"), wall, inner))
for method in os.environ["METHODS"].split():
    cmd = [python, "benchmarks/scipy_identify.py", dataset, "--method=" + method]
    wall, inner = median_of(cmd, parse_scipy)
    rows.append(("scipy least_squares " + method, wall, inner))

base_wall = rows[0][1]
base_inner = statistics.median(i["inner"] for i in rows[0][2])
print("dataset %s, %d timed runs each (median), %d cores, load average %s"
      % (dataset, runs, os.cpu_count(), " ".join(open("/proc/loadavg").read().split()[:3])))
if os.environ["NOTE"]:
    print("NOTE: " + os.environ["NOTE"])
head = "%-36s %10s %8s %12s %10s %10s %9s %10s" % (
    "run", "whole s", "x ringid", "in-proc s", "x ringid", "solutions", "cost", "converged")
print(head)
print("-" * len(head))
for name, wall, inner in rows:
    i = inner[-1]
    med_inner = statistics.median(x["inner"] for x in inner)
    print("%-36s %10.4f %8.1f %12.4f %10.1f %10d %9.2e %10s" % (
        name, wall, wall / base_wall, med_inner, med_inner / base_inner, i["solutions"],
        i["cost"], "yes" if i["converged"] else "NO"))
print("whole s: wall time of the process (SciPy: incl. interpreter start and imports).")
print("in-proc s: ringid's own identify time (fit + uncertainty analysis, from its output);")
print("           SciPy's least_squares call alone (the fit, nothing after it).")
print("solutions: model eigen-solutions used (ringid's 'model evaluations').")
EOF
