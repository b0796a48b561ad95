// Slight compressibility of the water in the pressure equation, eq. (6c) (docs/method.md 4.1):
// with the equation of state p - p^n = c^2 (rho - rho^n), the continuity equation taken
// implicitly over the step adds -(p_i - p^n_i)/(c dt)^2 to every interior and vicinity row,
//   <lap p^{n+1}>_i - (p^{n+1}_i - p^n_i)/(c dt)^2 = (rho0/dt) <div u*>_i,
// so a pressure disturbance spreads at the sound speed c instead of within one step. It
// vanishes on a steady pressure and sets no time-step limit; a fresh start takes its first
// p^n from the water at rest (IsphStep::initialPressure), so still water stays exact.
// Reads: constant/physicalProperties soundSpeed (m/s; absent: incompressible, nothing built).
#include "effects/EffectFactories.hpp"
#include "effects/PhysicalProperties.hpp"

namespace shizuku {

namespace {

template <int D>
class Compressibility final : public PressureSourceEffect<D> {
 public:
  explicit Compressibility(double soundSpeed) : PressureSourceEffect<D>("compressibility"), c_(soundSpeed) {}
  std::string describe() const override { return cat("soundSpeed = ", c_, " m/s (eq. 6c)"); }
  // The left-hand side's k p_i, k = 1/(c dt)^2; the known k p^n_i moves to the source.
  double rowDiagonal(const FlowState<D>& s) const override { return 1.0 / (c_ * c_ * s.dt * s.dt); }
  void addPressureSource(const FlowState<D>& s, std::vector<double>& source) override {
    // The row reads -<lap p>_i + k p_i = -b_i + k p^n_i, and the assembly puts -source on the right.
    const double k = rowDiagonal(s);
    const auto& p = s.particles.pressure;
    const long n = long(s.size());
#pragma omp parallel for schedule(static)
    for (long i = 0; i < n; ++i)
      if (s.isFluid(i)) source[i] -= k * p[i];
  }

 private:
  double c_;
};

}  // namespace

template <int D>
std::unique_ptr<Effect<D>> makeCompressibility(const Dictionary& props, const FlowState<D>&) {
  return std::make_unique<Compressibility<D>>(readSoundSpeed(props));
}

SHIZUKU_EFFECT_FACTORY(makeCompressibility);

}  // namespace shizuku
