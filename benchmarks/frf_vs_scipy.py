#!/usr/bin/env python3
"""ringid's FRF fit against SciPy's least_squares (trf) on a vectorised NumPy
model of the same FRFs, in one run.

The test: the standing hammer test of datasets/examples/hammer_spec.json
(datasets/synthetic.h HammerTest: 4 point forces on the tread, 7
accelerometers on tread and rim, 28 FRFs x 491 lines, 5-250 Hz, 2 % noise,
masses and inertias free), simulated by `ringid simulate --frf` from the
example car tire, one dataset per seed. The start: every free parameter 15 %
off the truth, up or down at random (the seed's), the same for both. One start
each, each tool with its default derivatives: ringid's auto (exact for FRFs,
dH = -H dZ H), SciPy's '2-point'.

The NumPy model is independent of ringid's C++: the 7-dof M, C, K of the
paper's eqs. (12) and (15) (with ERRATA.md; q = [x_b, z_b, theta_a, theta_b,
y_b, gamma_b, psi_b], hub held, the contact springs K/sigma), as
tests/frequency_response_test.cc writes them, and contract section 9's point
combinations; H = G (K - w^2 M + i w C)^-1 B (i w)^order solved for all lines
at once (batched np.linalg.solve). Before anything is timed, its H at the truth
must equal ringid's noise-free simulated FRFs to 1e-9 (relative to each
function's largest |H|), so both fit the same thing; and at ringid's fitted
parameters its chi-square must equal ringid's.

SciPy fits the same coordinates as ringid (the log of each free parameter),
unbounded, with its default tolerances. ringid is timed three ways: the
identify report's `seconds` (set-up, the fit, the uncertainty and
identifiability analysis: no process start, no file reading), the wall time of
`ringid.identify` in this process when the module is built (build/python), and
the wall time of the `ringid identify` command (process start, reading the
1.5 MB dataset, writing the report). The ratio is SciPy's wall time over the
report's seconds.

Usage: /usr/bin/python3 benchmarks/frf_vs_scipy.py [--seeds=1,2,3] [--runs=3]
           [--ringid=build/ringid] [--python=build/python] [--keep=FOLDER]
Exit status 2 with one line when SciPy, NumPy or ringid is missing.
"""
import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time

try:
    import numpy as np
    from scipy.optimize import least_squares
except ImportError as missing:
    print("frf_vs_scipy: needs %s (Debian: apt-get install python3-scipy; run it with "
          "/usr/bin/python3)" % missing.name, file=sys.stderr)
    sys.exit(2)

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
SPEC = os.path.join(ROOT, "datasets", "examples", "hammer_spec.json")
TIRE = os.path.join(ROOT, "datasets", "examples", "car_tire.json")
START_OFF = 0.15
CHECK_RELATIVE = 1e-9
ORDER = {"displacement": 0, "velocity": 1, "acceleration": 2}


# ---------------------------------------------------------------- NumPy model
def system(p):
    """M, C, K of eqs. (12) and (15) over q = [x_b, z_b, theta_a, theta_b, y_b,
    gamma_b, psi_b] (tests/frequency_response_test.cc's SecondOrder)."""
    M = np.diag([p["m_b"], p["m_b"], p["I_ay"], p["I_by"], p["m_b"], p["I_bx"], p["I_bz"]])
    C = np.zeros((7, 7))
    K = np.zeros((7, 7))
    kx, ky = p["K_cx"] / p["sigma_cx"], p["K_cy"] / p["sigma_cy"]
    r, rl, t = p["r_e0"], p["r_l0"], p["t_0"]
    K[0, 0] = p["k_bx"] + kx
    K[0, 3] = K[3, 0] = -r * kx
    K[3, 3] = p["k_btheta"] + r * r * kx
    K[2, 2] = p["k_btheta"]
    K[2, 3] = K[3, 2] = -p["k_btheta"]
    K[1, 1] = p["k_bz"] + p["k_cz"]
    C[0, 0] = p["c_bx"]
    C[1, 1] = p["c_bz"]
    C[2, 2] = C[3, 3] = p["c_btheta"]
    C[2, 3] = C[3, 2] = -p["c_btheta"]
    K[4, 4] = p["k_by"] + ky
    K[4, 5] = K[5, 4] = -rl * ky
    K[5, 5] = p["k_bgamma"] + rl * rl * ky + rl * p["F_cz0"]
    K[6, 4] = -t * ky
    K[6, 5] = rl * t * ky
    K[6, 6] = p["k_bpsi"]
    C[4, 4] = p["c_by"]
    C[5, 5] = p["c_bgamma"]
    C[6, 6] = p["c_bpsi"]
    return M, C, K


def combination(point):
    """Contract section 9: a belt point's coefficients on q; a rim point's
    theta_a alone (the hub held)."""
    pos = np.asarray(point["point_m"], float)
    d = np.asarray(point["direction"], float)
    d = d / np.linalg.norm(d)
    theta = d[2] * pos[0] - d[0] * pos[2]
    if point["on"] == "rim":
        return np.array([0, 0, theta, 0, 0, 0, 0])
    return np.array([d[0], d[2], 0, theta, d[1], d[2] * pos[1] - d[1] * pos[2],
                     d[1] * pos[0] - d[0] * pos[1]])


class FrfModel:
    """The dataset's FRFs as a function of the log of its free parameters."""

    def __init__(self, dataset, fixed):
        frf = dataset["conditions"][0]["frf"]
        self.names = sorted(dataset["initial"])
        self.ties = dataset.get("ties", {})
        self.fixed = dict(fixed)  # every parameter the model reads that is not free
        inputs = {x["name"]: k for k, x in enumerate(frf["inputs"])}
        outputs = {x["name"]: k for k, x in enumerate(frf["outputs"])}
        self.B = np.array([combination(x) for x in frf["inputs"]]).T  # 7 x inputs
        self.G = np.array([combination(x) for x in frf["outputs"]])   # outputs x 7
        self.order = np.array([ORDER[x["quantity"]] for x in frf["outputs"]])
        self.hz = np.array(frf["frequencies_hz"])
        self.w = 2 * np.pi * self.hz
        self.out = np.array([outputs[f["output"]] for f in frf["functions"]])
        self.inp = np.array([inputs[f["input"]] for f in frf["functions"]])
        self.measured = np.array([np.array(f["re"]) + 1j * np.array(f["im"])
                                  for f in frf["functions"]]).T  # lines x functions
        self.sigma = np.array([f["sigma"] for f in frf["functions"]]).T
        self.Bl = np.broadcast_to(self.B.astype(complex), (len(self.w),) + self.B.shape)
        # (i w)^order per line and output
        self.factor = (1j * self.w[:, None]) ** self.order[None, :]

    def parameters(self, x):
        p = dict(self.fixed)
        p.update(zip(self.names, np.exp(x)))
        for tied, to in self.ties.items():
            p[tied] = p[to]
        return p

    def H(self, p):
        M, C, K = system(p)
        w = self.w[:, None, None]
        D = K[None] - w * w * M[None] + 1j * w * C[None]
        X = np.linalg.solve(D, self.Bl)               # lines x 7 x inputs
        Y = np.einsum("oq,lqi->loi", self.G, X) * self.factor[:, :, None]
        return Y[:, self.out, self.inp]               # lines x functions

    def residuals(self, x):
        z = (self.H(self.parameters(x)) - self.measured) / self.sigma
        return np.concatenate([z.real.ravel(), z.imag.ravel()])


# ------------------------------------------------------------------ ringid side
def run(argv):
    out = subprocess.run(argv, capture_output=True, text=True)
    if out.returncode != 0:
        sys.exit("frf_vs_scipy: %s failed (%d): %s" % (" ".join(argv), out.returncode,
                                                      out.stderr.strip() or out.stdout.strip()))
    return out


def simulate(ringid, spec, seed, folder, name):
    data, truth = os.path.join(folder, name + ".json"), os.path.join(folder, name + "_truth.json")
    run([ringid, "simulate", "--parameters=" + TIRE, "--frf=" + spec, "--seed=%d" % seed,
         "--output=" + data, "--truth=" + truth])
    with open(data) as f, open(truth) as g:
        return data, json.load(f), {k: v["value"] for k, v in json.load(g)["parameters"].items()}


def check_model(ringid, folder):
    """The NumPy H at the truth against ringid's noise-free FRFs."""
    with open(SPEC) as f:
        spec = json.load(f)
    spec["noise"] = 0
    quiet = os.path.join(folder, "noise_free_spec.json")
    with open(quiet, "w") as f:
        json.dump(spec, f)
    _, dataset, truth = simulate(ringid, quiet, 1, folder, "noise_free")
    model = FrfModel(dataset, truth)
    H = model.H(truth)
    worst = 0.0
    for f in range(H.shape[1]):
        scale = np.max(np.abs(model.measured[:, f])) or np.max(np.abs(model.measured))
        worst = max(worst, np.max(np.abs(H[:, f] - model.measured[:, f])) / scale)
    if not worst <= CHECK_RELATIVE:
        sys.exit("frf_vs_scipy: the NumPy H differs from ringid's noise-free FRFs by %.3g "
                 "(relative to each function's largest |H|), more than %g" % (worst, CHECK_RELATIVE))
    return worst


def median_seconds(call, runs):
    times = []
    for _ in range(runs):
        t0 = time.perf_counter()
        result = call()
        times.append(time.perf_counter() - t0)
    return statistics.median(times), result


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seeds", default="1,2,3")
    parser.add_argument("--runs", type=int, default=3, help="median of this many runs of each")
    parser.add_argument("--ringid", default=os.path.join(ROOT, "build", "ringid"))
    parser.add_argument("--python", default=os.path.join(ROOT, "build", "python"))
    parser.add_argument("--keep", help="write the datasets and ringid's reports to this folder")
    args = parser.parse_args()
    if not os.access(args.ringid, os.X_OK):
        print("frf_vs_scipy: needs the ringid command, not found at %s (build it, or --ringid)"
              % args.ringid, file=sys.stderr)
        sys.exit(2)
    sys.path.insert(0, args.python)
    try:
        import ringid as module
    except ImportError:
        module = None

    rows = []
    with tempfile.TemporaryDirectory() as scratch:
        folder = args.keep or scratch
        if args.keep:
            os.makedirs(folder, exist_ok=True)
        gap = check_model(args.ringid, folder)
        for seed in [int(s) for s in args.seeds.split(",")]:
            path, dataset, truth = simulate(args.ringid, SPEC, seed, folder, "hammer_%d" % seed)
            rng = np.random.default_rng(seed)
            names = sorted(dataset["initial"])
            signs = rng.choice([-1.0, 1.0], size=len(names))
            dataset["initial"] = {n: truth[n] * (1 + START_OFF * s) for n, s in zip(names, signs)}
            with open(path, "w") as f:
                json.dump(dataset, f)
            model = FrfModel(dataset, {k: v for k, v in truth.items() if k not in names})
            x0 = np.log([dataset["initial"][n] for n in names])
            dof = 2 * model.measured.size - len(names)

            report = os.path.join(folder, "report_%d.json" % seed)
            cli, _ = median_seconds(lambda: run([args.ringid, "identify", "--dataset=" + path,
                                                 "--starts=1", "--output=" + report]), args.runs)
            with open(report) as f:
                fit = json.load(f)
            fitted = {n: fit["parameters"][n]["value"] for n in names}
            chi2 = 2 * fit["cost"]
            numpy_chi2 = np.sum(model.residuals(np.log([fitted[n] for n in names])) ** 2)
            if not abs(numpy_chi2 - chi2) <= 1e-6 * chi2:
                sys.exit("frf_vs_scipy: at ringid's fit the NumPy model's chi-square is %.10g, "
                         "ringid's %.10g" % (numpy_chi2, chi2))
            inside = None
            if module is not None:
                loaded = module.load_dataset(path)
                inside, _ = median_seconds(lambda: module.identify(loaded, starts=1), args.runs)

            scipy, out = median_seconds(lambda: least_squares(model.residuals, x0, method="trf"),
                                        args.runs)
            n = len(names)
            rows.append({
                "seed": seed, "ringid_seconds": fit["seconds"], "ringid_module": inside,
                "ringid_command": cli, "ringid_evaluations": fit["evaluations"],
                "ringid_chi2_dof": chi2 / dof, "ringid_converged": fit["converged"],
                "scipy_seconds": scipy, "scipy_evaluations": out.nfev + n * out.njev,
                "scipy_chi2_dof": 2 * out.cost / dof, "scipy_status": out.status,
                "scipy_per_evaluation": None})
            # One residual evaluation of the NumPy model, for the per-evaluation cost.
            each, _ = median_seconds(lambda: model.residuals(x0), 20)
            rows[-1]["scipy_per_evaluation"] = each

    print("standing hammer test (%s): 28 FRFs x 491 lines, 2 %% noise, %d free parameters, "
          "start %g %% off; %d cores, load average %s, numpy %s, median of %d runs"
          % (os.path.relpath(SPEC), len(names), 100 * START_OFF, os.cpu_count(),
             " ".join(open("/proc/loadavg").read().split()[:3]), np.__version__, args.runs))
    print("NumPy H at the truth against ringid's noise-free FRFs: %.2g (<= %g)" % (gap, CHECK_RELATIVE))
    head = ("%4s | %9s %6s %9s %9s %9s | %9s %6s %9s %6s %9s | %6s"
            % ("seed", "ringid s", "evals", "chi2/dof", "module s", "command s",
               "SciPy s", "evals", "chi2/dof", "status", "eval ms", "ratio"))
    print(head)
    print("-" * len(head))
    for r in rows:
        print("%4d | %9.4f %6d %9.4f %9s %9.4f | %9.4f %6d %9.4f %6d %9.3f | %6.1f"
              % (r["seed"], r["ringid_seconds"], r["ringid_evaluations"], r["ringid_chi2_dof"],
                 "-" if r["ringid_module"] is None else "%.4f" % r["ringid_module"],
                 r["ringid_command"], r["scipy_seconds"], r["scipy_evaluations"],
                 r["scipy_chi2_dof"], r["scipy_status"], 1e3 * r["scipy_per_evaluation"],
                 r["scipy_seconds"] / r["ringid_seconds"]))
    print("ringid s: identify's own seconds (one start, default derivatives: the fit and the "
          "analysis after it);\n  module s: ringid.identify in this process; command s: the "
          "whole `ringid identify` process.")
    print("SciPy s: least_squares(method='trf'), '2-point' differences, on the NumPy model; "
          "evals: its residual\n  calls, each Jacobian %d more; eval ms: one NumPy residual "
          "evaluation; ratio: SciPy s / ringid s." % len(names))


if __name__ == "__main__":
    main()
