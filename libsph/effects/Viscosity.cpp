// The viscous force of the predictor, nu <lap u> (eq. 4, docs/method.md 4.1), built only
// when nu > 0. Wall neighbours show the no-slip mirror velocity 2 U_w - u_i, or u_i with
// free slip (docs/method.md 11); inlet and outlet particles their own velocity (the flow
// beyond the open end, docs/boundaries.md). Its time-step limit is dt <= 0.125 h^2 / nu
// (docs/method.md 4.3).
// Reads (constant/physicalProperties): nu (m^2/s), wallCondition noSlip|slip.
#include "effects/EffectFactories.hpp"
#include "effects/PhysicalProperties.hpp"

namespace shizuku {
namespace {

template <int D>
class Viscosity final : public ForceEffect<D> {
 public:
  Viscosity(double nu, WallVelocity walls) : ForceEffect<D>("viscosity"), nu_(nu), walls_(walls) {}
  std::string describe() const override {
    return cat("nu = ", nu_, " m^2/s, walls ", walls_ == WallVelocity::noSlip ? "noSlip" : "slip");
  }
  TimeStepLimit timeStepLimit(const FlowState<D>& s) const override { return {0.125 * s.h * s.h / nu_, "viscous"}; }
  void addAcceleration(const FlowState<D>& s, std::vector<Vec<D>>& acc) override {
    Ops<D>::addVelocityLaplacian(s.neighbours, s.weights, nu_ * s.V(), s.particles.velocity, s.isFluidMask, walls_,
                                 acc, s.hasOpenBoundaries ? &s.isBufferMask : nullptr);
  }

 private:
  double nu_;
  WallVelocity walls_;
};

}  // namespace

template <int D>
std::unique_ptr<Effect<D>> makeViscosity(const Dictionary& props, const FlowState<D>&) {
  const PhysicalProperties p = readPhysicalProperties(props);
  if (!(p.nu > 0)) props.error("nu", "must be > 0 for the viscous term");
  return std::make_unique<Viscosity<D>>(p.nu, p.walls);
}

SHIZUKU_EFFECT_FACTORY(makeViscosity);

}  // namespace shizuku
