// Helpers shared by the io unit tests: a scratch case folder removed at the
// end, a file's whole content, random particle sets with awkward doubles,
// bit-exact comparison. Included after <boost/test/unit_test.hpp>.
#pragma once
#include <boost/test/unit_test.hpp>
#include "particles/ParticleSet.hpp"
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <sstream>
#include <string>

namespace shizuku::iotest {

struct ScratchDir {
  std::string path;
  ScratchDir() {
    char tmpl[] = "/tmp/shizuku_io_XXXXXX";
    const char* p = ::mkdtemp(tmpl);
    if (!p) throw std::runtime_error("mkdtemp failed");
    path = p;
  }
  ~ScratchDir() {
    std::error_code ec;
    std::filesystem::remove_all(path, ec);
  }
};

// The bytes of a file ("" when it cannot be read).
inline std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// A double with random sign, mantissa and an exponent anywhere in
// [1e-300, 1e300], plus a few special values, so text or float conversion
// anywhere on the way would show.
inline double awkward(std::mt19937_64& g) {
  std::uint64_t r = g();
  switch (r % 16) {
    case 0: return -0.0;
    case 1: return std::numeric_limits<double>::denorm_min() * double(1 + (r >> 40) % 1000);
    case 2: return std::numeric_limits<double>::max();
    case 3: return 0.1;
    default: break;
  }
  std::uniform_real_distribution<double> m(-1, 1), e(-300, 300);
  return m(g) * std::pow(10.0, e(g));
}

template <int D>
ParticleSet<D> randomSet(std::size_t n, bool optional, std::uint64_t seed) {
  std::mt19937_64 g(seed);
  ParticleSet<D> p;
  p.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    for (int k = 0; k < D; ++k) {
      p.position[i][k] = awkward(g);
      p.velocity[i][k] = awkward(g);
    }
    p.pressure[i] = awkward(g);
    p.density[i] = awkward(g);
    p.type[i] = std::uint8_t(g() % 2);
    p.surface[i] = std::uint8_t(g() % 4);
    p.id[i] = std::int64_t(g() >> 2);  // ids up to 2^62 (RestartChecks.hpp): a trip through double would lose bits
  }
  if (optional) {
    p.shift.resize(n);
    for (auto& s : p.shift)
      for (int k = 0; k < D; ++k) s[k] = awkward(g);
  }
  p.mass = 0.1 + 1e-17 * double(g() % 7);
  p.rho0 = 998.2071;
  p.spacing = 1.0 / 3.0;
  return p;
}

template <class T> bool sameBits(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

inline bool sameBits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

// The evolving state of two particle sets agrees bit for bit: positions,
// velocities, pressures and shifts (what a restart must carry over).
template <int D>
void checkSameState(const ParticleSet<D>& a, const ParticleSet<D>& b) {
  BOOST_TEST(sameBits(a.position, b.position));
  BOOST_TEST(sameBits(a.velocity, b.velocity));
  BOOST_TEST(sameBits(a.pressure, b.pressure));
  BOOST_TEST(sameBits(a.shift, b.shift));
}

}  // namespace shizuku::iotest
