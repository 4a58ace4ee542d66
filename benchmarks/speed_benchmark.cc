// Speed of one model evaluation and of LM fits of the paper's problem.
// Targets (README): model evaluation <= 10 us, in-plane LM fit <= 2 ms.
#include <benchmark/benchmark.h>

#include "datasets/dataset.h"
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
  for (auto _ : state) {
    ModalSolution s = model.Solve(p);
    benchmark::DoNotOptimize(s);
  }
}
BENCHMARK(BM_ModelEvaluation)->Unit(benchmark::kMicrosecond);

void Fit(benchmark::State& state, bool in_plane_only) {
  const Dataset d = Table1(in_plane_only);
  IdentifyOptions o;
  o.starts = 1;
  const RigidRingModel model;
  for (auto _ : state) {
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

}  // namespace
}  // namespace ringid

BENCHMARK_MAIN();
