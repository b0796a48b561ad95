// ascii field files: see AsciiFields.hpp (docs/design.md 1.3).
#include "io/AsciiFields.hpp"
#include "io/FieldInfo.hpp"
#include "io/FileOps.hpp"
#include "io/TimeName.hpp"
#include <charconv>

namespace shizuku {

namespace {

// Append the exact shortest text of v to out.
void put(std::string& out, double v) { out += exactNumber(v); }
void put(std::string& out, std::uint8_t v) { out += std::to_string(unsigned(v)); }
void put(std::string& out, std::int64_t v) { out += std::to_string(v); }
template <int D> void put(std::string& out, const Vec<D>& v) {
  for (int k = 0; k < D; ++k) {
    if (k) out += ' ';
    put(out, v[k]);
  }
}

template <class T> int components(const std::vector<T>&) { return 1; }
template <int D> int components(const std::vector<Vec<D>>&) { return D; }

template <class T>
void writeField(const std::string& dir, const char* name, const std::vector<T>& v, int D, double time) {
  const std::string path = dir + "/" + name;
  fileops::SyncedFile f(path);
  const int nc = components(v);
  std::string head = std::string("# field ") + name + "\n# unit " + fieldUnit(name, D) + "\n# time " +
                     exactNumber(time) + "\n# particles " + std::to_string(v.size()) + "\n# columns";
  const char* axes[] = {"x", "y", "z"};
  if (nc == 1) head += std::string(" ") + name;
  else
    for (int k = 0; k < nc; ++k) head += std::string(" ") + name + "_" + axes[k];
  head += "\n";
  f.write(head);
  std::string line;
  for (const auto& x : v) {
    line.clear();
    put(line, x);
    line += '\n';
    f.write(line);
  }
  f.close();
}

}  // namespace

template <int D>
void writeAsciiFields(const std::string& dir, const ParticleSet<D>& p, double time) {
  writeField(dir, "position", p.position, D, time);
  p.forEachField([&](const char* name, const auto& v) {
    if (!v.empty()) writeField(dir, name, v, D, time);
  });
}

template void writeAsciiFields<2>(const std::string&, const ParticleSet<2>&, double);
template void writeAsciiFields<3>(const std::string&, const ParticleSet<3>&, double);

}  // namespace shizuku
