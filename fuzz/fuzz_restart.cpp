// Fuzz target: the restart reader (libsph/io/TimeDirectory.cpp: VtpLayout's
// pre-scan, VTK's reader, RestartChecks, TimeFile) on a fuzzed time directory.
//
// Input: the bytes of particles.vtp, the separator line
// "\n--- uniform/time ---\n", then the text of uniform/time (no separator:
// all of it is the vtp, uniform/time is empty). Both are written into a
// scratch case as 0.002/particles.vtp and 0.002/uniform/time; the time file
// is read on its own, the vtp on its own, and, when the time file was read,
// the whole time directory. Bad input must end in InputError; what a read
// returns must hold what the checks promise (finite values, types fluid,
// wall, inlet or outlet, unique ids >= 0, finite time, index >= 0, time
// steps >= 0). Anything else (another exception, a sanitizer report, a
// crash, a hang) is a bug.
//
// Built two ways (fuzz/CMakeLists.txt): as a libFuzzer target and as a
// corpus-replay program run by ctest. Seeds: tests/badInput/makeRestartCases.py.
#include "io/TimeDirectory.hpp"
#include "io/TimeFile.hpp"
#include "io/VtpFile.hpp"
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

using namespace shizuku;

namespace {

const std::string kSeparator = "\n--- uniform/time ---\n";
const std::string kTime = "0.002";

// One scratch case per process, removed at exit.
struct Scratch {
  std::string dir;
  Scratch() {
    char tmpl[] = "/tmp/shizuku_fuzz_restart_XXXXXX";
    if (!::mkdtemp(tmpl)) std::abort();
    dir = tmpl;
    std::filesystem::create_directories(dir + "/" + kTime + "/uniform");
  }
  ~Scratch() {
    std::error_code ec;
    std::filesystem::remove_all(dir, ec);
  }
};

void writeFile(const std::string& path, const std::string& bytes) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), std::streamsize(bytes.size()));
  if (!out) std::abort();
}

void checkTime(const TimeState& s) {
  if (!std::isfinite(s.time) || s.step < 0) std::abort();
  if (!std::isfinite(s.deltaT) || !std::isfinite(s.deltaT0) || s.deltaT < 0 || s.deltaT0 < 0) std::abort();
}

void checkParticles(const ParticleSet<2>& p) {
  const std::size_t n = p.size();
  if (p.velocity.size() != n || p.pressure.size() != n || p.type.size() != n || p.id.size() != n) std::abort();
  if (!(p.mass > 0) || !(p.rho0 > 0) || !(p.spacing > 0) || !std::isfinite(p.mass)) std::abort();
  for (std::size_t i = 0; i < n; ++i) {
    if (!p.position[i].allFinite() || !p.velocity[i].allFinite() || !std::isfinite(p.pressure[i])) std::abort();
    if (p.type[i] > std::uint8_t(ParticleType::outlet) || p.id[i] < 0) std::abort();
  }
  std::vector<std::int64_t> ids = p.id;
  std::sort(ids.begin(), ids.end());
  if (std::adjacent_find(ids.begin(), ids.end()) != ids.end()) std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static Scratch scratch;
  const std::string input(reinterpret_cast<const char*>(data), size);
  const std::size_t cut = input.find(kSeparator);
  const std::string vtp = input.substr(0, cut);
  const std::string time = cut == std::string::npos ? std::string() : input.substr(cut + kSeparator.size());
  const std::string folder = scratch.dir + "/" + kTime;
  writeFile(folder + "/particles.vtp", vtp);
  writeFile(folder + "/uniform/time", time);
  bool timeRead = false;
  try {
    checkTime(readTimeFile(folder + "/uniform/time", kTime));
    timeRead = true;
  } catch (const InputError&) {
  }
  try {
    checkParticles(readVtp<2>(folder + "/particles.vtp"));
  } catch (const InputError&) {
  }
  if (timeRead) {
    try {
      TimeState s;
      checkParticles(readTimeDirectory<2>(scratch.dir, kTime, s));
      checkTime(s);
    } catch (const InputError&) {
    }
  }
  return 0;
}
