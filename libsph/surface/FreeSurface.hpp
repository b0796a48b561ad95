// Free-surface detection, particle classes and outward normals (docs/method.md 5).
//   divR_i  = -sum_j V r_ij . gradW_ij           (uncorrected kernel gradient, fluid + walls)
//   L_i     = -sum_j V r_ij (x) gradW_ij         (its matrix; divR_i = trace L_i)
//   gradC_i = sum_j V gradW_ij                   (non-difference form; points into the fluid)
//   n_i     = -gradC_i / |gradC_i|               (outward normal)
// Indicator s_i = sum of the two smallest eigenvalues of L_i: divR_i in 2D, trace less the
// largest eigenvalue in 3D, so a configuration extruded along z is classified as in 2D.
// Stage 1: s < splashThreshold -> splash; s < candidateThreshold -> candidate; else interior.
// Stage 2 (Marrone scan region): a candidate is NOT free surface if a neighbour j lies in the
// cone |r_ji| < sqrt(2) h, angle(n_i, r_ji) < pi/4, or, farther away, within h of r_i + h n_i.
// Vicinity: a non-free fluid particle with a free-surface particle within vicinityRadius (2h).
// Reads (system/sphSchemes): freeSurface { candidateThreshold; splashThreshold; vicinityRadius;
// enabled; scanRegion; pressureCondition; }; defaults and ranges are declared in FreeSurface.cpp.
#pragma once
#include "core/Dictionary.hpp"
#include "operators/FlowState.hpp"

namespace shizuku {

struct FreeSurfaceParameters {
  // Set by read(); defaults, ranges and meanings are declared once in FreeSurface.cpp.
  double candidateThreshold{};  // on the indicator s (the same number in 2D and 3D)
  double splashThreshold{};
  double vicinityRadius{};      // times h
  bool enabled{};               // false for a closed domain without free surface
  // Stage 2 (Marrone scan region) on the stage-1 candidates. Off by default: at a
  // dam-break toe the front particle on the wall is overhung by its neighbour,
  // the scan region reclassifies it as interior, its Laplacian row then has a
  // one-sided stencil without a Dirichlet neighbour and the pressure blows up
  // within 0.03 s (measured, tutorials/damBreak); stage 1 alone runs on.
  bool scanRegion{};
  // p = 0 on the surface, outside the free-surface particles (eq. 6b, docs/method.md 4.4),
  // rather than on the particles; read here, applied by the pressure equation.
  bool zeroPressureOnSurface{};
  static FreeSurfaceParameters read(const Dictionary* dict);
};

template <int D>
class FreeSurfaceDetector {
 public:
  explicit FreeSurfaceDetector(const FreeSurfaceParameters& p) : par_(p) {}
  const FreeSurfaceParameters& parameters() const { return par_; }
  // Fills s.divR, s.gradC, particles.surface and particles.normal (free, splash and vicinity).
  void detect(FlowState<D>& s) const;

 private:
  FreeSurfaceParameters par_;
};

}  // namespace shizuku
