// Rolling over an obstacle (contract §11): a road profile under the tire, the
// tandem cam that envelops it (Schmeitz 2004) and the lanes across the
// width, giving the effective height w, slope beta and banking beta_x that
// drive the ring as the contact centre moves along the profile.
#ifndef RINGID_MODEL_OBSTACLE_H_
#define RINGID_MODEL_OBSTACLE_H_

#include <array>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "model/enum_names.h"

namespace ringid {

enum class ProfileKind { kCleat, kLugs, kPoints };
template <>
struct EnumNames<ProfileKind> {
  static constexpr std::array<const char*, 3> kNames = {"cleat", "lugs", "points"};
};

// How each lane's copy of the profile is shifted along the path (§11):
// inclined y tan(phi), chevron |y| tan(phi), alternating as chevron plus
// half a pitch on the left (y < 0).
enum class LanePattern { kInclined, kChevron, kAlternating };
template <>
struct EnumNames<LanePattern> {
  static constexpr std::array<const char*, 3> kNames = {"inclined", "chevron", "alternating"};
};

// What a profile and a cam may be (Invalid): an obstacle a tire rolls over,
// not a cliff; the bounds keep each run's work and numbers finite.
inline constexpr double kMostObstacleHeight = 1;     // m, either way
inline constexpr double kShortestObstacle = 1e-4;   // m: a length, a width, points' spacing
inline constexpr double kLongestObstacle = 1e3;     // m
inline constexpr double kShortestPitch = 5e-3, kLongestPitch = 10;  // m
inline constexpr double kFarthestX = 1e4;           // m: points, and where a run starts
inline constexpr size_t kMostPoints = 10000;
inline constexpr double kWidestTread = 10;          // m
inline constexpr double kSteepestAngleDeg = 85;
inline constexpr int kMostLanes = 100;
inline constexpr double kLongestCam = 10;           // m: a_e, b_e, l_s
inline constexpr double kHighestCamOrder = 100;

// Heights up (m) along x, the cleat's centre at x = 0; flat road (h = 0)
// elsewhere. `points` is piecewise linear between its points, and 0 outside
// them (a jump where an end point is not at 0).
struct ObstacleProfile {
  ProfileKind kind = ProfileKind::kCleat;
  double height_m = 0;  // cleat, lugs
  double length_m = 0;  // cleat, lugs
  double pitch_m = 0;   // lugs: a rectangle centred at every multiple of it
  std::vector<double> x_m, h_m;  // points, x increasing
  std::optional<double> width_m;  // lanes across it; none: one lane at y = 0
  double angle_deg = 0;
  int lanes = 10;
  std::optional<LanePattern> pattern;  // none: inclined, chevron for lugs

  LanePattern Pattern() const;
  // Why the profile cannot be rolled over, naming the field; "" if it can.
  std::string Invalid() const;
};

// The cam, (|s|/a_e)^c_e + (|z|/b_e)^c_e = 1, and the two cams' distance.
struct TandemCam {
  double a_e = 0, b_e = 0, c_e = 2, l_s = 0;
  // Why the cam is not one, naming the parameter; "" if it is.
  std::string Invalid() const;
};

// The pieces of the profile one evaluation of the effective inputs (w, beta
// and beta_x at one X) visits at most: both cams of every lane, each over
// the pieces within its span. A run's work is this times its points.
double PieceEvaluations(const ObstacleProfile& profile, const TandemCam& cam);

// One lane across the width: its y (right positive) and its copy's shift.
struct Lane {
  double y_m = 0;
  double shift_m = 0;  // the lane sees h(x - shift)
};
std::vector<Lane> LanesOf(const ObstacleProfile& profile);

// The functions below take a profile and a cam whose Invalid() is empty.

// The height of the profile at x (one lane, unshifted).
double ProfileHeight(const ObstacleProfile& profile, double x);

// The cam's bottom resting on the lane's profile with its centre over X:
// H(X) = max over |s| <= a_e of [h(X + s - shift) + b_e((1 - |s/a_e|^c_e)^(1/c_e) - 1)],
// exact: on each linear piece of h the bracket is concave in s, its maximum
// where its slope vanishes (closed form) or at the piece's end.
double CamHeight(const ObstacleProfile& profile, const TandemCam& cam, const Lane& lane, double X);

// The effective inputs at X (§11): w and beta the lanes' means of the tandem's
// (H(X + l_s/2) + H(X - l_s/2)) / 2 and (H(X + l_s/2) - H(X - l_s/2)) / l_s,
// beta_x = sum y_j w_j / sum y_j^2 (0 for one lane).
struct EffectiveInput {
  double w = 0, beta = 0, beta_x = 0;
};
EffectiveInput Effective(const ObstacleProfile& profile, const TandemCam& cam, double X);
// The same over the profile's lanes, LanesOf(profile).
EffectiveInput Effective(const ObstacleProfile& profile, const TandemCam& cam,
                         const std::vector<Lane>& lanes, double X);

// The X interval outside which every lane's two cams rest on a flat road,
// so that w = beta = beta_x = 0 exactly: a non-zero height of the profile
// within a cam's reach (a_e) of its centre. The whole line for lugs; {inf,
// inf} for a flat profile.
std::pair<double, double> Reach(const ObstacleProfile& profile, const TandemCam& cam);
// Reach's first X: before it the road is flat (§11's rule for t = 0). For
// lugs, -infinity (the road is never flat).
double FirstContact(const ObstacleProfile& profile, const TandemCam& cam);

}  // namespace ringid

#endif  // RINGID_MODEL_OBSTACLE_H_
