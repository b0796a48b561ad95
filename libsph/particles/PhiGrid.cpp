// Signed distance sampled on voxels: see PhiGrid.hpp.
#include "particles/PhiGrid.hpp"
#include <algorithm>
#include <cmath>

namespace shizuku {

namespace {
constexpr double kMaxVoxels = 4e6;
}

PhiGrid::PhiGrid(const Vec<3>& lo, const Vec<3>& hi, double h, double reach, const RowPhi& rowPhi)
    : reach_(reach) {
  const Vec<3> extent = (hi - lo).array() + 2 * h;
  h_ = std::max({h, std::cbrt(extent.prod() / kMaxVoxels), 1e-300});
  lo_ = lo.array() - h_;
  for (int k = 0; k < 3; ++k) n_[k] = std::max(1L, long(std::ceil((hi[k] + h_ - lo_[k]) / h_)));
  r_ = 0.5 * std::sqrt(3.0) * h_ + 1e-6 * reach;  // the voxel's half diagonal, the float's round-off
  values_.resize(std::size_t(n_[0] * n_[1] * n_[2]));
  const long rows = n_[1] * n_[2];
#pragma omp parallel
  {
    std::vector<double> xs(static_cast<std::size_t>(n_[0])), phi;
    for (long i = 0; i < n_[0]; ++i) xs[std::size_t(i)] = lo_[0] + (double(i) + 0.5) * h_;
#pragma omp for schedule(dynamic, 16)
    for (long row = 0; row < rows; ++row) {
      const Vec<3> p(lo_[0], lo_[1] + (double(row % n_[1]) + 0.5) * h_, lo_[2] + (double(row / n_[1]) + 0.5) * h_);
      rowPhi(p, xs, phi);
      for (long i = 0; i < n_[0]; ++i) values_[std::size_t(row * n_[0] + i)] = float(phi[std::size_t(i)]);
    }
  }
}

int PhiGrid::deeperThan(const Vec<3>& x, double depth) const {
  long cell = 0;
  for (int k = 2; k >= 0; --k) {
    const double i = std::floor((x[k] - lo_[k]) / h_);
    if (!(i >= 0 && i < double(n_[k]))) return -1;
    cell = cell * n_[k] + long(i);
  }
  const double p = values_[std::size_t(cell)];
  if (p + r_ < -depth) return 1;                           // an upper bound, also when clamped
  if (p - r_ >= -depth && p > -reach_ * (1 - 1e-6)) return 0;  // a lower bound unless clamped at -reach
  return -1;
}

}  // namespace shizuku
