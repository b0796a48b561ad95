// What a restart checks in the values it has read (docs/reliability.md,
// "Restart files are validated before they are read"; the file's structure is
// checked before VTK reads it, VtpLayout.hpp):
//   - each particle: type fluid (0), wall (1), inlet (2) or outlet (3), a known surface class,
//     position, U, p, rhoN, normal and shift finite;
//   - ids unique, >= 0 and below the file's nextId (files without one: below
//     the particle count, as every id was then 0..n-1); particles may leave
//     and new ones be released, so ids need not be dense;
//   - fluid and wall counts as the field data states them (when it does);
//   - the time directory agrees with itself: uniform/time's value, index,
//     deltaT, deltaT0 equal the vtp's time, TimeValue, timeIndex, deltaT,
//     deltaT0 (those present).
// Each failure is an InputError naming the file and the particle (id and point
// index), array or keyword.
// Dictionary keys read: none.
#pragma once
#include "io/VtpFile.hpp"
#include <cstdint>
#include <optional>
#include <string>

namespace shizuku {

constexpr std::int64_t kMaxParticleId = std::int64_t(1) << 62;  // bound of nextId

struct ParticleCounts {
  std::optional<std::int64_t> fluid, wall;
  std::int64_t idLimit = 0;  // every id is below it
};

// The counts a writer states for the first `count` particles of p: fluid, wall, and one
// above the largest id (or p.nextId).
template <int D> ParticleCounts countParticles(const ParticleSet<D>& p, std::size_t count = std::size_t(-1));

// Throws InputError "corrupt particle file '<path>': ..." naming the particle.
template <int D> void checkParticleValues(const std::string& path, const ParticleSet<D>& p, const ParticleCounts& stated);

// The vtp's time fields against uniform/time (both files named on a mismatch).
void checkTimeAgreement(const std::string& vtpPath, const VtpTime& vtp, const std::string& timePath,
                        const TimeState& time);

}  // namespace shizuku
