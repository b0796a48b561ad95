// The halo of a rank (docs/parallel.md 4): copies ("ghosts") of the other ranks' particles
// that lie within `width` (the kernel support 2h) of this rank's own particles, appended
// after them, so that every neighbour loop runs unchanged over owned + ghost particles.
// A ghost's row of a neighbour loop is incomplete near the halo's outer edge, so a field
// that a later pass reads at neighbours is refreshed from its owner (update()) after the
// pass that computes it: the exchange points of the step (docs/parallel.md 5).
// Who sends what: every rank's bounding box of its own particles is gathered, and a
// particle goes to each rank whose box lies within `width` of it (periodic directions
// by the minimum image). That holds for any partition (RCB, HSFC, or one that drifted
// since the last) because a rank's particles lie inside its box. Ghosts keep the
// positions their owners have (wrapped); the neighbour search takes the minimum image.
// One message per neighbour rank and exchange; buffers are kept between steps.
// Reads no dictionary keys.
#pragma once
#include "core/types.hpp"
#include "parallel/Communicator.hpp"
#include "particles/NeighbourList.hpp"
#include "particles/ParticleSet.hpp"
#include <cstring>

namespace shizuku {

template <int D>
class Halo {
 public:
  Halo(double width, const PeriodicBox<D>& box) : width_(width), box_(box) {}

  // P holds this rank's own particles; appends the ghosts. Collective.
  void build(ParticleSet<D>& P);
  // Remove the ghosts (P keeps its own particles, in order).
  void strip(ParticleSet<D>& P) const { P.resize(numOwned_); }
  std::size_t numOwned() const { return numOwned_; }
  std::size_t numGhosts() const { return numGhosts_; }
  bool isGhost(std::size_t i) const { return i >= numOwned_; }
  // Ghosts' values of f (sized owned + ghosts) from their owners. Collective.
  template <class T> void update(std::vector<T>& f) const;

  // Statistics of the last build: neighbour ranks, and particles sent (docs/parallel.md 7).
  int numNeighbourRanks() const { return int(ranks_.size()); }
  long numSent() const { return long(sendIdx_.size()); }
  // Since the start: field updates, messages sent and bytes sent (the builds included).
  long updates() const { return updates_; }
  long messagesSent() const { return messages_; }
  double bytesSent() const { return bytes_; }
  const std::vector<int>& neighbourRanks() const { return ranks_; }

 private:
  void findNeighbourRanks(const ParticleSet<D>& P, std::vector<double>& boxes);
  double boxDistance(const double* lo, const double* hi, const double* box) const;

  double width_;
  PeriodicBox<D> box_;
  std::size_t numOwned_ = 0, numGhosts_ = 0;
  std::vector<int> ranks_;          // neighbour ranks, ascending
  std::vector<Index> sendIdx_;      // own particles sent, grouped by neighbour rank
  std::vector<long> sendStart_;     // per neighbour rank: start in sendIdx_ (size ranks + 1)
  std::vector<long> recvStart_;     // per neighbour rank: first ghost, counted from numOwned
  mutable std::vector<char> sendBuf_;
  std::vector<char> recvBuf_;
  mutable std::vector<const char*> sendPtr_;
  mutable std::vector<char*> recvPtr_;
  mutable std::vector<long> sendBytes_, recvBytes_;
  mutable long updates_ = 0, messages_ = 0;
  mutable double bytes_ = 0;
};

template <int D>
template <class T>
void Halo<D>::update(std::vector<T>& f) const {
  if (ranks_.empty()) return;
  const std::size_t nr = ranks_.size();
  sendBuf_.resize(sendIdx_.size() * sizeof(T));
  T* out = reinterpret_cast<T*>(sendBuf_.data());
  for (std::size_t k = 0; k < sendIdx_.size(); ++k) out[k] = f[std::size_t(sendIdx_[k])];
  // Ghosts from one rank are contiguous: they are received in place.
  for (std::size_t r = 0; r < nr; ++r) {
    sendPtr_[r] = sendBuf_.data() + sendStart_[r] * sizeof(T);
    sendBytes_[r] = (sendStart_[r + 1] - sendStart_[r]) * long(sizeof(T));
    recvPtr_[r] = reinterpret_cast<char*>(f.data() + numOwned_ + recvStart_[r]);
    recvBytes_[r] = (recvStart_[r + 1] - recvStart_[r]) * long(sizeof(T));
  }
  Communicator::world().exchange(ranks_, sendPtr_, sendBytes_, recvPtr_, recvBytes_, 11);
  ++updates_;
  for (std::size_t r = 0; r < nr; ++r) messages_ += sendBytes_[r] > 0;
  bytes_ += double(sendBuf_.size());
}

}  // namespace shizuku
