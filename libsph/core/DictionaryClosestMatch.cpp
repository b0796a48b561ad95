// "Did you mean" suggestions for misspelt keywords, options, units and macros
// (docs/design.md 1.2): the candidate with the smallest case-insensitive
// Damerau-Levenshtein distance (optimal string alignment: insertions,
// deletions, substitutions and swaps of two neighbouring letters each cost 1),
// accepted when the distance is at most max(2, length/3). Ties go to the
// earlier candidate. Reads no dictionary keys.
#include "core/Dictionary.hpp"
#include <algorithm>
#include <cctype>

namespace shizuku {

namespace {
int editDistance(const std::string& a0, const std::string& b0) {
  std::string a = a0, b = b0;
  for (auto& c : a) c = char(std::tolower((unsigned char)c));
  for (auto& c : b) c = char(std::tolower((unsigned char)c));
  const std::size_t n = a.size(), m = b.size();
  std::vector<std::vector<int>> d(n + 1, std::vector<int>(m + 1));
  for (std::size_t i = 0; i <= n; ++i) d[i][0] = int(i);
  for (std::size_t j = 0; j <= m; ++j) d[0][j] = int(j);
  for (std::size_t i = 1; i <= n; ++i)
    for (std::size_t j = 1; j <= m; ++j) {
      const int cost = a[i - 1] == b[j - 1] ? 0 : 1;
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + cost});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
        d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
    }
  return d[n][m];
}
}  // namespace

std::string closestMatch(const std::string& word, const std::vector<std::string>& candidates) {
  const int accept = std::max<int>(2, int(word.size()) / 3);
  std::string best;
  int bestDist = accept + 1;
  for (const auto& c : candidates) {
    const int dist = editDistance(word, c);
    if (dist < bestDist) { bestDist = dist; best = c; }
  }
  return best;
}

}  // namespace shizuku
