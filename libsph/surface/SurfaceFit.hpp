// Leave-one-out surface fit and surface curvature (docs/method.md 8.2 and 8.4,
// seed eqs. 19-21).
//
// For a free-surface (free or splash) or vicinity fluid particle i, let Q be the
// free-surface particles j != i within the support 2h (the set S_i,free of
// eq. 21 without i itself). With weights w_ij:
//   c = sum w_ij r_j / sum w_ij,   C = sum w_ij (r_j - c)(r_j - c)^T,
//   n_i = eigenvector of the smallest eigenvalue of C (a line in 2D, a plane in 3D),
//         oriented like the particle's existing outward normal,
//   s_i = (r_i - c) . n_i / d0    (signed, positive outside the fitted surface).
// Quality gate: the fit is used only if |Q| >= D, lambda_min / lambda_max <= maxEigenRatio
// (the points lie on a line/plane) and, in 3D, lambda_mid / lambda_max >= minSpreadRatio
// (they are not collinear). Leaving i out makes s exact for a flat surface with i
// displaced (docs/method.md 8.2: including i biases s to ~0.37 of the displacement).
//
// Curvature, eq. 20, in units of 1/d0:
//   kappa_i d0 = factor * d0 * sum_{j in S_i,free} V (n_j - n_i) . gradW_ij
// with the corrected SPH(2) gradient weights gradW (s.weights.gradW) and the fitted
// normals. The paper's factor is 0.34; docs/method.md 8.4 could not reproduce it (the
// factor giving kappa = 1/R on a lattice disc is ~0.9 with the FI gradient), see
// docs/shifting.md for the calibration measured here.
//
// Reads no dictionary keys itself: the surfaceFitting effect reads curvatureFactor.
#pragma once
#include "operators/FlowState.hpp"

namespace shizuku {

struct SurfaceFitSettings {
  double curvatureFactor = 0.34;  // seed eq. 20
  double maxEigenRatio = 0.3;     // docs/method.md 8.2 step 5
  double minSpreadRatio = 0.05;   // 3D only: second eigenvalue / largest
};

// True for the particles that count as free surface in the fit (free and splash).
inline bool isFreeSurfaceClass(SurfaceClass c) { return c == SurfaceClass::free || c == SurfaceClass::splash; }

// Fills s.fitDistance (s_i / d0) and s.curvature (kappa_i d0) for free, splash and
// vicinity fluid particles (NaN elsewhere and where the fit failed / the normal is
// undefined) and s.fitNormal: the fitted outward normal where the fit succeeded, the
// detector's normal elsewhere. Requires s.particles.normal to hold the detector's normals
// (zero vectors where undefined); it is left as it is, because the OPS distribution term
// projects with it: handing OPS the fitted normals instead doubled the interior density
// error of the dam break (docs/shifting.md). Arrays are resized only if their size differs from N.
template <int D>
void computeSurfaceFit(FlowState<D>& s, const SurfaceFitSettings& settings = {});

// The sum of eq. 20 without the factor, times d0, for particle i, with the
// normals in s.fitNormal (NaN if n_i is undefined). Lets an
// effect apply its own factor.
template <int D>
double curvatureSum(const FlowState<D>& s, std::size_t i);

}  // namespace shizuku
