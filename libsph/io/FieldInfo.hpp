// Units and descriptions of the particle fields as written to disk
// (docs/design.md 1.3; names from ParticleSet::forEachField). Used by the ascii
// writer's headers and by docs/output.md. Dictionary keys read: none.
#pragma once
#include <string>

namespace shizuku {

// SI unit of a field in D dimensions ("-" for dimensionless or labels).
inline std::string fieldUnit(const std::string& name, int D) {
  if (name == "position" || name == "shift" || name == "restPosition") return "m";
  if (name == "U") return "m/s";
  if (name == "p") return "Pa";
  if (name == "rhoN") return D == 3 ? "kg/m^3" : D == 2 ? "kg/m^2" : "kg/m";
  return "-";
}

}  // namespace shizuku
