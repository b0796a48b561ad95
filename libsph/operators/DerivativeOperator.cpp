// Scheme names and the factory behind DerivativeOperator (methods.md 3).
// Reads (system/sphSchemes): derivatives SPH2|corrected|standard (the solver
// passes the word to derivativeSchemeFromName).
#include "operators/DerivativeOperator.hpp"
#include "operators/Schemes.hpp"

namespace shizuku {

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
    case DerivativeScheme::SPH2: return makeSPH2Operator<D>();
    case DerivativeScheme::corrected: return makeCorrectedOperator<D>();
    case DerivativeScheme::standard: return makeStandardOperator<D>();
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
