// Advective dynamic stabilization (ADS, methods.md 9; Tsuruta, Khayyer & Gotoh 2023,
// reconstructed there): after advection, particles near the free surface that are
// closer than d_ADS to a neighbour are moved apart:
//   dr_i = C sum_{j : |r_ij| < d_ADS} omega_ij (d_ADS - |r_ij|) e_ij,  e_ij = r_ij / |r_ij|,
// for fluid i in free, splash or vicinity; j any neighbour (fluid or wall).
// omega_ij = m_j / (m_i + m_j) = 1/2 when j is moved by ADS too (equal masses), and
// omega_ij = 1 when j is not moved (a wall, as in methods.md 9, and, by the same
// rule, an interior fluid particle) so the pair recovers d_ADS either way.
// Jacobi: all dr_i are computed from one configuration, then applied. Walls are
// never moved; velocities are not changed (advective correction only). The
// solver refreshes the pair geometry afterwards.
// Reads (system/sphSchemes, ads): distance 1; (times d0)  C 1;
#pragma once
#include "effects/Effect.hpp"

namespace shizuku {

template <int D>
class ADS final : public Effect<D> {
 public:
  ADS(double distance, double C) : distance_(distance), C_(C) {}
  std::string name() const override { return "ads"; }
  EffectStage stage() const override { return EffectStage::postAdvection; }
  std::string describe() const override;
  void allocate(const FlowState<D>& s) override { delta_.assign(s.size(), Vec<D>::Zero()); }
  void correctPositions(FlowState<D>& s) override;
  long lastActionCount() const override { return count_; }

 private:
  double distance_;  // d_ADS / d0
  double C_;
  std::vector<Vec<D>> delta_;  // scratch, sized in allocate()
  long count_ = 0;
};

}  // namespace shizuku
