// Stabilized ISPH (Asai et al. 2012), eq. (9), docs/method.md 4.1: the PPE source
// gains alpha (rho - <rho>_i) / dt^2 on interior and vicinity rows.
// Reads (system/sphSchemes, pressureStabilization): type densityInvariant, alpha (both required).
#include "core/Parameter.hpp"
#include "effects/EffectFactories.hpp"

namespace shizuku {

namespace {
namespace key {
const ParameterGroup stabilization("system/sphSchemes: pressureStabilization",
    "Stabilized ISPH: the density-invariant PPE source term, eq. 9 (docs/method.md 4.1).");
const OptionParameter type = stabilization.option("type", {"densityInvariant"}, "the source term").required();
const ScalarParameter alpha = stabilization.scalar("alpha", dim::none, "relaxation coefficient").required().min(0).max(1);
}  // namespace key
}  // namespace

namespace {

template <int D>
class DensityInvariantSource final : public PressureSourceEffect<D> {
 public:
  explicit DensityInvariantSource(double alpha) : PressureSourceEffect<D>("pressureStabilization"), alpha_(alpha) {}
  std::string describe() const override { return cat("type densityInvariant, alpha = ", alpha_); }
  void addPressureSource(const FlowState<D>& s, std::vector<double>& rhs) override {
    const auto& rho = s.particles.density;
    const double c = alpha_ / (s.dt * s.dt);
    const long n = long(s.size());
#pragma omp parallel for schedule(static)
    for (long i = 0; i < n; ++i)
      if (s.isFluid(i)) rhs[i] += c * (s.rho0 - rho[i]);
  }

 private:
  double alpha_;
};

}  // namespace

template <int D>
std::unique_ptr<Effect<D>> makePressureStabilization(const Dictionary& dict, const FlowState<D>&) {
  key::type.read(dict);
  return std::make_unique<DensityInvariantSource<D>>(key::alpha.read(dict));
}

SHIZUKU_EFFECT_FACTORY(makePressureStabilization);

}  // namespace shizuku
