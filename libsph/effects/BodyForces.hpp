// Predictor forces of eq. (4): gravity (built only when constant/g exists) and
// the viscous term nu <lap u> (built only when nu > 0), methods.md 4.1.
// Reads: constant/g `value`; constant/physicalProperties `nu`.
#pragma once
#include "effects/Effect.hpp"

namespace shizuku {
template <int D> std::unique_ptr<Effect<D>> makeGravity(const Dictionary& gDict, const FlowState<D>& s);
template <int D> std::unique_ptr<Effect<D>> makeViscosity(const Dictionary& props, const FlowState<D>& s);
}  // namespace shizuku
