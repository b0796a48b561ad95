// SPH(2) derivative weights: the full-inverse (FI) model of methods.md 3.2
// (5x5 in 2D, 9x9 in 3D, scaled by h) with the per-particle fallback chain of
// methods.md 3.4: FI if n >= 6 (2D) / 12 (3D) neighbours and rcond(M) > 1e-4,
// else first-order KGC + renormalised Laplacian (3.5) if rcond(A) > 1e-3 and
// n >= 3 / 4, else standard SPH (defaults of FallbackThresholds, which
// create(scheme, thresholds) can change). order[i] records 2 / 1 / 0. Rows marked 2 in
// computeFor (free-surface particles) start the chain at first order: on the
// one-sided stencils of a free surface meeting a wall the FI weights grow two
// orders of magnitude larger than the kernel gradient and make the projection
// unstable (measured on the dam break toe), while the first-order weights stay bounded.
// Reads no dictionary keys (selected by `derivatives SPH2;` in system/sphSchemes).
#include "operators/Schemes.hpp"
#include "operators/WeightRows.hpp"

namespace shizuku {

namespace {

template <int D>
class SPH2Operator final : public DerivativeOperator<D> {
 public:
  DerivativeScheme scheme() const override { return DerivativeScheme::SPH2; }
  void computeWeights(const Kernel<D>& kernel, double V, const NeighbourList<D>& nl,
                      const std::vector<std::uint8_t>& computeFor, PairWeights<D>& out) const override {
    const double h = kernel.h();
    const weights::Limits<D> lim(this->thresholds_);
    weights::computeRows<D>(nl, computeFor, out, [&](std::size_t i, Index b, Index e) -> std::uint8_t {
      weights::kernelRow(kernel, nl, b, e, out);
      const std::uint8_t row = computeFor.empty() ? 1 : computeFor[i];
      if (row == 1 && weights::fiRow(lim, h, V, nl, b, e, out)) return weights::orderFI;
      if (row <= 2 && weights::firstOrderRow(lim, h, V, nl, b, e, out)) return weights::orderFirst;
      weights::standardRow(h, nl, b, e, out);
      return weights::orderStandard;
    });
  }
};

}  // namespace

template <int D>
std::unique_ptr<DerivativeOperator<D>> makeSPH2Operator() {
  return std::make_unique<SPH2Operator<D>>();
}

template std::unique_ptr<DerivativeOperator<2>> makeSPH2Operator<2>();
template std::unique_ptr<DerivativeOperator<3>> makeSPH2Operator<3>();

}  // namespace shizuku
