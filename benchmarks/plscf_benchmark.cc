// Speed of modal extraction from FRFs (issue 37): pLSCF over orders
// 1..max_order, the stabilisation diagram, the physical poles and LSFD on the
// car tire's standing hammer test (28 FRFs x 491 lines, 2 % noise), then
// (refine 1) the maximum-likelihood refinement. Target: the whole
// extraction, its refinement included, <= 1 s on one core.
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>

#include <benchmark/benchmark.h>

#include "datasets/synthetic.h"
#include "estimation/plscf.h"
#include "model/rigid_ring_model.h"

namespace ringid {
namespace {

Frf NoisyHammerTest() {
  const Parameters truth = ExampleCarTire();
  std::mt19937_64 rng(1);
  Dataset d = PlanSimulation(truth, 0.15, {0}, {}, &rng);
  d.conditions[0].frf = HammerTest(0.31, 5, 250, 0.5);
  SimulateOptions so;
  so.modes = false;
  so.frf_noise = 0.02;
  std::string why;
  if (!Simulate(RigidRingModel(), truth, so, &rng, &d, &why)) {
    std::fprintf(stderr, "ringid_benchmarks: %s\n", why.c_str());
    std::abort();
  }
  return *d.conditions[0].frf;
}

void BM_ExtractModes(benchmark::State& state) {
  const Frf frf = NoisyHammerTest();
  PlscfOptions o;
  o.max_order = static_cast<int>(state.range(0));
  o.refine = state.range(1) != 0;
  PlscfResult r;
  for (auto _ : state) {
    ExtractModes(frf, o, &r);
    if (!r.status.ok()) state.SkipWithError(r.status.message.c_str());
  }
  if (o.refine && !r.refinement.status.ok()) {
    state.SkipWithError(r.refinement.status.message.c_str());
  }
  state.counters["modes"] = static_cast<double>(r.modes.size());
  state.counters["iterations"] = r.refinement.iterations;
}
BENCHMARK(BM_ExtractModes)
    ->ArgNames({"max_order", "refine"})
    ->ArgsProduct({{20, 30, 40}, {0, 1}})
    ->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace ringid
