// Kernel normalisations and lattice sums (docs/method.md section 2).
// The kernel values themselves are inline in Kernel.hpp (hot loops).
// Reads no dictionary keys (kernel names and settings: KernelParameters.cpp).
#include "kernels/Kernel.hpp"
#include <cmath>

namespace shizuku {

template <int D>
Kernel<D>::Kernel(KernelType type, double h) : type_(type), h_(h) {
  if (!(h > 0) || !std::isfinite(h))
    throw InputError("kernel: smoothing length must be positive, got " + std::to_string(h));
  invH_ = 1.0 / h;
  const double hD = D == 2 ? h * h : h * h * h;
  if (type == KernelType::cubicSpline)
    sigma_ = (D == 2 ? 10.0 / (7.0 * M_PI) : 1.0 / M_PI) / hD;
  else
    sigma_ = (D == 2 ? 7.0 / (4.0 * M_PI) : 21.0 / (16.0 * M_PI)) / hD;
}

template <int D>
double Kernel<D>::latticeSum(double d0) const {
  if (!(d0 > 0)) throw InputError("kernel: lattice spacing must be positive");
  const int n = int(std::ceil(support() / d0));
  double sum = 0;
  int idx[3] = {0, 0, 0};
  const int nz = D == 3 ? n : 0;
  for (idx[2] = -nz; idx[2] <= nz; ++idx[2])
    for (idx[1] = -n; idx[1] <= n; ++idx[1])
      for (idx[0] = -n; idx[0] <= n; ++idx[0]) {
        double r2 = 0;
        for (int a = 0; a < D; ++a) r2 += double(idx[a]) * idx[a];
        sum += w(d0 * std::sqrt(r2));
      }
  return sum;
}

template class Kernel<2>;
template class Kernel<3>;

}  // namespace shizuku
