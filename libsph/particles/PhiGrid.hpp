// The signed distance phi of a solid body sampled at the centres of cubic voxels over its
// bounding box (grown by one voxel), stored as float, for a quick answer to "is
// phi(x) < -depth?" (the leak detector asks it of every fluid particle near an STL solid,
// every step). phi is 1-Lipschitz, so at a point x of a voxel whose centre has p,
// p - r <= phi(x) <= p + r with r = h sqrt(3)/2 (plus the float's round-off): the answer is
// certain unless -depth lies within r of p, and only those points (about the fluid within a
// spacing of the surface) are left to the exact test. Samples beyond the body's reach hold
// +-reach (|phi| is at least that): a bound on the right side for the certain answers.
// At most 4e6 voxels (larger ones for a body large against the spacing). Reads no keys.
#pragma once
#include "core/types.hpp"
#include <array>
#include <functional>
#include <vector>

namespace shizuku {

class PhiGrid {
 public:
  // out[j] = phi(rowPoint with x = xs[j]), clamped to +-reach.
  using RowPhi = std::function<void(const Vec<3>& rowPoint, const std::vector<double>& xs, std::vector<double>& out)>;
  PhiGrid() = default;
  PhiGrid(const Vec<3>& lo, const Vec<3>& hi, double h, double reach, const RowPhi& rowPhi);
  bool empty() const { return values_.empty(); }
  // 1: phi(x) < -depth for certain; 0: phi(x) >= -depth for certain; -1: cannot tell.
  int deeperThan(const Vec<3>& x, double depth) const;

 private:
  Vec<3> lo_ = Vec<3>::Zero();
  double h_ = 0, r_ = 0, reach_ = 0;
  std::array<long, 3> n_{};
  std::vector<float> values_;  // x fastest
};

}  // namespace shizuku
