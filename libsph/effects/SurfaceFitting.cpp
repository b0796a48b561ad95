// Surface-fitting shift, eq. (19); formula, gates and sign in SurfaceFitting.hpp.
#include "effects/SurfaceFitting.hpp"
#include "effects/EffectFactories.hpp"
#include "effects/EffectParameters.hpp"
#include "surface/SurfaceFit.hpp"
#include <cmath>

namespace shizuku {

template <int D>
std::string SurfaceFitting<D>::describe() const {
  return cat("C = ", par_.C, " (shift C h s n), gates 0 < |kappa| d0 < ", par_.maxCurvature, ", ",
             par_.minDistance, " < |s|/d0 < ", par_.maxDistance, ", curvatureFactor ", par_.curvatureFactor,
             ", sign ", par_.smoothingSign ? "smoothing (toward the fitted surface)" : "asPrinted");
}

template <int D>
void SurfaceFitting<D>::addShift(const FlowState<D>& s, std::vector<Vec<D>>& dr) {
  this->actionCount_ = 0;
  if (s.fitDistance.size() != s.size()) return;  // no fit this step
  const auto& nrm = s.fitNormal;
  const double coeff = (par_.smoothingSign ? -1.0 : 1.0) * par_.C * s.h;
  const long n = long(s.size());
  long count = 0;
#pragma omp parallel for schedule(static) reduction(+ : count)
  for (long i = 0; i < n; ++i) {
    if (!s.isFluid(i) || !isFreeSurfaceClass(s.surfaceClass(i))) continue;
    const double si = s.fitDistance[i];
    if (!(std::abs(si) > par_.minDistance && std::abs(si) < par_.maxDistance)) continue;  // NaN fails
    const double kappa = std::abs(par_.curvatureFactor * curvatureSum(s, std::size_t(i)));
    if (!(kappa > 0 && kappa < par_.maxCurvature)) continue;
    dr[i] += (coeff * si) * nrm[i];
    ++count;
  }
  this->actionCount_ = count;
}

template <int D>
std::unique_ptr<Effect<D>> makeSurfaceFitting(const Dictionary& d, const FlowState<D>&) {
  SurfaceFittingParameters p;
  p.C = nonNegative(d, "C", 1e-4);
  p.maxCurvature = positive(d, "maxCurvature", 0.2);
  p.minDistance = nonNegative(d, "minDistance", 0.15);
  p.maxDistance = positive(d, "maxDistance", 0.6);
  if (!(p.maxDistance > p.minDistance)) d.error("maxDistance", "must be greater than minDistance");
  p.curvatureFactor = positive(d, "curvatureFactor", 0.34);
  p.smoothingSign = d.getOptionOr("sign", {"smoothing", "asPrinted"}, "smoothing") == "smoothing";
  return std::make_unique<SurfaceFitting<D>>(p);
}

template class SurfaceFitting<2>;
template class SurfaceFitting<3>;

SHIZUKU_EFFECT_FACTORY(makeSurfaceFitting);

}  // namespace shizuku
