// Speed of one model evaluation against the bare Eigen eigen-solution of the
// same blocks, and of LM fits with numeric and analytic derivatives side by
// side. Targets: evaluation <= 1.2x the bare solve;
// in-plane fit with analytic derivatives <= 1 ms; the three-condition joint
// fit <= 4x the standing one.
#include <cstdio>
#include <cstdlib>

#include <benchmark/benchmark.h>

#include <filesystem>
#include <fstream>
#include <memory>
#include <random>
#include <string>


#include "datasets/dataset.h"
#include "datasets/synthetic.h"
#include "estimation/identify.h"
#include "estimation/problem.h"
#include "estimation/uncertainty.h"
#include "model/frequency_response.h"
#include "model/rigid_ring_model.h"
#include "model/time_response.h"
#include "report/campaign_merge.h"
#include "validation/speed_cases.h"

namespace ringid {
namespace {

// The cases, defined once in validation/speed_cases.h (also measured by
// `ringid bench --suite=speed`); a case that does not load stops the run.
void Require(const Status& s) {
  if (!s.ok()) {
    std::fprintf(stderr, "ringid_benchmarks: %s\n", s.message.c_str());
    std::abort();
  }
}

Dataset Table1(bool in_plane_only) {
  Dataset d;
  Require(SpeedTable1(RINGID_SOURCE_DIR, in_plane_only, &d));
  return d;
}

Parameters PaperParameters() {
  Parameters p;
  Require(SpeedPaperParameters(RINGID_SOURCE_DIR, &p));
  return p;
}

// The example car tire measured at `speeds`, its sidewall and contact free
// (the rolling suite's problem).
Dataset CarTire(const std::vector<double>& speeds) {
  Dataset d;
  Require(SpeedCarTire(speeds, &d));
  return d;
}

void BM_ModelEvaluation(benchmark::State& state) {
  Parameters p = PaperParameters();
  const RigidRingModel model;
  int i = 0;
  for (auto _ : state) {
    NextSpeedPoint(&p, &i);  // a new point each time, as in a fit
    ModalSolution s = model.Solve(p);
    benchmark::DoNotOptimize(s);
  }
}
BENCHMARK(BM_ModelEvaluation)->Unit(benchmark::kMicrosecond);

// The floor: Eigen's EigenSolver, with eigenvectors, on the state matrices of
// the paper's three blocks (x_b, theta_a, theta_b; z_b; y_b, gamma_b, psi_b),
// in the matrix type the model uses (on the stack, up to 22 x 22); and the
// same without eigenvectors: the model takes its standing shapes from the
// pencil's null vectors (docs/model.md §8), so the part of an evaluation
// that is not Eigen's is the evaluation less this.
void BareEigen(benchmark::State& state, bool vectors) {
  const std::vector<SpeedBlock> blocks = BareEigenBlocks(PaperParameters());
  for (auto _ : state) benchmark::DoNotOptimize(BareEigenSolve(blocks, vectors));
}
void BM_BareEigenSolve(benchmark::State& state) { BareEigen(state, true); }
void BM_BareEigenValues(benchmark::State& state) { BareEigen(state, false); }
BENCHMARK(BM_BareEigenSolve)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_BareEigenValues)->Unit(benchmark::kMicrosecond);

// One model evaluation with the derivatives of every mode (analytic Jacobians).
void BM_ModelEvaluationWithDerivatives(benchmark::State& state) {
  Parameters p = PaperParameters();
  const RigidRingModel model;
  int i = 0;
  for (auto _ : state) {
    NextSpeedPoint(&p, &i);
    ModalSolution s = model.Solve(p, 0.0, true);
    benchmark::DoNotOptimize(s);
  }
}
BENCHMARK(BM_ModelEvaluationWithDerivatives)->Unit(benchmark::kMicrosecond);

// One start of identify on `d`, from a cold standstill cache each time, and its
// model evaluations.
void TimeOneStart(benchmark::State& state, const Dataset& d, Derivatives derivatives) {
  IdentifyOptions o;
  o.starts = 1;
  o.residuals.derivatives = derivatives;
  for (auto _ : state) {
    const RigidRingModel model;
    IdentifyResult s;
    Identify(model, d, o, &s);
    if (!s.status.ok()) state.SkipWithError("fit failed");
    state.counters["evaluations"] = static_cast<double>(s.evaluations);
    benchmark::DoNotOptimize(s);
  }
}

void Fit(benchmark::State& state, bool in_plane_only, Derivatives derivatives) {
  TimeOneStart(state, Table1(in_plane_only), derivatives);
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
    NextSpeedPoint(&p, &i);
    ModalSolution s = model.Solve(p, 6.0);
    benchmark::DoNotOptimize(s);
  }
}
BENCHMARK(BM_ModelEvaluationRolling)->Unit(benchmark::kMicrosecond);

// Joint fits: the standing test alone (0), one drum speed alone (6), and
// standing with two drum speeds (0, 6, 12). Target: the last <= 4x the first.
void BM_JointFit(benchmark::State& state, std::vector<double> speeds, Derivatives derivatives) {
  TimeOneStart(state, CarTire(speeds), derivatives);
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

// Issue 23: the forces of three speeds, five orders and five channels with
// the parameters' covariance (std_total). Target: <= 0.1 s.
void BM_Forces(benchmark::State& state) {
  ForceParameters parameters;
  ResponseDataset data;
  if (!SpeedForcesCase(&parameters, &data).ok()) state.SkipWithError("the case failed");
  const RigidRingModel model;
  for (auto _ : state) {
    ForcesResult r;
    EstimateForces(model, parameters, data, ForcesOptions{}, &r);
    if (!r.status.ok()) state.SkipWithError("forces failed");
    benchmark::DoNotOptimize(r);
  }
}
BENCHMARK(BM_Forces)->Unit(benchmark::kMillisecond);

// Issue 36: the standing hammer test of benchmarks/frf_vs_scipy.py (28 FRFs x
// 491 lines, 2 % noise, masses free), every free parameter 15 % off the
// truth, up and down in turn.
Dataset HammerFrfs() {
  const Parameters truth = ExampleCarTire();
  std::mt19937_64 rng(1);
  Dataset d = PlanSimulation(truth, 0.15, {0}, {}, &rng);
  FreeMasses(truth, 0.15, &rng, &d);
  d.conditions[0].frf = HammerTest();
  SimulateOptions so;
  so.modes = false;
  std::string why;
  if (!Simulate(RigidRingModel(), truth, so, &rng, &d, &why)) {
    std::fprintf(stderr, "ringid_benchmarks: %s\n", why.c_str());
    std::abort();
  }
  int k = 0;
  for (auto& [q, v] : d.initial) v = truth[q] * (k++ % 2 ? 0.85 : 1.15);
  return d;
}

std::unique_ptr<Problem> HammerProblem(Derivatives derivatives) {
  ResidualOptions o;
  o.derivatives = derivatives;
  Status status;
  auto problem = Problem::Create(RigidRingModel(), HammerFrfs(), o, &status);
  Require(status);
  return problem;
}

// The model's H alone: 28 functions at 491 lines.
void BM_FrfModel(benchmark::State& state) {
  const Dataset d = HammerFrfs();
  const Frf& frf = *d.conditions[0].frf;
  ResponseRequest request;
  const auto on_rim = [](const std::optional<FrfPoint>& p) { return p && p->on == FrfBody::kRim; };
  for (const FrfInput& in : frf.inputs) {
    request.inputs.push_back(
        {in.contact, {in.coordinates.begin(), in.coordinates.end()}, on_rim(in.point)});
  }
  for (const FrfOutput& out : frf.outputs) {
    request.outputs.push_back({out.channel, {out.coordinates.begin(), out.coordinates.end()},
                               static_cast<int>(out.quantity), on_rim(out.point)});
  }
  for (const FrfFunction& f : frf.functions) request.pairs.push_back({f.output, f.input});
  request.frequencies_hz = frf.frequencies_hz;
  Parameters p = ExampleCarTire();
  const RigidRingModel model;
  int i = 0;
  for (auto _ : state) {
    NextSpeedPoint(&p, &i);
    const ResponseResult r = FrequencyResponse(model, p, 0, request);
    if (!r.ok) state.SkipWithError(r.error.c_str());
    benchmark::DoNotOptimize(r.H.data());
  }
}
BENCHMARK(BM_FrfModel)->Unit(benchmark::kMicrosecond);

// The car tire over a 15 mm x 20 mm cleat at 15 m/s, 1000 samples at 2 kHz
// (0.5 s): the cam's inputs on the 1 mm grid (7,500 steps) and the response.
void BM_CleatResponse(benchmark::State& state) {
  ObstacleRun run;
  run.speed_m_s = 15;
  run.profile.height_m = 0.015;
  run.profile.length_m = 0.02;
  run.cam = {0.12, 0.30, 1.8, 0.10};
  run.position_at_t0_m = -0.3;
  for (int k = 0; k < 1000; ++k) run.times_s.push_back(k / 2000.0);
  const RigidRingModel model;
  const Parameters p = ExampleCarTire();
  ObstacleResult r;
  std::string why;
  for (auto _ : state) {
    if (!ObstacleResponse(model, p, run, &r, &why)) state.SkipWithError(why.c_str());
    benchmark::DoNotOptimize(r.y.data());
  }
}
BENCHMARK(BM_CleatResponse)->Unit(benchmark::kMillisecond);

// One evaluation of the weighted residuals (27,496 rows), as a fit makes it.
void BM_FrfResiduals(benchmark::State& state) {
  const auto problem = HammerProblem(Derivatives::kNumeric);
  Eigen::VectorXd x = problem->start(), r(problem->num_residuals());
  int i = 0;
  for (auto _ : state) {
    x[i++ % x.size()] += 1e-9;  // a new point each time
    if (!problem->residuals().Evaluate(x.data(), r.data())) state.SkipWithError("no residuals");
    benchmark::DoNotOptimize(r.data());
  }
}
BENCHMARK(BM_FrfResiduals)->Unit(benchmark::kMicrosecond);

// One Jacobian (27,496 x 19) as the fit evaluates it: numeric (central
// differences, the default) and exact.
void BM_FrfJacobian(benchmark::State& state, Derivatives derivatives) {
  const auto problem = HammerProblem(derivatives);
  Eigen::VectorXd x = problem->start();
  Eigen::MatrixXd J;
  int i = 0;
  for (auto _ : state) {
    x[i++ % x.size()] += 1e-9;
    if (!internal::EvaluateJacobian(problem->residuals(), x, &J)) state.SkipWithError("no J");
    benchmark::DoNotOptimize(J.data());
  }
}
BENCHMARK_CAPTURE(BM_FrfJacobian, numeric, Derivatives::kNumeric)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_FrfJacobian, analytic, Derivatives::kAnalytic)->Unit(benchmark::kMillisecond);

// Identify with one start from 15 % off: numeric derivatives (the default)
// and exact.
void BM_FrfFit(benchmark::State& state, Derivatives derivatives) {
  TimeOneStart(state, HammerFrfs(), derivatives);
}
BENCHMARK_CAPTURE(BM_FrfFit, numeric, Derivatives::kNumeric)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_FrfFit, analytic, Derivatives::kAnalytic)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace ringid

namespace ringid {

// `ringid merge` of a campaign of 10,000 identified datasets in 4 shard
// summaries (each row with its 14 fitted values): reading, checking, writing
// nothing (MergeShards alone).
static void BM_CampaignMerge(benchmark::State& state) {
  const int n = 10000, shards = 4;
  const std::string dir = std::filesystem::temp_directory_path() / "ringid_bench_merge";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  std::vector<std::string> all;
  for (int i = 0; i < n; ++i) all.push_back("data/tire" + std::to_string(i) + ".json");
  const Parameters p = ExampleCarTire();
  for (int k = 0; k < shards; ++k) {
    CampaignReport r;
    r.body.shard = std::to_string(k) + "/" + std::to_string(shards);
    r.body.campaign_datasets = all;
    r.body.options = {"method=lm", "starts=6"};
    for (int i = k; i < n; i += shards) {
      CampaignRow row;
      row.dataset = all[i];
      row.report_file = "out/tire" + std::to_string(i) + ".json";
      row.status = Status::Success("converged");
      row.converged = true;
      row.cost = 10 + i % 7;
      row.relative_error_in_plane_eq19 = row.relative_error_out_of_plane_eq20 = 1e-8;
      row.seconds = 0.1;
      std::map<Param, double> values;
      for (Param q : {Param::k_bx, Param::k_btheta, Param::c_bx, Param::c_btheta, Param::K_cx,
                      Param::sigma_cx, Param::k_cz, Param::k_by, Param::k_bgamma, Param::c_by,
                      Param::c_bgamma, Param::K_cy, Param::sigma_cy, Param::t_0}) {
        values[q] = p[q] * (1 + 1e-3 * (i % 11));
      }
      row.parameters = values;
      r.body.datasets.push_back(row);
    }
    std::ofstream(dir + "/campaign." + std::to_string(k) + "-of-" + std::to_string(shards) +
                  ".json") << ReportText(r);
  }
  for (auto _ : state) {
    CampaignReport merged;
    std::string error;
    if (!MergeShards(dir, &merged, &error)) state.SkipWithError(error.c_str());
    benchmark::DoNotOptimize(merged.body.datasets.size());
  }
  std::filesystem::remove_all(dir);
}
BENCHMARK(BM_CampaignMerge)->Unit(benchmark::kMillisecond);

}  // namespace ringid

BENCHMARK_MAIN();
