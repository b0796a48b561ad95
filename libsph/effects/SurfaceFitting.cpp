// Surface-fitting shift, eq. (19); formula, gates and sign in SurfaceFitting.hpp.
#include "effects/SurfaceFitting.hpp"
#include "effects/EffectFactories.hpp"
#include "core/Parameter.hpp"
#include "surface/SurfaceFit.hpp"
#include <cmath>

namespace shizuku {

namespace {
namespace key {
const ParameterGroup fit("system/sphSchemes: shifting/surfaceFitting",
    "Surface-fitting shift of free-surface particles, eq. 19 (docs/method.md 8); gates in units of d0.");
const ScalarParameter C = fit.scalar("C", dim::none, "coefficient C_suf").def(1e-4).min(0).max(1);
const ScalarParameter maxCurvature = fit.scalar("maxCurvature", dim::none, "act only where |kappa| d0 is below this")
    .def(0.2).above(0);
const ScalarParameter minDistance = fit.scalar("minDistance", dim::none, "act only where |s|/d0 is above this").def(0.15).min(0);
const ScalarParameter maxDistance = fit.scalar("maxDistance", dim::none, "... and below this (> minDistance)").def(0.6).above(0);
const ScalarParameter curvatureFactor = fit.scalar("curvatureFactor", dim::none, "factor of the curvature of eq. 20")
    .def(0.34).above(0);
const OptionParameter sign = fit.option("sign", {"smoothing", "asPrinted"},
    "smoothing: toward the fitted surface; asPrinted: eq. 19 literally").def("smoothing");
}  // namespace key
}  // namespace

template <int D>
std::unique_ptr<Effect<D>> makeSurfaceFitting(const Dictionary& d, const FlowState<D>&) {
  SurfaceFittingParameters p;
  p.C = key::C.read(d);
  p.maxCurvature = key::maxCurvature.read(d);
  p.minDistance = key::minDistance.read(d);
  p.maxDistance = key::maxDistance.read(d);
  if (!(p.maxDistance > p.minDistance)) d.error("maxDistance", "must be greater than minDistance");
  p.curvatureFactor = key::curvatureFactor.read(d);
  p.smoothingSign = key::sign.read(d) == "smoothing";
  return std::make_unique<SurfaceFitting<D>>(p);
}

template <int D>
std::string SurfaceFitting<D>::describe() const {
  return cat("C = ", this->par_.C, " (shift C h s n), gates 0 < |kappa| d0 < ", this->par_.maxCurvature, ", ",
             this->par_.minDistance, " < |s|/d0 < ", this->par_.maxDistance, ", curvatureFactor ", this->par_.curvatureFactor,
             ", sign ", this->par_.smoothingSign ? "smoothing (toward the fitted surface)" : "asPrinted");
}

template <int D>
void SurfaceFitting<D>::addShift(const FlowState<D>& s, std::vector<Vec<D>>& dr) {
  this->actionCount_ = 0;
  if (s.fitDistance.size() != s.size()) return;  // no fit this step
  const auto& nrm = s.fitNormal;
  const double coeff = (this->par_.smoothingSign ? -1.0 : 1.0) * this->par_.C * s.h;
  const long n = long(s.size());
  long count = 0;
#pragma omp parallel for schedule(static) reduction(+ : count)
  for (long i = 0; i < n; ++i) {
    if (!s.isFluid(i) || !isFreeSurfaceClass(s.surfaceClass(i))) continue;
    const double si = s.fitDistance[i];
    if (!(std::abs(si) > this->par_.minDistance && std::abs(si) < this->par_.maxDistance)) continue;  // NaN fails
    const double kappa = std::abs(this->par_.curvatureFactor * curvatureSum(s, std::size_t(i)));
    if (!(kappa > 0 && kappa < this->par_.maxCurvature)) continue;
    dr[i] += (coeff * si) * nrm[i];
    ++count;
  }
  this->actionCount_ = count;
}

SHIZUKU_EFFECT(SurfaceFitting, makeSurfaceFitting);

}  // namespace shizuku
