// Particle-distribution shift (the dispersion term of eq. 10):
//
// OPS, eqs. (11)-(13) (docs/method.md 6):
//   gradC_i  = sum_{j in S_i} V [1 + Rp (W_ij / W(d0))^np] G_ij      (fluid and wall j)
//   dr_ps    = -C h^2 gradC_i
//   dr_dis   = dr_ps (interior),  (I - n_i n_i) dr_ps (free, splash, vicinity)
// with n_i the detector's normal (docs/method.md 5.3, the concentration-gradient normal).
// Vicinity particles whose support does not reach past the surface, |sum_j V grad W_ij| h
// < projectionThreshold, have no defined normal (it pointed inward on the rotating patch,
// breaking its symmetry) and are shifted like interior ones. Measured (docs/shifting.md):
// with the fitted normals of the surface fit (docs/method.md 5.3's recommendation) the dam
// break's interior density error at t = 0.5 s was twice as large.
// Sign: grad_i W_ij = W'(r) r_ij / r points from i toward j (W' < 0), so gradC_i points
// toward denser regions and -C h^2 gradC_i moves i toward sparser ones. W(d0) is the
// kernel at distance d0 (docs/method.md 2, 14.2). `gradient` chooses G_ij:
//   kernel (default): the plain kernel gradient grad_i W_ij (Lind et al. 2012).
//   corrected: the SPH(2) weights s.weights.gradW in the same non-difference sum, as the
//     seed writes. Measured UNSTABLE (docs/shifting.md): a corrected gradient is exact
//     for quadratics, so in the non-difference sum it cancels the smooth (long-wave)
//     part of the concentration gradient; the density spread of a perturbed lattice
//     grows (0.032 -> 0.10 in 40 shifts). Kept only to reproduce the literal reading.
//   concentration: the SPH(2) gradient of the concentration field C = <rho>/rho0 in
//     difference form, sum V (C_j - C_i) gradW_ij, plus the anti-clumping part
//     Rp sum V (W_ij/W(d0))^np grad_i W_ij with the kernel gradient (a pair repulsion).
//
// DPS, eq. (14) with the missing length factor C h (docs/method.md 7, 14.3):
//   dr_dis = C h sum_{j in S*_i} V W_ij e_ij,  e_ij = r_ij / |r_ij|, |r_ij| < 1.1 sqrt(D) d0
// (short-range repulsion; fluid and wall j). The same tangential projection as OPS is
// applied on free, splash and vicinity particles so that neither type pushes particles
// through the free surface.
//
// Beside a dry wall (a wall that rises above the water, docs/method.md 6): a free or splash
// particle whose surface fit (docs/method.md 8.2) holds and which has a wall neighbour beyond
// the surface, (r_j - r_i) . n_fit > d0/2 (the surface of eq. 6b), projects with the fitted normal and
// leaves those wall particles out of its sum, so that a still tank is a fixed point of the
// shift (otherwise the dry wall lifted the top corner particles and pushed the surface row
// along the surface, tests/unit/test_effects_ops.cpp). Vicinity particles are not treated so:
// measured, that raised the dam break's interior density error (docs/shifting.md).
//
// A free/splash/vicinity particle whose normal is undefined (zero) gets no shift.
// Wall particles are never shifted.
// Reads (system/sphSchemes, shifting/distribution): type (OPS|DPS), C, Rp, np, gradient
// (kernel|corrected|concentration), projectionThreshold; declared in ShiftingDistribution.cpp.
#pragma once
#include "effects/Effect.hpp"

namespace shizuku {

struct DistributionParameters {
  enum class Type { OPS, DPS };
  Type type = Type::OPS;
  double C = 0.2;               // C_dis (OPS: must be <= 0.5, diffusion stability)
  double Rp = 0.2;              // anti-clumping amplitude
  double np = 4;                // anti-clumping exponent
  enum class Gradient { kernel, corrected, concentration };
  Gradient gradient = Gradient::kernel;
  double projectionThreshold = 0.01;  // |sum V grad W| h below which vicinity is not projected
};

template <int D>
class ShiftingDistribution final : public ShiftTermWith<D, DistributionParameters> {
 public:
  explicit ShiftingDistribution(const DistributionParameters& p)
      : ShiftTermWith<D, DistributionParameters>("shifting/distribution", p) {
    this->needs_.normals = true;
    this->needs_.surfaceFit = true;  // the frame beside a dry wall
  }
  std::string describe() const override;
  void addShift(const FlowState<D>& s, std::vector<Vec<D>>& dr) override;
};

}  // namespace shizuku
