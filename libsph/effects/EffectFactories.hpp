// The factories of the built-in effects: each builds its effect from its dictionary entry
// (the keys are in the header comment of the effect's own file) and is registered by name
// in EffectRegistry.cpp.
#pragma once
#include "effects/Effect.hpp"

namespace shizuku {

template <int D> std::unique_ptr<Effect<D>> makeGravity(const Dictionary& dict, const FlowState<D>& s);
template <int D> std::unique_ptr<Effect<D>> makeDampingZone(const Dictionary& dict, const FlowState<D>& s);
template <int D> std::unique_ptr<Effect<D>> makeViscosity(const Dictionary& dict, const FlowState<D>& s);
template <int D> std::unique_ptr<Effect<D>> makeWallFriction(const Dictionary& dict, const FlowState<D>& s);
template <int D> std::unique_ptr<Effect<D>> makeCompressibility(const Dictionary& dict, const FlowState<D>& s);
template <int D> std::unique_ptr<Effect<D>> makePressureStabilization(const Dictionary& dict, const FlowState<D>& s);
template <int D> std::unique_ptr<Effect<D>> makeXSPH(const Dictionary& dict, const FlowState<D>& s);
template <int D> std::unique_ptr<Effect<D>> makeADS(const Dictionary& dict, const FlowState<D>& s);
template <int D> std::unique_ptr<Effect<D>> makeShiftingDistribution(const Dictionary& dict, const FlowState<D>& s);
template <int D> std::unique_ptr<Effect<D>> makeVolumeCorrection(const Dictionary& dict, const FlowState<D>& s);
template <int D> std::unique_ptr<Effect<D>> makeSurfaceFitting(const Dictionary& dict, const FlowState<D>& s);

// Explicit instantiation of a factory for 2D and 3D.
#define SHIZUKU_EFFECT_FACTORY(make)                                                     \
  template std::unique_ptr<Effect<2>> make<2>(const Dictionary&, const FlowState<2>&); \
  template std::unique_ptr<Effect<3>> make<3>(const Dictionary&, const FlowState<3>&)

// Explicit instantiation of an effect class and its factory for 2D and 3D.
#define SHIZUKU_EFFECT(Class, make) \
  template class Class<2>;          \
  template class Class<3>;          \
  SHIZUKU_EFFECT_FACTORY(make)

}  // namespace shizuku
