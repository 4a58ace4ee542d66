// Rolling over an obstacle (contract §11): a road profile under the tire, the
// tandem cam that envelops it (Schmeitz 2004) and the lanes across the
// width, giving the effective height w, slope beta and banking beta_x that
// drive the ring as the contact centre moves along the profile.
#ifndef RINGID_MODEL_OBSTACLE_H_
#define RINGID_MODEL_OBSTACLE_H_

#include <array>
#include <optional>
#include <string>
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

// The first X (increasing) at which a non-zero height of the profile comes
// within some lane's front cam's reach (a_e): before it the road is flat
// (§11's rule for t = 0). For lugs, -infinity (the road is never flat).
double FirstContact(const ObstacleProfile& profile, const TandemCam& cam);

}  // namespace ringid

#endif  // RINGID_MODEL_OBSTACLE_H_
