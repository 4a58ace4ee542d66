// Measured FRFs as a kind of measurement (contract §9, issue 36): a standing
// hammer test with the masses free identifies the synthetic truth; its exact
// Jacobian is the central differences'; with 2 % noise the fit's chi-square
// is its degrees of freedom's and the truth lies within the intervals; a
// drum's contact-to-axle FRFs are §8's forward model; the band selects lines;
// a coordinate the model lacks is refused naming it.
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <random>
#include <string>

#include <ceres/crs_matrix.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "datasets/measurement.h"
#include "datasets/synthetic.h"
#include "estimation/identify.h"
#include "estimation/problem.h"
#include "estimation/residuals.h"
#include "estimation/uncertainty.h"
#include "model/forced_response.h"
#include "tests/test_support.h"

namespace ringid {
namespace {

using P = Param;
constexpr P kMasses[] = {P::m_b, P::I_ay, P::I_by, P::I_bx, P::I_bz};

// The hammer test of synthetic.h on the car tire (lines every `step_hz`),
// the masses and inertias free (initial values scattered by `spread` like
// the rest), with FRF noise `noise`.
Dataset Hammer(double noise, double spread, double step_hz, std::mt19937_64* rng,
               double low_hz = 5, double high_hz = 250) {
  const Parameters truth = ExampleCarTire();
  Dataset d = PlanSimulation(truth, spread, {0}, {}, rng);
  d.name = "hammer";
  FreeMasses(truth, spread, rng, &d);
  d.conditions[0].frf = HammerTest(0.31, low_hz, high_hz, step_hz);
  SimulateOptions so;
  so.modes = false;
  so.frf_noise = noise;
  std::string why;
  EXPECT_TRUE(Simulate(RigidRingModel(), truth, so, rng, &d, &why)) << why;
  EXPECT_EQ(d.format, 3);
  EXPECT_TRUE(d.modes.empty());
  return d;
}

const ParameterEstimate* Estimate(const IdentifyResult& r, P p) {
  for (const ParameterEstimate& e : r.estimates) {
    if (e.param() == p && e.free) return &e;
  }
  return nullptr;
}

TEST(FrfMeasurementTest, ANoiseFreeHammerTestGivesTheTruthWithTheMassesFree) {
  std::mt19937_64 rng(7);
  const Dataset d = Hammer(0, 0.15, 1.0, &rng, 5, 150);
  IdentifyOptions o;
  o.starts = 1;
  o.residuals.derivatives = Derivatives::kAnalytic;
  IdentifyResult r;
  Identify(RigidRingModel(), d, o, &r);
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  const Parameters truth = ExampleCarTire();
  int free = 0;
  for (const ParameterEstimate& e : r.estimates) {
    if (!e.free) continue;
    ++free;
    EXPECT_LT(std::abs(e.value / truth[e.param()] - 1), 1e-6) << ParamName(e.param());
  }
  EXPECT_GE(free, 18);
  for (P q : kMasses) EXPECT_NE(Estimate(r, q), nullptr) << ParamName(q) << " not free";
}

// The exact Jacobian (dH = dG X + Y dB - Y dD X, chained to the coordinates)
// against central differences of the residuals.
TEST(FrfMeasurementTest, TheExactJacobianIsTheCentralDifferences) {
  std::mt19937_64 rng(8);
  const Dataset d = Hammer(0.02, 0.15, 5.0, &rng);
  ResidualOptions analytic;
  analytic.derivatives = Derivatives::kAnalytic;
  Status status;
  const auto problem = Problem::Create(RigidRingModel(), d, analytic, &status);
  ASSERT_TRUE(problem) << status.message;
  const Eigen::VectorXd x = problem->start();
  Eigen::VectorXd r;
  Eigen::MatrixXd J;
  ASSERT_TRUE(problem->Evaluate(x, &r, &J));
  for (int i = 0; i < x.size(); ++i) {
    const double h = 1e-6;
    Eigen::VectorXd up = x, down = x, r_up, r_down;
    up[i] += h;
    down[i] -= h;
    ASSERT_TRUE(problem->Evaluate(up, &r_up, nullptr));
    ASSERT_TRUE(problem->Evaluate(down, &r_down, nullptr));
    const Eigen::VectorXd numeric = (r_up - r_down) / (2 * h);
    EXPECT_LT((numeric - J.col(i)).norm(), 1e-6 * J.col(i).norm() + 1e-9)
        << problem->coordinate_name(i);
  }
}

// Numeric differences are made once per point: Ceres' trust region asks a
// bounded problem for the Jacobian at its candidate twice (its projected line
// search, then the step taken) and for the rows between; and a condition of
// FRFs alone solves no modes. So the first Jacobian costs 2n + 1 evaluations,
// and the rows and Jacobian at that point again none; the Jacobian is the
// one identify's analysis evaluates there. The exact Jacobian is kept too.
TEST(FrfMeasurementTest, ANumericJacobianIsMadeOncePerPointAndSolvesNoModes) {
  std::mt19937_64 rng(10);
  const Dataset d = Hammer(0.02, 0.15, 10.0, &rng);
  Status status;
  ResidualOptions numeric;
  numeric.derivatives = Derivatives::kNumeric;
  const auto problem = Problem::Create(RigidRingModel(), d, numeric, &status);
  ASSERT_TRUE(problem) << status.message;
  Eigen::VectorXd x = problem->start();
  ceres::Problem fit;
  internal::AddResidualBlocks(problem->residuals(), &x, &fit);
  const long before = problem->evaluations();
  double cost = 0;
  std::vector<double> r, again;
  ceres::CRSMatrix J, J_again;
  ASSERT_TRUE(fit.Evaluate(ceres::Problem::EvaluateOptions(), &cost, &r, nullptr, &J));
  EXPECT_EQ(problem->evaluations() - before, 2 * x.size() + 1);
  ASSERT_TRUE(fit.Evaluate(ceres::Problem::EvaluateOptions(), &cost, &again, nullptr, &J_again));
  ASSERT_TRUE(fit.Evaluate(ceres::Problem::EvaluateOptions(), &cost, nullptr, nullptr, nullptr));
  EXPECT_EQ(problem->evaluations() - before, 2 * x.size() + 1);
  EXPECT_EQ(again, r);
  EXPECT_EQ(J_again.values, J.values);
  Eigen::MatrixXd analysis;
  ASSERT_TRUE(internal::EvaluateJacobian(problem->residuals(), x, &analysis));
  ASSERT_EQ(J.num_rows, analysis.rows());
  for (int i = 0; i < J.num_rows; ++i) {
    for (int k = J.rows[i]; k < J.rows[i + 1]; ++k) {
      ASSERT_EQ(J.values[k], analysis(i, J.cols[k])) << "row " << i << ", column " << J.cols[k];
    }
  }
  // The exact Jacobian likewise: one evaluation, then none.
  ResidualOptions analytic;
  analytic.derivatives = Derivatives::kAnalytic;
  const auto exact = Problem::Create(RigidRingModel(), d, analytic, &status);
  ASSERT_TRUE(exact) << status.message;
  ceres::Problem exact_fit;
  internal::AddResidualBlocks(exact->residuals(), &x, &exact_fit);
  for (int k = 0; k < 2; ++k) {
    ASSERT_TRUE(exact_fit.Evaluate(ceres::Problem::EvaluateOptions(), &cost, &r, nullptr, &J));
  }
  EXPECT_EQ(exact->evaluations(), 1);
}

// The default derivatives (auto) are exact for a condition of FRFs, one
// evaluation a Jacobian, the same as analytic's to the bit; for a condition
// of measured modes they are the central differences of numeric.
TEST(FrfMeasurementTest, DefaultDerivativesAreExactForFrfsAndDifferencesForModes) {
  std::mt19937_64 rng(10);
  const Dataset frfs = Hammer(0.02, 0.15, 10.0, &rng);
  Dataset modes;
  LoadError error;
  ASSERT_TRUE(LoadDataset(testing::SourcePath("datasets/paper/table1.json"), &modes, &error))
      << error.OneLine();
  ASSERT_EQ(ResidualOptions{}.derivatives, Derivatives::kAuto);
  for (const auto& [d, same] : {std::pair<const Dataset*, Derivatives>{&frfs, Derivatives::kAnalytic},
                                std::pair<const Dataset*, Derivatives>{&modes, Derivatives::kNumeric}}) {
    Status status;
    const auto given = Problem::Create(RigidRingModel(), *d, ResidualOptions{}, &status);
    ASSERT_TRUE(given) << status.message;
    ResidualOptions o;
    o.derivatives = same;
    const auto other = Problem::Create(RigidRingModel(), *d, o, &status);
    ASSERT_TRUE(other) << status.message;
    Eigen::MatrixXd J, J_same;
    ASSERT_TRUE(internal::EvaluateJacobian(given->residuals(), given->start(), &J));
    ASSERT_TRUE(internal::EvaluateJacobian(other->residuals(), other->start(), &J_same));
    EXPECT_EQ(J, J_same) << ToString(same);
    if (same == Derivatives::kAnalytic) EXPECT_EQ(given->evaluations(), 1);
  }
}

// From the truth with 2 % noise: the chi-square per degree of freedom near 1
// and every parameter within four standard errors of the truth.
TEST(FrfMeasurementTest, WithNoiseTheFitIsAsGoodAsTheNoiseAndTheTruthWithinItsErrors) {
  std::mt19937_64 rng(9);
  Dataset d = Hammer(0.02, 0.15, 1.0, &rng, 5, 150);
  const Parameters truth = ExampleCarTire();
  for (auto& [q, v] : d.initial) v = truth[q];
  IdentifyOptions o;
  o.starts = 1;
  o.residuals.derivatives = Derivatives::kAnalytic;
  IdentifyResult r;
  Identify(RigidRingModel(), d, o, &r);
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  const double per_dof = r.fit.chi_square / r.fit.degrees_of_freedom;
  EXPECT_GT(per_dof, 0.9);
  EXPECT_LT(per_dof, 1.1);
  for (const ParameterEstimate& e : r.estimates) {
    if (!e.free) continue;
    ASSERT_TRUE(e.std) << ParamName(e.param());
    EXPECT_LT(std::abs(e.value - truth[e.param()]), 4 * *e.std) << ParamName(e.param());
  }
  // m_b from the force scale: well within 2 %.
  ASSERT_NE(Estimate(r, P::m_b), nullptr);
  EXPECT_LT(*Estimate(r, P::m_b)->std / truth[P::m_b], 0.02);
}

// On the drum: the FRFs from the contact forces to the held axle's channels
// are what `forces` predicts of lug forces at each line (contract §8). Both
// go through FrequencyResponse, so this checks the kind's wiring (names,
// pairs, channels, speed), not the response: the time integration of
// forced_response_test.cc and the hand-written M, C, K of
// frequency_response_test.cc check that.
TEST(FrfMeasurementTest, ADrumsContactToAxleFrfsAreTheLugForceForwardModel) {
  const Parameters truth = ExampleCarTire();
  Dataset d;
  d.format = 3;
  d.conditions = {{"drum_12", 12.0, {}, {}, Frf{}}};
  Frf& frf = *d.conditions[0].frf;
  for (int f = 0; f < kNumLugForces; ++f) {
    frf.inputs.push_back({ToString(static_cast<LugForce>(f)), std::nullopt,
                          static_cast<LugForce>(f), {}});
  }
  for (int c = 0; c < kNumAxleChannels; ++c) {
    frf.outputs.push_back({ToString(static_cast<AxleChannel>(c)), std::nullopt,
                           static_cast<AxleChannel>(c), {}, FrfQuantity::kDisplacement});
  }
  frf.frequencies_hz = {7.5, 33.0, 61.0, 97.0};
  for (int c = 0; c < kNumAxleChannels; ++c) {
    for (int f = 0; f < kNumLugForces; ++f) {
      frf.functions.push_back({c, f, std::vector<Complex>(4), std::vector<double>(4, 1.0),
                               std::nullopt});
    }
  }
  const Measurement& unit = MeasurementOf(Quantity::kFrf);
  const RigidRingModel model;
  const ModelAt at{&model, &truth, nullptr, nullptr};
  ASSERT_TRUE(unit.Measure(at, 0, MeasurementOptions{}, &d));
  for (int l = 0; l < 4; ++l) {
    AxleResponseMatrix H;
    std::string why;
    ASSERT_TRUE(AxleResponse(model, truth, 12.0, frf.frequencies_hz[l], &H, &why)) << why;
    for (const FrfFunction& fn : d.conditions[0].frf->functions) {
      EXPECT_EQ(fn.h[l], H(fn.output, fn.input))
          << frf.frequencies_hz[l] << " Hz, " << frf.outputs[fn.output].name << "/"
          << frf.inputs[fn.input].name;
    }
  }
}

TEST(FrfMeasurementTest, TheBandSelectsTheLinesFitted) {
  std::mt19937_64 rng(10);
  const Dataset d = Hammer(0.02, 0.15, 5.0, &rng);
  const Frf& frf = *d.conditions[0].frf;
  const int functions = static_cast<int>(frf.functions.size());
  ResidualOptions all, band, none;
  band.band_low_hz = 40;
  band.band_high_hz = 120;
  none.band_low_hz = 251;
  Status status;
  const auto whole = Problem::Create(RigidRingModel(), d, all, &status);
  ASSERT_TRUE(whole) << status.message;
  EXPECT_EQ(whole->num_residuals(), 2 * functions * 50);  // 5, 10, ..., 250 Hz
  const auto part = Problem::Create(RigidRingModel(), d, band, &status);
  ASSERT_TRUE(part) << status.message;
  EXPECT_EQ(part->num_residuals(), 2 * functions * 17);  // 40, 45, ..., 120 Hz
  EXPECT_EQ(Problem::Create(RigidRingModel(), d, none, &status), nullptr);
  EXPECT_TRUE(status.invalid_input());
  EXPECT_NE(status.message.find("band"), std::string::npos) << status.message;
}

TEST(FrfMeasurementTest, AnInputOnACoordinateTheModelLacksIsRefusedNamingIt) {
  std::mt19937_64 rng(11);
  Dataset d = Hammer(0.02, 0.15, 5.0, &rng);
  d.conditions[0].frf->inputs[1].point.reset();
  d.conditions[0].frf->inputs[1].coordinates = {{Dof::kXa, 1.0}};
  d.conditions[0].frf->inputs[1].name = "hub_x";
  Status status;
  EXPECT_EQ(Problem::Create(RigidRingModel(), d, ResidualOptions{}, &status), nullptr);
  EXPECT_TRUE(status.invalid_input());
  EXPECT_NE(status.message.find("input hub_x acts on x_a"), std::string::npos) << status.message;
  const Effect* hub = FindEffect("hub_compliance");
  d.initial[P::s_h] = 1e-6;
  d.initial[P::m_a] = 15;
  EXPECT_NE(Problem::Create(RigidRingModel({hub}), d, ResidualOptions{}, &status), nullptr)
      << status.message;
}

// The shipped example (README, From FRFs): the car tire's hammer test with
// the masses free, 2 % noise, lines every 2 Hz from 6 to 200 Hz.
TEST(FrfMeasurementTest, TheShippedHammerTestIsTheCarTiresFrfs) {
  std::mt19937_64 rng(2026);
  Dataset d = Hammer(0.02, 0.15, 2.0, &rng, 6, 200);
  d.name = "car_tire_hammer";
  d.description =
      "A standing hammer test of datasets/examples/car_tire.json (ExampleCarTire): four blows "
      "on the tread, six accelerometers on it and one on the rim, 28 FRFs from 6 to 200 Hz "
      "every 2 Hz with 2 % noise; masses and inertias free, initial values 15 % off. "
      "Simulated by ringid (tests/frf_measurement_test.cc), not measured.";
  const std::string path = testing::SourcePath("datasets/examples/car_tire_hammer_frf.json");
  const std::string text = DatasetToJson(d);
  if (std::getenv("RINGID_REGENERATE")) std::ofstream(path) << text;
  EXPECT_EQ(testing::ReadFile(path), text)
      << "RINGID_REGENERATE=1 build/tests/data_tests --gtest_filter=*ShippedHammerTest*";
}

// The README's run: identify fits the shipped hammer test within its noise
// from its initial values, with the masses free, and writes its report.
TEST(FrfMeasurementTest, IdentifyFitsTheShippedHammerTestWithinItsNoise) {
  const std::string report = ::testing::TempDir() + "/hammer_report.json";
  const testing::RunResult r = testing::Ringid(
      "identify --dataset=" + testing::SourcePath("datasets/examples/car_tire_hammer_frf.json") +
      " --starts=1 --derivatives=analytic --output=" + report);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("the model fits within the noise"), std::string::npos) << r.out;
  const Parameters truth = ExampleCarTire();
  const nlohmann::json j = nlohmann::json::parse(testing::ReadFile(report));
  for (P q : {P::m_b, P::I_by, P::k_bx, P::K_cy}) {
    const auto& e = j["parameters"][ParamName(q)];
    EXPECT_TRUE(e["free"].get<bool>()) << ParamName(q);
    EXPECT_LT(std::abs(e["value"].get<double>() - truth[q]), 4 * e["std"].get<double>())
        << ParamName(q);
  }
}

}  // namespace
}  // namespace ringid
