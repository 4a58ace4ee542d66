// The response over time against closed forms and the frequency response
// code (model/frequency_response.h), which assembles H another way.
#include <array>
#include <cmath>
#include <complex>
#include <string>
#include <vector>

#include <Eigen/LU>
#include <gtest/gtest.h>

#include "datasets/synthetic.h"
#include "model/effects.h"
#include "model/frequency_response.h"
#include "model/time_response.h"
#include "tests/test_support.h"

namespace ringid {
namespace {

// m x'' + c x' + k x = F, F a unit step at t = 0 (held constant, so the
// first-order hold is exact): x(t) = (1 - e^(-zeta wn t) (cos wd t +
// zeta / sqrt(1 - zeta^2) sin wd t)) / k.
TEST(TimeResponseTest, AOneDegreeOfFreedomStepIsItsClosedForm) {
  const double m = 2.0, c = 12.0, k = 8000.0;
  StateSpace s;
  s.A.resize(2, 2);
  s.A << 0, 1, -k / m, -c / m;
  s.B = Eigen::MatrixXd::Zero(2, 3);
  s.B(1, 0) = 1 / m;
  s.C = Eigen::MatrixXd::Zero(1, 2);
  s.C(0, 0) = 1;
  std::vector<double> t;
  for (int i = 0; i <= 2000; ++i) t.push_back(i * 1e-3);
  Eigen::MatrixXd u = Eigen::MatrixXd::Zero(3, t.size());
  u.row(0).setOnes();
  const Eigen::MatrixXd y = SimulateHeld(s, t, u);
  const double wn = std::sqrt(k / m), zeta = c / (2 * std::sqrt(k * m));
  const double wd = wn * std::sqrt(1 - zeta * zeta);
  for (size_t i = 0; i < t.size(); ++i) {
    const double closed = (1 - std::exp(-zeta * wn * t[i]) *
                                   (std::cos(wd * t[i]) +
                                    zeta / std::sqrt(1 - zeta * zeta) * std::sin(wd * t[i]))) /
                          k;
    EXPECT_NEAR(y(0, i), closed, 1e-12 / k) << t[i];
  }
}

// The FRF request of the time response's inputs and outputs.
ResponseRequest TimeRequest(double hz) {
  ResponseRequest r;
  for (Dof d : {Dof::kXb, Dof::kZb, Dof::kYb}) r.inputs.push_back({std::nullopt, {{d, 1.0}}});
  for (int c = 0; c < kNumAxleChannels; ++c) {
    r.outputs.push_back({static_cast<AxleChannel>(c), {}, 0});
  }
  r.outputs.push_back({std::nullopt, {{Dof::kThetaA, 1.0}}, 1});  // the rim's spin rate
  for (int o = 0; o < kNumTimeOutputs; ++o) {
    for (int i = 0; i < 3; ++i) r.pairs.push_back({o, i});
  }
  r.frequencies_hz = {hz};
  return r;
}

// The state space's transfer C (i w - A)^-1 B is the FRF code's H, standing
// and rolling, with an effect that adds coordinates (the hub) and one that
// couples the planes.
TEST(TimeResponseTest, TheStateSpacesTransferIsTheFrequencyResponse) {
  for (const char* name : {"", "hub_compliance", "lug_coupling", "contact_yaw_stiffness"}) {
    const Effect* effect = *name ? FindEffect(name) : nullptr;
    const RigidRingModel model(effect ? std::vector<const Effect*>{effect}
                                      : std::vector<const Effect*>{});
    const Parameters p =
        effect ? testing::WithEffectSized(*effect, ExampleCarTire()) : ExampleCarTire();
    for (double speed : {0.0, 12.0}) {
      StateSpace s;
      std::string why;
      ASSERT_TRUE(RollingStateSpace(model, p, speed, &s, &why)) << why;
      for (double hz : {7.0, 48.0, 95.0, 170.0}) {
        const ResponseResult h = FrequencyResponse(model, p, speed, TimeRequest(hz));
        ASSERT_TRUE(h.ok) << h.error;
        const std::complex<double> iw(0, 2 * M_PI * hz);
        const Eigen::MatrixXcd G =
            s.C.cast<std::complex<double>>() *
            (iw * Eigen::MatrixXcd::Identity(s.A.rows(), s.A.cols()) -
             s.A.cast<std::complex<double>>())
                .lu()
                .solve(s.B.cast<std::complex<double>>());
        for (int f = 0; f < static_cast<int>(h.H.cols()); ++f) {
          const auto [o, i] = TimeRequest(hz).pairs[f];
          EXPECT_LE(std::abs(G(o, i) - h.H(0, f)), 1e-9 * std::abs(h.H(0, f)) + 1e-14)
              << name << ", speed " << speed << ", " << hz << " Hz, output " << o << ", input "
              << i;
        }
      }
    }
  }
}

// From the steady state of sinusoidal forces at t = 0, the exact
// discretisation with the forces held first-order stays on it: y(t) =
// Re(H U e^(i w t)), H the FRF code's, to the hold's error, about
// (w dt)^2 / 12 of the amplitude.
TEST(TimeResponseTest, ASinusoidsResponseIsTheFrfTimesTheInput) {
  const RigidRingModel model;
  const Parameters p = ExampleCarTire();
  const double hz[3] = {23.0, 61.0, 88.0};  // one per input
  const double dt = 2e-6;  // (w dt)^2 / 12 at most 1.0e-7
  for (double speed : {0.0, 15.0}) {
    StateSpace s;
    std::string why;
    ASSERT_TRUE(RollingStateSpace(model, p, speed, &s, &why)) << why;
    const Eigen::Index n = s.A.rows();
    std::vector<double> t;
    for (int k = 0; k <= 25000; ++k) t.push_back(k * dt);
    Eigen::MatrixXd u(3, t.size());
    Eigen::VectorXcd x0 = Eigen::VectorXcd::Zero(n);
    std::vector<Eigen::VectorXcd> H(3);
    for (int i = 0; i < 3; ++i) {
      const double w = 2 * M_PI * hz[i];
      for (size_t k = 0; k < t.size(); ++k) u(i, k) = std::cos(w * t[k]);
      // The state's steady amplitude, (i w - A)^-1 B_i: the start only.
      x0 += (std::complex<double>(0, w) * Eigen::MatrixXcd::Identity(n, n) -
             s.A.cast<std::complex<double>>())
                .lu()
                .solve(s.B.col(i).cast<std::complex<double>>());
      const ResponseResult h = FrequencyResponse(model, p, speed, TimeRequest(hz[i]));
      ASSERT_TRUE(h.ok) << h.error;
      H[i] = Eigen::VectorXcd(kNumTimeOutputs);
      for (int o = 0; o < kNumTimeOutputs; ++o) H[i][o] = h.H(0, 3 * o + i);
    }
    const Eigen::MatrixXd y = SimulateHeld(s, t, u, x0.real());
    for (int o = 0; o < kNumTimeOutputs; ++o) {
      double amplitude = 0;
      for (int i = 0; i < 3; ++i) amplitude += std::abs(H[i][o]);
      for (size_t k = 0; k < t.size(); k += 101) {
        double expected = 0;
        for (int i = 0; i < 3; ++i) {
          expected += (H[i][o] * std::exp(std::complex<double>(0, 2 * M_PI * hz[i] * t[k]))).real();
        }
        EXPECT_NEAR(y(o, k), expected, 1e-6 * amplitude) << "speed " << speed << ", output " << o
                                                         << ", t " << t[k];
      }
    }
  }
}

// Chevron lugs (pitch 0.15 m, ten lanes at 15 degrees) at 10 m/s.
ObstacleRun LugRun(LanePattern pattern) {
  ObstacleRun run;
  run.speed_m_s = 10;
  run.profile.kind = ProfileKind::kLugs;
  run.profile.height_m = 0.025;
  run.profile.length_m = 0.05;
  run.profile.pitch_m = 0.15;
  run.profile.width_m = 0.4;
  run.profile.angle_deg = 15;
  run.profile.pattern = pattern;
  run.cam = {0.12, 0.30, 1.8, 0.10};
  run.position_at_t0_m = 0.013;
  for (int k = 0; k < 300; ++k) run.times_s.push_back(k * 1e-4);  // 1 mm apart, two pitches
  return run;
}

// The lugs' periodic steady state against the frequency response: the
// forces held first-order on the 1 mm grid are a periodic piecewise-linear
// u, whose Fourier coefficients are the samples' DFT times sinc^2(pi k / N);
// each order k responds through the FRF code's H at k V / P (the mean
// left out), summed to |k| = 3N.
TEST(TimeResponseTest, TheLugsSteadyStateIsTheResponseToTheForcesFourierSeries) {
  const RigidRingModel model;
  const Parameters p = ExampleCarTire();
  const ObstacleRun run = LugRun(LanePattern::kChevron);
  ObstacleResult r;
  std::string why;
  ASSERT_TRUE(ObstacleResponse(model, p, run, &r, &why)) << why;
  const Eigen::MatrixXd& y = r.y;
  const int N = 150;  // samples per pitch
  std::vector<std::array<double, 3>> u(N);
  for (int j = 0; j < N; ++j) {
    const EffectiveInput e = Effective(run.profile, run.cam, run.position_at_t0_m + j * 1e-3);
    u[j] = {-p[Param::F_cz0] * e.beta, -p[Param::k_cz] * e.w, -p[Param::F_cz0] * e.beta_x};
  }
  const int orders = 3 * N;
  const double f0 = run.speed_m_s / run.profile.pitch_m;
  ResponseRequest request = TimeRequest(f0);
  request.frequencies_hz.clear();
  for (int k = 1; k <= orders; ++k) request.frequencies_hz.push_back(k * f0);
  const ResponseResult h = FrequencyResponse(model, p, run.speed_m_s, request);
  ASSERT_TRUE(h.ok) << h.error;
  // The Fourier coefficient of each input at each order.
  std::vector<std::array<std::complex<double>, 3>> c(orders + 1);
  for (int k = 1; k <= orders; ++k) {
    const double x = M_PI * k / N, sinc2 = std::pow(std::sin(x) / x, 2);
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < N; ++j) {
        c[k][i] += u[j][i] * std::exp(std::complex<double>(0, -2 * M_PI * k * j / N));
      }
      c[k][i] *= sinc2 / N;
    }
  }
  for (int o = 0; o < kNumTimeOutputs; ++o) {
    double peak = 0;
    for (int k = 0; k < y.cols(); ++k) peak = std::max(peak, std::abs(y(o, k)));
    for (int s = 0; s < y.cols(); s += 7) {
      const double t = run.times_s[s];
      double expected = 0;
      for (int k = 1; k <= orders; ++k) {
        for (int i = 0; i < 3; ++i) {
          expected += 2 * (h.H(k - 1, 3 * o + i) * c[k][i] *
                           std::exp(std::complex<double>(0, 2 * M_PI * k * f0 * t)))
                              .real();
        }
      }
      EXPECT_NEAR(y(o, s), expected, 1e-6 * peak + 1e-9) << "output " << o << ", t " << t;
    }
  }
}

// Cross-stitch lugs: half a pitch on, the vertical and longitudinal response
// repeats and the lateral reverses (only even and only odd orders).
TEST(TimeResponseTest, AlternatingLugsShakeTheAxleVerticallyAtEvenOrdersAndLaterallyAtOdd) {
  const ObstacleRun run = LugRun(LanePattern::kAlternating);
  ObstacleResult r;
  std::string why;
  ASSERT_TRUE(ObstacleResponse(RigidRingModel(), ExampleCarTire(), run, &r, &why)) << why;
  const Eigen::MatrixXd& y = r.y;
  const int half = 75;  // half a pitch, in samples
  for (AxleChannel c : {AxleChannel::kForceX, AxleChannel::kForceZ, AxleChannel::kForceY,
                        AxleChannel::kMomentX, AxleChannel::kMomentZ}) {
    const int o = static_cast<int>(c);
    const double sign = c == AxleChannel::kForceX || c == AxleChannel::kForceZ ? 1 : -1;
    const double peak = y.row(o).cwiseAbs().maxCoeff();
    EXPECT_GT(peak, 0) << ToString(c);
    for (int k = 0; k + half < y.cols(); ++k) {
      EXPECT_NEAR(y(o, k + half), sign * y(o, k), 1e-9 * peak) << ToString(c) << " " << k;
    }
  }
}

// A cleat at 15 m/s sampled at 2 kHz (7.5 mm of travel, held on 8 steps of
// the 1 mm grid) against samples 0.094 mm apart: the grid is fine enough.
void ExpectConvergedOnTheMillimetreGrid(const TandemCam& cam, double tolerance) {
  ObstacleRun run;
  run.speed_m_s = 15;
  run.profile.height_m = 0.015;
  run.profile.length_m = 0.02;
  run.cam = cam;
  run.position_at_t0_m = -0.3;
  ObstacleRun fine = run;
  for (int k = 0; k < 100; ++k) run.times_s.push_back(k * 5e-4);
  for (int k = 0; k < 8000; ++k) fine.times_s.push_back(k * 6.25e-6);
  ObstacleResult coarse, fine_result;
  std::string why;
  ASSERT_TRUE(ObstacleResponse(RigidRingModel(), ExampleCarTire(), run, &coarse, &why)) << why;
  ASSERT_TRUE(ObstacleResponse(RigidRingModel(), ExampleCarTire(), fine, &fine_result, &why))
      << why;
  const Eigen::MatrixXd &y = coarse.y, &z = fine_result.y;
  EXPECT_FALSE(coarse.reaches_at_t0);  // the front cam reaches the cleat at X = -0.18 m
  for (int o = 0; o < kNumTimeOutputs; ++o) {
    const double peak = z.row(o).cwiseAbs().maxCoeff();
    for (int k = 0; k < 100; ++k) {
      EXPECT_NEAR(y(o, k), z(o, 80 * k), tolerance * peak) << o << " " << k;
    }
  }
}

TEST(TimeResponseTest, ACleatsResponseOnTheMillimetreGridIsConverged) {
  ExpectConvergedOnTheMillimetreGrid({0.12, 0.30, 1.8, 0.10}, 1e-3);
}

// A cleat higher than the cam's half-height b_e: where the cam's tip, b_e
// below its centre, meets an edge of the cleat, H jumps by h - b_e, and the
// held forces ramp each jump over one step. On the 1 mm grid, against 0.094
// mm, that costs 1.4 % of the peak here.
TEST(TimeResponseTest, ACleatAboveTheCamsHalfHeightIsStruckWithinAMillimetre) {
  ExpectConvergedOnTheMillimetreGrid({0.12, 0.01, 1.8, 0.10}, 2e-2);
}

// Slowly over a long, low cleat the belt follows statically: the contact
// spring k_cz in series with the sidewall k_bz (hub held) carries the cleat's
// height h on its top, k_cz k_bz h / (k_cz + k_bz), and never less than
// the load before it but for the ring's ringing where w has a kink (the cam
// leaving the edge: a velocity step V dw/dX, about k V dw/dX / w_n).
TEST(TimeResponseTest, SlowlyOverALongCleatTheContactForceIsTheSeriesSpringsOnItsHeight) {
  ObstacleRun run;
  run.speed_m_s = 0.02;  // the cam climbs the edge in 1.2 s, 100 vertical periods
  run.profile.height_m = 0.01;
  run.profile.length_m = 0.6;
  run.cam = {0.12, 0.30, 1.8, 0.10};
  run.position_at_t0_m = -0.6;
  for (int k = 0; k < 300; ++k) run.times_s.push_back(k * 0.2);
  const Parameters p = ExampleCarTire();
  ObstacleResult r;
  std::string why;
  ASSERT_TRUE(ObstacleResponse(RigidRingModel(), p, run, &r, &why)) << why;
  const double k_cz = p[Param::k_cz], k_bz = p[Param::k_bz];
  const double plateau = k_cz * k_bz * 0.01 / (k_cz + k_bz);
  EXPECT_NEAR(r.largest_load_change * p[Param::F_cz0], plateau, 1e-4 * plateau);
  EXPECT_NEAR(r.lowest_contact_force_n, p[Param::F_cz0], 5e-4 * plateau) << r.lowest_at_s;
}

TEST(TimeResponseTest, ARunThatCannotBeRolledIsRefusedNamingTheField) {
  ObstacleRun run = LugRun(LanePattern::kChevron);
  ObstacleResult y;
  std::string why;
  const auto refused = [&](const ObstacleRun& r, const std::string& field) {
    EXPECT_FALSE(ObstacleResponse(RigidRingModel(), ExampleCarTire(), r, &y, &why)) << field;
    EXPECT_EQ(why.rfind(field, 0), 0u) << field << ": " << why;
  };
  ObstacleRun bad = run;
  bad.speed_m_s = 0;
  refused(bad, "speed_m_s");
  bad = run;
  std::swap(bad.times_s[3], bad.times_s[4]);
  refused(bad, "time_s");
  bad = run;
  bad.times_s[0] = -1e-3;
  refused(bad, "time_s");
  bad = run;
  bad.profile.lanes = 0;
  refused(bad, "profile: lanes");
  bad = run;
  bad.cam.c_e = 0.5;
  refused(bad, "c_e");
  bad = run;
  bad.speed_m_s = 1e-9;
  refused(bad, "speed_m_s");
  bad = run;
  bad.times_s.back() = 2e3;  // 20 km at 10 m/s
  refused(bad, "time_s");
}

}  // namespace
}  // namespace ringid
