#!/usr/bin/env python3
"""Issue 25: in-process ringid.identify against SciPy's least_squares on the
same fit, in one Python process.

ringid: ringid.identify(DATASET, starts=1, derivatives="analytic"), the whole
identification as the command line runs it (set-up, Levenberg-Marquardt,
covariance and identifiability analysis, plausibility), report not written.

SciPy: least_squares on ringid.Problem(DATASET) -- the same weighted
residuals (ringid's model, called through the module), the same coordinates
(log of each positive parameter), the same start and box -- with Ceres'
tolerances as benchmarks/scipy_identify.py maps them (ftol 1e-14, xtol 1e-12,
gtol 1e-14). Each method runs with the module's exact Jacobian
(Problem.jacobian) and with SciPy's own central differences ('3-point').
The residuals cost the same on both sides; what differs is the solver and what
runs around it. A third residual is written in Python, as a user would without
ringid.Problem: the parameters from the coordinates (the dataset's known values,
exp of each log coordinate, its ties), ringid.predict of them, and the
weighted differences of the measured frequencies by label -- checked equal to
Problem.residuals at the start before anything is timed. The fourth is issue 13's
comparison, which issue 25's target is stated against: SciPy fitting the
model written in NumPy (scipy_identify.py, a transcription of ringid's model,
pairing and weights, with ringid's central-difference rule), no ringid code
inside the fit; its residuals are checked against Problem.residuals at the
start too. A SciPy fit converged when it reaches 2 cost <= 1e-10 (Table 1
has 7 frequencies for 16 free parameters: every exact fit has cost 0, and
ringid's reaches 1e-16).

Usage: PYTHONPATH=build/python python3 benchmarks/python_vs_scipy.py
           [--dataset=datasets/paper/table1.json] [--runs=20]
"""
import argparse
import json
import math
import os
import statistics
import sys
import time

import numpy as np
from scipy.optimize import least_squares

import ringid

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import scipy_identify  # noqa: E402  (the NumPy model, issue 13)
CONVERGED_CHI_SQUARE = 1e-10


def median_seconds(run, runs):
    run()  # warm caches; not counted
    times = []
    for _ in range(runs):
        t0 = time.perf_counter()
        run()
        times.append(time.perf_counter() - t0)
    return statistics.median(times)


def python_residuals(problem, path):
    """Table 1's weighted frequency residuals over ringid.predict (format-1 datasets with
    frequencies only; anything else is refused)."""
    with open(path) as f:
        d = json.load(f)
    modes = d["modes"]
    if any(k in m for m in modes for k in ("shape", "damping_ratio")) or "conditions" in d:
        raise SystemExit("python_vs_scipy: the Python residual is for frequencies alone")
    labels = [m["label"] for m in modes]
    measured = np.array([m["frequency_hz"] for m in modes])
    sigma = np.array([m["frequency_sigma_hz"] for m in modes])
    known, ties = d.get("known", {}), d.get("ties", {})
    names, logs = problem.names, problem.log_coordinates

    def residuals(x):
        values = dict(known)
        values.update({n: (math.exp(c) if log else c) for n, c, log in zip(names, x, logs)})
        for tied, target in ties.items():
            values[tied] = values[target]
        modes_now = ringid.predict(parameters=ringid.ParameterSet(values))
        hz = dict(zip(modes_now.labels, modes_now.frequencies))
        return (np.array([hz[label] for label in labels]) - measured) / sigma
    gap = np.max(np.abs(residuals(problem.start) - problem.residuals(problem.start)))
    if not gap <= 1e-9:
        raise SystemExit("python_vs_scipy: the Python residual differs from ringid's by %g" % gap)
    return residuals


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--dataset", default=os.path.join(HERE, "..", "datasets", "paper", "table1.json"))
    parser.add_argument("--runs", type=int, default=20)
    args = parser.parse_args()
    dataset = ringid.load_dataset(args.dataset)

    fit = ringid.identify(dataset, starts=1, derivatives="analytic")
    rows = [("ringid.identify (analytic, 1 start)", fit.evaluations, 2 * fit.cost, "-",
             fit.status == "success" and fit.converged,
             median_seconds(lambda: ringid.identify(dataset, starts=1, derivatives="analytic"),
                            args.runs))]

    problem = ringid.Problem(dataset, derivatives="analytic")
    in_python = python_residuals(problem, args.dataset)
    for method in ("trf", "dogbox"):
        for jac in ("ringid", "3-point", "python"):
            def run():
                return least_squares(in_python if jac == "python" else problem.residuals,
                                     problem.start,
                                     jac=problem.jacobian if jac == "ringid" else "3-point",
                                     bounds=(problem.lower, problem.upper), method=method,
                                     ftol=1e-14, xtol=1e-12, gtol=1e-14)
            out = run()
            chi_square = 2 * problem.cost(out.x)
            # SciPy's nfev leaves out the residual calls of its differences.
            evaluations = out.nfev + out.njev * (1 if jac == "ringid" else 2 * len(out.x))
            runs = args.runs if method == "dogbox" else 3  # trf runs seconds
            name = ("least_squares %s, Python residual, 3-point" % method if jac == "python"
                    else "least_squares %s, jac %s" % (method, jac))
            rows.append((name, evaluations, chi_square,
                         str(out.status),
                         chi_square <= CONVERGED_CHI_SQUARE, median_seconds(run, runs)))

    # Issue 13's comparison: SciPy on the model written in NumPy.
    numpy_ds = scipy_identify.load_dataset(args.dataset)
    if numpy_ds["free"] != list(problem.names):
        raise SystemExit("python_vs_scipy: scipy_identify.py frees %s, ringid %s"
                         % (numpy_ds["free"], list(problem.names)))
    gap = np.max(np.abs(scipy_identify.Residuals(numpy_ds)(problem.start)
                        - problem.residuals(problem.start)))
    if not gap <= 1e-6:  # the eigen-solvers differ by some 1e-10 relative
        raise SystemExit("python_vs_scipy: the NumPy residual differs from ringid's by %g" % gap)
    for method in ("trf", "dogbox"):
        options = argparse.Namespace(jac="ringid", method=method, x_scale=1.0,
                                     max_nfev=scipy_identify.MAX_ITERATIONS)
        out, residuals, _, _ = scipy_identify.fit(numpy_ds, options)
        chi_square = 2 * problem.cost(out.x)
        runs = args.runs if method == "dogbox" else 3
        rows.append(("least_squares %s, NumPy model (issue 13)" % method, residuals.solutions,
                     chi_square, str(out.status), chi_square <= CONVERGED_CHI_SQUARE,
                     median_seconds(lambda: scipy_identify.fit(numpy_ds, options), runs)))

    base = rows[0][5]
    print("dataset %s, median of %d runs, %d cores, load average %s, numpy %s"
          % (os.path.relpath(args.dataset), args.runs, os.cpu_count(),
             " ".join(open("/proc/loadavg").read().split()[:3]), np.__version__))
    head = "%-44s %12s %11s %7s %10s %10s %9s" % (
        "run", "evaluations", "chi-square", "status", "converged", "seconds", "x ringid")
    print(head)
    print("-" * len(head))
    for name, evaluations, chi_square, status, converged, seconds in rows:
        print("%-44s %12d %11.2e %7s %10s %10.6f %9.1f" % (
            name, evaluations, chi_square, status, "yes" if converged else "NO", seconds,
            seconds / base))
    print("Python residual: the residuals written in Python over ringid.predict (see above).")
    print("NumPy model: benchmarks/scipy_identify.py, ringid's model transcribed to NumPy, with\n"
          "             ringid's central differences; chi-square at its end by ringid's model.")
    print("evaluations: ringid's model evaluations; SciPy's residual calls, each Jacobian one more\n"
          "             (jac ringid) or 2 per coordinate (3-point).")
    print("status: SciPy's (0: evaluation limit, 1-4: gtol, ftol, xtol, both).")
    print("converged: chi-square <= %g (an exact fit; ringid's reaches 1e-16)." % CONVERGED_CHI_SQUARE)
    print("x ringid: that run's time over ringid.identify's (above 1: slower than ringid).")


if __name__ == "__main__":
    main()
