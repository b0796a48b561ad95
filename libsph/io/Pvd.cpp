// <case>/particles.pvd (docs/design.md 1.3): the VTK "Collection" file listing
// every complete time directory with its time, so ParaView opens the series:
//   <DataSet timestep="0.1" group="" part="0" file="0.1/particles.vtp"/>
// (file="0.1/particles.pvtp" for a time a run on several ranks wrote).
// Rewritten through a temporary file and a rename, so it is always whole.
// Dictionary keys read: none.
#include "io/FileOps.hpp"
#include "io/TimeDirectory.hpp"
#include "io/TimeName.hpp"
#include <unistd.h>

namespace shizuku {

void writePvd(const std::string& caseDir) {
  const std::uint16_t probe = 1;
  const bool little = *reinterpret_cast<const std::uint8_t*>(&probe) == 1;
  std::string x = "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"";
  x += little ? "LittleEndian" : "BigEndian";
  x += "\">\n  <Collection>\n";
  for (const auto& [t, name] : listTimeDirectories(caseDir)) {
    const std::string file = particleFileOf(caseDir + "/" + name);
    if (file.empty()) continue;  // removed since it was listed
    x += "    <DataSet timestep=\"" + exactNumber(t) + "\" group=\"\" part=\"0\" file=\"" + name +
         file.substr(file.rfind('/')) + "\"/>\n";
  }
  x += "  </Collection>\n</VTKFile>\n";
  const std::string path = caseDir + "/particles.pvd";
  const std::string tmp = path + ".tmp-" + std::to_string(::getpid());
  try {
    fileops::writeFileSynced(tmp, x);
    fileops::renamePath(tmp, path);
  } catch (...) {
    fileops::removeTree(tmp);
    throw;
  }
  fileops::syncPath(caseDir);
}

}  // namespace shizuku
