// The whole particle set on rank 0, gathered from every rank's own particles and sorted by
// id: what a distributed run hands to the one-file-per-field ascii format (writeFormat
// ascii), which is not written in pieces (docs/parallel.md 7). Rank 0 holds every particle
// while it writes.
// Reads no dictionary keys.
#pragma once
#include "decomposition/ParticlePacking.hpp"
#include "parallel/Communicator.hpp"
#include <algorithm>
#include <numeric>

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
  ParticleSet<D> unsorted = whole;
  unsorted.resize(n);
  ParticlePacking<D>::ensureFields(unsorted, mask);
  const char* in = all.data();
  for (std::size_t i = 0; i < n; ++i) in = ParticlePacking<D>::unpack(unsorted, mask, i, in);
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return unsorted.id[a] < unsorted.id[b]; });
  whole.resize(n);
  ParticlePacking<D>::ensureFields(whole, mask);
  std::vector<char> one(bytes);
  for (std::size_t k = 0; k < n; ++k) {
    ParticlePacking<D>::pack(unsorted, mask, order[k], one.data());
    ParticlePacking<D>::unpack(whole, mask, k, one.data());
  }
  return whole;
}

}  // namespace shizuku
