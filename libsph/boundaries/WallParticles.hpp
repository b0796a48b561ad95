// Fixed dummy wall particles (docs/method.md 11, option A).
//  - shepardFluidVelocity: the velocity a wall particle shows in the PPE
//    divergence: the Shepard average of its fluid neighbours' predicted
//    velocity, u_w = sum_f W_wf u*_f / sum_f W_wf (docs/method.md 4.2), so still
//    water sees no artificial velocity jump at the wall. Outlet particles show the same
//    average (the velocity's zero normal gradient at an outlet); inlet particles keep
//    their prescribed velocity (docs/boundaries.md, "Inlets and outlets").
//  - AdamiRow: the implicit wall-pressure row (docs/method.md 11 A), written with the
//    predicted velocity so that it also carries the kinematic condition:
//      p_w - sum_f (W_wf / sum W) p_f = rho sum_f W_wf a_f . r_wf / sum_f W_wf,
//      a_f = (u*_f - U_w) / dt,   r_wf = r_w - r_f,
//    p_w = 0 without fluid neighbours. Inlet particles take the same row with U_w their
//    prescribed velocity: the pressure is extrapolated from the fluid (a Neumann
//    condition carrying the hydrostatic and the inflow's acceleration term). For fluid at rest u*_f = g dt and this is
//    Adami's hydrostatic row rho g . r_wf (so still water stays exact); fluid
//    moving into the wall raises p_w by the pressure that stops it in one step,
//    the velocity-Neumann idea of Morikawa et al. (docs/method.md 7). With the plain
//    gravity row, fluid moving toward a wall (the dam-break toe) sank into it.
#pragma once
#include "operators/FlowState.hpp"

namespace shizuku {

// outletsOnly: only the outlet particles (the corrector's zero-gradient outlet velocity).
template <int D>
void shepardFluidVelocity(const FlowState<D>& s, std::vector<Vec<D>>& u, bool outletsOnly = false);

template <int D>
struct AdamiRow {
  double weightSum = 0;   // sum_f W_wf over fluid neighbours
  double rhs = 0;         // rho sum_f W_wf a_f . r_wf / sum W
  // Coefficient of fluid neighbour f (pair k of row w): -W_wf / sum W.
  static AdamiRow compute(const FlowState<D>& s, std::size_t w);
};

}  // namespace shizuku
