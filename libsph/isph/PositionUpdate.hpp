// The position update of the advection stage (docs/method.md 4.1, eqs. 7 and 7b), with v_i the
// advection velocity (u^{n+1}, plus XSPH's du where XSPH is on):
//   euler:    r_i <- r_i + dt v_i                                                     (7)
//   midpoint: r_i <- r_i + dt (I - dt/2 G_i)^{-1} v_i,   G_i = <grad u^{n+1}>_i       (7b)
// on interior and vicinity particles (free and splash particles take the Euler step: their
// gradient is one-sided and built from few neighbours). Eq. 7b is the implicit midpoint rule
// dr = dt v(r + dr/2) on the velocity field linearised at the particle. For a linear
// divergence-free field it is the Cayley map, which keeps areas exactly in 2D and volumes to
// O(dt^3) per step in 3D, where Euler's step changes them by dt^2 det G per step: under strain
// a compression proportional to dt per unit time, which grew the dam break's interior density
// error with the step (docs/performance.md, "How large a step"). G is the SPH(2) gradient of
// the corrected velocity, the walls showing the fluid's Shepard velocity (as the Taylor
// correction's, docs/method.md 13, here at r^n). Where |dt/2 G|_F >= 1/2 the Euler step is
// taken (the series behind the inverse would not converge).
// Reads no keys itself: system/sphSchemes positionUpdate (euler | midpoint) is read in
// isph/CaseSetup.cpp.
#pragma once
#include "operators/FlowState.hpp"
#include <string>
#include <vector>

namespace shizuku {

template <int D>
class PositionUpdate {
 public:
  enum class Rule { euler, midpoint };
  explicit PositionUpdate(Rule rule = Rule::euler) : rule_(rule) {}
  // Sizes the scratch of the midpoint rule (nothing for euler); called when the particle
  // count changes, never inside a step.
  void allocate(std::size_t n);
  // Moves every fluid particle of s by its displacement over s.dt (wrapped into a periodic
  // box); du: the extra advection velocity (XSPH), empty if none. The midpoint rule uses s.uStar
  // as scratch.
  void move(FlowState<D>& s, const std::vector<Vec<D>>& du);
  std::string describe() const;

 private:
  Rule rule_;
  std::vector<Mat<D>> gradient_;  // G_i
};

}  // namespace shizuku
