// Volume-conservation shift, eq. (17) with the summation density of eq. (18)
// (docs/method.md 7):
//   dr_vol_i = C h sum_{j in S*_i} (<rho>_i/rho0 - 1 + <rho>_j/rho0 - 1) e_ij,   i interior fluid,
//   S*_i = {j != i : |r_ij| < 1.1 sqrt(D) d0},   e_ij = (r_i - r_j) / |r_i - r_j| (from j to i).
// Sign (checked, docs/method.md 14.4): with e_ij from j to i an under-dense pair
// (negative bracket) moves i toward j, so an expanded region contracts and a
// compressed one expands; the opposite sign would be anti-conservative.
// Wall neighbours are in S*_i with their own term set to zero (<rho>_w := rho0) so
// that an interior particle next to a wall sees a symmetric neighbourhood. Fluid
// neighbours near the free surface (vicinity, free, splash) are treated the same way:
// their kernel sums are truncated by the missing outside, and reading that deficit as
// under-density pulled the interior outward and spread it (test_effects_volumeCorrection).
// <rho> is s.particles.density (computed by the solver at the current positions,
// self term and walls included); rho0 = s.rho0 (masses calibrated on the lattice).
// Reads (system/sphSchemes, shifting/volumeCorrection): C (declared in VolumeCorrection.cpp).
#pragma once
#include "effects/Effect.hpp"

namespace shizuku {

template <int D>
class VolumeCorrection final : public ShiftTerm<D> {
 public:
  explicit VolumeCorrection(double C) : ShiftTerm<D>("shifting/volumeCorrection"), C_(C) {}
  std::string describe() const override;
  void addShift(const FlowState<D>& s, std::vector<Vec<D>>& dr) override;
  double coefficient() const { return C_; }

 private:
  double C_;
};

}  // namespace shizuku
