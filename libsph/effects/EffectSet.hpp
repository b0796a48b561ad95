// The effects of a case, sorted by what they do, in the order the step calls them
// (docs/method.md 13): forces (step 5), PPE source terms (6), advection velocities (8),
// position corrections (9) and the particle shifting (10, null without shifting).
// Built from the case dictionaries: an effect the case does not name is not constructed.
// Reads: constant/g (gravity); constant/physicalProperties nu, wallCondition (viscosity,
// when nu > 0), wallFriction, soundSpeed (compressibility); system/sphSchemes dampingZone,
// pressureStabilization, xsph, ads, shifting.
#pragma once
#include "effects/ParticleShifting.hpp"

namespace shizuku {

template <int D>
class EffectSet {
 public:
  // gravity: constant/g or null; nu: the case's kinematic viscosity.
  static EffectSet build(const Dictionary* gravity, const Dictionary& physicalProperties, double nu,
                         const Dictionary& sphSchemes, const FlowState<D>& s);

  std::vector<std::unique_ptr<ForceEffect<D>>> forces;
  std::vector<std::unique_ptr<PressureSourceEffect<D>>> pressureSources;
  std::vector<std::unique_ptr<AdvectionVelocityEffect<D>>> advectionVelocities;
  std::vector<std::unique_ptr<PositionCorrectionEffect<D>>> positionCorrections;
  std::unique_ptr<ParticleShifting<D>> shifting;

  // Every effect in step order (the shift terms last), for the pipeline print-out and tests.
  std::vector<const Effect<D>*> all() const;
  // f(const Effect<D>&) for every effect in step order, without allocating.
  template <class F>
  void forEach(F&& f) const {
    for (const auto& e : forces) f(*e);
    for (const auto& e : pressureSources) f(*e);
    for (const auto& e : advectionVelocities) f(*e);
    for (const auto& e : positionCorrections) f(*e);
    if (shifting)
      for (const auto& e : shifting->terms()) f(*e);
  }
  EffectNeeds needs() const;
  void allocate(FlowState<D>& s);
  // The smallest time-step limit of all effects (INFINITY and "" when none limits).
  TimeStepLimit timeStepLimit(const FlowState<D>& s) const;
};

}  // namespace shizuku
