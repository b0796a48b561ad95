// Stabilized ISPH (Asai et al. 2012), eq. (9), methods.md 4.1: the PPE source
// gains alpha (rho - <rho>_i) / dt^2 on interior and vicinity rows.
// Reads (system/sphSchemes): pressureStabilization { type densityInvariant; alpha 1e-3; }
#pragma once
#include "effects/Effect.hpp"

namespace shizuku {
template <int D>
std::unique_ptr<Effect<D>> makePressureStabilization(const Dictionary& dict, const FlowState<D>& s);
}  // namespace shizuku
