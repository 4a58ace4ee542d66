#!/usr/bin/env python3
"""The fit of `ringid identify --starts=1 --method=lm`, in NumPy/SciPy.

A reimplementation for issue 13's speed comparison: the same free parameters,
coordinates, box, residuals, weights and modal solution as ringid with its
default options, minimised by scipy.optimize.least_squares (method 'trf',
bounded) instead of Ceres' Levenberg-Marquardt. Each function below names the
C++ source and the equation of docs/model.md it transcribes.

Modes:
  scipy_identify.py DATASET
      fit and print one JSON line: times, iterations, evaluations, final cost,
      fitted values.
  scipy_identify.py --check-predict PARAMETERS --ringid BINARY
      assert that this model reproduces `ringid predict --parameters=...`:
      the same labels, frequencies and damping ratios to 1e-9 relative.
  scipy_identify.py DATASET --check-identify --ringid BINARY
      run `ringid identify --starts=1 --output=...`; at ringid's fitted values
      compare this model's frequencies with the report's and this Jacobian's
      singular values with the report's; fit here and have ringid predict at
      this fit's values. Prints the costs and how far apart the values are.

What it does NOT do (and ringid's whole process does): the uncertainty and
identifiability analysis after the fit, the plausibility checks, the report.
Only what the fit itself needs is here: format-1 datasets (one standing
condition), the baseline model (no --effects), frequency weighting 'sigma',
the 'contract' shape convention, no priors (format 1 has none and ringid's
prior_sigma defaults to 0). Anything outside that is refused, not ignored.

Differences, by necessity or choice:
* Solver: Ceres LM (DENSE_QR, Jacobi scaling, projected bounds) against
  least_squares 'trf' (trust-region reflective, the default here, x_scale 1)
  or 'dogbox'. Ceres' tolerances and iteration limit are mapped onto
  ftol/xtol/gtol/max_nfev (see fit()). 'lm' (MINPACK) cannot run this fit.
* Jacobian: the same central differences and step rule as ringid (see
  ceres_central_jacobian), minus ringid's one extra r(x) per Jacobian.
* Eigen-solver: LAPACK dgeev, which balances A, against Eigen's EigenSolver,
  which does not. dgeev's frequencies are the more accurate ones; the two
  differ by up to a few 1e-10 relative (--check-predict prints by how much).
* Failure: where the model cannot be solved the residuals are NaN, which
  makes least_squares shrink its step as a failed Ceres evaluation does.
* Uniqueness: a dataset with fewer residuals than free parameters (Table 1:
  7 for 16) has a manifold of zero-cost fits, and two different solvers stop
  at different points of it. Only the cost is then comparable, and that each
  fit's values give zero cost in the other's model (--check-identify).
"""
import time

T_START = time.perf_counter()

import argparse  # noqa: E402
import json  # noqa: E402
import math  # noqa: E402
import os  # noqa: E402
import subprocess  # noqa: E402
import sys  # noqa: E402
import tempfile  # noqa: E402

import numpy as np  # noqa: E402
from scipy.optimize import least_squares  # noqa: E402

T_IMPORTED = time.perf_counter()

# ---------------------------------------------------------------------------
# Names: model/parameters.h (RINGID_PARAMETERS, in enum order), model/names.h.

# The baseline parameters, every one of Domain kPositive (so every free one
# moves in log space, estimation/setup.cc ToCoordinate). The effect group
# (m_a, dk_bz, ...) is not implemented here.
PARAMS = ["m_b", "I_ay", "I_by", "I_bx", "I_bz", "F_cz0",
          "c_bx", "c_bz", "c_btheta", "k_bx", "k_bz", "k_btheta", "K_cx", "sigma_cx", "r_e0",
          "k_cz",
          "c_by", "c_bgamma", "c_bpsi", "k_by", "k_bgamma", "k_bpsi", "K_cy", "sigma_cy", "r_l0",
          "t_0"]
EFFECT_PARAMS = ["m_a", "dk_bz", "dk_bpsi", "s_h", "k_cpsi", "k_atheta", "dm", "k_xy"]

# enum Dof: x_b z_b theta_a theta_b | y_b gamma_b psi_b | x_a z_a y_a
DOFS = ["x_b", "z_b", "theta_a", "theta_b", "y_b", "gamma_b", "psi_b", "x_a", "z_a", "y_a"]
XB, ZB, THA, THB, YB, GB, PB, XA, ZA, YA = range(10)
NDOF = 10
# The baseline's active degrees of freedom (model/system.h BasicSystem()):
# the seven belt and rim ones; the hub is held rigid.
ACTIVE = list(range(PB + 1))

# enum ModeLabel and its home degree of freedom (model/names.cc kLabelHomes).
LABELS = ["rotation_in_phase", "rotation_anti_phase", "vertical", "longitudinal",
          "camber", "yaw", "lateral", "hub_longitudinal", "hub_vertical", "hub_lateral"]
ROT_IN, ROT_ANTI, VERTICAL, LONGITUDINAL, CAMBER, YAW, LATERAL = range(7)
LABEL_HOME = [THA, THB, ZB, XB, GB, PB, YB, XA, ZA, YA]
NLABEL = 10

# estimation/identify.h IdentifyOptions and estimation/residuals.h
# ResidualOptions, their defaults.
BOUND_FACTOR = 1e3
MAX_ITERATIONS = 200
RELATIVE_SIGMA = 0.01
DEFAULT_DAMPING_SIGMA = 0.02
DEFAULT_SHAPE_SIGMA = 0.05
# estimation/residual_costs.cc CarriedDifferences: NumericDiffOptions.relative_step_size.
RELATIVE_STEP = 1e-4


# ---------------------------------------------------------------------------
# The mechanical system: model/system.h BasicSystem, element by element.

class System:
    def __init__(self):
        self.M = np.zeros((NDOF, NDOF))
        self.C = np.zeros((NDOF, NDOF))
        self.K = np.zeros((NDOF, NDOF))
        self.K_label = np.zeros((NLABEL, NDOF, NDOF))  # stiffness each label owns

    def add_mass(self, dof, m):
        self.M[dof, dof] += m

    def add_stiffness(self, owner, row, col, v):
        self.K[row, col] += v
        if owner is not None:
            self.K_label[owner, row, col] += v

    def add_spring(self, owner, k, d):
        """A spring k on the deformation d = sum c_i q_i adds k d d^T."""
        for a, ca in d:
            for b, cb in d:
                self.add_stiffness(owner, a, b, k * ca * cb)

    def add_damper(self, c, d):
        for a, ca in d:
            for b, cb in d:
                self.C[a, b] += c * ca * cb

    def add_slip_lag(self, owner, stiffness, relaxation_length, force, velocity):
        """At standstill the slip lag is the stiffness (K_c / sigma_c) f d^T
        (system.h AddSlipLag); its states enter only at speed (not here)."""
        k = stiffness / relaxation_length
        for a, fa in force:
            for b, db in velocity:
                self.add_stiffness(owner, a, b, k * fa * db)


def assemble(p):
    """model/rigid_ring_model.cc AssembleAny at speed 0, no effects:
    eq. (12) in-plane and eq. (15) out-of-plane as corrected (docs/model.md
    section 7, elements 1-21)."""
    s = System()
    # In-plane, eq. (12): q = [x_b, z_b, theta_a, theta_b]; the sidewall acts
    # on belt minus hub (eqs. 1, 3).
    s.add_mass(XB, p["m_b"])
    s.add_mass(ZB, p["m_b"])
    s.add_mass(THA, p["I_ay"])
    s.add_mass(THB, p["I_by"])
    s.add_damper(p["c_bx"], [(XB, 1), (XA, -1)])
    s.add_damper(p["c_bz"], [(ZB, 1), (ZA, -1)])
    s.add_damper(p["c_btheta"], [(THB, 1), (THA, -1)])
    s.add_spring(ROT_IN, p["k_bx"], [(XB, 1), (XA, -1)])
    s.add_spring(VERTICAL, p["k_bz"], [(ZB, 1), (ZA, -1)])
    s.add_spring(VERTICAL, p["k_cz"], [(ZB, 1)])
    s.add_spring(ROT_ANTI, p["k_btheta"], [(THB, 1), (THA, -1)])
    # Contact slip, eqs. (6), (8): K_cx / sigma_cx on x_b - r_e0 theta_b.
    slip_x = [(XB, 1), (THB, -p["r_e0"])]
    s.add_slip_lag(LONGITUDINAL, p["K_cx"], p["sigma_cx"], slip_x, slip_x)
    # Out-of-plane, eq. (15) as corrected: q = [y_b, gamma_b, psi_b].
    s.add_mass(YB, p["m_b"])
    s.add_mass(GB, p["I_bx"])
    s.add_mass(PB, p["I_bz"])
    s.add_damper(p["c_by"], [(YB, 1), (YA, -1)])
    s.add_damper(p["c_bgamma"], [(GB, 1)])
    s.add_damper(p["c_bpsi"], [(PB, 1)])
    r_l0 = p["r_l0"]
    s.add_spring(LATERAL, p["k_by"], [(YB, 1), (YA, -1)])
    s.add_spring(CAMBER, p["k_bgamma"] + r_l0 * p["F_cz0"], [(GB, 1)])
    s.add_spring(YAW, p["k_bpsi"], [(PB, 1)])
    # Lateral slip: force on y_b, on camber through r_l0, on yaw through the
    # trail t_0; the standing slip sees y_b - r_l0 gamma_b. This gives S of
    # eq. (15), unsymmetric on purpose (docs/model.md section 6).
    s.add_slip_lag(LATERAL, p["K_cy"], p["sigma_cy"],
                   [(YB, 1), (GB, -r_l0), (PB, -p["t_0"])],
                   [(YB, 1), (GB, -r_l0)])
    return s


# ---------------------------------------------------------------------------
# Labels: model/assignment.cc AssignMaxScore, line by line.

def assign_max_score(score):
    """One-to-one rows -> columns maximising the summed score; -1 where none."""
    rows, cols = score.shape
    result = [-1] * rows
    if rows == 0 or rows > cols or cols > 16:
        return result
    # Shortcut: every row's best column distinct is the answer.
    used = 0
    for row in range(rows):
        c_best = -1
        for c in range(cols):
            if score[row, c] > -math.inf and (c_best < 0 or score[row, c] > score[row, c_best]):
                c_best = c
        if c_best < 0 or (used & (1 << c_best)):
            break
        used |= 1 << c_best
        result[row] = c_best
        if row == rows - 1:
            return result
    result = [-1] * rows
    # best[mask]: best total of the first popcount(mask) rows on columns mask.
    n = 1 << cols
    best = [-math.inf] * n
    choice = [-1] * n
    best[0] = 0.0
    for mask in range(n):
        if best[mask] == -math.inf:
            continue
        row = bin(mask).count("1")
        if row >= rows:
            continue
        for c in range(cols):
            if mask & (1 << c):
                continue
            nxt = mask | (1 << c)
            v = best[mask] + score[row, c]
            if v > best[nxt]:
                best[nxt] = v
                choice[nxt] = c
    best_mask = -1
    for mask in range(n):
        if bin(mask).count("1") != rows or best[mask] == -math.inf:
            continue
        if best_mask < 0 or best[mask] > best[best_mask]:
            best_mask = mask
    if best_mask < 0:
        return result
    mask = best_mask
    for row in range(rows - 1, -1, -1):
        result[row] = choice[mask]
        mask &= ~(1 << choice[mask])
    return result


# ---------------------------------------------------------------------------
# The modal solution: model/modal.cc SolveModes and SolveBlock, standing.

class Mode:
    __slots__ = ("label", "eigenvalue", "frequency_hz", "damping_ratio", "energy", "shape")


class ModelError(Exception):
    pass


def solve_block(s, dofs, modes):
    k = len(dofs)
    ix = np.ix_(dofs, dofs)
    M, C, K = s.M[ix], s.C[ix], s.K[ix]
    Minv = np.linalg.inv(M)
    # Eq. (13): A = [[0, I], [-M^-1 K, -M^-1 C]] (eq. (17) alike for N, D, S).
    A = np.zeros((2 * k, 2 * k))
    A[:k, k:] = np.eye(k)
    A[k:, :k] = -Minv @ K
    A[k:, k:] = -Minv @ C
    if not np.isfinite(A).all():
        raise ModelError("state matrix is not finite")
    # LAPACK dgeev here, Eigen's EigenSolver in ringid: the same eigenvalues
    # to rounding; the eigenvector scaling differs but nothing below depends
    # on it (shapes are divided by their largest entry, energies use Y = V^-1).
    lam, V = np.linalg.eig(A)
    if not (np.isfinite(lam).all() and np.isfinite(V).all()):
        raise ModelError("eigen-solution is not finite")
    # Keep one root of each oscillating pair: Im > 1e-10 max(1, |lambda|).
    # Real roots are overdamped motion, not modes.
    keep = np.nonzero(lam.imag > 1e-10 * np.maximum(1.0, np.abs(lam)))[0]
    lam_k = lam[keep]
    v = V[:k, keep]  # displacement halves, one column per kept mode
    # Rows of Y = V^-1 are the left eigenvectors, scaled so that Y V = I; for
    # w^T (lambda^2 M + lambda C + K) = 0, w = M^-T y2 (docs/model.md section 9).
    try:
        Y = np.linalg.inv(V)
        have_left = bool(np.isfinite(Y).all())
    except np.linalg.LinAlgError:
        have_left = False
    w = Minv.T @ Y[keep, k:].T if have_left else np.conj(v)
    # The labels the block offers: those whose home lies in it.
    labels = [l for l in range(NLABEL) if LABEL_HOME[l] in dofs]
    K_l = s.K_label[labels][(slice(None),) + ix]           # (labels, k, k)
    # Stiffness no label of the block owns counts in the total only.
    rest = K - K_l.sum(axis=0)
    # Energy shares e_l = |w^T K_l v| / (sum_l e_l + |w^T K_rest v|).
    e = np.abs(np.einsum("aj,lab,bj->jl", w, K_l, v))      # (modes, labels)
    total = e.sum(axis=1) + np.abs(np.einsum("aj,ab,bj->j", w, rest, v))
    total[~((total > 0) & np.isfinite(total))] = 1.0
    share = e / total[:, None]
    # One-to-one labels maximising the product of energy shares.
    pick = assign_max_score(np.log(np.maximum(share, 1e-300)))
    for i, j in enumerate(keep):
        if pick[i] < 0:
            raise ModelError("could not label the modes of a block")
        z = lam_k[i]
        m = Mode()
        m.label = labels[pick[i]]
        m.eigenvalue = z
        m.frequency_hz = z.imag / (2 * math.pi)  # damped frequency, docs/model.md section 8
        m.damping_ratio = -z.real / abs(z)
        m.energy = np.zeros(NLABEL)
        m.energy[labels] = share[i]
        # The shape: v over its largest-magnitude entry (the first such).
        big = int(np.argmax(np.abs(v[:, i])))
        m.shape = np.zeros(NDOF, dtype=complex)
        m.shape[dofs] = v[:, i] / v[big, i]
        modes.append(m)


def solve_modes(s):
    """Checks, then blocks = connected components of the coupling graph of
    M, C and K on the active degrees of freedom; modes sorted by frequency."""
    act = np.ix_(ACTIVE, ACTIVE)
    finite = np.isfinite(s.M[act]) & np.isfinite(s.C[act]) & np.isfinite(s.K[act])
    for a in ACTIVE:
        if not finite[a].all():
            raise ModelError("system matrices are not finite at " + DOFS[a])
        if not (s.M[a, a] > 0):
            raise ModelError("mass matrix is singular: no positive mass on " + DOFS[a])
    parent = list(range(NDOF))

    def root(i):
        while parent[i] != i:
            parent[i] = parent[parent[i]]
            i = parent[i]
        return i

    coupled = (s.M[act] != 0) | (s.C[act] != 0) | (s.K[act] != 0)
    for a, b in zip(*np.nonzero(coupled)):
        if a != b:
            parent[root(ACTIVE[a])] = root(ACTIVE[b])
    modes = []
    for r in ACTIVE:
        if root(r) != r:
            continue
        solve_block(s, [a for a in ACTIVE if root(a) == r], modes)
    modes.sort(key=lambda m: m.frequency_hz)
    return modes


def solve(p):
    for q in PARAMS:
        if not math.isfinite(p[q]):
            raise ModelError("parameter %s is not finite" % q)
    return solve_modes(assemble(p))


# ---------------------------------------------------------------------------
# The dataset (format 1, docs/conventions.md section 3) and the parameter
# setup: estimation/setup.cc ParameterSetup::Build, datasets/dataset.cc
# InitialParameters.

def load_dataset(path):
    with open(path) as f:
        d = json.load(f)
    if d.get("format") != "ringid-modal-dataset/1":
        sys.exit("scipy_identify.py: only format ringid-modal-dataset/1 (one standing "
                 "condition) is implemented, not %r" % d.get("format"))
    known, initial, ties = d.get("known", {}), d.get("initial", {}), d.get("ties", {})
    for name in list(known) + list(initial) + list(ties) + list(ties.values()):
        if name not in PARAMS:
            sys.exit("scipy_identify.py: parameter %r: effect parameters are not "
                     "implemented here" % name)
    start = dict(known)
    start.update(initial)
    for frm, to in ties.items():
        start[frm] = start[to]
    # Free: every baseline parameter neither known nor tied, in enum order.
    free = [q for q in PARAMS if q not in known and q not in ties]
    for q in free:
        if q not in start:
            sys.exit("scipy_identify.py: free parameter %s has no value" % q)
    modes = []
    for m in d["modes"]:
        shape = [(DOFS.index(k), v) for k, v in m.get("shape", {}).items()]
        modes.append({
            "label": LABELS.index(m["label"]),
            "frequency_hz": m["frequency_hz"],
            # ResidualOptions: FrequencyWeighting::kSigma; relative_sigma * f
            # where no sigma is given (residuals.cc FrequencySigma).
            "frequency_sigma": m.get("frequency_sigma_hz", RELATIVE_SIGMA * m["frequency_hz"]),
            "damping_ratio": m.get("damping_ratio"),
            "damping_sigma": m.get("damping_sigma", DEFAULT_DAMPING_SIGMA),
            "shape": shape,
            "shape_sigma": m.get("shape_sigma", DEFAULT_SHAPE_SIGMA),
        })
    return {"name": d["name"], "start": start, "free": free, "ties": ties, "modes": modes}


def decode(ds, x):
    """Coordinates -> parameters: exp of the log coordinate, then the ties."""
    p = dict(ds["start"])
    for q, xi in zip(ds["free"], x):
        p[q] = math.exp(xi)
    for frm, to in ds["ties"].items():
        p[frm] = p[to]
    return p


# ---------------------------------------------------------------------------
# Residuals: estimation/residuals.cc ModalResiduals (one condition, no priors).

def mac(u, measured):
    mm = uu = mu = 0.0
    for dof, v in measured:
        mm += v * v
        uu += u[dof] * u[dof]
        mu += u[dof] * v
    if not (mm > 0) or not (uu > 0):
        return 0.0
    return mu * mu / (mm * uu)


def pair(ds, modes):
    """PairCondition: measured shapes pair by MAC (one-to-one), the rest by
    label. Never by frequency order."""
    measured = ds["modes"]
    pairs = [-1] * len(measured)
    shaped = [i for i, m in enumerate(measured) if m["shape"]]
    if shaped:
        if len(shaped) > len(modes):
            raise ModelError("fewer model modes than measured shapes")
        score = np.array([[mac(mo.shape.real, measured[i]["shape"]) for mo in modes]
                          for i in shaped])
        pick = assign_max_score(score)
        for a, i in enumerate(shaped):
            pairs[i] = pick[a]
    for i, m in enumerate(measured):
        if pairs[i] >= 0:
            continue
        for b, mo in enumerate(modes):
            if mo.label == m["label"]:
                pairs[i] = b
        if pairs[i] < 0:
            raise ModelError("the model has no oscillating %s mode" % LABELS[m["label"]])
    return pairs


class Residuals:
    def __init__(self, ds):
        self.ds = ds
        self.solutions = 0  # model solutions, as ringid's 'evaluations'
        self.failures = 0

    def __call__(self, x):
        """r(x), or NaNs where the model cannot be solved (ringid returns
        false: Ceres rejects the step; least_squares' trf shrinks its trust
        region on non-finite residuals, the same effect)."""
        self.solutions += 1
        try:
            return self.evaluate(decode(self.ds, x))
        except ModelError:
            self.failures += 1
            return np.full(self.size(), np.nan)

    def size(self):
        n = 0
        for m in self.ds["modes"]:
            n += 1 + (m["damping_ratio"] is not None) + len(m["shape"])
        return n

    def evaluate(self, p):
        modes = solve(p)
        pairs = pair(self.ds, modes)
        r = []
        for i, m in enumerate(self.ds["modes"]):
            mode = modes[pairs[i]]
            r.append((mode.frequency_hz - m["frequency_hz"]) / m["frequency_sigma"])
            if m["damping_ratio"] is not None:
                r.append((mode.damping_ratio - m["damping_ratio"]) / m["damping_sigma"])
            if m["shape"]:
                # Contract convention (Mode::RealShape): the real part of the
                # shape scaled to a largest entry of 1; the model shape is
                # fitted by least squares onto the measured one scaled to 1.
                u = mode.shape.real
                largest = max(abs(v) for _, v in m["shape"])
                uu = sum(u[dof] ** 2 for dof, _ in m["shape"])
                um = sum(u[dof] * v / largest for dof, v in m["shape"])
                alpha = um / uu if uu > 0 else 0.0
                for dof, v in m["shape"]:
                    r.append((alpha * u[dof] - v / largest) / m["shape_sigma"])
        r = np.array(r)
        if not np.all(np.isfinite(r)):
            raise ModelError("residuals are not finite")
        return r


def ceres_central_jacobian(res):
    """ceres::DynamicNumericDiffCostFunction<..., CENTRAL> with
    relative_step_size 1e-4 (residual_costs.cc): step max(sqrt(eps), 1e-4 |x_j|),
    (r(x + h e_j) - r(x - h e_j)) / 2h, no regard for the bounds. Ceres also
    evaluates r(x) once per Jacobian; least_squares has it already, so this
    saves one model solution per iteration over ringid."""
    min_step = math.sqrt(np.finfo(float).eps)

    def jac(x, *args):
        J = np.empty((res.size(), len(x)))
        for j in range(len(x)):
            h = max(min_step, abs(x[j]) * RELATIVE_STEP)
            xp = x.copy()
            xp[j] += h
            xm = x.copy()
            xm[j] -= h
            J[:, j] = (res(xp) - res(xm)) / (2 * h)
        return J

    return jac


# ---------------------------------------------------------------------------
# The fit: estimation/identify.cc Identify with starts = 1, estimation/fit.cc
# BoundsAround and FitLevenbergMarquardt.

def fit(ds, args):
    res = Residuals(ds)
    x0 = np.array([math.log(ds["start"][q]) for q in ds["free"]])
    # BoundsAround: log coordinates within a factor bound_factor of x0.
    lo, hi = x0 - math.log(BOUND_FACTOR), x0 + math.log(BOUND_FACTOR)
    if args.jac == "ringid":
        jac, diff_step = ceres_central_jacobian(res), None
    else:  # SciPy's own central differences, step 1e-4 * max(1, |x|), kept in the box
        jac, diff_step = "3-point", RELATIVE_STEP
    t0 = time.perf_counter()
    # Ceres: function_tolerance 1e-14, gradient_tolerance 1e-14,
    # parameter_tolerance 1e-12, max_num_iterations 200 (fit.cc). One trf
    # trial step is one Ceres iteration (successful or not), so max_nfev
    # stands for the iteration limit. (method 'lm', MINPACK, would need at
    # least as many residuals as free parameters: Table 1 has 7 for 16, and
    # it takes no bounds.)
    out = least_squares(res, x0, jac=jac, bounds=(lo, hi), method=args.method,
                        diff_step=diff_step, x_scale=args.x_scale,
                        ftol=1e-14, xtol=1e-12, gtol=1e-14, max_nfev=args.max_nfev)
    seconds = time.perf_counter() - t0
    return out, res, seconds, (lo, hi)


def run_fit(args):
    ds = load_dataset(args.dataset)
    out, res, seconds, (lo, hi) = fit(ds, args)
    p = decode(ds, out.x)
    # Box::On: within 0.1 % of the box's width of a bound.
    on_bound = [q for q, xi, a, b in zip(ds["free"], out.x, lo, hi)
                if xi <= a + 1e-3 * (b - a) or xi >= b - 1e-3 * (b - a)]
    report = {
        "tool": "scipy.optimize.least_squares",
        "method": args.method,
        "jacobian": "ringid's central differences (step max(sqrt(eps), 1e-4 |x|))"
                    if args.jac == "ringid" else "scipy 3-point, diff_step 1e-4",
        "x_scale": args.x_scale,
        "max_nfev": args.max_nfev,
        "dataset": ds["name"],
        "fit_seconds": seconds,
        "import_seconds": T_IMPORTED - T_START,
        "process_seconds_so_far": time.perf_counter() - T_START,
        "status": int(out.status),
        "converged": int(out.status) > 0,
        "message": out.message,
        "nfev": int(out.nfev),
        "njev": int(out.njev) if out.njev is not None else None,
        "model_solutions": res.solutions,
        "failed_solutions": res.failures,
        "cost": float(out.cost),
        "parameters": {q: p[q] for q in PARAMS},
        "free": ds["free"],
        "on_bound": on_bound,
    }
    print(json.dumps(report))
    return report


# ---------------------------------------------------------------------------
# Equivalence checks against the ringid binary.

def load_parameter_values(path):
    """ringid-parameters/1: {"parameters": {name: {"value": v}}}."""
    with open(path) as f:
        d = json.load(f)
    return {q: v["value"] for q, v in d["parameters"].items() if q in PARAMS}


def run_ringid(binary, args):
    """Runs ringid with --output and returns its JSON report."""
    with tempfile.TemporaryDirectory() as tmp:
        out = os.path.join(tmp, "report.json")
        done = subprocess.run([binary] + args + ["--output=" + out],
                              stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        if done.returncode != 0:
            sys.exit("scipy_identify.py: %s %s failed (%d): %s"
                     % (binary, " ".join(args), done.returncode, done.stderr.strip()))
        with open(out) as f:
            return json.load(f)


def ringid_predict(binary, p):
    """ringid predict at the parameter values p: its modes, by label."""
    with tempfile.TemporaryDirectory() as tmp:
        path = os.path.join(tmp, "parameters.json")
        with open(path, "w") as f:
            json.dump({"format": "ringid-parameters/1", "name": "scipy_identify",
                       "parameters": {q: {"value": v} for q, v in p.items()}}, f)
        report = run_ringid(binary, ["predict", "--parameters=" + path])
    return {m["label"]: m for m in report["modes"]}


def check_predict(args):
    p = load_parameter_values(args.check_predict)
    mine = solve(p)
    theirs = ringid_predict(args.ringid, p)
    if sorted(theirs) != sorted(LABELS[m.label] for m in mine):
        sys.exit("check-predict: labels %s here, %s from ringid"
                 % (sorted(LABELS[m.label] for m in mine), sorted(theirs)))
    worst_f = worst_z = 0.0
    rows = []
    for a in mine:
        label = LABELS[a.label]
        b = theirs[label]
        rel_f = abs(a.frequency_hz - b["model_hz"]) / b["model_hz"]
        rel_z = abs(a.damping_ratio - b["damping_ratio"]) / b["damping_ratio"]
        worst_f, worst_z = max(worst_f, rel_f), max(worst_z, rel_z)
        rows.append({"label": label, "hz": a.frequency_hz, "ringid_hz": b["model_hz"],
                     "rel_diff_hz": rel_f, "rel_diff_zeta": rel_z})
    print(json.dumps({"check": "predict", "parameters": args.check_predict, "modes": rows,
                      "max_rel_diff_hz": worst_f, "max_rel_diff_zeta": worst_z}))
    assert worst_f <= 1e-9, "frequencies differ from ringid predict by %.3g relative" % worst_f
    assert worst_z <= 1e-9, "damping ratios differ from ringid predict by %.3g relative" % worst_z


def cost_from_ringid_modes(ds, modes):
    """1/2 sum of squared frequency residuals from ringid's own frequencies
    (Table 1 has neither damping nor shapes; refused otherwise)."""
    r = []
    for m in ds["modes"]:
        if m["damping_ratio"] is not None or m["shape"]:
            return None
        r.append((modes[LABELS[m["label"]]]["model_hz"] - m["frequency_hz"]) / m["frequency_sigma"])
    return 0.5 * sum(v * v for v in r)


def check_identify(args):
    """The same fit? ringid's fitted point must be a minimum of this script's
    cost, and this script's fitted point one of ringid's model. With more
    free parameters than residuals (Table 1: 16 for 7) the zero-cost points
    form a manifold, so the two solvers need not stop at the same values;
    their distance is reported, not asserted."""
    ds = load_dataset(args.dataset)
    report = run_ringid(args.ringid, ["identify", "--dataset=" + args.dataset, "--starts=1",
                                      "--method=lm"])
    ringid_cost = report["cost"]
    ringid_p = {q: e["value"] for q, e in report["parameters"].items() if q in PARAMS}
    # 1. This script's model, cost and Jacobian at ringid's fitted values:
    # frequencies against the report's model_hz, the Jacobian's singular
    # values against the report's (covariance.singular_values).
    here = {LABELS[m.label]: m.frequency_hz for m in solve(ringid_p)}
    rel_hz = max(abs(here[m["label"]] - m["model_hz"]) / m["model_hz"] for m in report["modes"])
    res = Residuals(ds)
    r = res.evaluate(ringid_p)
    cost_here = 0.5 * float(r @ r)
    x_ringid = np.array([math.log(ringid_p[q]) for q in ds["free"]])
    sv_here = np.linalg.svd(ceres_central_jacobian(res)(x_ringid), compute_uv=False)
    sv_ringid = np.array(report["covariance"]["singular_values"])
    rel_sv = float(np.max(np.abs(sv_here[:len(sv_ringid)] / sv_ringid - 1)))
    # 2. This script's fit, and ringid's model at its fitted values.
    out, res, seconds, _ = fit(ds, args)
    p = decode(ds, out.x)
    cost_ringid_at_scipy = cost_from_ringid_modes(ds, ringid_predict(args.ringid, p))
    log_ratio = {q: math.log(p[q] / ringid_p[q]) for q in ds["free"]}
    print(json.dumps({
        "check": "identify",
        "ringid_cost": ringid_cost,
        "ringid_converged": report["converged"],
        "ringid_evaluations": report["evaluations"],
        "cost_here_at_ringid_values": cost_here,
        "max_rel_diff_hz_at_ringid_values": rel_hz,
        "jacobian_singular_values_here": sv_here.tolist(),
        "jacobian_singular_values_ringid": sv_ringid.tolist(),
        "max_rel_diff_singular_values": rel_sv,
        "scipy_method": args.method,
        "scipy_cost": float(out.cost),
        "scipy_converged": int(out.status) > 0,
        "scipy_message": out.message,
        "scipy_nfev": int(out.nfev),
        "scipy_model_solutions": res.solutions,
        "ringid_model_cost_at_scipy_values": cost_ringid_at_scipy,
        "max_abs_log_ratio_scipy_over_ringid": max(abs(v) for v in log_ratio.values()),
        "log_ratio_scipy_over_ringid": log_ratio,
        "ringid_values": {q: ringid_p[q] for q in ds["free"]},
        "scipy_values": {q: p[q] for q in ds["free"]},
    }))


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("dataset", nargs="?", default="datasets/paper/table1.json")
    ap.add_argument("--method", choices=["trf", "dogbox"], default="trf",
                    help="least_squares method with bounds (default trf)")
    ap.add_argument("--jac", choices=["ringid", "3-point"], default="ringid",
                    help="ringid: Ceres' central differences as ringid sets them (default); "
                         "3-point: least_squares' own, diff_step 1e-4")
    ap.add_argument("--x-scale", dest="x_scale", default="1.0",
                    help="least_squares x_scale: a number (default 1.0) or jac")
    ap.add_argument("--max-nfev", dest="max_nfev", type=int, default=MAX_ITERATIONS,
                    help="least_squares max_nfev (default 200, ringid's iteration limit)")
    ap.add_argument("--check-predict", metavar="PARAMETERS",
                    help="assert this model reproduces ringid predict on PARAMETERS")
    ap.add_argument("--check-identify", action="store_true",
                    help="compare cost and fitted values with ringid identify --starts=1")
    ap.add_argument("--ringid", default="./build/ringid", help="the ringid binary for checks")
    args = ap.parse_args()
    if args.x_scale != "jac":
        args.x_scale = float(args.x_scale)
    if args.check_predict:
        check_predict(args)
    elif args.check_identify:
        check_identify(args)
    else:
        run_fit(args)


if __name__ == "__main__":
    main()
