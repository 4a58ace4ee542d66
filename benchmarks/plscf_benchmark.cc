// Speed of modal extraction from FRFs (issue 37): pLSCF over orders
// 1..max_order, the stabilisation diagram, the physical poles and LSFD on the
// car tire's standing hammer test (28 FRFs x 491 lines, 2 % noise), then
// (refine 1) the maximum-likelihood refinement. Target: the whole
// extraction, its refinement included, <= 1 s on one core. And `ringid
// poles`'s (estimation/poles.h) on 3 FRFs x 1001 lines of a structure of
// five modes, 2 % noise, sigma given or estimated from the residuals.
// Target: <= 0.5 s.
#include <complex>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>

#include <benchmark/benchmark.h>

#include "datasets/synthetic.h"
#include "estimation/plscf.h"
#include "estimation/poles.h"
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

// Five modes (damped 40-310 Hz, damping ratios 0.01-0.03), accelerances at
// three points per a force at the first, lines 0.5-500.5 Hz every 0.5 Hz,
// 2 % noise at contract §9's sigma; `sigma` false: none given.
Frf FiveModes(bool sigma) {
  const double hz[5] = {40, 95, 160, 230, 310}, zeta[5] = {0.01, 0.02, 0.015, 0.03, 0.02};
  const double shape[3][5] = {{1, 0.8, 0.6, 0.9, 0.5}, {0.7, -0.5, 0.9, -0.4, 0.8}, {0.3, 0.9, -0.7, 0.6, -0.9}};
  Frf frf;
  frf.inputs.resize(1);
  frf.outputs.resize(3);
  for (int o = 0; o < 3; ++o) frf.outputs[o].quantity = FrfQuantity::kAcceleration;
  for (int l = 0; l < 1001; ++l) frf.frequencies_hz.push_back(0.5 + 0.5 * l);
  std::mt19937_64 rng(3);
  std::normal_distribution<double> normal;
  for (int o = 0; o < 3; ++o) {
    FrfFunction f;
    f.output = o;
    std::vector<std::complex<double>> clean;
    double peak = 0;
    for (double line : frf.frequencies_hz) {
      const double w = 2 * M_PI * line;
      std::complex<double> h = 0;
      for (int r = 0; r < 5; ++r) {
        const double wn = 2 * M_PI * hz[r];
        h += -w * w * shape[o][r] * shape[0][r] / std::complex<double>(wn * wn - w * w, 2 * zeta[r] * wn * w);
      }
      clean.push_back(h);
      peak = std::max(peak, std::abs(h));
    }
    for (const std::complex<double>& h : clean) {
      const double s = FrfSigma(0.02, h, peak);
      f.h.push_back(h + std::complex<double>(s * normal(rng), s * normal(rng)));
      if (sigma) f.sigma.push_back(s);
    }
    frf.functions.push_back(std::move(f));
  }
  return frf;
}

void BM_FindPoles(benchmark::State& state) {
  const Frf frf = FiveModes(state.range(0) != 0);
  FoundPoles found;
  for (auto _ : state) {
    FindPoles(frf, {}, &found);
    if (!found.status.ok()) state.SkipWithError(found.status.message.c_str());
  }
  state.counters["poles"] = static_cast<double>(found.plscf.modes.size());
  state.counters["max_order"] = found.max_order;
}
BENCHMARK(BM_FindPoles)->ArgNames({"sigma"})->Arg(1)->Arg(0)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace ringid
