// The effect registry: named creators for every optional effect, and the one list of
// the built-in effects with the names system/sphSchemes and the constant/ files use.
#include "effects/Effect.hpp"
#include "effects/EffectFactories.hpp"

namespace shizuku {

const char* toString(EffectStage s) {
  switch (s) {
    case EffectStage::force: return "force";
    case EffectStage::pressureSource: return "pressureSource";
    case EffectStage::advection: return "advection";
    case EffectStage::postAdvection: return "postAdvection";
    case EffectStage::shift: return "shift";
  }
  return "?";
}

template <int D>
EffectRegistry<D>& EffectRegistry<D>::instance() {
  static EffectRegistry r;
  return r;
}

template <int D>
std::unique_ptr<Effect<D>> EffectRegistry<D>::create(const std::string& name, const Dictionary& dict,
                                                     const FlowState<D>& s) const {
  auto it = table_.find(name);
  if (it == table_.end()) {
    std::vector<std::string> known = names();
    std::string hint = closestMatch(name, known);
    throw InputError(cat(dict.name(), ": unknown effect '", name, "'",
                         hint.empty() ? "" : cat("; did you mean '", hint, "'?")));
  }
  return it->second(dict, s);
}

template <int D>
std::vector<std::string> EffectRegistry<D>::names() const {
  std::vector<std::string> v;
  for (auto& kv : table_) v.push_back(kv.first);
  return v;
}

template <int D>
void registerBuiltinEffects(EffectRegistry<D>& r) {
  r.add("gravity", makeGravity<D>);
  r.add("viscosity", makeViscosity<D>);
  r.add("wallFriction", makeWallFriction<D>);
  r.add("dampingZone", makeDampingZone<D>);
  r.add("compressibility", makeCompressibility<D>);
  r.add("pressureStabilization", makePressureStabilization<D>);
  r.add("xsph", makeXSPH<D>);
  r.add("ads", makeADS<D>);
  r.add("shifting/distribution", makeShiftingDistribution<D>);
  r.add("shifting/volumeCorrection", makeVolumeCorrection<D>);
  r.add("shifting/surfaceFitting", makeSurfaceFitting<D>);
}

template <int D>
void registerBuiltinEffects() {
  auto& r = EffectRegistry<D>::instance();
  if (!r.has("gravity")) registerBuiltinEffects<D>(r);
}

template class EffectRegistry<2>;
template class EffectRegistry<3>;
template void registerBuiltinEffects<2>();
template void registerBuiltinEffects<3>();
template void registerBuiltinEffects<2>(EffectRegistry<2>&);
template void registerBuiltinEffects<3>(EffectRegistry<3>&);

}  // namespace shizuku
