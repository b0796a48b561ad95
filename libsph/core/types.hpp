// Basic types shared by every part of libsph: the spatial dimension D is a
// compile-time parameter (2 and 3 are instantiated), vectors are Eigen
// fixed-size types, particle indices are 32-bit.
#pragma once
#include <cmath>
#include <Eigen/Dense>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace shizuku {

template <int D> using Vec = Eigen::Matrix<double, D, 1>;
template <int D> using Mat = Eigen::Matrix<double, D, D>;
using Index = std::int32_t;
// Two doubles in one SSE2 register (GCC/Clang vector extension): the hot per-pair loops that
// the compiler does not vectorise on its own work two lanes at a time, each lane doing the
// scalar code's operations in its order (so the results are the same bits).
using DoublePair = double __attribute__((vector_size(16)));
// Both lanes' square roots (correctly rounded, as std::sqrt).
inline DoublePair sqrt(DoublePair x) {
#if defined(__SSE2__)
  return __builtin_ia32_sqrtpd(x);
#else
  return DoublePair{std::sqrt(x[0]), std::sqrt(x[1])};
#endif
}

// What a particle is: fluid; a wall; a particle of an inlet's buffer (moving at the
// prescribed velocity, released as fluid when it crosses the inlet's face); a particle of
// an outlet's buffer (fluid that crossed the outlet's face: prescribed pressure, removed
// past the buffer's far face). docs/boundaries.md.
enum class ParticleType : std::uint8_t { fluid = 0, wall = 1, inlet = 2, outlet = 3 };
inline const char* particleTypeName(std::uint8_t t) {
  return t == 0 ? "fluid" : t == 1 ? "wall" : t == 2 ? "inlet" : t == 3 ? "outlet" : "?";
}

// Free-surface class of a fluid particle (docs/method.md 5.2). Wall particles are `interior`.
enum class SurfaceClass : std::uint8_t { interior = 0, vicinity = 1, free = 2, splash = 3 };

inline const char* surfaceClassName(SurfaceClass c) {
  switch (c) {
    case SurfaceClass::interior: return "interior";
    case SurfaceClass::vicinity: return "vicinity";
    case SurfaceClass::free: return "free surface";
    case SurfaceClass::splash: return "splash";
  }
  return "?";
}

inline bool nearSurface(SurfaceClass c) {
  return c == SurfaceClass::free || c == SurfaceClass::vicinity || c == SurfaceClass::splash;
}

// Bad input: exit status 1 (docs/design.md 1.1). `what()` is the whole message,
// already naming file, line and keyword where known.
struct InputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Numerical failure: exit status 2 after the last good state is written.
struct NumericalError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace shizuku
