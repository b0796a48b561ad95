// Registers the particle-shifting terms, ADS and XSPH (methods.md 6-10) with
// the effect registry under the names used in system/sphSchemes:
//   shifting/distribution, shifting/volumeCorrection, shifting/surfaceFitting, ads, xsph.
#pragma once
#include "effects/Effect.hpp"

namespace shizuku {
template <int D> void registerShiftingEffects(EffectRegistry<D>& registry);
}  // namespace shizuku
