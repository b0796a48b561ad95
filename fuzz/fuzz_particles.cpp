// Fuzz target: the particle generator (libsph/particles/ParticleGenerator.*)
// on a fuzzed system/particlesDict.
//
// Input: the text of a particlesDict. The first byte picks the dimension
// (even: 2D, odd: 3D); the rest is parsed with Dictionary::fromString and
// handed to generateParticles<D> with a cap of 1e5 particles, the
// generator's own limit (maxParticles, checked before anything is allocated),
// lowered so each input runs in milliseconds. Bad input must end in
// InputError; the particles made must be finite, of a known type, in the
// generator's order (fluid, then walls, then inlet and outlet buffers), with
// ids 0..n-1. Anything else (another exception, a sanitizer report, a crash, a
// hang) is a bug.
//
// Built two ways (fuzz/CMakeLists.txt): as a libFuzzer target and as a
// corpus-replay program run by ctest.
#include "core/Dictionary.hpp"
#include "particles/ParticleGenerator.hpp"
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

using namespace shizuku;

namespace {

constexpr double kCap = 1e5;

template <int D> void generate(const Dictionary& d) {
  const GeneratedParticles<D> g = generateParticles<D>(d, kCap);
  const ParticleSet<D>& s = g.set;
  if (double(s.size()) > kCap) std::abort();  // the limit was not kept
  // Rank in the generator's order: fluid 0, wall 1, an inlet's or outlet's buffer 2.
  const auto rank = [](std::uint8_t t) { return t < std::uint8_t(ParticleType::inlet) ? int(t) : 2; };
  int previous = 0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (!s.position[i].allFinite() || !s.velocity[i].allFinite()) std::abort();
    if (s.id[i] != std::int64_t(i)) std::abort();
    if (s.type[i] > std::uint8_t(ParticleType::outlet)) std::abort();
    if (rank(s.type[i]) < previous) std::abort();  // fluid, then walls, then buffers
    previous = rank(s.type[i]);
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 1 || size > 16384) return 0;
  const std::string text(reinterpret_cast<const char*>(data) + 1, size - 1);
  // No #include: the generator is the target here (fuzz_dictionary covers includes).
  if (text.find('#') != std::string::npos) return 0;
  try {
    const Dictionary d = Dictionary::fromString(text, "fuzz/system/particlesDict");
    if (data[0] % 2 == 0) generate<2>(d);
    else generate<3>(d);
  } catch (const InputError&) {
  }
  Dictionary::defaultsUsed().clear();
  return 0;
}
