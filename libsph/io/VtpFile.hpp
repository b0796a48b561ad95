// One particles.vtp file (docs/design.md 1.3): VTK XML PolyData, Float64, binary
// (appended raw data, no compression, 64-bit headers), read back bit for bit.
// Points: positions (z = 0 in 2D); one vertex cell per particle so ParaView
// draws points; point data: every non-empty field of ParticleSet::forEachField
// (vectors padded to 3 components, uint8 -> UInt8, int64 -> Int64, doubles ->
// Float64); field data: mass, rho0, spacing, volume (= mass/rho0), dimension,
// time, TimeValue (ParaView's name for it), timeIndex, deltaT, deltaT0.
// Dictionary keys read: none.
#pragma once
#include "io/TimeDirectory.hpp"
#include <string>

namespace shizuku {

// Throws std::runtime_error naming the file on any write failure.
template <int D> void writeVtp(const std::string& path, const ParticleSet<D>& p, const TimeState& s);
// Throws InputError naming the file if it is missing, corrupt, or of another
// dimension. If `s` is non-null, the time state kept in the field data is
// stored there (note stays empty).
template <int D> ParticleSet<D> readVtp(const std::string& path, TimeState* s = nullptr);

}  // namespace shizuku
