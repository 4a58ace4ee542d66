// Each measured FRF against the fitted model (estimation/frf_fits.h, issue 36):
// FRAC against hand computations and its invariances; per function, the
// chi-square is its rows' share of the fit's, the curves are the dataset's
// lines in the band, and the identify report carries them (absent without
// FRFs).
#include <cmath>
#include <complex>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "datasets/synthetic.h"
#include "estimation/frf_fits.h"
#include "estimation/identify.h"
#include "estimation/problem.h"
#include "report/report.h"
#include "tests/test_support.h"

namespace ringid {
namespace {

using C = std::complex<double>;
using P = Param;

TEST(FracTest, IsOneForTheSameFunctionAndForAnyComplexMultipleOfIt) {
  const std::vector<C> h = {{1, 2}, {-0.5, 3}, {4, -1}, {0.1, 0.2}};
  std::vector<C> twice, rotated, scaled;
  for (const C& v : h) {
    twice.push_back(2.0 * v);
    rotated.push_back(C(0, 1) * v);
    scaled.push_back(C(-3, 0.7) * v);
  }
  EXPECT_NEAR(Frac(h, h), 1, 1e-15);
  EXPECT_NEAR(Frac(h, twice), 1, 1e-15);
  // i H: sum H* (i H) = i sum |H|^2, whose modulus squared is (sum |H|^2)^2.
  EXPECT_NEAR(Frac(h, rotated), 1, 1e-15);
  EXPECT_NEAR(Frac(h, scaled), 1, 1e-15);
}

TEST(FracTest, MatchesHandComputations) {
  // a = (1, i), b = (1, 1): sum a* b = 1 - i, |.|^2 = 2; sum |a|^2 = sum |b|^2 = 2.
  EXPECT_NEAR(Frac({{1, 0}, {0, 1}}, {{1, 0}, {1, 0}}), 2.0 / 4.0, 1e-15);
  // Orthogonal over the lines: 0.
  EXPECT_EQ(Frac({{1, 0}, {0, 0}}, {{0, 0}, {0, 2}}), 0);
  // a = (1, 2), b = (2, 1) real: (2 + 2)^2 / (5 * 5) = 16/25.
  EXPECT_NEAR(Frac({{1, 0}, {2, 0}}, {{2, 0}, {1, 0}}), 16.0 / 25.0, 1e-15);
  // a = (1, 1), b = (1, -1): a phase flip at the second line cancels: 0.
  EXPECT_NEAR(Frac({{1, 0}, {1, 0}}, {{1, 0}, {-1, 0}}), 0, 1e-15);
  // Zero at every line: not defined.
  EXPECT_TRUE(std::isnan(Frac({{0, 0}, {0, 0}}, {{1, 0}, {1, 0}})));
}

TEST(FracTest, IsSymmetricAndWithinZeroAndOne) {
  std::mt19937_64 rng(5);
  std::normal_distribution<double> n(0, 1);
  for (int trial = 0; trial < 20; ++trial) {
    std::vector<C> a, b;
    for (int k = 0; k < 7; ++k) {
      a.push_back({n(rng), n(rng)});
      b.push_back({n(rng), n(rng)});
    }
    const double ab = Frac(a, b);
    EXPECT_NEAR(ab, Frac(b, a), 1e-14);
    EXPECT_GE(ab, 0);
    EXPECT_LE(ab, 1 + 1e-15);
  }
}

// The car tire's standing hammer test (datasets/synthetic.h HammerTest),
// lines every 5 Hz from 5 to 150 Hz, 2 % noise, fitted from the truth.
Dataset Hammer(std::mt19937_64* rng) {
  const Parameters truth = ExampleCarTire();
  Dataset d = PlanSimulation(truth, 0.0, {0}, {}, rng);
  d.name = "hammer";
  d.conditions[0].frf = HammerTest(0.31, 5, 150, 5);
  SimulateOptions so;
  so.modes = false;
  so.frf_noise = 0.02;
  std::string why;
  EXPECT_TRUE(Simulate(RigidRingModel(), truth, so, rng, &d, &why)) << why;
  return d;
}

TEST(FrfFitsTest, EachFunctionsChiSquareIsItsRowsShareOfTheFits) {
  std::mt19937_64 rng(21);
  const Dataset d = Hammer(&rng);
  IdentifyOptions o;
  o.starts = 1;
  o.residuals.derivatives = Derivatives::kAnalytic;
  o.residuals.band_low_hz = 20;
  o.residuals.band_high_hz = 120;
  IdentifyResult r;
  Identify(RigidRingModel(), d, o, &r);
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  ASSERT_TRUE(r.frfs);
  const Frf& frf = *d.conditions[0].frf;
  ASSERT_EQ(r.frfs->size(), frf.functions.size());
  // The fit's residuals at its best point: the FRF rows alone (no modes, no
  // priors), function-major, re and im per line in the band.
  Status status;
  const auto problem = Problem::Create(RigidRingModel(), d, o.residuals, &status);
  ASSERT_TRUE(problem) << status.message;
  Eigen::VectorXd residuals;
  ASSERT_TRUE(problem->Evaluate(r.x, &residuals, nullptr));
  const int lines = 21;  // 20, 25, ..., 120 Hz
  ASSERT_EQ(residuals.size(), 2 * lines * static_cast<int>(frf.functions.size()));
  double total = 0;
  int across_planes = 0;
  for (size_t k = 0; k < r.frfs->size(); ++k) {
    const FrfFit& f = (*r.frfs)[k];
    const FrfFunction& fn = frf.functions[k];
    EXPECT_EQ(f.output, frf.outputs[fn.output].name);
    EXPECT_EQ(f.input, frf.inputs[fn.input].name);
    EXPECT_EQ(f.condition, d.conditions[0].name);  // format 3 names its conditions
    EXPECT_EQ(f.values(), 2 * lines);
    ASSERT_EQ(f.frequency_hz.size(), static_cast<size_t>(lines));
    EXPECT_NEAR(f.chi2, residuals.segment(2 * lines * k, 2 * lines).squaredNorm(),
                1e-9 * f.chi2);
    total += f.chi2;
    // The measured curve is the dataset's lines in the band, with their sigma.
    for (int l = 0; l < lines; ++l) {
      const int line = l + 3;  // 20 Hz is the fourth line from 5 Hz
      EXPECT_EQ(f.frequency_hz[l], frf.frequencies_hz[line]);
      EXPECT_EQ(f.measured_re[l], fn.h[line].real());
      EXPECT_EQ(f.measured_im[l], fn.h[line].imag());
      EXPECT_EQ(f.sigma[l], fn.sigma[line]);
    }
    // 2 % noise on the model's own functions: the shapes agree, except where
    // the model's function is zero (standing, an input in one plane does not
    // move an output in the other): there FRAC is not defined.
    bool zero = true;
    for (int l = 0; l < lines; ++l) zero &= f.model_re[l] == 0 && f.model_im[l] == 0;
    if (zero) {
      EXPECT_TRUE(std::isnan(f.frac)) << f.output << "/" << f.input;
      ++across_planes;
      continue;
    }
    EXPECT_GT(f.frac, 0.99) << f.output << "/" << f.input;
    EXPECT_LE(f.frac, 1.0);
  }
  EXPECT_GT(across_planes, 0);
  EXPECT_LT(across_planes, static_cast<int>(frf.functions.size()) / 2);
  EXPECT_NEAR(total, r.fit.chi_square, 1e-9 * total);
}

// The report's `frfs` only where the dataset has FRFs: a modal dataset's
// identify report is unchanged.
TEST(FrfFitsTest, OnlyADatasetWithFrfsGetsThem) {
  std::mt19937_64 rng(22);
  const Parameters truth = ExampleCarTire();
  Dataset modal = PlanSimulation(truth, 0.0, {0}, {}, &rng);
  std::string why;
  ASSERT_TRUE(Simulate(RigidRingModel(), truth, SimulateOptions{}, &rng, &modal, &why)) << why;
  EXPECT_TRUE(FrfFits(RigidRingModel(), modal, [&](int) { return truth; }, MeasurementOptions{})
                  .empty());
  IdentifyOptions o;
  o.starts = 1;
  IdentifyResult r;
  Identify(RigidRingModel(), modal, o, &r);
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  EXPECT_FALSE(r.frfs);
  IdentifyReport report;
  report.body.result = r;
  EXPECT_EQ(ReportText(report).find("\"frfs\""), std::string::npos);
}

}  // namespace
}  // namespace ringid
