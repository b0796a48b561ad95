// The memory check before allocation: see MemoryCheck.hpp.
#include "particles/MemoryCheck.hpp"
#include "core/Log.hpp"
#include <fstream>
#include <sstream>
#include <sys/resource.h>

namespace shizuku {

namespace {

// "3.2 GB"
std::string bytesText(double b) {
  const char* units[] = {"B", "kB", "MB", "GB", "TB", "PB"};
  int k = 0;
  while (b >= 1000 && k < 5) { b /= 1000; ++k; }
  std::ostringstream s;
  s.precision(3);
  s << b << " " << units[k];
  return s.str();
}

// A "Name:  N kB" field of a /proc file, in bytes; negative when absent.
double procField(const char* path, const std::string& name) {
  std::ifstream in(path);
  std::string key;
  double value;
  std::string unit;
  while (in >> key >> value >> unit)
    if (key == name + ":") return value * 1024;
  return -1;
}

}  // namespace

// Measured with shizuku -threads 1 (peak RSS of /usr/bin/time -v, 2026-12): the
// damBreak tutorial at d0 = 1 cm and 0.5 cm (6418 and 20818 particles, 36.7 and 74.5
// MB): 2685 B per particle in 2D; a 3D tank of 3868 and 10558 particles (42.6 and 89.2
// MB): 7124 B per particle in 3D. Rounded up by about 10 %.
double bytesPerParticle(int dimension) { return dimension == 3 ? 8000 : 3000; }

double availableBytes(std::string& limitedBy) {
  double avail = procField("/proc/meminfo", "MemAvailable");
  limitedBy = "MemAvailable in /proc/meminfo";
  rlimit lim{};
  if (getrlimit(RLIMIT_AS, &lim) == 0 && lim.rlim_cur != RLIM_INFINITY) {
    const double used = std::max(0.0, procField("/proc/self/status", "VmSize"));
    const double left = double(lim.rlim_cur) - used;
    if (avail < 0 || left < avail) {
      avail = left;
      limitedBy = "RLIMIT_AS (ulimit -v) less the " + bytesText(used) + " already mapped";
    }
  }
  return avail;
}

void checkMemoryFor(const Dictionary& d, const std::string& key, double particles, int dimension) {
  std::string limitedBy;
  const double avail = availableBytes(limitedBy);
  const double need = particles * bytesPerParticle(dimension);
  if (avail < 0 || need <= avail) return;
  d.error(key, cat("the regions would hold ", particles, " particles, needing about ", bytesText(need), " (",
                   bytesPerParticle(dimension), " bytes per particle in ", dimension, "D) but only ",
                   bytesText(std::max(avail, 0.0)), " are available (", limitedBy,
                   "): use a larger spacing or a machine with more memory"));
}

}  // namespace shizuku
