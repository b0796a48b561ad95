// Gravity, the body force of the predictor (eq. 4, docs/method.md 4.1), built only when
// constant/g exists. Its time-step limit is the force condition dt <= 0.25 sqrt(h/|g|)
// (docs/method.md 4.3).
// Reads: constant/g `value` (acceleration vector).
#pragma once
#include "effects/Effect.hpp"

namespace shizuku {
template <int D> std::unique_ptr<Effect<D>> makeGravity(const Dictionary& gDict, const FlowState<D>& s);
}  // namespace shizuku
