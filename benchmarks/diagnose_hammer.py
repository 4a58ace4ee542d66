#!/usr/bin/env python3
"""ringid diagnose on a standing hammer test: the default (effects screened by
their score test, only those it keeps refitted) against every effect refitted
(--screen=1), in one run.

The test: the standing hammer test of datasets/examples/hammer_spec.json (28
FRFs x 491 lines, 2 % noise, masses and inertias free) of the example car
tire, simulated by `ringid simulate --frf --seed=SEED`; every free
parameter's initial value scattered log-uniformly within a factor 3 of the
truth (the seed's). First the clean test: its `none` verdict states the size of
each effect the data would show. Then the same test (same seed, same noise,
same initial values) with an axle torsion at twice its stated k_atheta, and
with a contact yaw stiffness at twice its stated k_cpsi. Each is diagnosed
with the default 6 starts; the time is the wall time of the whole `ringid
diagnose` command, the median of --runs runs.

Usage: python3 benchmarks/diagnose_hammer.py [--seed=1] [--runs=3]
           [--ringid=build/ringid] [--keep=FOLDER]
Exit status 2 with one line when ringid is missing.
"""
import argparse
import json
import os
import random
import statistics
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
SPEC = os.path.join(ROOT, "datasets", "examples", "hammer_spec.json")
TIRE = os.path.join(ROOT, "datasets", "examples", "car_tire.json")
START_FACTOR = 3.0
WITHHELD = [("axle_torsion", "k_atheta"), ("contact_yaw_stiffness", "k_cpsi")]


def run(args):
    done = subprocess.run(args, capture_output=True, text=True)
    if done.returncode > 1:
        sys.exit("diagnose_hammer: %s failed: %s" % (args[1], done.stderr.strip()))
    return done


def simulate(ringid, folder, name, seed, initial, effect=None):
    """The hammer test (with `effect`, NAME=VALUE), its initial values `initial`
    (or scattered within START_FACTOR of the truth when None); returns the
    dataset's path and its initial values."""
    raw = os.path.join(folder, name + "_raw.json")
    truth = os.path.join(folder, name + "_truth.json")
    args = [ringid, "simulate", "--parameters=" + TIRE, "--frf=" + SPEC, "--seed=%d" % seed,
            "--output=" + raw, "--truth=" + truth]
    if effect:
        args += ["--effects=" + effect[0], "--set=%s=%r" % (effect[1], effect[2])]
    run(args)
    with open(raw) as f:
        data = json.load(f)
    if initial is None:
        with open(truth) as f:
            values = {k: v["value"] for k, v in json.load(f)["parameters"].items()}
        scatter = random.Random(seed)
        initial = {k: values[k] * START_FACTOR ** scatter.uniform(-1, 1)
                   for k in sorted(data["initial"])}
    data["initial"] = initial
    path = os.path.join(folder, name + ".json")
    with open(path, "w") as f:
        json.dump(data, f)
    return path, initial


def diagnose(ringid, dataset, runs, extra):
    """The median wall time over `runs` and the last report."""
    seconds = []
    out = dataset[:-5] + "_diagnosis.json"
    for _ in range(runs):
        t0 = time.perf_counter()
        run([ringid, "diagnose", "--dataset=" + dataset, "--output=" + out] + extra)
        seconds.append(time.perf_counter() - t0)
    with open(out) as f:
        return statistics.median(seconds), json.load(f)


def verdict(report):
    v = report["verdict"]
    group = [e for e in v.get("indistinguishable", []) if e != v["effect"]]
    return v["effect"] + (" (with %s)" % ", ".join(group) if group else "")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--runs", type=int, default=3)
    parser.add_argument("--ringid", default=os.path.join(ROOT, "build", "ringid"))
    parser.add_argument("--keep", default=None)
    a = parser.parse_args()
    if not os.access(a.ringid, os.X_OK):
        print("diagnose_hammer: no ringid at %s (build it first)" % a.ringid, file=sys.stderr)
        sys.exit(2)
    folder = a.keep or tempfile.mkdtemp(prefix="diagnose_hammer_")
    os.makedirs(folder, exist_ok=True)
    clean, initial = simulate(a.ringid, folder, "clean", a.seed, None)
    cases = [("clean", "-", clean)]
    _, first = diagnose(a.ringid, clean, 1, [])
    for effect, param in WITHHELD:
        stated = next(r["minimal_detectable"][param] for r in first["ranking"]
                      if r["effect"] == effect)
        path, _ = simulate(a.ringid, folder, effect, a.seed, initial,
                           (effect, param, 2 * stated))
        cases.append((effect, "%s = 2 x %.3g" % (param, stated), path))
    print("standing hammer test (datasets/examples/hammer_spec.json), seed %d, masses free, "
          "initial values within a factor %g, 6 starts; %d cores, load average %s; "
          "median of %d runs" % (a.seed, START_FACTOR, os.cpu_count(),
                                 " ".join("%.2f" % x for x in os.getloadavg()), a.runs))
    print("%-22s %-24s | %-50s %8s %8s | %-50s %8s | %6s" %
          ("withheld", "size", "verdict (screened)", "refitted", "s", "verdict (--screen=1)",
           "s", "ratio"))
    print("-" * 192)
    for name, size, path in cases:
        fast, screened = diagnose(a.ringid, path, a.runs, [])
        slow, every = diagnose(a.ringid, path, a.runs, ["--screen=1"])
        refitted = sum(1 for r in screened["ranking"] if r["fitted"])
        print("%-22s %-24s | %-50s %6d/%d %8.2f | %-50s %8.2f | %6.1f" %
              (name, size, verdict(screened), refitted, len(screened["ranking"]), fast,
               verdict(every), slow, slow / fast))
    print("s: wall time of the whole `ringid diagnose` command (process start and the 0.9 MB "
          "dataset's reading included);\n  refitted: the effects the score test kept, with "
          "their rivals; ratio: refitting every effect over the default.")


if __name__ == "__main__":
    main()
