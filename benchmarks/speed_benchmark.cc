// Speed of one model evaluation and of LM fits of the paper's problem.
// Targets (README): model evaluation <= 10 us, in-plane LM fit <= 2 ms.
#include <benchmark/benchmark.h>

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

void BM_ModelEvaluation(benchmark::State& state) {
  Parameters p;
  LoadError e;
  if (!LoadParameterSet(Path("datasets/paper/parameters.json"), &p, &e)) std::abort();
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

void Fit(benchmark::State& state, bool in_plane_only) {
  const Dataset d = Table1(in_plane_only);
  IdentifyOptions o;
  o.starts = 1;
  for (auto _ : state) {
    const RigidRingModel model;  // a cold standstill cache
    IdentifySummary s;
    Identify(model, d, o, &s);
    if (!s.status.ok()) state.SkipWithError("fit failed");
    benchmark::DoNotOptimize(s);
  }
}
void BM_LmFitInPlane(benchmark::State& state) { Fit(state, true); }
void BM_LmFitBothPlanes(benchmark::State& state) { Fit(state, false); }
BENCHMARK(BM_LmFitInPlane)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_LmFitBothPlanes)->Unit(benchmark::kMillisecond);

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
void BM_JointFit(benchmark::State& state, std::vector<double> speeds) {
  const Dataset d = CarTire(speeds);
  IdentifyOptions o;
  o.starts = 1;
  for (auto _ : state) {
    const RigidRingModel model;  // a cold standstill cache
    IdentifySummary s;
    Identify(model, d, o, &s);
    if (!s.status.ok()) state.SkipWithError("fit failed");
    benchmark::DoNotOptimize(s);
  }
}
BENCHMARK_CAPTURE(BM_JointFit, standing, std::vector<double>{0})->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_JointFit, drum_6, std::vector<double>{6})->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_JointFit, standing_drum_6_drum_12, std::vector<double>{0, 6, 12})
    ->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace ringid

BENCHMARK_MAIN();
