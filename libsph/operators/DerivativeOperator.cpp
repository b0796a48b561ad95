// Scheme names, the factory behind DerivativeOperator, and the three schemes
// (docs/method.md 3). Reads (system/sphSchemes): derivatives SPH2|corrected|standard
// (the solver passes the word to derivativeSchemeFromName).
//
// The three schemes are one per-particle fallback chain (docs/method.md 3.4), each
// entered at a different top; every row keeps the first link it passes and
// records it in order[i]:
//   FI (SPH2 only): the full-inverse model of docs/method.md 3.2 (5x5 in 2D, 9x9 in
//       3D, scaled by h), if n >= 6 (2D) / 12 (3D) neighbours and rcond(M) > 1e-4;
//   first order (SPH2, corrected): kernel gradient correction tilde gradW =
//       L_i gradW, L_i = (V sum_j gradW (x) r_ji)^-1, and the renormalised
//       Laplacian of Basic et al. (2018), exact for linear fields (3.5), if
//       n >= 3 / 4 and rcond(A) > 1e-3;
//   (FI and first order only where no corrected gradient weight exceeds ten times the
//   row's largest kernel gradient);
//   standard (all): tilde gradW = grad_i W_ij, Laplacian weight
//       2 (r_ji . grad_i W_ij) / r^2 (Morris/Brookshaw; positive, so
//       <lap (x^2+y^2)> ~ 2D on a lattice).
// The limits are the defaults of FallbackThresholds, which create(scheme,
// thresholds) can change. Rows marked 2 in computeFor (free-surface particles)
// start the chain at first order: on the one-sided stencils of a free surface
// meeting a wall the FI weights grow two orders of magnitude larger than the
// kernel gradient and make the projection unstable (measured on the dam break
// toe), while the first-order weights stay bounded. Rows marked 3 (splash) take
// the standard weights (DerivativeOperator.hpp says why).
#include "operators/DerivativeOperator.hpp"
#include "operators/WeightRows.hpp"

namespace shizuku {

namespace {

// The chain entered at `Top` (weights::orderFI, orderFirst or orderStandard).
template <int D, weights::Order Top>
class FallbackOperator final : public DerivativeOperator<D> {
 public:
  DerivativeScheme scheme() const override {
    return Top == weights::orderFI      ? DerivativeScheme::SPH2
           : Top == weights::orderFirst ? DerivativeScheme::corrected
                                        : DerivativeScheme::standard;
  }
  void computeWeights(const Kernel<D>& kernel, double V, const NeighbourList<D>& nl,
                      const std::vector<std::uint8_t>& computeFor, PairWeights<D>& out) const override {
    const double h = kernel.h();
    const weights::Limits<D> lim(this->thresholds_);
    weights::computeRows<D>(nl, computeFor, out, [&](std::size_t i, Index b, Index e) -> std::uint8_t {
      const double kernelGradient = weights::kernelRow(kernel, nl, i, b, e, out);
      const std::uint8_t row = computeFor.empty() ? 1 : computeFor[i];
      if constexpr (Top == weights::orderFI)
        if (row == 1 && weights::fiRow(lim, h, V, nl, i, b, e, out)) {
          if (weights::gradientBounded(lim, kernelGradient, b, e, out)) return weights::orderFI;
          weights::kernelRow(kernel, nl, i, b, e, out);  // fiRow wrote over the kernel pass's scratch
        }
      if constexpr (Top != weights::orderStandard)
        if (row <= 2 && weights::firstOrderRow(lim, kernel, V, nl, i, b, e, out)) {
          if (weights::gradientBounded(lim, kernelGradient, b, e, out)) return weights::orderFirst;
          weights::kernelRow(kernel, nl, i, b, e, out);
        }
      weights::standardRow(h, nl, i, b, e, out);
      return weights::orderStandard;
    });
  }
};

}  // namespace

DerivativeScheme derivativeSchemeFromName(const std::string& name) {
  if (name == "SPH2") return DerivativeScheme::SPH2;
  if (name == "corrected") return DerivativeScheme::corrected;
  if (name == "standard") return DerivativeScheme::standard;
  throw InputError("unknown derivative scheme '" + name + "': valid schemes are SPH2, corrected, standard");
}

std::string toString(DerivativeScheme s) {
  switch (s) {
    case DerivativeScheme::SPH2: return "SPH2";
    case DerivativeScheme::corrected: return "corrected";
    case DerivativeScheme::standard: return "standard";
  }
  return "unknown";
}

template <int D>
std::unique_ptr<DerivativeOperator<D>> DerivativeOperator<D>::create(DerivativeScheme s) {
  switch (s) {
    case DerivativeScheme::SPH2: return std::make_unique<FallbackOperator<D, weights::orderFI>>();
    case DerivativeScheme::corrected: return std::make_unique<FallbackOperator<D, weights::orderFirst>>();
    case DerivativeScheme::standard: return std::make_unique<FallbackOperator<D, weights::orderStandard>>();
  }
  throw InputError("unknown derivative scheme");
}

template <int D>
std::unique_ptr<DerivativeOperator<D>> DerivativeOperator<D>::create(DerivativeScheme s, const FallbackThresholds& t) {
  auto op = create(s);
  op->thresholds_ = t;
  return op;
}

template class DerivativeOperator<2>;
template class DerivativeOperator<3>;

}  // namespace shizuku
