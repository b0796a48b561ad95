// First-order corrected derivative weights (methods.md 3.4 step 2 and 3.5):
// kernel gradient correction tilde gradW = L_i gradW, L_i = (V sum_j gradW (x) r_ji)^-1,
// and the renormalised Laplacian of Basic et al. (2018), exact for linear fields.
// Falls back to standard SPH where the correction matrix is singular
// (rcond <= 1e-3 or fewer than 3 (2D) / 4 (3D) neighbours). order[i] = 1 / 0.
// Reads no dictionary keys (selected by `derivatives corrected;`).
#include "operators/Schemes.hpp"
#include "operators/WeightRows.hpp"

namespace shizuku {

namespace {

template <int D>
class CorrectedOperator final : public DerivativeOperator<D> {
 public:
  DerivativeScheme scheme() const override { return DerivativeScheme::corrected; }
  void computeWeights(const Kernel<D>& kernel, double V, const NeighbourList<D>& nl,
                      const std::vector<std::uint8_t>& computeFor, PairWeights<D>& out) const override {
    const double h = kernel.h();
    const weights::Limits<D> lim(this->thresholds_);
    weights::computeRows<D>(nl, computeFor, out, [&](std::size_t i, Index b, Index e) -> std::uint8_t {
      weights::kernelRow(kernel, nl, b, e, out);
      const bool splashRow = !computeFor.empty() && computeFor[i] == 3;
      if (!splashRow && weights::firstOrderRow(lim, h, V, nl, b, e, out)) return weights::orderFirst;
      weights::standardRow(h, nl, b, e, out);
      return weights::orderStandard;
    });
  }
};

}  // namespace

template <int D>
std::unique_ptr<DerivativeOperator<D>> makeCorrectedOperator() {
  return std::make_unique<CorrectedOperator<D>>();
}

template std::unique_ptr<DerivativeOperator<2>> makeCorrectedOperator<2>();
template std::unique_ptr<DerivativeOperator<3>> makeCorrectedOperator<3>();

}  // namespace shizuku
