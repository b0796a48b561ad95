// particles.pvtp writer and strict reader: see VtpPieces.hpp.
#include "io/VtpPieces.hpp"
#include "io/FileOps.hpp"
#include "io/VtpLayout.hpp"
#include "core/types.hpp"
#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>
#include <type_traits>

namespace shizuku {

namespace {
const std::string kHead = "particles_", kTail = ".vtp";
}  // namespace

std::string pieceFileName(int k) { return kHead + std::to_string(k) + kTail; }

bool isPieceFileName(const std::string& name) {
  if (name.size() <= kHead.size() + kTail.size() || name.compare(0, kHead.size(), kHead) != 0 ||
      name.compare(name.size() - kTail.size(), kTail.size(), kTail) != 0)
    return false;
  return name.find_first_not_of("0123456789", kHead.size()) == name.size() - kTail.size();
}

namespace {

template <class T, int D>
void describe(const char* name, std::string& x) {
  using V = typename T::value_type;
  const char* type = std::is_same_v<V, std::uint8_t> ? "UInt8" : std::is_same_v<V, std::int64_t> ? "Int64" : "Float64";
  const int components = std::is_same_v<V, Vec<D>> ? 3 : 1;
  x += std::string("      <PDataArray type=\"") + type + "\" Name=\"" + name + "\" NumberOfComponents=\"" +
       std::to_string(components) + "\"/>\n";
}

// The value of attribute `name` in the element text `e` ("" when absent).
std::string attribute(const std::string& e, const std::string& name) {
  const std::string key = " " + name + "=\"";
  const std::size_t at = e.find(key);
  if (at == std::string::npos) return "";
  const std::size_t start = at + key.size(), end = e.find('"', start);
  return end == std::string::npos ? "" : e.substr(start, end - start);
}

}  // namespace

template <int D>
void writePvtp(const std::string& path, const ParticleSet<D>& p, int pieces) {
  const std::uint16_t probe = 1;
  const bool little = *reinterpret_cast<const std::uint8_t*>(&probe) == 1;
  std::string x = "<?xml version=\"1.0\"?>\n<VTKFile type=\"PPolyData\" version=\"1.0\" byte_order=\"";
  x += little ? "LittleEndian" : "BigEndian";
  x += "\" header_type=\"UInt64\">\n  <PPolyData GhostLevel=\"0\">\n    <PPointData>\n";
  p.forEachField([&](const char* name, const auto& v) {
    if (!v.empty() || ParticleSet<D>::isMandatory(name)) describe<std::decay_t<decltype(v)>, D>(name, x);
  });
  x += "    </PPointData>\n    <PPoints>\n";
  describe<std::vector<Vec<D>>, D>("position", x);
  x += "    </PPoints>\n";
  for (int k = 0; k < pieces; ++k) x += "    <Piece Source=\"" + pieceFileName(k) + "\"/>\n";
  x += "  </PPolyData>\n</VTKFile>\n";
  fileops::writeFileSynced(path, x);
}

std::vector<std::string> readPvtpPieces(const std::string& path) {
  if (!fileops::isRegularFile(path))
    throw InputError("cannot read particle file '" + path + "': " +
                     (fileops::isDirectory(path) ? std::string("it is a folder") : std::strerror(ENOENT)));
  std::ifstream in(path, std::ios::binary);
  in.seekg(0, std::ios::end);
  const std::streamoff size = in.tellg();
  if (!in || size < 0) corruptVtp(path, "cannot be read");
  if (size > (std::streamoff(64) << 20)) corruptVtp(path, "larger than 64 MB, which no header of pieces is");
  in.seekg(0);
  std::string text(std::size_t(size), '\0');
  in.read(text.data(), size);
  if (!in) corruptVtp(path, "cannot be read");
  const std::size_t root = text.find("<VTKFile");
  if (root == std::string::npos || attribute(text.substr(root, text.find('>', root) - root), "type") != "PPolyData")
    corruptVtp(path, "not a VTKFile of type PPolyData");
  if (text.find("</VTKFile>") == std::string::npos) corruptVtp(path, "ends before </VTKFile>");
  std::vector<std::string> pieces;
  for (std::size_t at = text.find("<Piece"); at != std::string::npos; at = text.find("<Piece", at + 1)) {
    const std::size_t end = text.find('>', at);
    if (end == std::string::npos) corruptVtp(path, "a <Piece> element is not closed");
    const std::string source = attribute(text.substr(at, end - at), "Source");
    const int k = int(pieces.size());
    if (k >= kMaxPieces) corruptVtp(path, "more than " + std::to_string(kMaxPieces) + " pieces");
    if (source != pieceFileName(k))
      corruptVtp(path, "piece " + std::to_string(k) + " is '" + source + "', expected '" + pieceFileName(k) +
                           "' (a run on several ranks names its pieces particles_0.vtp, particles_1.vtp, ... in order)");
    pieces.push_back(source);
  }
  if (pieces.empty()) corruptVtp(path, "names no piece");
  return pieces;
}

template void writePvtp<2>(const std::string&, const ParticleSet<2>&, int);
template void writePvtp<3>(const std::string&, const ParticleSet<3>&, int);

}  // namespace shizuku
