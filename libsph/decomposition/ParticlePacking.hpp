// Particles as bytes, for sending them to another rank (migration, halo copies): the
// position and every field of forEachField (the list the writer and the reordering use)
// that the field mask names, one particle after the other. All fields are plain values
// (Vec<D>, double, integers), so a particle is copied byte for byte. The mask is agreed
// across ranks (fieldMask, OR-ed by the caller): a rank that holds no particle cannot
// tell an optional field from an absent one.
// Reads no dictionary keys.
#pragma once
#include "parallel/Communicator.hpp"
#include "particles/ParticleSet.hpp"
#include <cstring>

namespace shizuku {

template <int D>
struct ParticlePacking {
  // Bit f set: forEachField's field number f is present (non-empty) here.
  static long fieldMask(const ParticleSet<D>& P) {
    long mask = 0, f = 0;
    P.forEachField([&](const char*, const auto& v) { mask |= long(!v.empty()) << f++; });
    return mask;
  }
  // The fields present on any rank (fieldMask OR-ed over the ranks). Collective.
  static long agreedFieldMask(const ParticleSet<D>& P) {
    long mask = 0;
    for (long m : Communicator::world().allGather(fieldMask(P))) mask |= m;
    return mask;
  }
  // Size the fields of the mask to the particle count (a rank that had none of them).
  static void ensureFields(ParticleSet<D>& P, long mask) {
    long f = 0;
    P.forEachField([&](const char*, auto& v) {
      if ((mask >> f++) & 1) v.resize(P.size());
    });
  }
  // Bytes one particle takes.
  static std::size_t bytesPerParticle(const ParticleSet<D>& P, long mask) {
    std::size_t b = sizeof(Vec<D>);
    long f = 0;
    P.forEachField([&](const char*, const auto& v) {
      if ((mask >> f++) & 1) b += sizeof(typename std::decay_t<decltype(v)>::value_type);
    });
    return b;
  }
  // Copy particle i of P to dst; returns the end.
  static char* pack(const ParticleSet<D>& P, long mask, std::size_t i, char* dst) {
    std::memcpy(dst, &P.position[i], sizeof(Vec<D>));
    dst += sizeof(Vec<D>);
    long f = 0;
    P.forEachField([&](const char*, const auto& v) {
      if (!((mask >> f++) & 1)) return;
      using T = typename std::decay_t<decltype(v)>::value_type;
      std::memcpy(dst, &v[i], sizeof(T));
      dst += sizeof(T);
    });
    return dst;
  }
  // Write the particle at src into slot i of P (the fields of the mask sized past i).
  static const char* unpack(ParticleSet<D>& P, long mask, std::size_t i, const char* src) {
    std::memcpy(&P.position[i], src, sizeof(Vec<D>));
    src += sizeof(Vec<D>);
    long f = 0;
    P.forEachField([&](const char*, auto& v) {
      if (!((mask >> f++) & 1)) return;
      using T = typename std::decay_t<decltype(v)>::value_type;
      std::memcpy(&v[i], src, sizeof(T));
      src += sizeof(T);
    });
    return src;
  }
};

}  // namespace shizuku
