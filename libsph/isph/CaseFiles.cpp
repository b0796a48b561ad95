// Reading the case dictionaries.
#include "isph/CaseFiles.hpp"
#include <filesystem>

namespace shizuku {

namespace fs = std::filesystem;

CaseFiles CaseFiles::read(const std::string& caseDir) {
  if (!fs::is_directory(caseDir)) throw InputError(caseDir + ": case directory not found");
  CaseFiles c;
  c.dir = caseDir;
  c.controlDict = Dictionary::fromFile(c.path("system/controlDict"));
  c.sphSchemes = Dictionary::fromFileIfPresent(c.path("system/sphSchemes"));
  c.sphSolution = Dictionary::fromFileIfPresent(c.path("system/sphSolution"));
  c.particlesDict = Dictionary::fromFile(c.path("system/particlesDict"));
  c.physicalProperties = Dictionary::fromFile(c.path("constant/physicalProperties"));
  if (fs::exists(c.path("constant/g"))) c.gravity = Dictionary::fromFile(c.path("constant/g"));
  if (fs::exists(c.path("system/decomposeParDict")))
    c.decomposeParDict = Dictionary::fromFile(c.path("system/decomposeParDict"));
  return c;
}

void CaseFiles::checkAllRead() const {
  controlDict.checkAllRead();
  sphSchemes.checkAllRead();
  sphSolution.checkAllRead();
  particlesDict.checkAllRead();
  physicalProperties.checkAllRead();
  if (gravity) gravity->checkAllRead();
  if (decomposeParDict) decomposeParDict->checkAllRead();
}

int caseDimension(const std::string& caseDir) {
  if (!fs::is_directory(caseDir)) throw InputError(caseDir + ": case directory not found");
  const Dictionary d = Dictionary::fromFile(caseDir + "/system/particlesDict");
  if (d.found("dimension")) {
    const int n = d.getInt("dimension");
    if (n != 2 && n != 3) d.error("dimension", "must be 2 or 3");
    return n;
  }
  if (const Dictionary* regions = d.subDictPtr("regions")) {
    for (const auto& name : regions->keys()) {
      if (!regions->isDict(name)) continue;
      const Dictionary& r = regions->subDict(name);
      for (const char* key : {"min", "centre", "point1"})
        if (r.found(key)) {
          const DictValue& v = r.value(key);
          if (v.kind == DictValue::Kind::list && (v.items.size() == 2 || v.items.size() == 3))
            return int(v.items.size());
        }
    }
  }
  return 2;
}

}  // namespace shizuku
