// An optional physical or numerical effect of the step (gravity, viscosity,
// PPE stabilization, shifting terms, ADS, XSPH). Effects are built by name from
// their dictionary entry through EffectRegistry; an absent entry builds
// nothing, so it allocates no array and adds no loop (the user's demand 3).
// Each effect acts at one stage of the step (methods.md 13) by overriding the
// matching hook; the solver calls only the effects of each stage.
#pragma once
#include "core/Dictionary.hpp"
#include "core/Log.hpp"
#include "operators/FlowState.hpp"
#include <functional>
#include <map>
#include <memory>
#include <string>

namespace shizuku {

enum class EffectStage {
  force,          // step 5: predictor accelerations (gravity, viscosity)
  pressureSource, // step 6: extra PPE source terms (stabilized ISPH, eq. 9)
  advection,      // step 8: extra advection velocity (XSPH)
  postAdvection,  // step 9: position corrections after advection (ADS)
  shift           // step 10: particle-shift contributions (OPS/DPS, volume, surface fit)
};
const char* toString(EffectStage s);

// Per-step quantities an effect needs; the solver computes each once per step
// only if some active effect asks for it.
struct EffectNeeds {
  bool normals = false;          // outward unit normals on free-surface and vicinity particles
  bool surfaceFit = false;       // leave-one-out line fit (signed distance, fitted normal, curvature)
  bool velocityGradient = false; // <grad u> of the corrected velocity
};

template <int D>
class Effect {
 public:
  virtual ~Effect() = default;
  virtual std::string name() const = 0;       // e.g. "gravity", "shifting/distribution"
  virtual EffectStage stage() const = 0;
  virtual std::string describe() const = 0;   // parameters with units, for -dryRun and the log
  virtual EffectNeeds needs() const { return {}; }
  // Size the effect's own arrays (called before the time loop and after a particle-count change).
  virtual void allocate(const FlowState<D>&) {}
  // Stage hooks (only the one of stage() is called).
  virtual void addAcceleration(const FlowState<D>&, std::vector<Vec<D>>& /*acc*/) {}
  virtual void addPressureSource(const FlowState<D>&, std::vector<double>& /*rhs, per particle*/) {}
  virtual void addAdvectionVelocity(const FlowState<D>&, const std::vector<Vec<D>>& /*uNew*/,
                                    std::vector<Vec<D>>& /*du*/) {}
  virtual void correctPositions(FlowState<D>&) {}
  virtual void addShift(const FlowState<D>&, std::vector<Vec<D>>& /*dr*/) {}
  // Number of particles the effect acted on in its last call (for the log; -1 = not counted).
  virtual long lastActionCount() const { return -1; }
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

template <int D> void registerBuiltinEffects();

}  // namespace shizuku
