// Speed of one model evaluation against the bare Eigen eigen-solution of the
// same blocks, and of LM fits with numeric and analytic derivatives side by
// side. Targets (README, issue 13): evaluation <= 1.2x the bare solve;
// in-plane fit with analytic derivatives <= 1 ms; the three-condition joint
// fit <= 4x the standing one.
#include <benchmark/benchmark.h>

#include <Eigen/Eigenvalues>

#include "datasets/dataset.h"
#include "datasets/synthetic.h"
#include "estimation/identify.h"
#include "model/rigid_ring_model.h"

namespace ringid {
namespace {

std::string Path(const char* f) { return std::string(RINGID_SOURCE_DIR) + "/" + f; }

Dataset Table1(bool in_plane_only) {
  Dataset d;
  LoadError e;
  if (!LoadDataset(Path("datasets/paper/table1.json"), &d, &e)) std::abort();
  if (in_plane_only) {
    std::vector<MeasuredMode> keep;
    for (const MeasuredMode& m : d.modes) {
      if (LabelPlane(m.label) == Plane::kInPlane) keep.push_back(m);
    }
    d.modes = keep;
    // Out-of-plane parameters do not move in-plane modes: hold them.
    for (auto it = d.initial.begin(); it != d.initial.end();) {
      if (Info(it->first).group == Group::kOutOfPlane) {
        d.known[it->first] = it->second;
        it = d.initial.erase(it);
      } else {
        ++it;
      }
    }
    for (auto it = d.ties.begin(); it != d.ties.end();) {
      if (Info(it->first).group == Group::kOutOfPlane) it = d.ties.erase(it);
      else ++it;
    }
    d.known[Param::c_bpsi] = d.known[Param::c_bgamma];
    d.known[Param::k_bpsi] = d.known[Param::k_bgamma];
  }
  return d;
}

Parameters PaperParameters() {
  Parameters p;
  LoadError e;
  if (!LoadParameterSet(Path("datasets/paper/parameters.json"), &p, &e)) std::abort();
  return p;
}

void BM_ModelEvaluation(benchmark::State& state) {
  Parameters p = PaperParameters();
  const RigidRingModel model;
  int i = 0;
  for (auto _ : state) {
    // A new point each time, as in a fit: the model's standstill cache
    // (64 points) never answers.
    p[Param::k_bx] *= 1 + (++i % 128 == 0 ? -127e-15 : 1e-15);
    ModalSolution s = model.Solve(p);
    benchmark::DoNotOptimize(s);
  }
}
BENCHMARK(BM_ModelEvaluation)->Unit(benchmark::kMicrosecond);

// The floor: Eigen's EigenSolver, with eigenvectors, on the state matrices of
// the paper's three blocks (x_b, theta_a, theta_b; z_b; y_b, gamma_b, psi_b),
// in the matrix type the model uses (on the stack, up to 22 x 22).
void BM_BareEigenSolve(benchmark::State& state) {
  using Mat = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 22, 22>;
  const MechanicalSystem s = RigidRingModel().Assemble(PaperParameters());
  std::vector<Mat> blocks;
  for (const std::vector<Dof>& dofs :
       {std::vector<Dof>{Dof::kXb, Dof::kThetaA, Dof::kThetaB}, std::vector<Dof>{Dof::kZb},
        std::vector<Dof>{Dof::kYb, Dof::kGammaB, Dof::kPsiB}}) {
    const int k = static_cast<int>(dofs.size());
    Eigen::MatrixXd M(k, k), C(k, k), K(k, k);
    for (int a = 0; a < k; ++a) {
      for (int b = 0; b < k; ++b) {
        M(a, b) = s.M()(static_cast<int>(dofs[a]), static_cast<int>(dofs[b]));
        C(a, b) = s.C()(static_cast<int>(dofs[a]), static_cast<int>(dofs[b]));
        K(a, b) = s.K()(static_cast<int>(dofs[a]), static_cast<int>(dofs[b]));
      }
    }
    // Balanced as the model balances it (model/modal.cc): velocities in
    // units of w, the power of two nearest the largest sqrt(K_aa / M_aa).
    double w2 = 0;
    for (int a = 0; a < k; ++a) w2 = std::max(w2, K(a, a) / M(a, a));
    const double w = std::exp2(std::round(0.5 * std::log2(w2)));
    Eigen::MatrixXd A = Eigen::MatrixXd::Zero(2 * k, 2 * k);
    A.topRightCorner(k, k).setIdentity() *= w;
    A.bottomLeftCorner(k, k) = -M.inverse() * K / w;
    A.bottomRightCorner(k, k) = -M.inverse() * C;
    blocks.push_back(A);
  }
  for (auto _ : state) {
    for (const Mat& A : blocks) {
      Eigen::EigenSolver<Mat> es(A, true);
      benchmark::DoNotOptimize(es.pseudoEigenvectors());
    }
  }
}
BENCHMARK(BM_BareEigenSolve)->Unit(benchmark::kMicrosecond);

// One model evaluation with the derivatives of every mode (analytic Jacobians).
void BM_ModelEvaluationWithDerivatives(benchmark::State& state) {
  Parameters p = PaperParameters();
  const RigidRingModel model;
  int i = 0;
  for (auto _ : state) {
    p[Param::k_bx] *= 1 + (++i % 128 == 0 ? -127e-15 : 1e-15);
    ModalSolution s = model.Solve(p, 0.0, true);
    benchmark::DoNotOptimize(s);
  }
}
BENCHMARK(BM_ModelEvaluationWithDerivatives)->Unit(benchmark::kMicrosecond);

void Fit(benchmark::State& state, bool in_plane_only, Derivatives derivatives) {
  const Dataset d = Table1(in_plane_only);
  IdentifyOptions o;
  o.starts = 1;
  o.residuals.derivatives = derivatives;
  for (auto _ : state) {
    const RigidRingModel model;  // a cold standstill cache
    IdentifySummary s;
    Identify(model, d, o, &s);
    if (!s.status.ok()) state.SkipWithError("fit failed");
    benchmark::DoNotOptimize(s);
  }
}
// Identify with one start: the LM fit and the uncertainty analysis after it.
BENCHMARK_CAPTURE(Fit, in_plane_numeric, true, Derivatives::kNumeric)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(Fit, in_plane_analytic, true, Derivatives::kAnalytic)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(Fit, both_planes_numeric, false, Derivatives::kNumeric)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(Fit, both_planes_analytic, false, Derivatives::kAnalytic)
    ->Unit(benchmark::kMillisecond);

void BM_ModelEvaluationRolling(benchmark::State& state) {
  Parameters p = ExampleCarTire();
  const RigidRingModel model;
  int i = 0;
  for (auto _ : state) {
    p[Param::k_bx] *= 1 + (++i % 128 == 0 ? -127e-15 : 1e-15);
    ModalSolution s = model.Solve(p, 6.0);
    benchmark::DoNotOptimize(s);
  }
}
BENCHMARK(BM_ModelEvaluationRolling)->Unit(benchmark::kMicrosecond);

// The example car tire measured at `speeds`, its sidewall and contact free
// (the rolling suite's problem).
Dataset CarTire(const std::vector<double>& speeds) {
  const Parameters truth = ExampleCarTire();
  Dataset d;
  d.name = "bench";
  d.format = 2;
  d.conditions.clear();
  for (double v : speeds) {
    Condition c;
    c.name = "v" + std::to_string(static_cast<int>(v));
    c.speed_m_s = v;
    d.conditions.push_back(c);
  }
  std::mt19937_64 rng(7);
  std::string error;
  if (!Simulate(RigidRingModel(), truth, SimulateOptions(), &rng, &d, &error)) std::abort();
  for (int i = 0; i < kNumParams; ++i) {
    if (Info(ParamAt(i)).group != Group::kEffect) d.known[ParamAt(i)] = truth[ParamAt(i)];
  }
  d.ties = {{Param::c_bz, Param::c_bx}, {Param::k_bz, Param::k_bx},
            {Param::c_bpsi, Param::c_bgamma}, {Param::k_bpsi, Param::k_bgamma}};
  for (const auto& [from, to] : d.ties) d.known.erase(from);
  for (Param p : {Param::c_bx, Param::c_btheta, Param::k_bx, Param::k_btheta, Param::K_cx,
                  Param::sigma_cx, Param::k_cz, Param::c_by, Param::c_bgamma, Param::k_by,
                  Param::k_bgamma, Param::K_cy, Param::sigma_cy, Param::t_0}) {
    d.known.erase(p);
    d.initial[p] = truth[p] * (IsDamping(p) ? 0.8 : 1.25);
  }
  return d;
}

// Joint fits: the standing test alone (0), one drum speed alone (6), and
// standing with two drum speeds (0, 6, 12). Target: the last <= 4x the first.
void BM_JointFit(benchmark::State& state, std::vector<double> speeds, Derivatives derivatives) {
  const Dataset d = CarTire(speeds);
  IdentifyOptions o;
  o.starts = 1;
  o.residuals.derivatives = derivatives;
  for (auto _ : state) {
    const RigidRingModel model;  // a cold standstill cache
    IdentifySummary s;
    Identify(model, d, o, &s);
    if (!s.status.ok()) state.SkipWithError("fit failed");
    benchmark::DoNotOptimize(s);
  }
}
BENCHMARK_CAPTURE(BM_JointFit, standing_numeric, std::vector<double>{0}, Derivatives::kNumeric)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_JointFit, drum_6_numeric, std::vector<double>{6}, Derivatives::kNumeric)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_JointFit, standing_drum_6_drum_12_numeric, std::vector<double>{0, 6, 12},
                  Derivatives::kNumeric)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_JointFit, standing_analytic, std::vector<double>{0}, Derivatives::kAnalytic)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_JointFit, drum_6_analytic, std::vector<double>{6}, Derivatives::kAnalytic)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_JointFit, standing_drum_6_drum_12_analytic, std::vector<double>{0, 6, 12},
                  Derivatives::kAnalytic)
    ->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace ringid

BENCHMARK_MAIN();
