// One particles.vtp file (docs/design.md 1.3): VTK XML PolyData, Float64, binary
// (appended raw data, no compression, 64-bit headers), read back bit for bit.
// Points: positions (z = 0 in 2D); one vertex cell per particle so ParaView
// draws points; point data: every non-empty field of ParticleSet::forEachField
// (vectors padded to 3 components, uint8 -> UInt8, int64 -> Int64, doubles ->
// Float64); field data: mass, rho0, spacing, volume (= mass/rho0), dimension,
// time, TimeValue (ParaView's name for it), timeIndex, deltaT, deltaT0,
// fluidParticles, wallParticles, nextId (every id is below it).
// Reading validates before VTK sees the file (VtpLayout.hpp) and the values
// after (RestartChecks.hpp): a damaged or hostile file is an InputError
// naming the file and the array, field or particle id, never a crash.
// Dictionary keys read: none.
#pragma once
#include "io/TimeDirectory.hpp"
#include <optional>
#include <string>

namespace shizuku {

// The time state a particles.vtp keeps in its field data (absent in files of
// older versions). Each present value is finite, steps are >= 0, time steps
// > 0 (or 0 at step 0).
struct VtpTime {
  std::optional<double> time, timeValue, deltaT, deltaT0;
  std::optional<long> step;
};

// The first `count` particles of p (all by default; a rank writes its own, not its
// ghosts). Throws std::runtime_error naming the file on any write failure.
template <int D>
void writeVtp(const std::string& path, const ParticleSet<D>& p, const TimeState& s,
              std::size_t count = std::size_t(-1));
// Throws InputError naming the file if it is missing, corrupt, of another
// dimension, or holds values a run cannot start from. If `t` is non-null,
// the time state kept in the field data is stored there.
template <int D> ParticleSet<D> readVtp(const std::string& path, VtpTime* t = nullptr);

}  // namespace shizuku
