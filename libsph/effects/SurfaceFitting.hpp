// Surface-fitting shift, eq. (19) with the gates of the paper (docs/method.md 8.1, 8.3):
//   dr_suf_i = sign * C h s_i n_i   for free-surface particles i (free, splash) with
//   0 < |kappa_i d0| < maxCurvature  and  minDistance < |s_i| < maxDistance,
// s_i = signed distance to the leave-one-out fitted line/plane in units of d0
// (s.fitDistance, positive outside), n_i the fitted outward normal, kappa_i the
// curvature of eq. 20 recomputed here with this effect's curvatureFactor (so the
// gate uses the factor the user chose, whatever factor the solver's fit used).
// sign = -1 (`sign smoothing`, default: moves i toward the fitted surface, the
// stated purpose) or +1 (`sign asPrinted`, eq. 19 literally, which moves an outside
// particle further out; docs/method.md 8.3, 14.5). All gates are in units of d0.
// Reads (system/sphSchemes, shifting/surfaceFitting): C, maxCurvature, minDistance, maxDistance,
// curvatureFactor, sign (smoothing|asPrinted); declared in SurfaceFitting.cpp.
#pragma once
#include "effects/Effect.hpp"

namespace shizuku {

struct SurfaceFittingParameters {
  double C = 1e-4;
  double maxCurvature = 0.2;   // on |kappa| d0
  double minDistance = 0.15;   // on |s| / d0
  double maxDistance = 0.6;    // on |s| / d0
  double curvatureFactor = 0.34;
  bool smoothingSign = true;
};

template <int D>
class SurfaceFitting final : public ShiftTermWith<D, SurfaceFittingParameters> {
 public:
  explicit SurfaceFitting(const SurfaceFittingParameters& p)
      : ShiftTermWith<D, SurfaceFittingParameters>("shifting/surfaceFitting", p) {
    this->needs_.normals = true;
    this->needs_.surfaceFit = true;
  }
  std::string describe() const override;
  void addShift(const FlowState<D>& s, std::vector<Vec<D>>& dr) override;
};

}  // namespace shizuku
