// Particle shifting, step 10 of docs/method.md 13 (eq. 10): the sum of the shift terms
// the case names (distribution OPS/DPS eqs. 11-14, volume correction eq. 17, surface
// fitting eq. 19), capped at |dr_i| <= maxShift h, added to the fluid positions, and the
// Taylor correction of the velocity u_i += <grad u>_i dr_i (docs/method.md 6) on the
// particles where the velocity gradient is two-sided. One object owns the terms, the
// cap and the correction; a case without shifting terms builds none of it.
// Reads (system/sphSchemes, shifting): the terms' sub-dictionaries distribution, volumeCorrection,
// surfaceFitting (keys in each term's header); maxShift (times h), maxCoPerPass and taylorCorrection
// on|belowSurface|interior|everywhere|off (on = belowSurface: interior and vicinity particles;
// on free-surface and splash particles the one-sided gradient is unreliable and the product
// pumps energy, docs/shifting.md); declared in ParticleShifting.cpp.
#pragma once
#include "core/StageTimers.hpp"
#include "effects/Effect.hpp"

namespace shizuku {

// How a step's shift is applied: `count` passes, each the terms' shift times `scale`.
struct ShiftPasses {
  int count = 1;
  double scale = 1.0;
};

template <int D>
class ParticleShifting {
 public:
  enum class TaylorCorrection { off, interior, belowSurface, everywhere };

  // The shifting of the case, or null when `shifting` is absent or names no term.
  static std::unique_ptr<ParticleShifting> create(const Dictionary* shifting, const EffectRegistry<D>& registry,
                                                  const FlowState<D>& s);

  // Sizes dr, <grad u> and particles.shift, and each term's own arrays.
  void allocate(FlowState<D>& s);
  EffectNeeds needs() const;
  // Timed stages: "shifting" (gradient, density, cap and update) and one per term.
  void registerTimers(StageTimers& timers);
  // <grad u^{n+1}> for the Taylor correction, walls showing the fluid's Shepard velocity,
  // at the advected positions r' (step 8 of docs/method.md 13): called before the
  // position corrections (ADS) move particles, so that the Shepard weights W_wf are those
  // of r'. Nothing without a Taylor correction.
  void velocityGradient(FlowState<D>& s, StageTimers& timers);
  // dr = cap(sum of the terms); r += dr; u += <grad u> dr where Taylor-corrected, with
  // the <grad u> of this step's velocityGradient; in the passes beginStep chose.
  void apply(FlowState<D>& s, StageTimers& timers);
  // The passes of a step of Courant number Co = dt max|u| / h (fluid particles): one while
  // Co <= maxCoPerPass; above, ceil(Co / maxCoPerPass) passes, each scaled by
  // Co / (count maxCoPerPass), so that a step shifts Co / maxCoPerPass times one pass and the
  // shifting per unit time stays that of a step of Courant number maxCoPerPass
  // (docs/method.md 6, "Larger steps").
  ShiftPasses passes(double courant) const;
  // Chooses this step's passes from its Courant number, taken with the largest fluid speed of
  // the state it starts from (the one the time-step control limits: a step of maxCo <=
  // maxCoPerPass takes one pass).
  void beginStep(double courant) { passes_ = passes(courant); }
  int stepPasses() const { return passes_.count; }

  const std::vector<std::unique_ptr<ShiftTerm<D>>>& terms() const { return terms_; }
  double maxShift() const { return maxShift_; }
  std::string describe() const;  // the cap and the Taylor correction

 private:
  bool taylorCorrected(SurfaceClass c) const;
  std::vector<std::unique_ptr<ShiftTerm<D>>> terms_;
  std::vector<int> termTimer_;
  int timer_ = -1;
  double maxShift_ = 0.1;  // times h
  double maxCoPerPass_ = 0.2;
  ShiftPasses passes_;
  TaylorCorrection taylor_ = TaylorCorrection::belowSurface;
  std::vector<Vec<D>> dr_;
  std::vector<Mat<D>> gradU_;
};

}  // namespace shizuku
