// The halo of a rank: see Halo.hpp.
#include "decomposition/Halo.hpp"
#include "decomposition/ParticlePacking.hpp"
#include <algorithm>
#include <cmath>
#include <limits>

namespace shizuku {

namespace {
// Gap between [a, b] and [c, d] along a line (0 when they overlap).
double gap(double a, double b, double c, double d) { return std::max({0.0, c - b, a - d}); }
}  // namespace

// Distance between the box (lo[D], hi[D]) and `box` (the same layout); in periodic
// directions the nearest image. A point is the box lo = hi = x.
template <int D>
double Halo<D>::boxDistance(const double* lo, const double* hi, const double* box) const {
  double d2 = 0;
  for (int a = 0; a < D; ++a) {
    double g = gap(lo[a], hi[a], box[a], box[D + a]);
    if (box_.periodic[a]) {
      const double L = box_.hi[a] - box_.lo[a];
      g = std::min({g, gap(lo[a] - L, hi[a] - L, box[a], box[D + a]), gap(lo[a] + L, hi[a] + L, box[a], box[D + a])});
    }
    d2 += g * g;
  }
  return std::sqrt(d2);
}

// Every rank's box of its own particles (lo, hi; an empty box where a rank has none),
// and the ranks whose boxes lie within the halo width of this rank's.
template <int D>
void Halo<D>::findNeighbourRanks(const ParticleSet<D>& P, std::vector<double>& boxes) {
  const auto& world = Communicator::world();
  std::vector<double> mine(2 * D);
  for (int a = 0; a < D; ++a) {
    mine[a] = std::numeric_limits<double>::infinity();
    mine[D + a] = -std::numeric_limits<double>::infinity();
  }
  for (std::size_t i = 0; i < numOwned_; ++i)
    for (int a = 0; a < D; ++a) {
      mine[a] = std::min(mine[a], P.position[i][a]);
      mine[D + a] = std::max(mine[D + a], P.position[i][a]);
    }
  boxes = world.allGather(mine);
  ranks_.clear();
  if (numOwned_ == 0) return;
  for (int r = 0; r < world.size(); ++r) {
    const double* b = &boxes[std::size_t(r) * 2 * D];
    if (r == world.rank() || !(b[0] <= b[D])) continue;
    if (boxDistance(&mine[0], &mine[D], b) < width_) ranks_.push_back(r);
  }
}

template <int D>
void Halo<D>::build(ParticleSet<D>& P) {
  numOwned_ = P.size();
  numGhosts_ = 0;
  std::vector<double> boxes;
  findNeighbourRanks(P, boxes);
  const auto& world = Communicator::world();
  // The field mask every rank agrees on (a rank without particles cannot tell).
  const long mask = ParticlePacking<D>::agreedFieldMask(P);
  ParticlePacking<D>::ensureFields(P, mask);

  const std::size_t nr = ranks_.size();
  sendIdx_.clear();
  sendStart_.assign(nr + 1, 0);
  for (std::size_t r = 0; r < nr; ++r) {
    const double* b = &boxes[std::size_t(ranks_[r]) * 2 * D];
    for (std::size_t i = 0; i < numOwned_; ++i)
      if (boxDistance(P.position[i].data(), P.position[i].data(), b) < width_) sendIdx_.push_back(Index(i));
    sendStart_[r + 1] = long(sendIdx_.size());
  }
  // Counts first (one long each way per neighbour), then the particles.
  std::vector<long> sendCount(nr), recvCount(nr);
  sendPtr_.resize(nr);
  recvPtr_.resize(nr);
  sendBytes_.assign(nr, long(sizeof(long)));
  recvBytes_.assign(nr, long(sizeof(long)));
  for (std::size_t r = 0; r < nr; ++r) {
    sendCount[r] = sendStart_[r + 1] - sendStart_[r];
    sendPtr_[r] = reinterpret_cast<const char*>(&sendCount[r]);
    recvPtr_[r] = reinterpret_cast<char*>(&recvCount[r]);
  }
  world.exchange(ranks_, sendPtr_, sendBytes_, recvPtr_, recvBytes_, 10);
  recvStart_.assign(nr + 1, 0);
  for (std::size_t r = 0; r < nr; ++r) recvStart_[r + 1] = recvStart_[r] + recvCount[r];
  numGhosts_ = std::size_t(recvStart_[nr]);

  const std::size_t bytes = ParticlePacking<D>::bytesPerParticle(P, mask);
  sendBuf_.resize(sendIdx_.size() * bytes);
  recvBuf_.resize(numGhosts_ * bytes);
  char* out = sendBuf_.data();
  for (Index i : sendIdx_) out = ParticlePacking<D>::pack(P, mask, std::size_t(i), out);
  for (std::size_t r = 0; r < nr; ++r) {
    sendPtr_[r] = sendBuf_.data() + sendStart_[r] * bytes;
    sendBytes_[r] = sendCount[r] * long(bytes);
    recvPtr_[r] = recvBuf_.data() + recvStart_[r] * bytes;
    recvBytes_[r] = recvCount[r] * long(bytes);
  }
  world.exchange(ranks_, sendPtr_, sendBytes_, recvPtr_, recvBytes_, 12);
  for (std::size_t r = 0; r < nr; ++r) messages_ += 1 + (sendBytes_[r] > 0);  // the count, then the particles
  bytes_ += double(nr * sizeof(long) + sendBuf_.size());
  P.resize(numOwned_ + numGhosts_);
  ParticlePacking<D>::ensureFields(P, mask);
  const char* in = recvBuf_.data();
  for (std::size_t g = 0; g < numGhosts_; ++g) in = ParticlePacking<D>::unpack(P, mask, numOwned_ + g, in);
}

template class Halo<2>;
template class Halo<3>;

}  // namespace shizuku
