// The tandem cam's effective inputs (contract §11) against closed forms, a
// brute-force maximum and the symmetries of the lanes.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "model/obstacle.h"

namespace ringid {
namespace {

// A car tire's cam: half-length, half-height, order, the cams' distance.
TandemCam CarCam() { return {0.12, 0.30, 1.8, 0.10}; }

ObstacleProfile Cleat(double h, double L) {
  ObstacleProfile p;
  p.kind = ProfileKind::kCleat;
  p.height_m = h;
  p.length_m = L;
  return p;
}

// The cam's drop below its lowest point at offset s, written out.
double CamDrop(const TandemCam& c, double s) {
  return c.b_e * (std::pow(1 - std::pow(std::abs(s) / c.a_e, c.c_e), 1 / c.c_e) - 1);
}

// A rectangle h over |x| <= L/2: the cam rests on its top while its lowest
// point is over it, else on the nearer edge, d past it, until the drop at d
// exceeds h.
TEST(ObstacleTest, ACleatsCamHeightIsTheRectanglesClosedForm) {
  const TandemCam cam = CarCam();
  const double h = 0.015, L = 0.02;
  const ObstacleProfile cleat = Cleat(h, L);
  for (double X = -0.3; X <= 0.3; X += 0.0005) {
    const double d = std::abs(X) - L / 2;
    const double closed = d <= 0 ? h : d < cam.a_e ? std::max(0.0, h + CamDrop(cam, d)) : 0.0;
    EXPECT_NEAR(CamHeight(cleat, cam, Lane{}, X), closed, 1e-15) << X;
  }
}

// h piecewise linear (a ramp up, a plateau, a dip below the road, a jump
// down at its last point): the exact maximum against the largest of 200,001
// offsets across the cam, h interpolated here.
TEST(ObstacleTest, APointsProfilesCamHeightIsTheMaximumOverTheCam) {
  ObstacleProfile p;
  p.kind = ProfileKind::kPoints;
  p.x_m = {-0.05, -0.02, 0.0, 0.01, 0.04, 0.06};
  p.h_m = {0.0, 0.012, 0.012, -0.004, 0.02, 0.008};
  const TandemCam cam = CarCam();
  const auto h = [&](double x) {
    if (x < p.x_m.front() || x > p.x_m.back()) return 0.0;
    const size_t i = std::min<size_t>(
        std::upper_bound(p.x_m.begin(), p.x_m.end(), x) - p.x_m.begin(), p.x_m.size() - 1);
    const double t = (x - p.x_m[i - 1]) / (p.x_m[i] - p.x_m[i - 1]);
    return p.h_m[i - 1] + t * (p.h_m[i] - p.h_m[i - 1]);
  };
  const int n = 200000;
  for (double X = -0.25; X <= 0.25; X += 0.025) {
    double brute = -1;
    for (int k = 0; k <= n; ++k) {
      const double s = cam.a_e * (2.0 * k / n - 1);
      brute = std::max(brute, h(X + s) + CamDrop(cam, s));
    }
    const double exact = CamHeight(p, cam, Lane{}, X);
    EXPECT_GE(exact, brute - 1e-14) << X;
    EXPECT_LE(exact, brute + 2e-6) << X;  // the grid's step, 1.2e-6 m, times h's steepest slope
  }
}

// For h well below b_e, H = h - b_e d^c_e / (c_e a_e^c_e) at a distance d
// from the cleat (§11): a low cleat shows only c_e and b_e / a_e^c_e.
TEST(ObstacleTest, ALowCleatShowsOnlyTheCamsOrderAndHeightOverLengthToTheOrder) {
  const TandemCam cam = CarCam();
  TandemCam other = cam;
  other.a_e = 0.2;
  other.b_e = cam.b_e * std::pow(other.a_e / cam.a_e, cam.c_e);  // the same b_e / a_e^c_e
  const double h = 0.004, L = 0.02;
  const ObstacleProfile cleat = Cleat(h, L);
  for (double d = 0; d < cam.a_e; d += 0.001) {
    const double X = L / 2 + d;
    const double H = CamHeight(cleat, cam, Lane{}, X);
    const double low = h - cam.b_e * std::pow(d, cam.c_e) / (cam.c_e * std::pow(cam.a_e, cam.c_e));
    EXPECT_NEAR(H, std::max(low, 0.0), 0.01 * h) << d;
    EXPECT_NEAR(CamHeight(cleat, other, Lane{}, X), H, 0.02 * h) << d;
  }
}

// The first X (increasing) where the effective height leaves 0.
double Onset(const ObstacleProfile& p, const TandemCam& cam) {
  double X = FirstContact(p, cam);
  while (Effective(p, cam, X).w == 0) X += 1e-5;
  return X;
}

// Flat road: H = 0 exactly until a cam's reach meets the cleat (where
// FirstContact says), and the road rises within a reach after it.
TEST(ObstacleTest, TheRoadIsFlatUntilTheFirstCamReachesTheCleat) {
  const TandemCam cam = CarCam();
  ObstacleProfile cleat = Cleat(0.015, 0.02);
  cleat.width_m = 0.2;
  cleat.angle_deg = 25;
  const double first = FirstContact(cleat, cam);
  EXPECT_NEAR(first, -0.01 - 0.1 * std::tan(25 * M_PI / 180) * 0.9 - 0.05 - 0.12, 1e-12);
  for (double X = first - 0.5; X < first; X += 0.001) {
    const EffectiveInput e = Effective(cleat, cam, X);
    EXPECT_EQ(e.w, 0.0) << X;
    EXPECT_EQ(e.beta, 0.0) << X;
    EXPECT_EQ(e.beta_x, 0.0) << X;
  }
  EXPECT_LT(Onset(cleat, cam), first + cam.a_e);
}

// Lanes of angle 0 across the width all see the same profile: one lane.
TEST(ObstacleTest, LanesAtAngleZeroAreOneLane) {
  const TandemCam cam = CarCam();
  const ObstacleProfile one = Cleat(0.015, 0.02);
  ObstacleProfile wide = one;
  wide.width_m = 0.2;
  for (double X = -0.3; X <= 0.3; X += 0.001) {
    const EffectiveInput a = Effective(one, cam, X), b = Effective(wide, cam, X);
    EXPECT_NEAR(b.w, a.w, 1e-15) << X;
    EXPECT_NEAR(b.beta, a.beta, 1e-13) << X;
    EXPECT_NEAR(b.beta_x, 0.0, 1e-13) << X;
  }
}

// With angle > 0 an inclined cleat's left edge (y < 0) strikes first: the
// road rises on the left, beta_x < 0; the mirrored cleat the other way. The
// slope leads the height: beta > 0 as the front cam climbs.
TEST(ObstacleTest, AnInclinedCleatStrikesItsLeftEdgeFirst) {
  const TandemCam cam = CarCam();
  for (double angle : {30.0, -30.0}) {
    ObstacleProfile cleat = Cleat(0.015, 0.02);
    cleat.width_m = 0.2;
    cleat.angle_deg = angle;
    const EffectiveInput e = Effective(cleat, cam, Onset(cleat, cam) + 0.002);
    EXPECT_GT(e.w, 0) << angle;
    EXPECT_GT(e.beta, 0) << angle;
    EXPECT_EQ(e.beta_x < 0, angle > 0) << angle << ": " << e.beta_x;
  }
}

// Cross-stitch lugs: the left half a pitch behind the right. Half a pitch
// on, the halves trade places: the height and slope repeat (only even
// orders of the lug frequency) and the banking reverses (only odd ones).
TEST(ObstacleTest, AlternatingLugsRepeatVerticallyEveryHalfPitchAndReverseLaterally) {
  const TandemCam cam = CarCam();
  ObstacleProfile lugs;
  lugs.kind = ProfileKind::kLugs;
  lugs.height_m = 0.03;
  lugs.length_m = 0.04;
  lugs.pitch_m = 0.15;
  lugs.width_m = 0.4;
  lugs.angle_deg = 20;
  lugs.pattern = LanePattern::kAlternating;
  ASSERT_EQ(lugs.Invalid(), "");
  double largest_bank = 0;
  for (double X = -0.3; X <= 0.3; X += 0.0037) {
    const EffectiveInput a = Effective(lugs, cam, X), b = Effective(lugs, cam, X + 0.075);
    EXPECT_NEAR(b.w, a.w, 1e-14) << X;
    EXPECT_NEAR(b.beta, a.beta, 1e-12) << X;
    EXPECT_NEAR(b.beta_x, -a.beta_x, 1e-12) << X;
    largest_bank = std::max(largest_bank, std::abs(a.beta_x));
  }
  EXPECT_GT(largest_bank, 0.01);  // the banking is there to reverse
  // One lug row a pitch on is the same road.
  for (double X = -0.3; X <= 0.3; X += 0.0037) {
    EXPECT_NEAR(Effective(lugs, cam, X + 0.15).w, Effective(lugs, cam, X).w, 1e-14) << X;
  }
}

// A profile or cam that cannot be rolled over is refused, naming the field.
TEST(ObstacleTest, BadProfilesAndCamsAreRefusedNamingTheField) {
  const auto refuses = [](ObstacleProfile p, const std::string& field) {
    const std::string why = p.Invalid();
    EXPECT_EQ(why.rfind(field, 0), 0u) << field << ": " << why;
  };
  ObstacleProfile lugs;
  lugs.kind = ProfileKind::kLugs;
  lugs.height_m = 0.02;
  lugs.length_m = 0.04;
  lugs.pitch_m = 0.03;
  refuses(lugs, "pitch_m");
  lugs.pitch_m = 0.15;
  lugs.width_m = 0.3;
  lugs.lanes = 9;
  lugs.pattern = LanePattern::kAlternating;
  refuses(lugs, "lanes");
  lugs.lanes = 0;
  refuses(lugs, "lanes");
  ObstacleProfile cleat = Cleat(0.01, 0);
  refuses(cleat, "length_m");
  cleat.length_m = 0.02;
  cleat.pattern = LanePattern::kAlternating;
  refuses(cleat, "pattern");
  cleat.pattern.reset();
  cleat.width_m = -1;
  refuses(cleat, "width_m");
  cleat.width_m.reset();
  cleat.angle_deg = 90;
  refuses(cleat, "angle_deg");
  ObstacleProfile points;
  points.kind = ProfileKind::kPoints;
  points.x_m = {0, 0.01, 0.01};
  points.h_m = {0, 0.01, 0};
  refuses(points, "x_m");
  points.h_m.pop_back();
  refuses(points, "x_m, h_m");
  const auto cam_refuses = [](TandemCam c, const std::string& field) {
    EXPECT_EQ(c.Invalid().rfind(field, 0), 0u) << field << ": " << c.Invalid();
  };
  TandemCam cam = CarCam();
  EXPECT_EQ(cam.Invalid(), "");
  cam.c_e = 1;
  cam_refuses(cam, "c_e");
  cam = CarCam();
  cam.l_s = 0;
  cam_refuses(cam, "l_s");
  cam = CarCam();
  cam.a_e = -0.1;
  cam_refuses(cam, "a_e");
}

}  // namespace
}  // namespace ringid
