// Smoothing kernels with support 2h (methods.md section 2): cubic B-spline
// (default) and Wendland C2, in D = 2 or 3 dimensions.
// Reads (system/sphSchemes): kernel { type cubicSpline|WendlandC2; smoothingLengthRatio 1.2; }
#pragma once
#include "core/types.hpp"
#include <cmath>

namespace shizuku {

enum class KernelType { cubicSpline, WendlandC2 };

template <int D>
class Kernel {
 public:
  Kernel() = default;
  Kernel(KernelType type, double h);
  KernelType type() const { return type_; }
  double h() const { return h_; }
  double support() const { return 2.0 * h_; }
  double w(double r) const;      // kernel value
  double dwdr(double r) const;   // dW/dr (<= 0)
  // grad_i W_ij = dW/dr * r_ij / r, with r_ij = r_i - r_j (points from i toward j, times -1 ...)
  Vec<D> gradW(const Vec<D>& rij, double r) const {
    return r > 0 ? Vec<D>(dwdr(r) / r * rij) : Vec<D>::Zero();
  }

 private:
  KernelType type_ = KernelType::cubicSpline;
  double h_ = 1, sigma_ = 1;
};

extern template class Kernel<2>;
extern template class Kernel<3>;

}  // namespace shizuku
