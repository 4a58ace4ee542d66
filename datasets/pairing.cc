#include "datasets/pairing.h"

#include <algorithm>
#include <cmath>
#include <complex>

#include "datasets/measurement.h"
#include "model/assignment.h"

namespace ringid::internal {

double ShapeScore(const Mode& mode, const ModeToPair& measured, ShapeConvention convention) {
  return Mac(ComparableShape(mode, convention, *measured.shape), *measured.shape);
}

double FrequencyScore(const Mode& mode, const ModeToPair& measured) {
  const bool other_plane = measured.label && mode.plane() != LabelPlane(*measured.label);
  double distance = std::abs(std::log(mode.frequency_hz / measured.frequency_hz));
  if (measured.damping_ratio && *measured.damping_ratio >= 0 && *measured.damping_ratio < 1) {
    // λ = ω_d (-ζ / sqrt(1 - ζ²) + i) for a damped frequency ω_d (contract §2).
    const auto pole = [](double hz, double zeta) {
      return 2 * M_PI * hz * std::complex<double>(-zeta / std::sqrt(1 - zeta * zeta), 1);
    };
    distance = std::abs(std::log(pole(measured.frequency_hz, *measured.damping_ratio)) -
                        std::log(pole(mode.frequency_hz, mode.damping_ratio)));
  }
  return -distance - (other_plane ? 100 : 0);
}

bool PairModes(const std::vector<ModeToPair>& measured, const std::vector<const Mode*>& modes,
               ShapeConvention convention, std::vector<int>* pairs, std::vector<PairedBy>* by,
               std::string* why) {
  const int n = static_cast<int>(measured.size()), m = static_cast<int>(modes.size());
  pairs->assign(n, -1);
  by->assign(n, PairedBy::kFrequency);
  // Rows `rows` against the model modes `cols` by `score`, one to one.
  const auto assign = [&](const std::vector<int>& rows, const std::vector<int>& cols,
                          auto score, PairedBy how) {
    Eigen::MatrixXd s(rows.size(), cols.size());
    for (size_t a = 0; a < rows.size(); ++a) {
      for (size_t b = 0; b < cols.size(); ++b) s(a, b) = score(*modes[cols[b]], measured[rows[a]]);
    }
    const std::vector<int> pick = AssignMaxScore(s);
    if (std::find(pick.begin(), pick.end(), -1) != pick.end()) {
      *why = "the measured modes cannot be paired one to one with the model's (a score is not "
             "finite)";
      return false;
    }
    for (size_t a = 0; a < rows.size(); ++a) {
      (*pairs)[rows[a]] = cols[pick[a]];
      (*by)[rows[a]] = how;
    }
    return true;
  };
  std::vector<int> all(m), shaped;
  for (int b = 0; b < m; ++b) all[b] = b;
  for (int i = 0; i < n; ++i) {
    if (measured[i].HasShape()) shaped.push_back(i);
  }
  // 1. Measured shapes decide their pairing by MAC ...
  if (!shaped.empty()) {
    if (shaped.size() > modes.size()) {
      *why = "fewer model modes than measured shapes";
      return false;
    }
    const auto mac = [&](const Mode& mode, const ModeToPair& p) {
      return ShapeScore(mode, p, convention);
    };
    if (!assign(shaped, all, mac, PairedBy::kShape)) return false;
  }
  // 2. ... a known label the rest, with its model mode where a shape left it
  // free ...
  std::vector<bool> taken(m, false);
  for (int i : shaped) taken[(*pairs)[i]] = true;
  std::vector<int> left;
  for (int i = 0; i < n; ++i) {
    if ((*pairs)[i] >= 0) continue;
    const std::optional<ModeLabel> label = measured[i].label;
    bool exists = false;
    for (int b = 0; b < m && label; ++b) {
      if (modes[b]->label != *label) continue;
      exists = true;
      if (!taken[b]) (*pairs)[i] = b;
    }
    if ((*pairs)[i] >= 0) {
      taken[(*pairs)[i]] = true;
      (*by)[i] = PairedBy::kLabel;
    } else if (label && !exists) {
      *why = std::string("the model has no oscillating ") + LabelName(*label) +
             " mode (its roots are real)";
      return false;
    } else {
      left.push_back(i);
    }
  }
  // 3. ... and the nearest free model mode in frequency, of its own plane
  // where the label gives one, the others.
  if (left.empty()) return true;
  std::vector<int> free;
  for (int b = 0; b < m; ++b) {
    if (!taken[b]) free.push_back(b);
  }
  if (free.size() < left.size()) {
    *why = "fewer model modes than measured modes";
    return false;
  }
  return assign(left, free, FrequencyScore, PairedBy::kFrequency);
}

}  // namespace ringid::internal
