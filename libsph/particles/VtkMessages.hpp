// VTK's error and warning messages of one reader, writer or filter collected as text, so
// that they end up in our exception (which names the file) instead of on stderr. Used by
// the STL reader (particles/StlFile.cpp) and the particles.vtp reader and writer
// (io/VtpFile.cpp). Reads no keys.
#pragma once
#include <string>
#include <vtkCommand.h>

namespace shizuku {

class VtkMessages : public vtkCommand {
 public:
  static VtkMessages* New() { return new VtkMessages; }
  void Execute(vtkObject*, unsigned long, void* data) override {
    if (!data) return;
    std::string m = static_cast<const char*>(data);
    while (!m.empty() && (m.back() == '\n' || m.back() == ' ')) m.pop_back();
    auto cut = m.rfind("): ");  // drop "ERROR: In file, line N\nvtkClass (0x..): "
    if (cut != std::string::npos) m = m.substr(cut + 3);
    if (!text.empty()) text += "; ";
    text += m;
  }
  std::string text;
};

}  // namespace shizuku
