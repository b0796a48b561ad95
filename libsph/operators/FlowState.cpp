// FlowState helpers: the type masks and the summation density (eq. 18).
#include "operators/FlowState.hpp"

namespace shizuku {

template <int D>
void FlowState<D>::refreshTypeMasks() {
  const auto& P = particles;
  const std::size_t n = P.size();
  isFluidMask.resize(n);
  for (std::size_t i = 0; i < n; ++i) isFluidMask[i] = P.isFluid(i);
  if (!hasOpenBoundaries) return;
  isBufferMask.resize(n);
  for (std::size_t i = 0; i < n; ++i) isBufferMask[i] = P.isInlet(i) || P.isOutlet(i);
}

template <int D>
void FlowState<D>::computeDensity() {
  auto& rho = particles.density;
  const auto& nl = neighbours;
  const double m = particles.mass, w0 = kernel.w(0.0);
  const long n = long(size());
  rho.resize(size());
#pragma omp parallel for schedule(static)
  for (long i = 0; i < n; ++i) {
    double s = w0;
    for (Index k = nl.begin(i); k < nl.end(i); ++k) s += w(std::size_t(i), k);
    rho[i] = m * s;
  }
  exchange(rho);
}

template struct FlowState<2>;
template struct FlowState<3>;

}  // namespace shizuku
