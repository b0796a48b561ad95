// Selecting saved time directories on a command line (shizukuPostProcess,
// docs/design.md 1.1), e.g. `-time 0.1,0.2`, `-time 0.1:0.5`, `-time latestTime`:
// comma-separated items, each
//   a number      the saved time equal to it (relative tolerance 1e-9) or named so;
//   a:b a: :b     every saved time t with a <= t <= b (bounds optional, tolerance 1e-9);
//   latestTime    the last saved time;  firstTime the first one;  all  every time.
// The result is sorted by time without repeats. A non-finite number (inf, nan)
// is an InputError, as is a number that matches no
// saved time, an empty range or a malformed item is an InputError listing the
// saved times.
// Dictionary keys read: none.
#pragma once
#include <string>
#include <utility>
#include <vector>

namespace shizuku {

// `available`: (time, name) pairs sorted by time (listTimeDirectories()).
// An empty `selection` selects every time.
std::vector<std::pair<double, std::string>> selectTimes(const std::vector<std::pair<double, std::string>>& available,
                                                        const std::string& selection);

}  // namespace shizuku
