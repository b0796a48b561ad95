// The whole particle set on rank 0, gathered from every rank's own particles and sorted by
// id: what a distributed run hands to the one-file-per-field ascii format (writeFormat
// ascii), which is not written in pieces (docs/parallel.md 7). Rank 0 holds every particle
// while it writes.
// Reads no dictionary keys.
#pragma once
#include "decomposition/ParticlePacking.hpp"
#include "parallel/Communicator.hpp"

namespace shizuku {

// P's first `owned` particles of every rank, on rank 0 (other ranks get an empty set with
// P's constants). Collective.
template <int D>
ParticleSet<D> gatherParticles(const ParticleSet<D>& P, std::size_t owned) {
  const auto& world = Communicator::world();
  const long mask = ParticlePacking<D>::agreedFieldMask(P);
  const std::size_t bytes = ParticlePacking<D>::bytesPerParticle(P, mask);
  std::vector<char> mine(owned * bytes);
  char* out = mine.data();
  for (std::size_t i = 0; i < owned; ++i) out = ParticlePacking<D>::pack(P, mask, i, out);
  const std::vector<char> all = world.gatherToRoot(mine);
  ParticleSet<D> whole;
  whole.mass = P.mass;
  whole.rho0 = P.rho0;
  whole.spacing = P.spacing;
  whole.nextId = P.nextId;
  const std::size_t n = all.size() / bytes;
  whole.resize(n);
  ParticlePacking<D>::ensureFields(whole, mask);
  const char* in = all.data();
  for (std::size_t i = 0; i < n; ++i) in = ParticlePacking<D>::unpack(whole, mask, i, in);
  whole.sortById();
  return whole;
}

}  // namespace shizuku
