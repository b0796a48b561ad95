// "Did you mean" suggestions for misspelt keywords, options, units and macros
// (docs/design.md 1.2): the candidate with the smallest case-insensitive
// Damerau-Levenshtein distance (optimal string alignment: insertions,
// deletions, substitutions and swaps of two neighbouring letters each cost 1),
// accepted when the distance is at most max(2, length/3). Ties go to the
// earlier candidate. The search stays cheap for hostile input: a candidate whose
// length differs from the word's by more than the accepted distance cannot match and
// is skipped, and a word longer than kLongestSuggested (no keyword, option or unit is)
// gets no suggestion at all, so a 50 MB word costs nothing.
// Also echoed(): how a message quotes a token (at most kEchoedChars characters).
// Reads no dictionary keys.
#include "core/Dictionary.hpp"
#include <algorithm>
#include <cctype>

namespace shizuku {

namespace {

constexpr std::size_t kLongestSuggested = 64;

std::string lower(std::string s) {
  for (auto& c : s) c = char(std::tolower((unsigned char)c));
  return s;
}

// Optimal string alignment distance with three rolling rows (O(n m) time, O(m) memory).
int editDistance(const std::string& a, const std::string& b) {
  const std::size_t n = a.size(), m = b.size();
  std::vector<int> prev2(m + 1), prev(m + 1), cur(m + 1);
  for (std::size_t j = 0; j <= m; ++j) prev[j] = int(j);
  for (std::size_t i = 1; i <= n; ++i) {
    cur[0] = int(i);
    for (std::size_t j = 1; j <= m; ++j) {
      const int cost = a[i - 1] == b[j - 1] ? 0 : 1;
      cur[j] = std::min({prev[j] + 1, cur[j - 1] + 1, prev[j - 1] + cost});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) cur[j] = std::min(cur[j], prev2[j - 2] + 1);
    }
    std::swap(prev2, prev);
    std::swap(prev, cur);
  }
  return prev[m];
}

}  // namespace

std::string closestMatch(const std::string& word, const std::vector<std::string>& candidates) {
  if (word.size() > kLongestSuggested) return "";
  const int accept = std::max<int>(2, int(word.size()) / 3);
  const std::string w = lower(word);
  std::string best;
  int bestDist = accept + 1;
  for (const auto& c : candidates) {
    const long lengthGap = long(c.size()) - long(w.size());
    if (std::abs(lengthGap) >= bestDist) continue;  // the distance is at least the length gap
    const int dist = editDistance(w, lower(c));
    if (dist < bestDist) { bestDist = dist; best = c; }
  }
  return best;
}

std::string echoed(const std::string& token) {
  if (token.size() <= kEchoedChars) return token;
  std::size_t cut = kEchoedChars - 20;
  while (cut > 0 && (((unsigned char)token[cut]) & 0xc0) == 0x80) --cut;  // not inside a UTF-8 character
  return token.substr(0, cut) + "... (" + std::to_string(token.size()) + " characters)";
}

}  // namespace shizuku
