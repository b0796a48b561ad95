// An optional physical or numerical effect of the step, typed by what it does:
//   ForceEffect              adds an acceleration to the predictor (gravity, viscosity; eq. 4)
//   PressureSourceEffect     adds a term to the PPE source, and may add one to its rows'
//                            diagonal (stabilized ISPH, eq. 9; compressibility, eq. 6c)
//   AdvectionVelocityEffect  adds a velocity to the advection of eq. 7 (XSPH)
//   PositionCorrectionEffect moves particles after advection (ADS)
//   ShiftTerm                contributes to the particle shift (OPS/DPS, volume, surface fit),
//                            owned by ParticleShifting, which caps and applies the sum.
// Effects are built by name from their dictionary entry through EffectRegistry; an absent
// entry builds nothing, so it allocates no array and adds no loop. Each effect states the
// time-step limit it imposes (docs/method.md 4.3), so the time loop needs no physics of its own.
#pragma once
#include "core/Dictionary.hpp"
#include "core/Log.hpp"
#include "operators/FlowState.hpp"
#include <cmath>
#include <functional>
#include <map>
#include <memory>
#include <string>

namespace shizuku {

// The step stage an effect acts in (docs/method.md 13), in execution order.
enum class EffectStage {
  force,          // step 5: predictor accelerations
  pressureSource, // step 6: extra PPE source terms
  advection,      // step 8: extra advection velocity
  postAdvection,  // step 9: position corrections after advection
  shift           // step 10: particle-shift contributions
};
const char* toString(EffectStage s);

// Per-step quantities an effect needs; the step computes each once per step
// only if some active effect asks for it.
struct EffectNeeds {
  bool normals = false;          // outward unit normals on free-surface and vicinity particles
  bool surfaceFit = false;       // leave-one-out line fit (signed distance, fitted normal, curvature)
  bool velocityGradient = false; // <grad u> of the corrected velocity
  EffectNeeds& operator|=(const EffectNeeds& o) {
    normals |= o.normals;
    surfaceFit |= o.surfaceFit;
    velocityGradient |= o.velocityGradient;
    return *this;
  }
};

// The largest time step an effect allows, and the name the progress line shows for it.
struct TimeStepLimit {
  double dt = INFINITY;
  const char* name = "";
};

template <int D>
class Effect {
 public:
  explicit Effect(std::string name) : name_(std::move(name)) {}
  virtual ~Effect() = default;
  const std::string& name() const { return name_; }  // e.g. "gravity", "shifting/distribution"
  virtual EffectStage stage() const = 0;      // fixed by the typed base below
  virtual std::string describe() const = 0;   // parameters with units, for -dryRun and the log
  EffectNeeds needs() const { return needs_; }
  // Size the effect's own arrays (called before the time loop and after a particle-count change).
  virtual void allocate(const FlowState<D>&) {}
  virtual TimeStepLimit timeStepLimit(const FlowState<D>&) const { return {}; }
  // Number of particles the effect acted on in its last call (for the log; -1 = not counted).
  long lastActionCount() const { return actionCount_; }

 protected:
  std::string name_;
  EffectNeeds needs_;       // set by the constructor of an effect that needs more than the basics
  long actionCount_ = -1;   // set by the stage hook of an effect that counts
};

// The typed bases: each fixes the stage and declares the one hook of that stage.
template <int D, EffectStage S>
class EffectAt : public Effect<D> {
 public:
  using Effect<D>::Effect;
  EffectStage stage() const final { return S; }
};

template <int D>
struct ForceEffect : EffectAt<D, EffectStage::force> {
  using EffectAt<D, EffectStage::force>::EffectAt;
  // Adds the force per unit mass to acc (the predictor sums it in u*'s storage: a force
  // reads the velocity and positions, never FlowState::uStar).
  virtual void addAcceleration(const FlowState<D>&, std::vector<Vec<D>>& acc) = 0;
};
template <int D>
struct PressureSourceEffect : EffectAt<D, EffectStage::pressureSource> {
  using EffectAt<D, EffectStage::pressureSource>::EffectAt;
  virtual void addPressureSource(const FlowState<D>&, std::vector<double>& rhsPerParticle) = 0;
  // A term k p_i the effect adds to the left-hand side of every interior and vicinity row
  // (1/m^2, the units of the Laplacian's weights; 0: none).
  virtual double rowDiagonal(const FlowState<D>&) const { return 0; }
};
template <int D>
struct AdvectionVelocityEffect : EffectAt<D, EffectStage::advection> {
  using EffectAt<D, EffectStage::advection>::EffectAt;
  virtual void addAdvectionVelocity(const FlowState<D>&, const std::vector<Vec<D>>& uNew, std::vector<Vec<D>>& du) = 0;
};
template <int D>
struct PositionCorrectionEffect : EffectAt<D, EffectStage::postAdvection> {
  using EffectAt<D, EffectStage::postAdvection>::EffectAt;
  virtual void correctPositions(FlowState<D>&) = 0;
};
template <int D>
struct ShiftTerm : EffectAt<D, EffectStage::shift> {
  using EffectAt<D, EffectStage::shift>::EffectAt;
  virtual void addShift(const FlowState<D>&, std::vector<Vec<D>>& dr) = 0;
};

// A shift term whose settings are one parameter struct P (read from its dictionary).
template <int D, class P>
class ShiftTermWith : public ShiftTerm<D> {
 public:
  ShiftTermWith(std::string name, const P& p) : ShiftTerm<D>(std::move(name)), par_(p) {}
  const P& parameters() const { return par_; }

 protected:
  P par_;
};

// Named creators. Built-in effects are added by registerBuiltinEffects() (one
// explicit list: static libraries drop self-registering objects).
template <int D>
class EffectRegistry {
 public:
  using Factory = std::function<std::unique_ptr<Effect<D>>(const Dictionary&, const FlowState<D>&)>;
  static EffectRegistry& instance();
  void add(const std::string& name, Factory f) { table_[name] = std::move(f); }
  bool has(const std::string& name) const { return table_.count(name) != 0; }
  std::unique_ptr<Effect<D>> create(const std::string& name, const Dictionary& dict,
                                    const FlowState<D>& s) const;
  std::vector<std::string> names() const;

 private:
  std::map<std::string, Factory> table_;
};

template <int D> void registerBuiltinEffects();                      // into instance(), once
template <int D> void registerBuiltinEffects(EffectRegistry<D>& r);  // into r

}  // namespace shizuku
