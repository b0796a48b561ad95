// The effects of a case, built from its dictionaries and sorted by type: see EffectSet.hpp.
#include "effects/EffectSet.hpp"

namespace shizuku {

namespace {
// Moves a freshly built effect into the list of its type.
template <class Typed, int D>
void adopt(std::unique_ptr<Effect<D>> e, std::vector<std::unique_ptr<Typed>>& list, const Dictionary& where,
           const std::string& key) {
  auto* t = dynamic_cast<Typed*>(e.get());
  if (!t) where.error(key, "names an effect of another kind");
  e.release();
  list.emplace_back(t);
}
}  // namespace

template <int D>
EffectSet<D> EffectSet<D>::build(const Dictionary* gravity, const Dictionary& props, double nu,
                                 const Dictionary& sch, const FlowState<D>& s) {
  registerBuiltinEffects<D>();
  const auto& reg = EffectRegistry<D>::instance();
  EffectSet set;
  if (gravity) adopt(reg.create("gravity", *gravity, s), set.forces, *gravity, "value");
  if (nu > 0) adopt(reg.create("viscosity", props, s), set.forces, props, "nu");
  else props.markRead("wallCondition");
  if (props.subDictPtr("wallFriction")) adopt(reg.create("wallFriction", props, s), set.forces, props, "wallFriction");
  if (const Dictionary* d = sch.subDictPtr("dampingZone")) adopt(reg.create("dampingZone", *d, s), set.forces, sch, "dampingZone");
  if (props.found("soundSpeed"))
    adopt(reg.create("compressibility", props, s), set.pressureSources, props, "soundSpeed");
  if (const Dictionary* d = sch.subDictPtr("pressureStabilization"))
    adopt(reg.create("pressureStabilization", *d, s), set.pressureSources, sch, "pressureStabilization");
  if (const Dictionary* d = sch.subDictPtr("xsph")) adopt(reg.create("xsph", *d, s), set.advectionVelocities, sch, "xsph");
  if (const Dictionary* d = sch.subDictPtr("ads")) adopt(reg.create("ads", *d, s), set.positionCorrections, sch, "ads");
  set.shifting = ParticleShifting<D>::create(sch.subDictPtr("shifting"), reg, s);
  return set;
}

template <int D>
std::vector<const Effect<D>*> EffectSet<D>::all() const {
  std::vector<const Effect<D>*> v;
  forEach([&](const Effect<D>& e) { v.push_back(&e); });
  return v;
}

template <int D>
EffectNeeds EffectSet<D>::needs() const {
  EffectNeeds n;
  forEach([&](const Effect<D>& e) { n |= e.needs(); });
  if (shifting) n |= shifting->needs();
  return n;
}

template <int D>
void EffectSet<D>::allocate(FlowState<D>& s) {
  for (auto& e : forces) e->allocate(s);
  for (auto& e : pressureSources) e->allocate(s);
  for (auto& e : advectionVelocities) e->allocate(s);
  for (auto& e : positionCorrections) e->allocate(s);
  if (shifting) shifting->allocate(s);
}

template <int D>
TimeStepLimit EffectSet<D>::timeStepLimit(const FlowState<D>& s) const {
  TimeStepLimit lim;
  forEach([&](const Effect<D>& e) {
    const TimeStepLimit l = e.timeStepLimit(s);
    if (l.dt < lim.dt) lim = l;
  });
  return lim;
}

template class EffectSet<2>;
template class EffectSet<3>;

}  // namespace shizuku
