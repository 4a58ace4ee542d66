// The speed suite: issue 13's speed figures timed in process with
// std::chrono::steady_clock, on the cases the Google Benchmark times
// (validation/speed_cases.h), numeric and analytic derivatives side by side.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "datasets/synthetic.h"
#include "estimation/identify.h"
#include "model/rigid_ring_model.h"
#include "validation/speed_cases.h"
#include "validation/suites.h"

namespace ringid {
namespace {

using Clock = std::chrono::steady_clock;

// Each call's result is read into this, so that the optimiser keeps the work.
volatile double g_sink = 0;

// `n` calls of one case in one mode; false when a call failed.
using Batch = std::function<bool(long n)>;

double Elapsed(Clock::time_point since) {
  return std::chrono::duration<double>(Clock::now() - since).count();
}

// The median seconds per call of each of `modes`. Each is calibrated to a
// number of calls per batch that takes o.speed_seconds_per_case /
// o.speed_batches; then the batches run in turn, one of each mode per round,
// so that a change in the machine's load falls on every mode alike (a ratio
// of two modes compares like with like).
Status TimeSideBySide(const char* what, const std::vector<Batch>& modes, const SuiteOptions& o,
                      std::vector<double>* medians) {
  const Status failed = Status::Failed(std::string(what) + ": a call failed");
  const double per_batch = o.speed_seconds_per_case / o.speed_batches;
  std::vector<long> calls;
  for (const Batch& batch : modes) {
    // Double the calls until a batch takes an eighth of its time (the first
    // call warms the caches), then scale.
    long n = 1;
    double t = 0;
    for (;;) {
      const auto start = Clock::now();
      if (!batch(n)) return failed;
      t = Elapsed(start);
      if (t >= per_batch / 8 || n >= (1L << 30)) break;
      n *= 2;
    }
    calls.push_back(std::max(1L, std::lround(std::ceil(n * per_batch / std::max(t, 1e-9)))));
  }
  std::vector<std::vector<double>> per_call(modes.size());
  for (int b = 0; b < o.speed_batches; ++b) {
    for (size_t m = 0; m < modes.size(); ++m) {
      const auto start = Clock::now();
      if (!modes[m](calls[m])) return failed;
      per_call[m].push_back(Elapsed(start) / static_cast<double>(calls[m]));
    }
  }
  medians->clear();
  for (std::vector<double>& t : per_call) {
    std::sort(t.begin(), t.end());
    const size_t k = t.size();
    medians->push_back(k % 2 ? t[k / 2] : 0.5 * (t[k / 2 - 1] + t[k / 2]));
  }
  return Status::Success();
}

// Model evaluations at `speed` from `p`, a new point each call as in a fit
// (NextSpeedPoint, as BM_ModelEvaluation).
Batch Evaluations(Parameters p, double speed, bool derivatives) {
  auto model = std::make_shared<const RigidRingModel>();
  return [model, p = std::move(p), speed, derivatives, i = 0](long n) mutable {
    for (long k = 0; k < n; ++k) {
      NextSpeedPoint(&p, &i);
      const ModalSolution s = model->Solve(p, speed, derivatives);
      if (!s.ok || s.modes.empty()) return false;
      g_sink = s.modes[0].frequency_hz;
    }
    return true;
  };
}

// Eigen's EigenSolver, with eigenvectors or without, on each of `blocks`
// (as BM_BareEigenSolve and BM_BareEigenValues).
Batch BareSolves(std::vector<SpeedBlock> blocks, bool vectors) {
  return [blocks = std::move(blocks), vectors](long n) {
    for (long k = 0; k < n; ++k) {
      g_sink = BareEigenSolve(blocks, vectors);
      if (std::isnan(g_sink)) return false;
    }
    return true;
  };
}

// Identify with one start (the LM fit and the uncertainty analysis after
// it), each with a new model: a cold standstill cache.
Batch Fits(const Dataset& d, Derivatives derivatives) {
  IdentifyOptions io;
  io.starts = 1;
  io.residuals.derivatives = derivatives;
  return [d, io](long n) {
    for (long k = 0; k < n; ++k) {
      const RigidRingModel model;
      IdentifyResult s;
      Identify(model, d, io, &s);
      if (!s.status.ok()) return false;
      g_sink = s.seconds;
    }
    return true;
  };
}

std::string Times(double limit) {
  char text[32];
  std::snprintf(text, sizeof text, "%g×", limit);
  return text;
}

}  // namespace

const char* SpeedCaseText(SpeedCase c) {
  switch (c) {
    case SpeedCase::kModelEvaluation:
      return "model evaluation, paper's tire, both planes, labelled (analytic: with "
             "every mode's derivatives)";
    case SpeedCase::kBareEigenSolve:
      return "Eigen's EigenSolver alone, the same three balanced blocks";
    case SpeedCase::kBareEigenValues:
      return "the same, eigenvalues only";
    case SpeedCase::kModelEvaluationRolling:
      return "model evaluation, example car tire at 6 m/s";
    case SpeedCase::kIdentifyInPlane:
      return "identify, 1 start, Table 1 in-plane";
    case SpeedCase::kIdentifyBothPlanes:
      return "identify, 1 start, Table 1 both planes";
    case SpeedCase::kJointFitStanding:
      return "joint fit, car tire's 14 parameters, standing";
    case SpeedCase::kJointFitDrum6:
      return "the same, one drum condition at 6 m/s";
    case SpeedCase::kJointFitThreeConditions:
      return "the same, standing + 6 + 12 m/s (one Ceres problem)";
  }
  return "";
}

Status RunSpeedSuite(const SuiteOptions& o, SpeedSuite* suite) {
  if (o.speed_batches < 1) return Status::InvalidInput("speed_batches: must be at least 1");
  if (!(o.speed_seconds_per_case > 0) || !std::isfinite(o.speed_seconds_per_case)) {
    return Status::InvalidInput("speed_seconds_per_case: must be positive and finite");
  }
  const auto start = Clock::now();
  Parameters paper;
  Dataset in_plane, both_planes, standing, drum_6, three_conditions;
  for (const Status& s :
       {SpeedPaperParameters(o.source_dir, &paper), SpeedTable1(o.source_dir, true, &in_plane),
        SpeedTable1(o.source_dir, false, &both_planes), SpeedCarTire({0}, &standing),
        SpeedCarTire({6}, &drum_6), SpeedCarTire({0, 6, 12}, &three_conditions)}) {
    if (!s.ok()) return s;
  }
  *suite = SpeedSuite();
  suite->batches = o.speed_batches;
  suite->seconds_per_case = o.speed_seconds_per_case;
  constexpr int kGroups = 5;
  int done = 0;
  const auto finished = [&] {
    if (o.on_case) o.on_case(++done, kGroups);
  };
  const auto row = [&](SpeedCase c, std::optional<double> numeric,
                       std::optional<double> analytic) {
    suite->rows.push_back({c, numeric, analytic, "", std::nullopt});
  };
  std::vector<double> t;
  // The evaluation and the bare solve of the same blocks, in the same rounds.
  if (Status s = TimeSideBySide("model evaluation",
                                {Evaluations(paper, 0, false), Evaluations(paper, 0, true),
                                 BareSolves(BareEigenBlocks(paper), true),
                                 BareSolves(BareEigenBlocks(paper), false)},
                                o, &t);
      !s.ok()) {
    return s;
  }
  row(SpeedCase::kModelEvaluation, t[0], t[1]);
  row(SpeedCase::kBareEigenSolve, t[2], std::nullopt);
  row(SpeedCase::kBareEigenValues, t[3], std::nullopt);
  finished();
  if (Status s = TimeSideBySide("rolling model evaluation",
                                {Evaluations(ExampleCarTire(), 6, false)}, o, &t);
      !s.ok()) {
    return s;
  }
  row(SpeedCase::kModelEvaluationRolling, t[0], std::nullopt);
  finished();
  for (const auto& [c, d] : {std::pair<SpeedCase, const Dataset*>{SpeedCase::kIdentifyInPlane,
                                                                  &in_plane},
                             {SpeedCase::kIdentifyBothPlanes, &both_planes}}) {
    if (Status s = TimeSideBySide(
            ToString(c), {Fits(*d, Derivatives::kNumeric), Fits(*d, Derivatives::kAnalytic)}, o,
            &t);
        !s.ok()) {
      return s;
    }
    row(c, t[0], t[1]);
    finished();
  }
  // The three joint fits in the same rounds: their ratio is a target.
  if (Status s = TimeSideBySide(
          "joint fit",
          {Fits(standing, Derivatives::kNumeric), Fits(standing, Derivatives::kAnalytic),
           Fits(drum_6, Derivatives::kNumeric), Fits(drum_6, Derivatives::kAnalytic),
           Fits(three_conditions, Derivatives::kNumeric),
           Fits(three_conditions, Derivatives::kAnalytic)},
          o, &t);
      !s.ok()) {
    return s;
  }
  row(SpeedCase::kJointFitStanding, t[0], t[1]);
  row(SpeedCase::kJointFitDrum6, t[2], t[3]);
  row(SpeedCase::kJointFitThreeConditions, t[4], t[5]);
  finished();
  for (SpeedRow& r : suite->rows) {
    switch (r.name) {
      case SpeedCase::kModelEvaluation:
        r.target = "≤ " + Times(suite->evaluation_over_bare_solve_max) +
                   " the bare solve (numeric)";
        break;
      case SpeedCase::kIdentifyInPlane: {
        char text[48];
        std::snprintf(text, sizeof text, "analytic ≤ %g ms",
                      1e3 * suite->identify_in_plane_max_seconds);
        r.target = text;
        break;
      }
      case SpeedCase::kJointFitThreeConditions:
        r.target = "analytic ≤ " + Times(suite->joint_fit_over_standing_max) + " standing";
        break;
      default:
        break;
    }
    r.met = suite->Met(r.name);
  }
  suite->seconds = Elapsed(start);
  return Status::Success();
}

const SpeedRow* SpeedSuite::Find(SpeedCase c) const {
  for (const SpeedRow& r : rows) {
    if (r.name == c) return &r;
  }
  return nullptr;
}

namespace {

std::optional<double> Ratio(std::optional<double> a, std::optional<double> b) {
  if (!a || !b || !(*b > 0)) return std::nullopt;
  return *a / *b;
}

}  // namespace

std::optional<double> SpeedSuite::EvaluationOverBareSolve() const {
  const SpeedRow* evaluation = Find(SpeedCase::kModelEvaluation);
  const SpeedRow* bare = Find(SpeedCase::kBareEigenSolve);
  if (!evaluation || !bare) return std::nullopt;
  return Ratio(evaluation->numeric_seconds, bare->numeric_seconds);
}

std::optional<double> SpeedSuite::EvaluationOverBareEigenvalues() const {
  const SpeedRow* evaluation = Find(SpeedCase::kModelEvaluation);
  const SpeedRow* bare = Find(SpeedCase::kBareEigenValues);
  if (!evaluation || !bare) return std::nullopt;
  return Ratio(evaluation->numeric_seconds, bare->numeric_seconds);
}

std::optional<double> SpeedSuite::DerivativesOverEvaluation() const {
  const SpeedRow* evaluation = Find(SpeedCase::kModelEvaluation);
  if (!evaluation) return std::nullopt;
  return Ratio(evaluation->analytic_seconds, evaluation->numeric_seconds);
}

std::optional<double> SpeedSuite::JointFitOverStanding(Derivatives d) const {
  const SpeedRow* three = Find(SpeedCase::kJointFitThreeConditions);
  const SpeedRow* standing = Find(SpeedCase::kJointFitStanding);
  if (!three || !standing) return std::nullopt;
  return d == Derivatives::kNumeric ? Ratio(three->numeric_seconds, standing->numeric_seconds)
                                    : Ratio(three->analytic_seconds, standing->analytic_seconds);
}

bool SpeedSuite::Target(SpeedCase c, std::optional<double>* value, double* limit) const {
  switch (c) {
    case SpeedCase::kModelEvaluation:
      *value = EvaluationOverBareSolve();
      *limit = evaluation_over_bare_solve_max;
      return true;
    case SpeedCase::kIdentifyInPlane: {
      const SpeedRow* r = Find(c);
      *value = r ? r->analytic_seconds : std::nullopt;
      *limit = identify_in_plane_max_seconds;
      return true;
    }
    case SpeedCase::kJointFitThreeConditions:
      *value = JointFitOverStanding(Derivatives::kAnalytic);
      *limit = joint_fit_over_standing_max;
      return true;
    default:
      return false;
  }
}

std::optional<bool> SpeedSuite::Met(SpeedCase c) const {
  std::optional<double> value;
  double limit = 0;
  if (!Target(c, &value, &limit) || !value) return std::nullopt;
  return *value <= limit;
}

}  // namespace ringid
