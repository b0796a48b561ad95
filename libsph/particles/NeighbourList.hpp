// Neighbour lists in compressed-row (CSR) form, built by a cell-linked list
// in O(N) and reused by every pass of a step (docs/method.md 13 step 1).
// Per pair only the neighbour index j (j != i) is stored; r_ij = r_i - r_j (minimum
// image in periodic directions) and |r_ij| are computed from the positions the list
// was built on, where a pass needs them: 4 bytes a pair instead of 4 + 8 D + 8, the
// same values, and always those of the positions' current values (a pass after the
// particles moved within the step sees the moved pairs, as a refreshed list would).
#pragma once
#include "core/types.hpp"
#include <array>
#include <cmath>
#include <memory>

namespace shizuku {

// Periodicity: per direction, whether it is periodic and the box [lo, hi).
template <int D>
struct PeriodicBox {
  std::array<bool, D> periodic{};
  Vec<D> lo = Vec<D>::Zero(), hi = Vec<D>::Zero();
  bool any() const { for (bool p : periodic) if (p) return true; return false; }
  // Wrap a position into the box in periodic directions.
  void wrap(Vec<D>& x) const;
  // Minimum-image difference a - b (inline: the pair loops call it through
  // NeighbourList::rij, and an opaque call would keep them from hoisting their loads).
  Vec<D> difference(const Vec<D>& a, const Vec<D>& b) const {
    Vec<D> d = a - b;
    for (int k = 0; k < D; ++k) {
      if (!periodic[k]) continue;
      const double L = hi[k] - lo[k];
      d[k] -= L * std::nearbyint(d[k] / L);
    }
    return d;
  }
};

template <int D>
struct NeighbourList {
  std::vector<Index> offset;  // size N+1; pairs of i are [offset[i], offset[i+1])
  std::vector<Index> j;       // neighbour index
  // The positions the list was built on: the caller's array, which must outlive the
  // list's use and keep its address (ParticleSet::position does); and its periodicity
  // (`periodic` caches box.any() for the pair loops). Set by attach().
  const std::vector<Vec<D>>* x = nullptr;
  PeriodicBox<D> box;
  bool periodic = false;
  void attach(const std::vector<Vec<D>>& positions, const PeriodicBox<D>& b) {
    x = &positions;
    box = b;
    periodic = b.any();
  }
  // r_ij = r_i - r_j of pair p of row i, and |r_ij|.
  Vec<D> rij(std::size_t i, std::size_t p) const {
    const Vec<D>& xi = (*x)[i];
    const Vec<D>& xj = (*x)[std::size_t(j[p])];
    return periodic ? box.difference(xi, xj) : Vec<D>(xi - xj);
  }
  double r(std::size_t i, std::size_t p) const { return rij(i, p).norm(); }
  // r_ij of pairs p and p + 1 of row i into rij, and their lengths (the same bits as r(), two
  // square roots in one).
  DoublePair r2(std::size_t i, std::size_t p, Vec<D> (&rij2)[2]) const {
    rij2[0] = rij(i, p);
    rij2[1] = rij(i, p + 1);
    return shizuku::sqrt(DoublePair{rij2[0].squaredNorm(), rij2[1].squaredNorm()});
  }
  DoublePair r2(std::size_t i, std::size_t p) const {
    Vec<D> rij2[2];
    return r2(i, p, rij2);
  }
  std::size_t numParticles() const { return offset.empty() ? 0 : offset.size() - 1; }
  std::size_t numPairs() const { return j.size(); }
  Index begin(std::size_t i) const { return offset[i]; }
  Index end(std::size_t i) const { return offset[i + 1]; }
};

// Cell-linked-list search with cell size = radius. Buffers are kept between
// calls so that a rebuild inside the time loop does not allocate once the
// capacity has been reached.
template <int D>
class NeighbourSearch {
 public:
  // Throws InputError if radius <= 0 or a periodic length is < 2 radius.
  explicit NeighbourSearch(double radius, PeriodicBox<D> box = {});
  double radius() const { return radius_; }
  const PeriodicBox<D>& box() const { return box_; }
  // All pairs j != i with |r_ij| < radius (coincident particles give r = 0),
  // rows sorted by j and identical for any thread count (OpenMP parallel).
  // Throws NumericalError on a non-finite position.
  void build(const std::vector<Vec<D>>& x, NeighbourList<D>& out);
  // A permutation that sorts particles by cell (for memory locality):
  // new index k holds old particle perm[k].
  std::vector<Index> cellOrder(const std::vector<Vec<D>>& x);
  // The grid of the last build (diagnostics, tests): number of cells and the cell
  // edge along direction a.
  std::int64_t numCells() const;
  double cellSize(int a) const;
  // Whether the last build kept its rows as 16-bit offsets into each cell's candidates
  // (false: a cell held more than 65535 / 3^D particles; diagnostics, tests).
  bool usedOffsets() const;

 private:
  double radius_;
  PeriodicBox<D> box_;
  struct Impl;
  std::shared_ptr<Impl> impl_;
};

// Brute-force O(N^2) reference used by the tests.
template <int D>
void bruteForceNeighbours(const std::vector<Vec<D>>& x, double radius, const PeriodicBox<D>& box,
                          NeighbourList<D>& out);

}  // namespace shizuku
