// Command-line time selection: see TimeSelection.hpp.
#include "functionObjects/TimeSelection.hpp"
#include "core/types.hpp"
#include "io/TimeName.hpp"
#include <algorithm>
#include <cmath>
#include <optional>

namespace shizuku {

namespace {
std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t");
  if (b == std::string::npos) return "";
  return s.substr(b, s.find_last_not_of(" \t") - b + 1);
}

// A time of the selection: a finite number (inf or nan would match every saved
// time through the tolerance), or nullopt when `text` is no number at all.
std::optional<double> finiteTime(const std::string& text, const std::string& item) {
  const auto v = parseNumber(text);
  if (v && !std::isfinite(*v))
    throw InputError("-time: '" + item + "': '" + text + "' is not a finite time; give a saved time, a range a:b " +
                     "(leave an end empty for no bound: 0.1: or :0.5), latestTime, firstTime or all");
  return v;
}

bool near(double a, double b) { return std::abs(a - b) <= 1e-9 * std::max(1.0, std::max(std::abs(a), std::abs(b))); }
}  // namespace

std::vector<std::pair<double, std::string>> selectTimes(const std::vector<std::pair<double, std::string>>& available,
                                                        const std::string& selection) {
  std::string list;
  for (const auto& t : available) list += " " + t.second;
  const std::string saved = available.empty() ? "there are no saved times" : "saved times:" + list;
  if (trim(selection).empty()) return available;
  std::vector<bool> chosen(available.size(), false);
  std::size_t start = 0;
  while (start <= selection.size()) {
    std::size_t end = selection.find(',', start);
    if (end == std::string::npos) end = selection.size();
    const std::string item = trim(selection.substr(start, end - start));
    start = end + 1;
    if (item.empty()) throw InputError("-time '" + selection + "': empty item");
    if (item == "all") {
      std::fill(chosen.begin(), chosen.end(), true);
    } else if (item == "latestTime" || item == "firstTime") {
      if (available.empty()) throw InputError("-time " + item + ": " + saved);
      chosen[item == "latestTime" ? available.size() - 1 : 0] = true;
    } else if (const auto colon = item.find(':'); colon != std::string::npos) {
      const std::string a = trim(item.substr(0, colon)), b = trim(item.substr(colon + 1));
      const auto lo = a.empty() ? std::optional<double>(-INFINITY) : finiteTime(a, item);
      const auto hi = b.empty() ? std::optional<double>(INFINITY) : finiteTime(b, item);
      if (!lo || !hi) throw InputError("-time: '" + item + "' is not a range a:b of times");
      bool any = false;
      for (std::size_t k = 0; k < available.size(); ++k) {
        const double t = available[k].first;
        if ((t >= *lo || near(t, *lo)) && (t <= *hi || near(t, *hi))) chosen[k] = any = true;
      }
      if (!any) throw InputError("-time: no saved time in " + item + "; " + saved);
    } else {
      const auto v = finiteTime(item, item);
      if (!v) throw InputError("-time: '" + item + "' is not a time, a range a:b, latestTime, firstTime or all");
      bool any = false;
      for (std::size_t k = 0; k < available.size(); ++k)
        if (available[k].second == item || near(available[k].first, *v)) chosen[k] = any = true;
      if (!any) throw InputError("-time: no saved time " + item + "; " + saved);
    }
  }
  std::vector<std::pair<double, std::string>> out;
  for (std::size_t k = 0; k < available.size(); ++k)
    if (chosen[k]) out.push_back(available[k]);
  return out;
}

}  // namespace shizuku
