// The lug excitation from geometry: the series per order against the time
// domain's periodic steady state (model/time_response.h, checked there
// against the FRF code), and the symmetry of cross-stitch lugs.
#include <cmath>
#include <complex>
#include <string>

#include <gtest/gtest.h>

#include "datasets/synthetic.h"
#include "model/lug_excitation.h"
#include "model/time_response.h"

namespace ringid {
namespace {

// Lugs 25 mm high, 50 mm long, every 0.15 m, ten lanes at 15 degrees over
// 0.4 m; the example car tire with a shorter cam.
ObstacleProfile Lugs(LanePattern pattern) {
  ObstacleProfile lugs;
  lugs.kind = ProfileKind::kLugs;
  lugs.height_m = 0.025;
  lugs.length_m = 0.05;
  lugs.pitch_m = 0.15;
  lugs.width_m = 0.4;
  lugs.angle_deg = 15;
  lugs.pattern = pattern;
  return lugs;
}
Parameters Tire() {
  Parameters p = ExampleCarTire();
  p[Param::a_e] = 0.12, p[Param::b_e] = 0.30, p[Param::c_e] = 1.8, p[Param::l_s] = 0.10;
  return p;
}

// sum_k Re(Y_k e^{i 2 pi k V t / P}) over 200 orders is the time domain's
// steady state about the mean, which holds the forces first-order on 1 mm
// of travel: order k's coefficients differ by sinc^2(pi k mm / P), 1.5e-4 at
// the first, and the orders above 200 are left out.
TEST(LugExcitationTest, TheOrdersSumToTheTimeDomainsSteadyState) {
  const RigidRingModel model;
  const Parameters p = Tire();
  const ObstacleProfile lugs = Lugs(LanePattern::kChevron);
  const double speed = 10;
  LugExcitation e;
  std::string why;
  ASSERT_TRUE(LugExcitationOf(model, p, lugs, speed, 200, &e, &why)) << why;
  ASSERT_EQ(e.orders.size(), 200u);
  EXPECT_DOUBLE_EQ(e.orders[2].frequency_hz, 3 * speed / lugs.pitch_m);
  ObstacleRun run;
  run.speed_m_s = speed;
  run.profile = lugs;
  run.cam = CamOf(p);
  for (int k = 0; k < 300; ++k) run.times_s.push_back(k * 1e-4);  // two pitches
  ObstacleResult r;
  ASSERT_TRUE(ObstacleResponse(model, p, run, &r, &why)) << why;
  for (int o = 0; o < kNumTimeOutputs; ++o) {
    if (o == static_cast<int>(AxleChannel::kForceY) || o == static_cast<int>(AxleChannel::kMomentX) ||
        o == static_cast<int>(AxleChannel::kMomentZ)) {
      continue;  // chevron lugs excite nothing out of plane
    }
    const double peak = r.y.row(o).cwiseAbs().maxCoeff();
    ASSERT_GT(peak, 0);
    double worst = 0;
    for (size_t s = 0; s < run.times_s.size(); ++s) {
      double sum = 0;
      for (const LugOrderExcitation& k : e.orders) {
        sum += (k.response[o] * std::polar(1.0, 2 * M_PI * k.frequency_hz * run.times_s[s])).real();
      }
      worst = std::max(worst, std::abs(sum - r.y(o, s)));
    }
    EXPECT_LT(worst, 2e-3 * peak) << TimeOutputName(o);
  }
}

// Half a pitch on, the left lanes' lugs are where the right lanes' were: w
// and beta repeat (no odd orders) and beta_x reverses (no even orders).
TEST(LugExcitationTest, CrossStitchLugsPushVerticallyAtEvenOrdersAndLaterallyAtOdd) {
  LugExcitation e;
  std::string why;
  ASSERT_TRUE(LugExcitationOf(RigidRingModel(), Tire(), Lugs(LanePattern::kAlternating), 8, 12,
                              &e, &why))
      << why;
  double largest = 0;
  for (const LugOrderExcitation& k : e.orders) {
    for (const auto& f : k.force) largest = std::max(largest, std::abs(f));
  }
  for (const LugOrderExcitation& k : e.orders) {
    const bool even = k.order % 2 == 0;
    for (int i : {0, 1}) {  // F_x, F_z
      if (!even) EXPECT_LT(std::abs(k.force[i]), 1e-9 * largest) << k.order;
    }
    if (even) EXPECT_LT(std::abs(k.force[2]), 1e-9 * largest) << k.order;
  }
  // and they do push there: the second order vertically, the first laterally.
  EXPECT_GT(std::abs(e.orders[1].force[1]), 0.1 * largest);
  EXPECT_GT(std::abs(e.orders[0].force[2]), 0.1 * largest);
}

TEST(LugExcitationTest, WhatCannotBeRolledIsRefusedNamingIt) {
  std::string why;
  LugExcitation e;
  ObstacleProfile cleat;
  cleat.height_m = 0.01, cleat.length_m = 0.02;
  EXPECT_FALSE(LugExcitationOf(RigidRingModel(), Tire(), cleat, 10, 5, &e, &why));
  EXPECT_EQ(why.rfind("profile", 0), 0u) << why;
  EXPECT_FALSE(LugExcitationOf(RigidRingModel(), Tire(), Lugs(LanePattern::kChevron), 0, 5, &e, &why));
  EXPECT_EQ(why.rfind("speed_m_s", 0), 0u) << why;
  Parameters no_cam = Tire();
  no_cam[Param::c_e] = 0.5;
  EXPECT_FALSE(LugExcitationOf(RigidRingModel(), no_cam, Lugs(LanePattern::kChevron), 10, 5, &e, &why));
  EXPECT_EQ(why.rfind("c_e", 0), 0u) << why;
}

}  // namespace
}  // namespace ringid
