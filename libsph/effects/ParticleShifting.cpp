// Particle shifting, eq. (10): see ParticleShifting.hpp.
#include "effects/ParticleShifting.hpp"
#include "boundaries/WallParticles.hpp"
#include "core/Parameter.hpp"
#include <cmath>
#include "effects/ShiftCap.hpp"

namespace shizuku {

namespace {
namespace key {
const ParameterGroup shifting("system/sphSchemes: shifting",
    "Particle shifting, eq. 10: its terms (sub-dictionaries distribution, volumeCorrection, surfaceFitting), the cap "
    "and the Taylor correction (docs/method.md 6-8).");
const ScalarParameter maxShift = shifting.scalar("maxShift", dim::none, "cap on |dr|, times h").def(0.1).above(0).max(1);
const ScalarParameter maxCoPerPass = shifting.scalar("maxCoPerPass", dim::none,
    "a step of Courant number Co above this shifts in ceil(Co / maxCoPerPass) passes, together Co / maxCoPerPass "
    "times one pass (docs/method.md 6)").def(0.2).above(0);
const OptionParameter taylorCorrection = shifting.option("taylorCorrection",
    {"on", "yes", "true", "off", "no", "false", "everywhere", "belowSurface", "interior"},
    "u += <grad u> dr on: interior and vicinity (on = belowSurface), interior, everywhere, or off").def("on");
}  // namespace key
}  // namespace

template <int D>
std::unique_ptr<ParticleShifting<D>> ParticleShifting<D>::create(const Dictionary* sh,
                                                                 const EffectRegistry<D>& registry,
                                                                 const FlowState<D>& s) {
  if (!sh) return nullptr;
  auto p = std::unique_ptr<ParticleShifting>(new ParticleShifting);
  for (const char* term : {"distribution", "volumeCorrection", "surfaceFitting"})
    if (const Dictionary* d = sh->subDictPtr(term)) {
      std::unique_ptr<Effect<D>> e = registry.create(std::string("shifting/") + term, *d, s);
      auto* t = dynamic_cast<ShiftTerm<D>*>(e.get());
      if (!t) sh->error(term, "is not a shift term");
      e.release();
      p->terms_.emplace_back(t);
    }
  p->maxShift_ = key::maxShift.read(*sh);
  p->maxCoPerPass_ = key::maxCoPerPass.read(*sh);
  const std::string t = key::taylorCorrection.read(*sh);
  if (t == "off" || t == "no" || t == "false") p->taylor_ = TaylorCorrection::off;
  else if (t == "everywhere") p->taylor_ = TaylorCorrection::everywhere;
  else if (t == "interior") p->taylor_ = TaylorCorrection::interior;
  else p->taylor_ = TaylorCorrection::belowSurface;
  if (p->terms_.empty()) return nullptr;
  return p;
}

template <int D>
bool ParticleShifting<D>::taylorCorrected(SurfaceClass c) const {
  switch (taylor_) {
    case TaylorCorrection::off: return false;
    case TaylorCorrection::interior: return c == SurfaceClass::interior;
    case TaylorCorrection::belowSurface: return c == SurfaceClass::interior || c == SurfaceClass::vicinity;
    case TaylorCorrection::everywhere: return true;
  }
  return false;
}

template <int D>
void ParticleShifting<D>::allocate(FlowState<D>& s) {
  s.particles.shift.resize(s.size(), Vec<D>::Zero());
  dr_.resize(s.size());
  if (taylor_ != TaylorCorrection::off) gradU_.resize(s.size());
  for (auto& t : terms_) t->allocate(s);
}

template <int D>
EffectNeeds ParticleShifting<D>::needs() const {
  EffectNeeds n;
  for (const auto& t : terms_) n |= t->needs();
  n.velocityGradient |= taylor_ != TaylorCorrection::off;
  return n;
}

template <int D>
void ParticleShifting<D>::registerTimers(StageTimers& timers) {
  timer_ = timers.stage("shifting");
  termTimer_.clear();
  for (const auto& t : terms_) termTimer_.push_back(timers.stage(t->name()));
}

template <int D>
std::string ParticleShifting<D>::describe() const {
  const char* taylor = "";
  switch (taylor_) {
    case TaylorCorrection::off: break;
    case TaylorCorrection::interior: taylor = ", Taylor-corrected velocity on interior particles"; break;
    case TaylorCorrection::belowSurface: taylor = ", Taylor-corrected velocity on interior and vicinity particles"; break;
    case TaylorCorrection::everywhere: taylor = ", Taylor-corrected velocity on every fluid particle"; break;
  }
  return cat("shift cap |dr| <= ", maxShift_, " h per pass, one pass per Courant number ", maxCoPerPass_, taylor);
}

// The Shepard weights at r' rather than after ADS: with W_wf taken after ADS had pushed
// particles off the walls, the Buchner impact's P1 plateau noise rose from 0.087-0.114 to
// 0.127-0.193 rho g H (H/30, four trajectories each, docs/validation.md).
template <int D>
void ParticleShifting<D>::velocityGradient(FlowState<D>& s, StageTimers& timers) {
  if (taylor_ == TaylorCorrection::off) return;
  StageTimers::Scope t(timers, timer_);
  velocityGradientWithShepardWalls(s, gradU_);
}

template <int D>
ShiftPasses ParticleShifting<D>::passes(double courant) const {
  const double ratio = courant / maxCoPerPass_;
  // A step the CFL limit set has Co = maxCo up to rounding: at maxCo = maxCoPerPass it is one
  // pass, at twice it two, not one more for the last bit.
  const int count = std::isfinite(ratio) ? int(std::ceil(ratio - 1e-9)) : 1;
  if (count <= 1) return {1, 1.0};
  return {count, ratio / count};
}

template <int D>
void ParticleShifting<D>::apply(FlowState<D>& s, StageTimers& timers) {
  auto& P = s.particles;
  const long n = long(s.size());
  const ShiftPasses pass = passes_;
  for (int k = 0; k < pass.count; ++k) {
    {
      StageTimers::Scope t(timers, timer_);
      if (k > 0) s.exchange(P.position);  // the terms read the neighbours' shifted positions
      s.computeDensity();
#pragma omp parallel for schedule(static)
      for (long i = 0; i < n; ++i) dr_[i].setZero();
    }
    for (std::size_t m = 0; m < terms_.size(); ++m) {
      StageTimers::Scope t(timers, termTimer_[m]);
      terms_[m]->addShift(s, dr_);
    }
    StageTimers::Scope t(timers, timer_);
    if (pass.scale != 1.0)
#pragma omp parallel for schedule(static)
      for (long i = 0; i < n; ++i) dr_[i] *= pass.scale;
    capShift(dr_, maxShift_ * s.h);
#pragma omp parallel for schedule(static)
    for (long i = 0; i < n; ++i) {
      if (!s.isFluid(i)) { P.shift[i].setZero(); continue; }
      P.position[i] += dr_[i];
      if (s.periodic.any()) s.periodic.wrap(P.position[i]);
      if (taylorCorrected(P.surfaceClass(i))) P.velocity[i] += gradU_[i] * dr_[i];
      P.shift[i] = k == 0 ? dr_[i] : Vec<D>(P.shift[i] + dr_[i]);
    }
  }
}

template class ParticleShifting<2>;
template class ParticleShifting<3>;

}  // namespace shizuku
