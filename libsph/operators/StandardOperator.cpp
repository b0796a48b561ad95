// Standard (uncorrected) SPH derivative weights (methods.md 3.3 baseline):
// tilde gradW = grad_i W_ij, Laplacian weight 2 (r_ji . grad_i W_ij) / r^2
// (Morris/Brookshaw; positive, so <lap (x^2+y^2)> ~ 2D on a lattice).
// order[i] = 0. Reads no dictionary keys (selected by `derivatives standard;`).
#include "operators/Schemes.hpp"
#include "operators/WeightRows.hpp"

namespace shizuku {

namespace {

template <int D>
class StandardOperator final : public DerivativeOperator<D> {
 public:
  DerivativeScheme scheme() const override { return DerivativeScheme::standard; }
  void computeWeights(const Kernel<D>& kernel, double V, const NeighbourList<D>& nl,
                      const std::vector<std::uint8_t>& computeFor, PairWeights<D>& out) const override {
    const double h = kernel.h();
    weights::computeRows<D>(nl, computeFor, out, [&](std::size_t, Index b, Index e) -> std::uint8_t {
      weights::kernelRow(kernel, nl, b, e, out);
      weights::standardRow(h, nl, b, e, out);
      return weights::orderStandard;
    });
  }
};

}  // namespace

template <int D>
std::unique_ptr<DerivativeOperator<D>> makeStandardOperator() {
  return std::make_unique<StandardOperator<D>>();
}

template std::unique_ptr<DerivativeOperator<2>> makeStandardOperator<2>();
template std::unique_ptr<DerivativeOperator<3>> makeStandardOperator<3>();

}  // namespace shizuku
