#include "model/spelling.h"

#include <algorithm>

namespace ringid {

int EditDistance(std::string_view a, std::string_view b) {
  // Optimal string alignment: Levenshtein plus the swap of two neighbours,
  // the commonest typo ("lable").
  const size_t n = a.size(), m = b.size();
  std::vector<std::vector<int>> d(n + 1, std::vector<int>(m + 1));
  for (size_t i = 0; i <= n; ++i) d[i][0] = static_cast<int>(i);
  for (size_t j = 0; j <= m; ++j) d[0][j] = static_cast<int>(j);
  for (size_t i = 1; i <= n; ++i) {
    for (size_t j = 1; j <= m; ++j) {
      const int cost = a[i - 1] == b[j - 1] ? 0 : 1;
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + cost});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) {
        d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
      }
    }
  }
  return d[n][m];
}

std::optional<std::string> NearestName(std::string_view text,
                                       const std::vector<std::string>& candidates) {
  // About a third of the letters wrong is still recognisably the same word
  // (one in "zb", two in "datset"); beyond that, or in a name of one letter,
  // a suggestion is a guess that misleads more than it helps.
  const int allowed = (static_cast<int>(text.size()) + 1) / 3;
  std::optional<std::string> best;
  int best_distance = allowed + 1;
  for (const std::string& c : candidates) {
    const int distance = EditDistance(text, c);
    if (distance < best_distance) {
      best = c;
      best_distance = distance;
    }
  }
  return best;
}

std::string OneOf(const std::vector<std::string>& names) {
  std::string out;
  for (size_t i = 0; i < names.size(); ++i) {
    out += (i == 0 ? "" : i + 1 == names.size() ? " or " : ", ") + names[i];
  }
  return out;
}

std::string UnknownName(const std::string& what, std::string_view text,
                        const std::vector<std::string>& candidates, bool list) {
  std::string line = "unknown " + what + " '" + std::string(text) + "'";
  const std::optional<std::string> nearest = NearestName(text, candidates);
  std::string note;
  if (nearest) note = "did you mean '" + *nearest + "'?";
  if (list) note += (note.empty() ? "" : " ") + std::string("expected ") + OneOf(candidates);
  return note.empty() ? line : line + " (" + note + ")";
}

}  // namespace ringid
