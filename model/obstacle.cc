#include "model/obstacle.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "model/plausibility.h"

namespace ringid {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();


// A linear piece of the profile over [x0, x1] (closed: a jump's higher side
// counts at the jump, as the sup in H does).
struct Piece {
  double x0, x1, h0, h1;
};

// The profile's pieces over [lo, hi], each clipped to it.
template <class F>
void ForEachPiece(const ObstacleProfile& p, double lo, double hi, const F& f) {
  const auto flat_or = [&](double x0, double x1, double h0, double h1) {
    const double a = std::max(x0, lo), b = std::min(x1, hi);
    if (a > b) return;
    const double slope = x1 > x0 && std::isfinite(x1 - x0) ? (h1 - h0) / (x1 - x0) : 0;
    const double at_a = std::isfinite(x0) ? h0 + slope * (a - x0) : h0;
    const double at_b = std::isfinite(x0) ? h0 + slope * (b - x0) : h1;
    f({a, b, at_a, at_b});
  };
  switch (p.kind) {
    case ProfileKind::kCleat: {
      const double half = 0.5 * p.length_m;
      flat_or(-kInf, -half, 0, 0);
      flat_or(-half, half, p.height_m, p.height_m);
      flat_or(half, kInf, 0, 0);
      return;
    }
    case ProfileKind::kLugs: {
      const double half = 0.5 * p.length_m, P = p.pitch_m;
      const long long last = static_cast<long long>(std::ceil(hi / P)) + 1;
      for (long long k = static_cast<long long>(std::floor(lo / P)) - 1; k <= last; ++k) {
        const double at = static_cast<double>(k) * P;
        flat_or(at - half, at + half, p.height_m, p.height_m);
        flat_or(at + half, at + P - half, 0, 0);
      }
      return;
    }
    case ProfileKind::kPoints: {
      const std::vector<double>& x = p.x_m;
      const size_t n = x.size();
      if (lo <= x.front()) flat_or(-kInf, x.front(), 0, 0);
      // the pieces [x_i, x_i+1] that meet [lo, hi]
      size_t i = std::upper_bound(x.begin(), x.end(), lo) - x.begin();
      i = i > 0 ? i - 1 : 0;
      for (; i + 1 < n && x[i] <= hi; ++i) flat_or(x[i], x[i + 1], p.h_m[i], p.h_m[i + 1]);
      if (hi >= x.back()) flat_or(x.back(), kInf, 0, 0);
      return;
    }
  }
}

// The cam's bottom below its lowest point at offset s (|s| <= a), <= 0.
double Drop(const TandemCam& c, double s) {
  const double u = std::min(std::abs(s) / c.a_e, 1.0);
  return c.b_e * (std::pow(1 - std::pow(u, c.c_e), 1 / c.c_e) - 1);
}

// Where the drop's slope is -m: the offset s (sign of m) with
// (b/a) g(|s|/a) = |m|, g(u) = u^(c-1) (1 - u^c)^((1-c)/c) = t^((c-1)/c) for
// t = u^c / (1 - u^c).
double Stationary(const TandemCam& c, double m) {
  if (m == 0) return 0;
  const double t = std::pow(std::abs(m) * c.a_e / c.b_e, c.c_e / (c.c_e - 1));
  const double u = std::isfinite(t) ? std::pow(t / (1 + t), 1 / c.c_e) : 1.0;
  return std::copysign(c.a_e * u, m);
}

}  // namespace

LanePattern ObstacleProfile::Pattern() const {
  if (pattern) return *pattern;
  return kind == ProfileKind::kLugs ? LanePattern::kChevron : LanePattern::kInclined;
}

std::string ObstacleProfile::Invalid() const {
  const auto within = [](double v, double lo, double hi) { return v >= lo && v <= hi; };
  const std::string height = "must be a height of at most " + FormatSignificant3(kMostObstacleHeight) + " m either way";
  if (kind != ProfileKind::kPoints) {
    if (!within(height_m, -kMostObstacleHeight, kMostObstacleHeight)) return "height_m: " + height;
    if (!within(length_m, kShortestObstacle, kLongestObstacle)) {
      return "length_m: must lie in [" + FormatSignificant3(kShortestObstacle) + ", " + FormatSignificant3(kLongestObstacle) + "] m";
    }
  }
  if (kind == ProfileKind::kLugs &&
      !(within(pitch_m, kShortestPitch, kLongestPitch) && pitch_m > length_m)) {
    return "pitch_m: must exceed length_m (a lug's length) and lie in [" + FormatSignificant3(kShortestPitch) +
           ", " + FormatSignificant3(kLongestPitch) + "] m";
  }
  if (kind == ProfileKind::kPoints) {
    if (x_m.size() < 2 || x_m.size() != h_m.size()) {
      return "x_m, h_m: need two or more points, as many heights as positions";
    }
    if (x_m.size() > kMostPoints) return "x_m: at most " + std::to_string(kMostPoints) + " points";
    for (size_t i = 0; i < x_m.size(); ++i) {
      if (!within(x_m[i], -kFarthestX, kFarthestX)) {
        return "x_m: must lie within " + FormatSignificant3(kFarthestX) + " m of 0";
      }
      if (!within(h_m[i], -kMostObstacleHeight, kMostObstacleHeight)) return "h_m: " + height;
      if (i > 0 && !(x_m[i] - x_m[i - 1] >= kShortestObstacle * (1 - 1e-9))) {
        return "x_m: must increase by at least " + FormatSignificant3(kShortestObstacle) + " m";
      }
    }
  }
  if (width_m && !within(*width_m, kShortestObstacle, kWidestTread)) {
    return "width_m: must lie in [" + FormatSignificant3(kShortestObstacle) + ", " + FormatSignificant3(kWidestTread) + "] m";
  }
  if (!within(angle_deg, -kSteepestAngleDeg, kSteepestAngleDeg)) {
    return "angle_deg: must lie in [-" + FormatSignificant3(kSteepestAngleDeg) + ", " + FormatSignificant3(kSteepestAngleDeg) + "]";
  }
  if (lanes < 1 || lanes > kMostLanes) return "lanes: must lie in [1, " + std::to_string(kMostLanes) + "]";
  if (Pattern() == LanePattern::kAlternating) {
    if (kind != ProfileKind::kLugs) return "pattern: alternating is for lugs only";
    if (lanes % 2 != 0) return "lanes: alternating needs an even number";
    if (!width_m) return "width_m: alternating needs the tread's width";
  }
  return "";
}

std::string TandemCam::Invalid() const {
  const auto length = [](double v) { return v > 0 && v <= kLongestCam; };
  const std::string most = "m, at most " + FormatSignificant3(kLongestCam) + " m";
  if (!length(a_e)) return "a_e: must be a positive length of " + most;
  if (!length(b_e)) return "b_e: must be a positive length of " + most;
  if (!(c_e > 1 && c_e <= kHighestCamOrder)) {
    return "c_e: must exceed 1 and be at most " + FormatSignificant3(kHighestCamOrder);
  }
  if (!length(l_s)) return "l_s: must be a positive length of " + most;
  return "";
}

double PieceEvaluations(const ObstacleProfile& profile, const TandemCam& cam) {
  double pieces = 3;
  if (profile.kind == ProfileKind::kLugs) pieces = 2 * (2 * cam.a_e / profile.pitch_m + 3);
  if (profile.kind == ProfileKind::kPoints) {
    pieces = static_cast<double>(profile.x_m.size()) + 1;
    double closest = kInf;  // the points' least spacing bounds the pieces in a cam's span
    for (size_t i = 1; i < profile.x_m.size(); ++i) {
      closest = std::min(closest, profile.x_m[i] - profile.x_m[i - 1]);
    }
    pieces = std::min(pieces, 2 * cam.a_e / closest + 3);
  }
  return 2.0 * static_cast<double>(LanesOf(profile).size()) * pieces;
}

std::vector<Lane> LanesOf(const ObstacleProfile& p) {
  if (!p.width_m) return {Lane{}};
  const double W = *p.width_m, tan = std::tan(p.angle_deg * M_PI / 180);
  std::vector<Lane> lanes;
  for (int j = 0; j < p.lanes; ++j) {
    const double y = W * (j + 0.5) / p.lanes - 0.5 * W;
    double shift = p.Pattern() == LanePattern::kInclined ? y * tan : std::abs(y) * tan;
    if (p.Pattern() == LanePattern::kAlternating && y < 0) shift += 0.5 * p.pitch_m;
    lanes.push_back({y, shift});
  }
  return lanes;
}

double ProfileHeight(const ObstacleProfile& profile, double x) {
  double h = 0;
  bool first = true;
  ForEachPiece(profile, x, x, [&](const Piece& p) {
    h = first ? p.h0 : std::max(h, p.h0);  // at a jump, its higher side
    first = false;
  });
  return h;
}

double CamHeight(const ObstacleProfile& profile, const TandemCam& cam, const Lane& lane,
                 double X) {
  const double centre = X - lane.shift_m;  // the profile's x under the cam's lowest point
  double H = -kInf;
  ForEachPiece(profile, centre - cam.a_e, centre + cam.a_e, [&](const Piece& p) {
    const double slope = p.x1 > p.x0 ? (p.h1 - p.h0) / (p.x1 - p.x0) : 0;
    const double s = std::clamp(Stationary(cam, slope), p.x0 - centre, p.x1 - centre);
    H = std::max(H, p.h0 + slope * (centre + s - p.x0) + Drop(cam, s));
  });
  return H;
}

EffectiveInput Effective(const ObstacleProfile& profile, const TandemCam& cam, double X) {
  return Effective(profile, cam, LanesOf(profile), X);
}

EffectiveInput Effective(const ObstacleProfile& profile, const TandemCam& cam,
                         const std::vector<Lane>& lanes, double X) {
  EffectiveInput e;
  double yw = 0, yy = 0;
  for (const Lane& lane : lanes) {
    const double front = CamHeight(profile, cam, lane, X + 0.5 * cam.l_s);
    const double rear = CamHeight(profile, cam, lane, X - 0.5 * cam.l_s);
    const double w = 0.5 * (front + rear);
    e.w += w / lanes.size();
    e.beta += (front - rear) / cam.l_s / lanes.size();
    yw += lane.y_m * w;
    yy += lane.y_m * lane.y_m;
  }
  e.beta_x = yy > 0 ? yw / yy : 0;
  return e;
}

std::pair<double, double> Reach(const ObstacleProfile& profile, const TandemCam& cam) {
  if (profile.kind == ProfileKind::kLugs) return {-kInf, kInf};
  double first = kInf, last = -kInf;  // where the profile leaves 0, and comes back for good
  if (profile.kind == ProfileKind::kCleat) {
    if (profile.height_m != 0) first = -0.5 * profile.length_m, last = 0.5 * profile.length_m;
  } else {
    const size_t n = profile.x_m.size();
    for (size_t i = 0; i < n; ++i) {
      if (profile.h_m[i] == 0) continue;
      first = std::min(first, i > 0 ? profile.x_m[i - 1] : profile.x_m[0]);
      last = std::max(last, i + 1 < n ? profile.x_m[i + 1] : profile.x_m[n - 1]);
    }
  }
  if (first == kInf) return {kInf, kInf};  // a flat road: no cam ever rises
  double lo = kInf, hi = -kInf;
  for (const Lane& lane : LanesOf(profile)) {
    lo = std::min(lo, first + lane.shift_m);
    hi = std::max(hi, last + lane.shift_m);
  }
  const double half = 0.5 * cam.l_s + cam.a_e;
  return {lo - half, hi + half};
}

double FirstContact(const ObstacleProfile& profile, const TandemCam& cam) {
  return Reach(profile, cam).first;
}

}  // namespace ringid
