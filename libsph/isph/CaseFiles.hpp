// The dictionaries of a case directory (docs/design.md 1.2), parsed once:
// system/{controlDict, sphSchemes, sphSolution, particlesDict},
// constant/physicalProperties and the optional constant/g and system/decomposeParDict.
#pragma once
#include "core/Dictionary.hpp"
#include <optional>
#include <string>

namespace shizuku {

struct CaseFiles {
  std::string dir;
  Dictionary controlDict, sphSchemes, sphSolution, particlesDict, physicalProperties;
  std::optional<Dictionary> gravity;  // constant/g: absent = no body force is built
  std::optional<Dictionary> decomposeParDict;  // system/decomposeParDict: distributed runs' settings

  static CaseFiles read(const std::string& caseDir);
  std::string path(const std::string& relative) const { return dir + "/" + relative; }
  // Every keyword nobody asked for is an error (with did-you-mean).
  void checkAllRead() const;
};

// Spatial dimension of a case: `dimension` in system/particlesDict, else the
// number of components of the first region's `min`, `centre` or `point1` (an STL-only
// case without `dimension` is 2D, and its STL region an error saying so).
int caseDimension(const std::string& caseDir);

}  // namespace shizuku
