// Two small helpers of the particle generator: a loop over a box of integer
// indices, and points hashed into cubic cells of size h (O(1) "which point lies
// closer than r <= h to x?" queries while regions are built).
// Reads no dictionary keys.
#pragma once
#include "core/types.hpp"
#include <array>
#include <cmath>
#include <unordered_map>

namespace shizuku {

// Calls f(i) for every integer index i with lo <= i < hi, x fastest.
template <int D, class F>
void forEachIndex(const std::array<long, D>& lo, const std::array<long, D>& hi, F&& f) {
  for (int k = 0; k < D; ++k)
    if (hi[k] <= lo[k]) return;
  std::array<long, D> i = lo;
  for (;;) {
    f(i);
    int k = 0;
    for (; k < D; ++k) {
      if (++i[k] < hi[k]) break;
      i[k] = lo[k];
    }
    if (k == D) return;
  }
}

// Points hashed into cubic cells of size h: "is any point closer than r <= h?"
template <int D>
class PointGrid {
 public:
  PointGrid(double h, const std::vector<Vec<D>>& points) : h_(h), points_(points) {}
  void insert(Index i) { cells_[cellOf(points_[i])].push_back(i); }
  bool anyCloserThan(const Vec<D>& x, double r) const { return closest(x, r) >= 0; }
  // The index of the point nearest to x among those closer than r <= h, or -1.
  Index closest(const Vec<D>& x, double r) const {
    const Cell c = cellOf(x);
    std::array<long, D> lo, hi;
    for (int k = 0; k < D; ++k) { lo[k] = c[k] - 1; hi[k] = c[k] + 2; }
    Index best = -1;
    double bestR2 = r * r;
    forEachIndex<D>(lo, hi, [&](const Cell& n) {
      auto it = cells_.find(n);
      if (it == cells_.end()) return;
      for (Index j : it->second) {
        const double r2 = (points_[j] - x).squaredNorm();
        if (r2 < bestR2 || (r2 == bestR2 && best >= 0 && j < best)) { bestR2 = r2; best = j; }
      }
    });
    return best;
  }

 private:
  using Cell = std::array<long, D>;
  struct Hash {
    std::size_t operator()(const Cell& c) const {
      std::size_t h = 0;
      for (int k = 0; k < D; ++k) h = h * 1000003u ^ std::hash<long>()(c[k]);
      return h;
    }
  };
  Cell cellOf(const Vec<D>& x) const {
    Cell c;
    for (int k = 0; k < D; ++k) c[k] = long(std::floor(x[k] / h_));
    return c;
  }
  double h_;
  const std::vector<Vec<D>>& points_;
  std::unordered_map<Cell, std::vector<Index>, Hash> cells_;
};

}  // namespace shizuku
