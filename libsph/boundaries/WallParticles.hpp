// Fixed dummy wall particles (docs/method.md 11, option A).
//  - shepardFluidVelocity: the velocity a wall particle shows in the PPE
//    divergence: the Shepard average of its fluid neighbours' predicted
//    velocity, u_w = sum_f W_wf u*_f / sum_f W_wf (docs/method.md 4.2), so still
//    water sees no artificial velocity jump at the wall. Outlet particles show the same
//    average (the velocity's zero normal gradient at an outlet); inlet particles keep
//    their prescribed velocity (docs/boundaries.md, "Inlets and outlets").
//  - velocityGradientWithShepardWalls: <grad u> of the fluid's velocity with the walls
//    showing its Shepard average (the Taylor correction's gradient, docs/method.md 13, and the
//    midpoint position update's, 4.1 eq. 7b).
//  - WallContacts: per fluid particle, the wall normal it sees (docs/method.md 11, eq. 11d),
//    seenWallNormal (wall particles only, not inlet or outlet buffers; zero without any),
//    and whether it is lone (no other fluid particle within its support).
//  - AdamiRow: the implicit wall-pressure row (docs/method.md 11, eqs. 11a, 11b, 11d):
//      p_w - sum_f (W_wf / sum W) p_f = rho0 sum_f W_wf a_f . r_wf / sum_f W_wf,
//      a_f = F_f + n_f (n_f . (u^n_f - U_w)) / dt,     F_f = (u*_f - u^n_f) / dt,
//    r_wf = r_w - r_f, F_f the forces of the predictor per unit mass. The forces enter
//    whole (Adami's hydrostatic extrapolation: still water stays exact), the velocity only
//    along the wall normal (the velocity-Neumann term stops motion into or out of the wall
//    in one step and leaves the motion along it alone). A lone particle's forces enter
//    along n_f only: nothing below it carries its weight beside a vertical wall.
//    Where the velocity part would lower the wall below ambient pressure (eq. 11b, with the
//    fluid neighbours' previous pressure as the estimate of sum W p_f), the row is p_w = 0:
//    water does not pull on a wall, it separates (a jet leaving a box's top edge).
//    p_w = 0 without fluid neighbours. Inlet particles take the row with the whole
//    relative velocity, a_f = (u*_f - U_w)/dt, U_w their prescribed velocity: an inlet
//    prescribes every component of the velocity (docs/boundaries.md).
#pragma once
#include "operators/FlowState.hpp"

namespace shizuku {

// outletsOnly: only the outlet particles (the corrector's zero-gradient outlet velocity).
template <int D>
void shepardFluidVelocity(const FlowState<D>& s, std::vector<Vec<D>>& u, bool outletsOnly = false);

// out(a, b) = d u_a / d x_b (SPH(2) weights of the step) of the fluid's velocity, each wall
// particle showing the Shepard average of its fluid neighbours' velocity at the current
// positions. s.uStar is the scratch: it is free once the corrector has used it.
template <int D>
void velocityGradientWithShepardWalls(FlowState<D>& s, std::vector<Mat<D>>& out);

// The wall normal fluid particle f sees (eq. 11d): its wall neighbours' surface normals
// (`wallNormal`), each turned to agree with the direction from the walls to f,
// c_f = sum_w W_fw r_fw (a container's normals point into it, and water may meet a hollow
// box's layers from outside), W-weighted and normalised; c_f / |c_f| where the case has no
// wall normals or they cancel; zero without wall neighbours.
template <int D>
Vec<D> seenWallNormal(const FlowState<D>& s, std::size_t f);

template <int D>
struct WallContacts {
  std::vector<Vec<D>> normal;          // n_f (fluid particles; zero without wall neighbours)
  std::vector<std::uint8_t> lone;      // 1: no other fluid particle within the support
  void update(const FlowState<D>& s);  // sized to the particle count, capacity kept
};

template <int D>
struct AdamiRow {
  double weightSum = 0;   // sum_f W_wf over fluid neighbours
  double rhs = 0;         // rho0 sum_f W_wf a_f . r_wf / sum W
  bool ambient = false;   // eq. 11b binds: the row is p_w = 0, without fluid coefficients
  // Coefficient of fluid neighbour f (pair k of row w): -W_wf / sum W.
  static AdamiRow compute(const FlowState<D>& s, const WallContacts<D>& contacts, std::size_t w);
};

}  // namespace shizuku
