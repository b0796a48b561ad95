// Gravity, the body force of the predictor (eq. 4, docs/method.md 4.1), built only when
// constant/g exists. Its time-step limit is the force condition dt <= 0.25 sqrt(h/|g|)
// (docs/method.md 4.3).
// Reads: constant/g `value` (acceleration vector).
#include "effects/EffectFactories.hpp"
#include "effects/PhysicalProperties.hpp"

namespace shizuku {
namespace {

template <int D>
class Gravity final : public ForceEffect<D> {
 public:
  explicit Gravity(const Vec<D>& g) : ForceEffect<D>("gravity"), g_(g) {}
  std::string describe() const override {
    std::ostringstream os;
    os << "g = (" << g_.transpose() << ") m/s^2";
    return os.str();
  }
  TimeStepLimit timeStepLimit(const FlowState<D>& s) const override {
    const double g = g_.norm();
    return {g > 0 ? 0.25 * std::sqrt(s.h / g) : INFINITY, "force"};
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

}  // namespace

template <int D>
std::unique_ptr<Effect<D>> makeGravity(const Dictionary& gDict, const FlowState<D>&) {
  return std::make_unique<Gravity<D>>(readGravity<D>(gDict));
}

SHIZUKU_EFFECT_FACTORY(makeGravity);

}  // namespace shizuku
