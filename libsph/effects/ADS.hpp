// Advective dynamic stabilization (ADS, docs/method.md 9; Tsuruta, Khayyer & Gotoh 2023,
// reconstructed there): after advection, particles near the free surface that are
// closer than d_ADS to a neighbour are moved apart:
//   dr_i = C sum_{j : |r_ij| < d_ADS} omega_ij (d_ADS - |r_ij|) e_ij,  e_ij = r_ij / |r_ij|,
// for fluid i in free, splash or vicinity; j any neighbour (fluid or wall).
// omega_ij = m_j / (m_i + m_j) = 1/2 when j is moved by ADS too (equal masses), and
// omega_ij = 1 when j is not moved (a wall, as in docs/method.md 9, and, by the same
// rule, an interior fluid particle) so the pair recovers d_ADS either way.
// Jacobi: all dr_i are computed from one configuration, then applied. Walls are
// never moved; velocities are not changed (advective correction only). The
// solver refreshes the pair geometry afterwards.
// Options (docs/method.md 9 leaves them open):
//   partners surface  (default) only near-surface particles move; an interior
//                     fluid partner or a wall stays and i takes the whole correction;
//   partners pair     both fluid partners of a pair with a near-surface particle move by
//                     half (the pair's centroid stays: no outward push of the surface);
//   approaching yes   only pairs closing in, (u_i - u_j) . r_ij < 0, act.
//   wallDistance      d_ADS for a wall partner (times d0), default: `distance`
//                     (1 pushed the coarse dam break and drop over-dense, docs/shifting.md).
// Reads (system/sphSchemes, ads): distance, wallDistance (times d0), C, partners, approaching;
// defaults and ranges are declared in ADS.cpp (docs/dictionaries.md, keyword reference).
#pragma once
#include "effects/Effect.hpp"

namespace shizuku {

template <int D>
class ADS final : public PositionCorrectionEffect<D> {
 public:
  struct Options {
    bool pairwise = false;         // partners pair
    bool approachingOnly = false;  // approaching yes
    double wallDistance = -1;      // d_ADS / d0 for wall partners; < 0: the same as distance
  };
  ADS(double distance, double C, Options o = {}) : PositionCorrectionEffect<D>("ads"), distance_(distance), C_(C), o_(o) {
    if (o_.wallDistance < 0) o_.wallDistance = distance;
  }
  std::string describe() const override;
  void allocate(const FlowState<D>& s) override { delta_.assign(s.size(), Vec<D>::Zero()); }
  void correctPositions(FlowState<D>& s) override;

 private:
  double distance_;  // d_ADS / d0
  double C_;
  Options o_;
  std::vector<Vec<D>> delta_;  // scratch, sized in allocate()
};

}  // namespace shizuku
