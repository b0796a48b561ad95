// Fixed dummy wall particles (methods.md 11, option A).
//  - shepardFluidVelocity: the velocity a wall particle shows in the PPE
//    divergence: the Shepard average of its fluid neighbours' predicted
//    velocity, u_w = sum_f W_wf u*_f / sum_f W_wf (methods.md 4.2), so still
//    water sees no artificial velocity jump at the wall.
//  - AdamiRow: the implicit wall-pressure row
//      p_w - sum_f (W_wf / sum W) p_f = rho (g - a_w) . sum_f r_wf W_wf / sum_f W_wf,
//    r_wf = r_w - r_f, a_w = 0 for a fixed tank; p_w = 0 without fluid neighbours.
#pragma once
#include "operators/FlowState.hpp"

namespace shizuku {

template <int D>
void shepardFluidVelocity(const FlowState<D>& s, std::vector<Vec<D>>& u);

template <int D>
struct AdamiRow {
  double weightSum = 0;   // sum_f W_wf over fluid neighbours
  double rhs = 0;         // rho (g - a_w) . sum_f r_wf W_wf / sum W
  // Coefficient of fluid neighbour f (pair k of row w): -W_wf / sum W.
  static AdamiRow compute(const FlowState<D>& s, std::size_t w);
};

}  // namespace shizuku
