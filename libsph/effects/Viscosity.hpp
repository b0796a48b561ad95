// The viscous force of the predictor, nu <lap u> (eq. 4, docs/method.md 4.1), built only
// when nu > 0. Wall neighbours show the no-slip mirror velocity 2 U_w - u_i, or u_i with
// free slip (docs/method.md 11). Its time-step limit is dt <= 0.125 h^2 / nu
// (docs/method.md 4.3).
// Reads (constant/physicalProperties): nu (m^2/s), wallCondition noSlip|slip.
#pragma once
#include "effects/Effect.hpp"

namespace shizuku {
template <int D> std::unique_ptr<Effect<D>> makeViscosity(const Dictionary& props, const FlowState<D>& s);
}  // namespace shizuku
