// XSPH advection velocity (docs/method.md 10); formula in XSPH.hpp.
#include "effects/XSPH.hpp"
#include "effects/EffectFactories.hpp"
#include "core/Parameter.hpp"

namespace shizuku {

namespace key {  // const: internal linkage
const ParameterGroup xsph("system/sphSchemes: xsph", "XSPH advection velocity near the free surface (docs/method.md 10).");
const ScalarParameter epsilon = xsph.scalar("epsilon", dim::none, "XSPH coefficient").def(0.5).min(0).max(1);
}  // namespace key

template <int D>
std::unique_ptr<Effect<D>> makeXSPH(const Dictionary& d, const FlowState<D>&) { return std::make_unique<XSPH<D>>(key::epsilon.read(d)); }

template <int D>
void XSPH<D>::addAdvectionVelocity(const FlowState<D>& s, const std::vector<Vec<D>>& u,
                                   std::vector<Vec<D>>& du) {
  const auto& nl = s.neighbours;
  const double c = epsilon_ * s.V();
  const long n = long(s.size());
  long count = 0;
#pragma omp parallel for schedule(static) reduction(+ : count)
  for (long i = 0; i < n; ++i) {
    if (!s.isFluid(i) || !nearSurface(s.surfaceClass(i))) continue;
    Vec<D> sum = Vec<D>::Zero();
    for (Index k = nl.begin(i); k < nl.end(i); ++k) {
      const Index j = nl.j[k];
      if (s.isFluid(j)) sum += s.w(std::size_t(i), k) * (u[j] - u[i]);
    }
    du[i] += c * sum;
    ++count;
  }
  this->actionCount_ = count;
}

SHIZUKU_EFFECT(XSPH, makeXSPH);

}  // namespace shizuku
