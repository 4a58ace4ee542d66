#include "model/assignment.h"

#include <algorithm>
#include <limits>

namespace ringid {
namespace internal {

std::vector<int> AssignMaxScore(const Eigen::Ref<const Eigen::MatrixXd>& score) {
  const int rows = static_cast<int>(score.rows());
  const int cols = static_cast<int>(score.cols());
  std::vector<int> result(rows, -1);
  if (rows == 0 || rows > cols || cols > 16) return result;
  // When every row's best column is its own, no assignment beats the sum of
  // the row maxima: that is the answer (the usual case for mode labels).
  int used = 0;
  for (int row = 0; row < rows; ++row) {
    int c_best = -1;
    for (int c = 0; c < cols; ++c) {
      if (score(row, c) > -std::numeric_limits<double>::infinity() &&
          (c_best < 0 || score(row, c) > score(row, c_best))) {
        c_best = c;
      }
    }
    if (c_best < 0 || (used & (1 << c_best))) break;
    used |= 1 << c_best;
    result[row] = c_best;
    if (row == rows - 1) return result;
  }
  std::fill(result.begin(), result.end(), -1);
  const double kNone = -std::numeric_limits<double>::infinity();
  // best[mask]: best total for the first popcount(mask) rows using columns mask.
  const int n = 1 << cols;
  std::vector<double> best(n, kNone);
  std::vector<int> choice(n, -1);
  best[0] = 0;
  for (int mask = 0; mask < n; ++mask) {
    if (best[mask] == kNone) continue;
    const int row = __builtin_popcount(mask);
    if (row >= rows) continue;
    for (int c = 0; c < cols; ++c) {
      if (mask & (1 << c)) continue;
      const int next = mask | (1 << c);
      const double v = best[mask] + score(row, c);
      if (v > best[next]) {
        best[next] = v;
        choice[next] = c;
      }
    }
  }
  int best_mask = -1;
  for (int mask = 0; mask < n; ++mask) {
    if (__builtin_popcount(mask) != rows || best[mask] == kNone) continue;
    if (best_mask < 0 || best[mask] > best[best_mask]) best_mask = mask;
  }
  if (best_mask < 0) return result;
  for (int row = rows - 1, mask = best_mask; row >= 0; --row) {
    result[row] = choice[mask];
    mask &= ~(1 << choice[mask]);
  }
  return result;
}

}  // namespace internal
}  // namespace ringid
