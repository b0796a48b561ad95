// A damping zone (a sponge layer) that absorbs waves at the end of a flume (docs/method.md
// 4.5, docs/boundaries.md "Damping zone"): inside the box [min, max] the fluid feels
//   a_i = -sigma(xi_i) u_i,   sigma(xi) = rate xi^2,   xi = (x_i . e - min . e) / (max - min) . e,
// e the unit vector of `axis`, so the damping rises smoothly from zero where the waves enter
// the zone to `rate` at its far end (its reflection is measured in tutorials/waveFlume:
// 0.7-0.9 % of the amplitude). Outside the box nothing. Time-step limit dt <= 1 / rate (the explicit
// decay u (1 - sigma dt) stays monotone).
// Reads (system/sphSchemes): dampingZone { min (..); max (..); axis x|y|z; rate [1/s]; }.
#include "core/Parameter.hpp"
#include "effects/EffectFactories.hpp"
#include <sstream>

namespace shizuku {
namespace {

namespace key {
const ParameterGroup zone("system/sphSchemes: dampingZone",
    "A sponge layer that absorbs waves: a = -rate xi^2 u inside the box, xi rising from 0 to 1 along axis.");
const VectorParameter min = zone.vector("min", dim::length, "lower corner of the zone").required();
const VectorParameter max = zone.vector("max", dim::length, "upper corner of the zone").required();
const OptionParameter axis = zone.option("axis", {"x", "y", "z"}, "the direction the waves run into the zone").def("x");
const ScalarParameter rate = zone.scalar("rate", dim::inverseTime, "damping rate at the zone's far end").required().above(0);
}  // namespace key

template <int D>
class DampingZone final : public ForceEffect<D> {
 public:
  DampingZone(const Vec<D>& lo, const Vec<D>& hi, int axis, double rate)
      : ForceEffect<D>("dampingZone"), lo_(lo), hi_(hi), axis_(axis), rate_(rate) {}
  std::string describe() const override {
    std::ostringstream os;
    os << "a = -" << rate_ << " xi^2 u in min (" << lo_.transpose() << ") max (" << hi_.transpose() << ") m, xi along "
       << "xyz"[axis_];
    return os.str();
  }
  TimeStepLimit timeStepLimit(const FlowState<D>&) const override { return {1 / rate_, "dampingZone"}; }
  void addAcceleration(const FlowState<D>& s, std::vector<Vec<D>>& acc) override {
    const long n = long(s.size());
    const double length = hi_[axis_] - lo_[axis_];
#pragma omp parallel for schedule(static)
    for (long i = 0; i < n; ++i) {
      if (!s.isFluid(i)) continue;
      const Vec<D>& x = s.particles.position[i];
      if (((x - lo_).array() < 0).any() || ((x - hi_).array() > 0).any()) continue;
      const double xi = (x[axis_] - lo_[axis_]) / length;
      acc[i] -= rate_ * xi * xi * s.particles.velocity[i];
    }
  }

 private:
  Vec<D> lo_, hi_;
  int axis_;
  double rate_;
};

}  // namespace

template <int D>
std::unique_ptr<Effect<D>> makeDampingZone(const Dictionary& dict, const FlowState<D>&) {
  const Vec<D> lo = key::min.read<D>(dict), hi = key::max.read<D>(dict);
  for (int k = 0; k < D; ++k)
    if (!(hi[k] > lo[k])) dict.error("max", cat("must exceed min in every direction (", "xyz"[k], ")"));
  const std::string a = key::axis.read(dict);
  const int axis = a == "x" ? 0 : a == "y" ? 1 : 2;
  if (axis >= D) dict.error("axis", "a 2D case has no z axis");
  return std::make_unique<DampingZone<D>>(lo, hi, axis, key::rate.read(dict));
}

SHIZUKU_EFFECT_FACTORY(makeDampingZone);

}  // namespace shizuku
