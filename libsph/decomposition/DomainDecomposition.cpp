// The domain decomposition of a distributed run: see DomainDecomposition.hpp.
#include "decomposition/DomainDecomposition.hpp"
#include "decomposition/ParticlePacking.hpp"
#include "core/Log.hpp"
#include <algorithm>
#include <numeric>

namespace shizuku {

template <int D>
DomainDecomposition<D>::DomainDecomposition(const DecompositionSettings& settings, double haloWidth,
                                            const PeriodicBox<D>& box)
    : settings_(settings), zoltan_(settings.method, D), halo_(haloWidth, box) {}

template <int D>
void DomainDecomposition<D>::start(ParticleSet<D>& P, long step) {
  partition(P, true);
  migrate(P);
  lastMigration_ = step;
  distribute(P, step);
}

template <int D>
void DomainDecomposition<D>::partition(const ParticleSet<D>& P, bool fromScratch) {
  const std::size_t n = P.size();
  coords_.resize(n * D);
  for (std::size_t i = 0; i < n; ++i)
    for (int a = 0; a < D; ++a) coords_[i * D + a] = P.position[i][a];
  zoltan_.partition(coords_, P.id, fromScratch, owner_);
  ++stats_.repartitions;
}

template <int D>
void DomainDecomposition<D>::distribute(ParticleSet<D>& P, long step) {
  const auto& world = Communicator::world();
  stripGhosts(P);
  const long mine = long(P.size()), total = world.sum(mine), most = world.max(mine);
  const double mean = double(total) / world.size();
  // step < lastMigration_: an earlier state was restored.
  if (step - lastMigration_ >= settings_.migrationInterval || step < lastMigration_) {
    if (mean > 0 && most / mean - 1 > settings_.rebalanceThreshold) {
      partition(P, false);
    } else {
      owner_.resize(P.size());
      for (std::size_t i = 0; i < P.size(); ++i) owner_[i] = zoltan_.ownerOf(P.position[i].data());
    }
    migrate(P);
    lastMigration_ = step;
  } else {
    stats_.migrated = 0;
  }
  halo_.build(P);
  ghostsPresent_ = true;
  const long owned = long(halo_.numOwned());
  stats_.owned = owned;
  stats_.ghosts = long(halo_.numGhosts());
  stats_.neighbourRanks = halo_.numNeighbourRanks();
  stats_.imbalance = mean > 0 ? world.max(owned) / mean - 1 : 0;
  ++stats_.distributions;
  stats_.ghostSum += double(stats_.ghosts);
  stats_.ownedSum += double(owned);
  stats_.neighbourSum += stats_.neighbourRanks;
  stats_.migratedSum += double(stats_.migrated);
}

template <int D>
std::string DomainDecomposition<D>::summary() const {
  const auto& world = Communicator::world();
  const double n = std::max<long>(1, stats_.distributions);
  const std::vector<double> mine = {stats_.ghostSum / n, stats_.ghostSum / std::max(1.0, stats_.ownedSum),
                                    stats_.neighbourSum / n, double(halo_.messagesSent()) / n,
                                    halo_.bytesSent() / n, double(halo_.updates()) / n};
  const std::vector<double> all = world.allGather(mine);
  std::vector<double> mean(mine.size(), 0.0), most(mine.size(), 0.0);
  for (int r = 0; r < world.size(); ++r)
    for (std::size_t k = 0; k < mine.size(); ++k) {
      mean[k] += all[std::size_t(r) * mine.size() + k] / world.size();
      most[k] = std::max(most[k], all[std::size_t(r) * mine.size() + k]);
    }
  return cat("Halo per rank and step (mean / largest over ", world.size(), " ranks): ghosts ", mean[0], " / ", most[0],
             " (", 100 * mean[1], " / ", 100 * most[1], " % of its own particles), neighbour ranks ", mean[2], " / ",
             most[2], ", field updates ", mean[5], ", messages sent ", mean[3], " / ", most[3], ", bytes sent ",
             mean[4], " / ", most[4], "; particles migrated per step ", stats_.migratedSum / n,
             ", repartitions ", stats_.repartitions);
}

// Send every particle whose owner is another rank to it; append the ones received.
template <int D>
void DomainDecomposition<D>::migrate(ParticleSet<D>& P) {
  const auto& world = Communicator::world();
  const int me = world.rank(), nranks = world.size();
  const long mask = ParticlePacking<D>::agreedFieldMask(P);
  ParticlePacking<D>::ensureFields(P, mask);
  const std::size_t bytes = ParticlePacking<D>::bytesPerParticle(P, mask);
  const std::size_t n = P.size();
  std::vector<long> sendCount(nranks, 0);
  for (std::size_t i = 0; i < n; ++i) sendCount[owner_[i]] += owner_[i] != me;
  const std::vector<long> recvCount = world.exchangeCounts(sendCount);
  std::vector<long> sendStart(nranks + 1, 0);
  for (int r = 0; r < nranks; ++r) sendStart[r + 1] = sendStart[r] + sendCount[r];
  sendBuf_.resize(std::size_t(sendStart[nranks]) * bytes);
  std::vector<long> fill(sendStart.begin(), sendStart.end() - 1);
  leaving_.assign(n, 0);
  for (std::size_t i = 0; i < n; ++i)
    if (owner_[i] != me) {
      ParticlePacking<D>::pack(P, mask, i, sendBuf_.data() + std::size_t(fill[owner_[i]]++) * bytes);
      leaving_[i] = 1;
    }
  long received = 0;
  for (int r = 0; r < nranks; ++r) received += recvCount[r];
  recvBuf_.resize(std::size_t(received) * bytes);
  std::vector<long> sendBytes(sendCount), recvBytes(recvCount);
  for (int r = 0; r < nranks; ++r) {
    sendBytes[r] *= long(bytes);
    recvBytes[r] *= long(bytes);
  }
  world.allToAll(sendBuf_.data(), sendBytes, recvBuf_.data(), recvBytes, 13);
  const long sent = sendStart[nranks];
  stats_.migrated = world.sum(sent);
  P.removeMarked(leaving_);
  const std::size_t kept = P.size();
  P.resize(kept + std::size_t(received));
  ParticlePacking<D>::ensureFields(P, mask);
  const char* in = recvBuf_.data();
  for (long k = 0; k < received; ++k) in = ParticlePacking<D>::unpack(P, mask, kept + std::size_t(k), in);
}

template class DomainDecomposition<2>;
template class DomainDecomposition<3>;

}  // namespace shizuku
