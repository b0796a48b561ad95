// Gravity and viscosity: the force stage of the predictor, eq. (4).
#include "effects/BodyForces.hpp"

namespace shizuku {
namespace {

template <int D>
class Gravity final : public Effect<D> {
 public:
  explicit Gravity(const Vec<D>& g) : g_(g) {}
  std::string name() const override { return "gravity"; }
  EffectStage stage() const override { return EffectStage::force; }
  std::string describe() const override {
    std::ostringstream os;
    os << "g = (" << g_.transpose() << ") m/s^2";
    return os.str();
  }
  void addAcceleration(const FlowState<D>& s, std::vector<Vec<D>>& acc) override {
    const long n = long(s.size());
#pragma omp parallel for schedule(static)
    for (long i = 0; i < n; ++i)
      if (s.isFluid(i)) acc[i] += g_;
  }

 private:
  Vec<D> g_;
};

// nu <lap u>_i with the operator's Laplacian weights; wall neighbours take the
// no-slip mirror velocity 2 U_w - u_i (methods.md 11) or, with slip, u_i.
template <int D>
class Viscosity final : public Effect<D> {
 public:
  Viscosity(double nu, bool noSlip) : nu_(nu), noSlip_(noSlip) {}
  std::string name() const override { return "viscosity"; }
  EffectStage stage() const override { return EffectStage::force; }
  std::string describe() const override {
    return cat("nu = ", nu_, " m^2/s, walls ", noSlip_ ? "noSlip" : "slip");
  }
  void addAcceleration(const FlowState<D>& s, std::vector<Vec<D>>& acc) override {
    const auto& nl = s.neighbours;
    const auto& u = s.particles.velocity;
    const double V = s.V();
    const long n = long(s.size());
#pragma omp parallel for schedule(static)
    for (long i = 0; i < n; ++i) {
      if (!s.isFluid(i)) continue;
      Vec<D> lap = Vec<D>::Zero();
      for (Index k = nl.begin(i); k < nl.end(i); ++k) {
        const Index j = nl.j[k];
        Vec<D> uj = u[j];
        if (!s.isFluid(j)) uj = noSlip_ ? Vec<D>(2.0 * u[j] - u[i]) : u[i];
        lap += s.weights.lapW[k] * (uj - u[i]);
      }
      acc[i] += nu_ * V * lap;
    }
  }

 private:
  double nu_;
  bool noSlip_;
};

}  // namespace

template <int D>
std::unique_ptr<Effect<D>> makeGravity(const Dictionary& gDict, const FlowState<D>&) {
  return std::make_unique<Gravity<D>>(gDict.getVector<D>("value", dim::acceleration));
}

template <int D>
std::unique_ptr<Effect<D>> makeViscosity(const Dictionary& props, const FlowState<D>&) {
  const double nu = props.getScalarOr("nu", 0.0, dim::kinematicViscosity);
  const std::string wall = props.getOptionOr("wallCondition", {"noSlip", "slip"}, "noSlip");
  if (nu < 0) props.error("nu", "must be >= 0");
  return std::make_unique<Viscosity<D>>(nu, wall == "noSlip");
}

template std::unique_ptr<Effect<2>> makeGravity<2>(const Dictionary&, const FlowState<2>&);
template std::unique_ptr<Effect<3>> makeGravity<3>(const Dictionary&, const FlowState<3>&);
template std::unique_ptr<Effect<2>> makeViscosity<2>(const Dictionary&, const FlowState<2>&);
template std::unique_ptr<Effect<3>> makeViscosity<3>(const Dictionary&, const FlowState<3>&);

}  // namespace shizuku
