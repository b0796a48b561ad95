// The row of a free-surface particle when p = 0 is imposed on the surface itself, not on the
// particle (docs/method.md 4.4, eq. 6b). The free surface lies delta_i outside particle i,
// along its outward normal n_i; the pressure is extrapolated linearly along -n_i from the
// fluid neighbours j that lie deeper than i (d_ij = (r_j - r_i) . (-n_i) > 0):
//   p_i (sum_j a_ij d_ij + delta_i sum_j a_ij) - delta_i sum_j a_ij p_j = 0,
//   a_ij = W_ij d_ij / |r_ij|                                                  (6b)
// which is exact for any p linear along the normal with p = 0 at delta_i outside i (the
// ghost-fluid extrapolation; with one neighbour p_i = delta/(delta + d) p_j). The row is
// strictly diagonally dominant with non-positive off-diagonals, so the M-matrix pattern of
// the system is kept.
//   delta_i = d0 / 2: a particle carries the volume d0^D around it, so the surface stands half
//             a spacing outside its own centre (measured: taking the fit's distance s_i
//             instead, delta = d0 (1/2 - s_i), made the still tank's error 100 times larger
//             at the wall corners, docs/method.md 4.4);
//   n_i     = the surface fit's normal (FlowState::fitNormal) where the fit passed its
//             quality gate (the pressure equation runs the fit when this condition is on),
//             the detector's normal elsewhere (which tilts by 15 degrees where the surface
//             meets a wall).
// Neighbours used: fluid, not splash (splash particles keep p = 0). Reads no dictionary keys
// (freeSurface { pressureCondition; } is read in surface/FreeSurface.cpp).
#pragma once
#include "operators/FlowState.hpp"
#include <cmath>

namespace shizuku {

template <int D>
struct FreeSurfaceRow {
  // The inward unit normal -n_i and delta_i of free-surface particle i; false if i has no
  // normal (then it keeps p = 0).
  static bool frame(const FlowState<D>& s, std::size_t i, Vec<D>& inward, double& delta) {
    const bool fitted = s.fitDistance.size() == s.size() && std::isfinite(s.fitDistance[i]);
    const Vec<D>& n = fitted ? s.fitNormal[i] : s.particles.normal[i];
    if (!(n.squaredNorm() > 0.25)) return false;
    inward = -n.normalized();
    delta = 0.5 * s.d0;
    return true;
  }

  // a_ij of pair k and the depth d_ij of j below i; a = 0 where j is not used.
  static double weight(const FlowState<D>& s, std::size_t i, Index k, const Vec<D>& inward, double& d) {
    const auto& nl = s.neighbours;
    const Index j = nl.j[k];
    const Vec<D> rij = nl.rij(i, k);
    d = -rij.dot(inward);  // r_ij = r_i - r_j
    if (!(d > 0) || !s.isFluid(j) || s.surfaceClass(j) == SurfaceClass::splash) return 0;
    const double r = rij.norm();
    return s.kernel.w(r) * d / r;
  }

  // sum_j a_ij d_ij: positive when some usable neighbour lies deeper than i.
  static double depthMoment(const FlowState<D>& s, std::size_t i, const Vec<D>& inward) {
    const auto& nl = s.neighbours;
    double m = 0, d = 0;
    for (Index k = nl.begin(i); k < nl.end(i); ++k) m += weight(s, i, k, inward, d) * d;
    return m;
  }
};

}  // namespace shizuku
