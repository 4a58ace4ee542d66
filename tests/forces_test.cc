// The lug forces from the axle's response (estimation/forces.h) against a
// synthetic truth: noise-free responses give the forces back; with noise,
// the estimates are unbiased and spread as std_measurement says (a Monte
// Carlo); sampling the parameters spreads them as the linearised std_total
// says; the response dataset's reader keeps the error contract.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <random>

#include <Eigen/SVD>
#include <gtest/gtest.h>

#include "datasets/response_dataset.h"
#include "datasets/synthetic.h"
#include "estimation/forces.h"
#include "model/effects.h"
#include "model/forced_response.h"
#include "report/report.h"
#include "tests/test_support.h"

namespace ringid {
namespace {

using testing::Ringid;
using testing::RunResult;
using testing::Scratch;

constexpr int kLugs = 20;
const std::vector<double> kSpeeds = {5, 10, 20};

// The lug force of order k: a spectrum falling with the order.
Complex TrueForce(LugForce f, int order) {
  const double size[] = {300, 900, 150};  // F_x, F_z, F_y (N)
  return std::polar(size[static_cast<int>(f)] / order, 0.7 * order + static_cast<int>(f));
}

// The axle's response to the true forces at each speed and orders 1-5 on
// `channels`, sigma `relative_noise` of each |Y| (1e-3 without noise), the
// noise added with `rng`.
ResponseDataset Responses(const Parameters& p, const std::vector<AxleChannel>& channels,
                          double relative_noise, std::mt19937_64* rng) {
  ResponseDataset d;
  d.name = "synthetic";
  std::string why;
  EXPECT_TRUE(SimulateResponses(
      RigidRingModel(), p, kLugs, kSpeeds, 5, channels,
      [](int k) {
        return std::array<Complex, kNumLugForces>{TrueForce(LugForce::kFx, k),
                                                  TrueForce(LugForce::kFz, k),
                                                  TrueForce(LugForce::kFy, k)};
      },
      relative_noise > 0 ? relative_noise : 1e-3, rng, &d, &why))
      << why;
  return d;
}

const std::vector<AxleChannel> kAll = {AxleChannel::kForceX, AxleChannel::kForceZ,
                                       AxleChannel::kForceY, AxleChannel::kMomentX,
                                       AxleChannel::kMomentZ};

ForcesResult Estimate(const ForceParameters& fp, const ResponseDataset& d,
                      const RigidRingModel& model = RigidRingModel()) {
  ForcesResult r;
  EstimateForces(model, fp, d, ForcesOptions{}, &r);
  EXPECT_TRUE(r.status.ok()) << r.status.message;
  return r;
}

TEST(ForcesTest, NoiseFreeResponsesGiveTheForcesBack) {
  ForceParameters fp;
  fp.shared = ExampleCarTire();
  const ForcesResult r = Estimate(fp, Responses(fp.shared, kAll, 0, nullptr));
  ASSERT_EQ(r.conditions.size(), kSpeeds.size());
  for (const ConditionForces& c : r.conditions) {
    for (const OrderForces& o : c.orders) {
      ASSERT_EQ(o.forces.size(), 3u) << c.name << " order " << o.order;
      for (const auto& [f, e] : o.forces) {
        EXPECT_LT(std::abs(e.value - TrueForce(f, o.order)), 1e-8 * std::abs(TrueForce(f, o.order)))
            << c.name << " " << ToString(f) << " order " << o.order;
      }
      ASSERT_TRUE(o.chi_square.has_value());
      EXPECT_LT(*o.chi_square, 1e-12);
      EXPECT_EQ(o.degrees_of_freedom, 4);
    }
  }
}

// The in-plane channels alone say nothing of F_y: it is named undetermined,
// and F_x and F_z are estimated exactly from two channels.
TEST(ForcesTest, WhatTheChannelsDoNotDetermineIsSaid) {
  ForceParameters fp;
  fp.shared = ExampleCarTire();
  const ForcesResult r =
      Estimate(fp, Responses(fp.shared, {AxleChannel::kForceX, AxleChannel::kForceZ}, 0, nullptr));
  for (const ConditionForces& c : r.conditions) {
    for (const OrderForces& o : c.orders) {
      EXPECT_EQ(o.forces.size(), 2u);
      ASSERT_EQ(o.undetermined.count(LugForce::kFy), 1u);
      EXPECT_NE(o.undetermined.at(LugForce::kFy).why.find("no measured channel"), std::string::npos);
      EXPECT_FALSE(o.undetermined.at(LugForce::kFy).condition_number_with_it.has_value());
      EXPECT_FALSE(o.chi_square.has_value());
    }
  }
}

// The condition number an undetermined force is refused for is the one of
// the kept forces with it, computed here from the SVD of the weighted
// response: infinite with one channel for two forces (it said 1, the kept
// force's alone), and the finite number where a channel's sigma makes two
// forces nearly indistinguishable.
TEST(ForcesTest, AnUndeterminedForceCarriesTheConditionNumberWithIt) {
  ForceParameters fp;
  fp.shared = ExampleCarTire();
  ForcesResult r = Estimate(fp, Responses(fp.shared, {AxleChannel::kForceZ}, 0, nullptr));
  for (const ConditionForces& c : r.conditions) {
    for (const OrderForces& o : c.orders) {
      ASSERT_EQ(o.forces.size(), 1u) << c.name << " order " << o.order;
      ASSERT_EQ(o.undetermined.size(), 2u);
      int conditioning = 0;
      for (const auto& [f, u] : o.undetermined) {
        if (!u.condition_number_with_it) continue;  // the force no channel responds to
        ++conditioning;
        EXPECT_TRUE(std::isinf(*u.condition_number_with_it)) << *u.condition_number_with_it;
        EXPECT_NE(u.why.find("condition number with it infinite: 2 forces from 1 channel"),
                  std::string::npos)
            << u.why;
      }
      EXPECT_EQ(conditioning, 1) << c.name << " order " << o.order;
    }
  }
  // axle_force_x with a sigma 1e9 times its amplitude: F_x and F_z are told
  // apart by it alone, the condition number ~1e9.
  ResponseDataset d = Responses(fp.shared, {AxleChannel::kForceX, AxleChannel::kForceZ}, 0, nullptr);
  for (ResponseCondition& c : d.conditions) {
    for (OrderResponse& o : c.orders) o.channels.at(AxleChannel::kForceX).sigma *= 1e9;
  }
  r = Estimate(fp, d);
  const ResponseCondition& c = d.conditions[1];
  const OrderResponse& order = c.orders[0];
  AxleResponseMatrix H;
  std::string why;
  ASSERT_TRUE(AxleResponse(RigidRingModel(), fp.shared, c.speed_m_s,
                           r.conditions[1].orders[0].frequency_hz, &H, &why))
      << why;
  Eigen::Matrix2cd A;  // rows axle_force_x, axle_force_z; columns F_x, F_z
  for (int row = 0; row < 2; ++row) {
    const AxleChannel ch = row ? AxleChannel::kForceZ : AxleChannel::kForceX;
    for (int col = 0; col < 2; ++col) {
      A(row, col) = H(static_cast<int>(ch), col) / order.channels.at(ch).sigma;
    }
  }
  const Eigen::Vector2d s = Eigen::JacobiSVD<Eigen::Matrix2cd>(A).singularValues();
  const OrderForces& o = r.conditions[1].orders[0];
  ASSERT_EQ(o.forces.size(), 1u);
  const auto refused = std::find_if(o.undetermined.begin(), o.undetermined.end(),
                                    [](const auto& u) { return u.first != LugForce::kFy; });
  ASSERT_NE(refused, o.undetermined.end());
  ASSERT_TRUE(refused->second.condition_number_with_it.has_value());
  EXPECT_GT(s(0) / s(1), 1e8);
  EXPECT_NEAR(*refused->second.condition_number_with_it, s(0) / s(1), 1e-6 * s(0) / s(1));
  char expected[80];
  std::snprintf(expected, sizeof expected, "condition number with it %.3g, above 1e+06", s(0) / s(1));
  EXPECT_NE(refused->second.why.find(expected), std::string::npos) << refused->second.why;
}

// Each condition's model range is 1.5 times the highest of the car tire's
// standing modes (rotation_anti_phase, 117.888 Hz: `ringid predict`), and
// every order above it is flagged, in the result and in its text.
TEST(ForcesTest, TheOrdersAboveTheModelsRangeAreFlagged) {
  ForceParameters fp;
  fp.shared = ExampleCarTire();
  const ForcesResult r = Estimate(fp, Responses(fp.shared, kAll, 0, nullptr));
  int above = 0, within = 0;
  for (const ConditionForces& c : r.conditions) {
    EXPECT_NEAR(c.model_valid_below_hz, 1.5 * 117.888, 1.5 * 0.001) << c.name;
    for (const OrderForces& o : c.orders) {
      EXPECT_EQ(o.above_model_range, o.frequency_hz > c.model_valid_below_hz)
          << c.name << " order " << o.order;
      ++(o.above_model_range ? above : within);
    }
  }
  EXPECT_GT(above, 0);
  EXPECT_GT(within, 0);
  // At 5 m/s (f_lug 53.05 Hz) orders 4 and 5 lie above 176.8 Hz.
  const std::string text = r.FullReport();
  EXPECT_NE(text.find("drum_5 at 5 m/s, f_lug 53.05 Hz (lugs V / (2 pi r_e0)); the model holds "
                      "below 176.8 Hz"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("      4  212.21* F_z"), std::string::npos) << text;
  EXPECT_NE(text.find("      3  159.15  F_z"), std::string::npos) << text;
  EXPECT_NE(text.find("  * orders 4, 5: above the model's range"), std::string::npos) << text;
}

// 400 replicates at 20 dB (noise of |Y| / 10 on re and on im): per force and
// order, the mean is the truth within 2 % of |F| plus 3 standard errors of
// the mean, and the spread of re and im is std_measurement within 10 %.
TEST(ForcesTest, TheEstimatesAreUnbiasedAndSpreadAsStdMeasurementSays) {
  ForceParameters fp;
  fp.shared = ExampleCarTire();
  std::mt19937_64 rng(11);
  const int replicates = 400;
  const ResponseDataset clean = Responses(fp.shared, kAll, 0.1, nullptr);
  std::map<std::tuple<int, int, LugForce>, std::vector<Complex>> estimates;
  std::map<std::tuple<int, int, LugForce>, double> stds;
  for (int rep = 0; rep < replicates; ++rep) {
    const ForcesResult r = Estimate(fp, Responses(fp.shared, kAll, 0.1, &rng));
    for (size_t c = 0; c < r.conditions.size(); ++c) {
      for (const OrderForces& o : r.conditions[c].orders) {
        for (const auto& [f, e] : o.forces) {
          estimates[{static_cast<int>(c), o.order, f}].push_back(e.value);
          stds[{static_cast<int>(c), o.order, f}] = e.std_measurement;
        }
      }
    }
  }
  ASSERT_EQ(estimates.size(), kSpeeds.size() * 5 * 3);
  for (const auto& [key, values] : estimates) {
    const auto& [c, order, f] = key;
    Complex mean = 0;
    for (const Complex& v : values) mean += v / double(values.size());
    double re2 = 0, im2 = 0;
    for (const Complex& v : values) {
      re2 += std::norm((v - mean).real()) / (values.size() - 1);
      im2 += std::norm((v - mean).imag()) / (values.size() - 1);
    }
    const double sd = stds.at(key), truth = std::abs(TrueForce(f, order));
    const std::string what = std::string(ToString(f)) + " at " + std::to_string(c) + ", order " +
                             std::to_string(order);
    EXPECT_LT(std::abs(mean - TrueForce(f, order)), 0.02 * truth + 3 * sd / std::sqrt(replicates))
        << what;
    EXPECT_NEAR(std::sqrt(re2) / sd, 1, 0.1) << what;
    EXPECT_NEAR(std::sqrt(im2) / sd, 1, 0.1) << what;
  }
}

// std_total adds the parameters' share, linearised; parameters sampled from
// the same covariance spread the estimates by that share (500 samples:
// within 15 %).
TEST(ForcesTest, TheParametersShareOfStdTotalIsTheSpreadUnderSampledParameters) {
  const Parameters truth = ExampleCarTire();
  const ResponseDataset data = Responses(truth, kAll, 0.1, nullptr);
  ForceParameters fp;
  fp.shared = truth;
  // r_e0 moves the lug frequency too (the dataset does not give it).
  const std::vector<Param> uncertain = {Param::k_bz, Param::c_bz, Param::k_cz, Param::k_bx,
                                        Param::k_by, Param::sigma_cy, Param::r_e0};
  Eigen::VectorXd sd(uncertain.size());
  for (size_t i = 0; i < uncertain.size(); ++i) {
    fp.coordinates.push_back({ParameterKey{uncertain[i], ""}, {}});
    sd(i) = 0.03 + 0.01 * i;  // log coordinates: 3-8 %
  }
  fp.covariance = sd.cwiseAbs2().asDiagonal();
  const ForcesResult linear = Estimate(fp, data);
  std::mt19937_64 rng(5);
  std::normal_distribution<double> n(0, 1);
  const int samples = 500;
  const int c = 1, order = 3;  // 10 m/s, the third order
  std::map<LugForce, std::vector<Complex>> spread;
  for (int s = 0; s < samples; ++s) {
    ForceParameters sampled;
    sampled.shared = truth;
    for (size_t i = 0; i < uncertain.size(); ++i) sampled.shared[uncertain[i]] *= std::exp(sd(i) * n(rng));
    const ForcesResult r = Estimate(sampled, data);
    for (const auto& [f, e] : r.conditions[c].orders[order - 1].forces) spread[f].push_back(e.value);
  }
  for (const auto& [f, values] : spread) {
    Complex mean = 0;
    for (const Complex& v : values) mean += v / double(samples);
    double var = 0;
    for (const Complex& v : values) var += std::norm(v - mean) / 2 / (samples - 1);
    const ForceEstimate& e = linear.conditions[c].orders[order - 1].forces.at(f);
    const double share = std::sqrt(e.std_total * e.std_total - e.std_measurement * e.std_measurement);
    ASSERT_GT(share, 0.05 * e.std_measurement) << ToString(f);  // the parameters matter here
    EXPECT_NEAR(std::sqrt(var) / share, 1, 0.15) << ToString(f);
  }
}

// A parameter that is not positive is fitted as value / TypicalScale: its
// covariance is in those units, and sampling it so spreads the estimates as
// the linearised share says (an anisotropic sidewall's dk_bz).
TEST(ForcesTest, AnEffectParameterCarriesItsUncertaintyInItsFittedCoordinate) {
  const RigidRingModel model({FindEffect("anisotropic_sidewall")});
  Parameters truth = ExampleCarTire();
  truth[Param::dk_bz] = 0.1 * truth[Param::k_bz];
  truth[Param::dk_bpsi] = 0;
  ResponseDataset data;
  std::string why;
  ASSERT_TRUE(SimulateResponses(
      model, truth, kLugs, kSpeeds, 5, kAll,
      [](int k) {
        return std::array<Complex, kNumLugForces>{TrueForce(LugForce::kFx, k),
                                                  TrueForce(LugForce::kFz, k),
                                                  TrueForce(LugForce::kFy, k)};
      },
      0.1, nullptr, &data, &why))
      << why;
  ForceParameters fp;
  fp.shared = truth;
  fp.coordinates.push_back({ParameterKey{Param::dk_bz, ""}, {}});
  // 5 % of k_bz: small enough for the linearisation (a scale mistaken for 1
  // would be a factor 1e4 off).
  const double sd = 0.05 * truth[Param::k_bz] / TypicalScale(Param::dk_bz);
  fp.covariance = Eigen::MatrixXd::Constant(1, 1, sd * sd);
  const ForcesResult linear = Estimate(fp, data, model);
  std::mt19937_64 rng(9);
  std::normal_distribution<double> n(0, 1);
  const int samples = 400, c = 0, order = 2;
  std::vector<Complex> values;
  for (int s = 0; s < samples; ++s) {
    ForceParameters sampled;
    sampled.shared = truth;
    sampled.shared[Param::dk_bz] += sd * TypicalScale(Param::dk_bz) * n(rng);
    values.push_back(Estimate(sampled, data, model).conditions[c].orders[order - 1].forces.at(
        LugForce::kFz).value);
  }
  Complex mean = 0;
  for (const Complex& v : values) mean += v / double(samples);
  double var = 0;
  for (const Complex& v : values) var += std::norm(v - mean) / 2 / (samples - 1);
  const ForceEstimate& e = linear.conditions[c].orders[order - 1].forces.at(LugForce::kFz);
  const double share = std::sqrt(e.std_total * e.std_total - e.std_measurement * e.std_measurement);
  ASSERT_GT(share, 0.05 * e.std_measurement);
  EXPECT_NEAR(std::sqrt(var) / share, 1, 0.15);
}

// datasets/examples/car_tire_lug_response.json is what it says it is (its
// README): the car tire's axle response at 6, 12 and 18 m/s, orders 1-5,
// every channel, to TrueForce, with 10 % noise drawn from seed 2026.
// RINGID_REGENERATE=1 writes it again.
// A covariance that does not match the coordinates is refused, not read
// out of its bounds.
TEST(ForcesTest, ACovarianceOfTheWrongSizeIsInvalidInput) {
  ForceParameters fp;
  fp.shared = ExampleCarTire();
  fp.coordinates = {{ParameterKey{Param::k_bz, ""}, {}}, {ParameterKey{Param::k_cz, ""}, {}}};
  fp.covariance = Eigen::MatrixXd::Identity(1, 1);
  ForcesResult r;
  EstimateForces(RigidRingModel(), fp, Responses(fp.shared, kAll, 0.1, nullptr), ForcesOptions{}, &r);
  EXPECT_TRUE(r.status.invalid_input()) << r.status.message;
  EXPECT_NE(r.status.message.find("2 x 2"), std::string::npos) << r.status.message;
}

// The lug forces of the shipped examples: TrueForce at orders 1-5.
LugForceSpectrum ShippedLugForces() {
  LugForceSpectrum s;
  s.name = "car_tire_lug_forces";
  s.description =
      "The lug forces of car_tire_lug_response.json (20 lugs; order k: F_x 300/k N at phase 0.7k "
      "rad, F_z 900/k N at 0.7k + 1, F_y 150/k N at 0.7k + 2). Made by ringid's tests: see "
      "datasets/examples/README.md.";
  s.lugs_per_revolution = kLugs;
  for (int k = 1; k <= 5; ++k) {
    s.orders[k] = {TrueForce(LugForce::kFx, k), TrueForce(LugForce::kFz, k),
                   TrueForce(LugForce::kFy, k)};
  }
  return s;
}

TEST(ResponseDatasetTest, TheShippedLugForcesAreThoseItsReadmeDescribes) {
  const std::string path = testing::SourcePath("datasets/examples/car_tire_lug_forces.json");
  const std::string text = LugForcesToJson(ShippedLugForces());
  if (std::getenv("RINGID_REGENERATE")) std::ofstream(path) << text;
  EXPECT_EQ(testing::ReadFile(path), text)
      << "RINGID_REGENERATE=1 build/tests/estimation_tests --gtest_filter=*ShippedLugForces*";
  LugForceSpectrum back;
  LoadError e;
  ASSERT_TRUE(LoadLugForces(path, &back, &e)) << e.OneLine();
  EXPECT_EQ(LugForcesToJson(back), text);
}

// `ringid simulate --lug_forces` of the shipped lug forces, at the shipped
// response's speeds, noise and seed, writes that response (its name and
// description aside): both examples are ringid's.
TEST(ForcesCommandTest, SimulateOfTheShippedLugForcesWritesTheShippedResponse) {
  const std::string out = Scratch("shipped_response.json");
  std::remove(out.c_str());
  const RunResult r = Ringid(
      "simulate --parameters=" + testing::SourcePath("datasets/examples/car_tire.json") +
      " --lug_forces=" + testing::SourcePath("datasets/examples/car_tire_lug_forces.json") +
      " --speeds=6,12,18 --response_noise=0.1 --seed=2026 --output=" + out);
  ASSERT_EQ(r.status, 0) << r.err;
  const Json made = Json::parse(testing::ReadFile(out));
  const Json shipped = Json::parse(
      testing::ReadFile(testing::SourcePath("datasets/examples/car_tire_lug_response.json")));
  EXPECT_EQ(made["conditions"], shipped["conditions"]);
  EXPECT_EQ(made["lugs_per_revolution"], shipped["lugs_per_revolution"]);
}

TEST(ResponseDatasetTest, TheShippedExampleIsTheSimulationItsReadmeDescribes) {
  ResponseDataset d;
  d.name = "car_tire_lug_response";
  d.description =
      "The axle's response of car_tire.json (ExampleCarTire) on a drum at 6, 12 and 18 m/s to "
      "known lug forces (20 lugs; order k: F_x 300/k N, F_z 900/k N, F_y 150/k N with phases), "
      "every channel, noise of a tenth of each amplitude (seed 2026). Simulated, not measured: "
      "see datasets/examples/README.md.";
  std::mt19937_64 rng(2026);
  std::string why;
  ASSERT_TRUE(SimulateResponses(
      RigidRingModel(), ExampleCarTire(), kLugs, {6, 12, 18}, 5, kAll,
      [](int k) {
        return std::array<Complex, kNumLugForces>{TrueForce(LugForce::kFx, k),
                                                  TrueForce(LugForce::kFz, k),
                                                  TrueForce(LugForce::kFy, k)};
      },
      0.1, &rng, &d, &why))
      << why;
  const std::string path = testing::SourcePath("datasets/examples/car_tire_lug_response.json");
  if (std::getenv("RINGID_REGENERATE")) std::ofstream(path) << ResponseDatasetToJson(d);
  EXPECT_EQ(testing::ReadFile(path), ResponseDatasetToJson(d))
      << "RINGID_REGENERATE=1 build/tests/estimation_tests --gtest_filter=*ShippedExample*";
}

TEST(ResponseDatasetTest, WritesReadsAndWritesTheSameBytes) {
  const ResponseDataset d = Responses(ExampleCarTire(), kAll, 0.1, nullptr);
  const std::string text = ResponseDatasetToJson(d);
  ResponseDataset again;
  LoadError e;
  ASSERT_TRUE(ParseResponseDataset(text, "r.json", &again, &e)) << e.OneLine();
  EXPECT_EQ(ResponseDatasetToJson(again), text);
  ASSERT_EQ(again.conditions.size(), 3u);
  EXPECT_EQ(again.conditions[1].orders[2].channels.at(AxleChannel::kForceZ).value,
            d.conditions[1].orders[2].channels.at(AxleChannel::kForceZ).value);
}

TEST(ResponseDatasetTest, RefusesEachKindOfBadFileNamingTheField) {
  const std::string good = R"({"format": "ringid-lug-response/1", "name": "r", "lugs_per_revolution": 20,
    "conditions": [{"name": "drum_8", "speed_m_s": 8.0, "orders": [{"order": 1,
      "response": {"axle_force_x": {"re": 12.3, "im": -4.1, "sigma": 0.5}}}]}]})";
  ResponseDataset d;
  LoadError e;
  ASSERT_TRUE(ParseResponseDataset(good, "r.json", &d, &e)) << e.OneLine();
  auto with = [&](const std::string& from, const std::string& to) {
    std::string text = good;
    const size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    return text.replace(at, from.size(), to);
  };
  const std::pair<std::string, std::string> bad[] = {
      {with("\"name\": \"r\", ", ""), "name"},
      {with("\"lugs_per_revolution\": 20", "\"lugs_per_revolution\": 0"), "lugs_per_revolution"},
      {with("\"lugs_per_revolution\": 20", "\"lugs_per_revolution\": 2.5"), "lugs_per_revolution"},
      {with("\"speed_m_s\": 8.0", "\"speed_m_s\": 0"), "conditions[0].speed_m_s"},
      {with("\"speed_m_s\": 8.0", "\"speed_m_s\": -3"), "conditions[0].speed_m_s"},
      {with("\"order\": 1", "\"order\": 0"), "conditions[0].orders[0].order"},
      {with("{\"axle_force_x\": {\"re\": 12.3, \"im\": -4.1, \"sigma\": 0.5}}", "{}"),
       "conditions[0].orders[0].response"},
      {with("axle_force_x", "axle_force_q"), "conditions[0].orders[0].response.axle_force_q"},
      {with("\"sigma\": 0.5", "\"sigma\": 0"), "conditions[0].orders[0].response.axle_force_x.sigma"},
      {with("\"im\": -4.1", "\"im\": \"x\""), "conditions[0].orders[0].response.axle_force_x.im"},
      {with("\"orders\"", "\"f_lug_hz\": -1, \"orders\""), "conditions[0].f_lug_hz"},
      {with("\"orders\"", "\"known\": {\"k_cz\": -1}, \"orders\""), "conditions[0].known.k_cz"},
      {with("\"orders\"", "\"extra\": 1, \"orders\""), "conditions[0].extra"},
      {with("ringid-lug-response/1", "ringid-lug-response/2"), "format"},
      {with("\"lugs_per_revolution\": 20", "\"lugs_per_revolution\": 4294967316"),
       "lugs_per_revolution"},
  };
  for (const auto& [text, field] : bad) {
    EXPECT_FALSE(ParseResponseDataset(text, "r.json", &d, &e)) << text;
    EXPECT_EQ(e.field, field) << e.OneLine();
    EXPECT_EQ(e.OneLine().rfind("r.json: ", 0), 0u) << e.OneLine();
  }
  EXPECT_FALSE(ParseResponseDataset(with("axle_force_x", "axle_forc_x"), "r.json", &d, &e));
  EXPECT_NE(e.message.find("did you mean 'axle_force_x'"), std::string::npos) << e.message;
}

// The command: a report that reads back; bad input exits 2 and writes nothing.
TEST(ForcesCommandTest, WritesAReportAndRefusesBadInputWithExitTwo) {
  const std::string data = Scratch("forces_data.json"), set = Scratch("forces_set.json"),
                    out = Scratch("forces_report.json");
  std::ofstream(data) << ResponseDatasetToJson(Responses(ExampleCarTire(), kAll, 0.1, nullptr));
  std::ofstream(set) << ParameterSetToJson(ExampleCarTire(), "car", "example");
  std::remove(out.c_str());
  RunResult r = Ringid("forces --parameters=" + set + " --dataset=" + data + " --output=" + out);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("F_z"), std::string::npos);
  ForcesReport report;
  std::string error;
  ASSERT_TRUE(ReadReport(Json::parse(testing::ReadFile(out)), &report, &error)) << error;
  EXPECT_EQ(report.body.result.conditions.size(), 3u);
  std::remove(out.c_str());
  const std::string bad = Scratch("forces_bad.json");
  std::ofstream(bad) << R"({"format": "ringid-lug-response/1", "name": "r", "lugs_per_revolution": 20,
    "conditions": [{"name": "d", "speed_m_s": 8, "orders": [{"order": 1, "response": {}}]}]})";
  r = Ringid("forces --parameters=" + set + " --dataset=" + bad + " --output=" + out);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find(bad + ": conditions[0].orders[0].response: names no channel"),
            std::string::npos)
      << r.err;
  EXPECT_FALSE(testing::Exists(out));
}

// The forces use the model that was fitted: a set holding an effect's
// parameter without --effects is refused; predict's lug orders need speeds.
TEST(ForcesCommandTest, TheModelOfTheFitIsAskedForAndLugsNeedSpeeds) {
  const std::string data = Scratch("forces_effect_data.json"), set = Scratch("forces_effect_set.json");
  std::ofstream(data) << ResponseDatasetToJson(Responses(ExampleCarTire(), kAll, 0.1, nullptr));
  Parameters p = ExampleCarTire();
  p[Param::dk_bz] = 1e4;
  std::ofstream(set) << ParameterSetToJson(p, "car", "with a sidewall anisotropy");
  RunResult r = Ringid("forces --parameters=" + set + " --dataset=" + data);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("parameters.dk_bz: a parameter of anisotropic_sidewall, which the model "
                       "lacks; give --effects=anisotropic_sidewall"),
            std::string::npos)
      << r.err;
  r = Ringid("forces --effects=anisotropic_sidewall --parameters=" + set + " --dataset=" + data);
  EXPECT_EQ(r.status, 0) << r.err;
  r = Ringid("predict --parameters=" + set + " --effects=anisotropic_sidewall --lugs_per_revolution=20");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("--lugs_per_revolution: needs --speeds"), std::string::npos) << r.err;
}

// simulate --lug_forces writes the axle's response to the forces given, at
// the orders given; forces recovers them (to the noise asked for, 1e-6).
// Zero speeds, a truth file and a misspelt force are refused with exit 2.
TEST(ForcesCommandTest, SimulateWritesTheResponseToGivenLugForcesAndForcesRecoversThem) {
  const std::string set = Scratch("lugs_set.json"), lugs = Scratch("lugs.json"),
                    response = Scratch("lugs_response.json"), out = Scratch("lugs_forces.json");
  std::ofstream(set) << ParameterSetToJson(ExampleCarTire(), "car", "example");
  const std::string lug_forces = R"({"format": "ringid-lug-forces/1", "name": "tread",
    "lugs_per_revolution": 20,
    "orders": [{"order": 1, "forces": {"F_x": {"re": 300, "im": 0}, "F_z": {"re": 0, "im": 900},
                                       "F_y": {"re": -150, "im": 50}}},
               {"order": 3, "forces": {"F_z": {"re": 200, "im": -100}}}]})";
  std::ofstream(lugs) << lug_forces;
  const std::string base = "simulate --parameters=" + set + " --lug_forces=" + lugs;
  RunResult r = Ringid(base + " --speeds=8,14 --response_noise=1e-6 --seed=3 --output=" + response);
  ASSERT_EQ(r.status, 0) << r.err;
  r = Ringid("forces --parameters=" + set + " --dataset=" + response + " --output=" + out);
  ASSERT_EQ(r.status, 0) << r.err;
  ForcesReport report;
  std::string error;
  ASSERT_TRUE(ReadReport(Json::parse(testing::ReadFile(out)), &report, &error)) << error;
  const std::map<int, std::array<Complex, 3>> given = {
      {1, {Complex(300, 0), Complex(0, 900), Complex(-150, 50)}}, {3, {0.0, Complex(200, -100), 0.0}}};
  ASSERT_EQ(report.body.result.conditions.size(), 2u);
  for (const ConditionForces& c : report.body.result.conditions) {
    ASSERT_EQ(c.orders.size(), 2u) << c.name;  // orders 1 and 3 only
    for (const OrderForces& o : c.orders) {
      for (const auto& [f, e] : o.forces) {
        const Complex truth = given.at(o.order)[static_cast<int>(f)];
        EXPECT_LT(std::abs(e.value - truth), 1e-3 * 900) << c.name << " " << ToString(f);
      }
    }
  }
  r = Ringid(base + " --speeds=0,8 --output=" + Scratch("lugs_zero.json"));
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("a lug order exists only rolling"), std::string::npos) << r.err;
  // Without --speeds (whose default, 0, is standing) the speeds are asked for by name.
  r = Ringid(base + " --output=" + Scratch("lugs_no_speeds.json"));
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, "ringid: simulate --lug_forces needs --speeds=V1,V2,... (drum speeds in m/s, "
                   "each > 0: a lug order exists only rolling)\n");
  EXPECT_FALSE(testing::Exists(Scratch("lugs_no_speeds.json")));
  r = Ringid(base + " --speeds=8 --truth=" + Scratch("t.json") + " --output=" + Scratch("l2.json"));
  EXPECT_EQ(r.status, 2);
  std::string misspelt = lug_forces;
  misspelt.replace(misspelt.find("\"F_y\""), 5, "\"F_q\"");
  std::ofstream(lugs) << misspelt;
  r = Ringid(base + " --speeds=8 --output=" + Scratch("l3.json"));
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find(lugs + ": orders[0].forces.F_q: unknown force 'F_q'"), std::string::npos)
      << r.err;
  EXPECT_FALSE(testing::Exists(Scratch("l3.json")));
}

// A fit with the load per condition gives it to a response condition of the
// same name; another name without the load is refused, naming both.
TEST(ForcesCommandTest, APerConditionValueComesFromTheFitsConditionOfThatName) {
  const std::string set = Scratch("forces_loads_set.json"), modes = Scratch("forces_loads.json"),
                    fit = Scratch("forces_loads_fit.json"), data = Scratch("forces_loads_data.json");
  std::ofstream(set) << ParameterSetToJson(ExampleCarTire(), "car", "example");
  RunResult r = Ringid("simulate --parameters=" + set + " --speeds=0,6 --loads=3000,4500 --output=" +
                       modes + " --truth=" + Scratch("forces_loads_truth.json"));
  ASSERT_EQ(r.status, 0) << r.err;
  r = Ringid("identify --starts=1 --derivatives=analytic --dataset=" + modes + " --output=" + fit);
  ASSERT_EQ(r.status, 0) << r.err;
  ResponseDataset d = Responses(ExampleCarTire(), kAll, 0.1, nullptr);
  d.conditions.resize(1);
  d.conditions[0].name = "drum_6_4500N";
  std::ofstream(data) << ResponseDatasetToJson(d);
  r = Ringid("forces --parameters=" + fit + " --dataset=" + data);
  EXPECT_EQ(r.status, 0) << r.err;
  // The report of a fit that failed gives no forces.
  Json failed = Json::parse(testing::ReadFile(fit));
  failed["status"] = "failed";
  const std::string failed_fit = Scratch("forces_loads_failed_fit.json");
  std::ofstream(failed_fit) << failed.dump(2);
  r = Ringid("forces --parameters=" + failed_fit + " --dataset=" + data);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find(failed_fit + ": status: the identification did not succeed"), std::string::npos)
      << r.err;
  d.conditions[0].name = "drum_5";
  std::ofstream(data) << ResponseDatasetToJson(d);
  r = Ringid("forces --parameters=" + fit + " --dataset=" + data);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find(data + ": conditions[0].known.F_cz0: missing: " + fit +
                       " fitted F_cz0 per condition (drum_6_3000N, drum_6_4500N"),
            std::string::npos)
      << r.err;
}

// forces on the shipped response with axle_force_z alone: the report says
// why F_x is not determined and with what condition number (infinite: null
// in JSON), and flags the orders above the model's range.
TEST(ForcesCommandTest, TheReportSaysTheConditionNumberWithTheForceAndTheModelsRange) {
  Json d = Json::parse(
      testing::ReadFile(testing::SourcePath("datasets/examples/car_tire_lug_response.json")));
  for (Json& c : d["conditions"]) {
    for (Json& o : c["orders"]) o["response"] = {{"axle_force_z", o["response"]["axle_force_z"]}};
  }
  const std::string data = Scratch("forces_z_only.json"), out = Scratch("forces_z_only_report.json");
  std::ofstream(data) << d.dump(2);
  std::remove(out.c_str());
  const RunResult r = Ringid("forces --parameters=" +
                             testing::SourcePath("datasets/examples/car_tire.json") +
                             " --dataset=" + data + " --output=" + out);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("F_x   not determined: the measured channels cannot tell it from the forces "
                       "kept (condition number with it infinite: 2 forces from 1 channel)"),
            std::string::npos)
      << r.out;
  EXPECT_EQ(r.out.find("condition number 1 with it"), std::string::npos) << r.out;
  const Json report = Json::parse(testing::ReadFile(out));
  const Json& order1 = report["conditions"][0]["orders"][0];
  ASSERT_TRUE(order1["undetermined"]["F_x"].contains("condition_number_with_it")) << order1.dump();
  EXPECT_TRUE(order1["undetermined"]["F_x"]["condition_number_with_it"].is_null());
  EXPECT_FALSE(order1["undetermined"]["F_y"].contains("condition_number_with_it"));
  // drum_18: f_lug 191 Hz, every order above 1.5 x 117.9 Hz.
  const Json& drum_18 = report["conditions"][2];
  EXPECT_NEAR(drum_18["model_valid_below_hz"].get<double>(), 176.83, 0.01);
  for (const Json& o : drum_18["orders"]) EXPECT_TRUE(o["above_model_range"].get<bool>()) << o.dump();
  EXPECT_FALSE(report["conditions"][0]["orders"][0]["above_model_range"].get<bool>());
  ForcesReport back;
  std::string error;
  EXPECT_TRUE(ReadReport(report, &back, &error)) << error;
}

// predict --max_order bounds the orders whose critical speeds are listed
// (default 5); the crossings kept are those of the full list up to it.
TEST(ForcesCommandTest, PredictListsTheCriticalSpeedsUpToMaxOrder) {
  const std::string base = "predict --parameters=" +
                           testing::SourcePath("datasets/examples/car_tire.json") +
                           " --speeds=0,0.1,5,10,15 --lugs_per_revolution=20 --output=";
  const auto Listed = [&](const std::string& flag) {
    const std::string out = Scratch("max_order.json");
    std::remove(out.c_str());
    const RunResult r = Ringid(base + out + flag);
    EXPECT_EQ(r.status, 0) << flag << ": " << r.err;
    return std::make_pair(r.out, Json::parse(testing::ReadFile(out)));
  };
  const auto [text, by_default] = Listed("");
  const auto [all_text, all] = Listed(" --max_order=200");
  EXPECT_EQ(by_default["max_order"], 5);
  EXPECT_NE(text.find("critical speeds (20 lugs per revolution; orders 1 to 5, --max_order):"),
            std::string::npos)
      << text;
  int highest = 0;
  Json expected = Json::array();
  for (const Json& c : all["critical_speeds"]) {
    highest = std::max(highest, c["order"].get<int>());
    if (c["order"].get<int>() <= 5) expected.push_back(c);
  }
  EXPECT_GT(highest, 50);  // slow speeds alone meet orders by the dozen
  EXPECT_GT(all["critical_speeds"].size(), 5 * by_default["critical_speeds"].size());
  EXPECT_EQ(by_default["critical_speeds"], expected);
  EXPECT_LE(by_default["critical_speeds"].size(), 40u);
  for (const std::string bad : {"0", "201"}) {
    const RunResult r = Ringid(base + Scratch("max_order_bad.json") + " --max_order=" + bad);
    EXPECT_EQ(r.status, 2) << bad;
    EXPECT_EQ(r.err, "ringid: --max_order: must lie in [1, 200]\n") << bad;
  }
}

}  // namespace
}  // namespace ringid
