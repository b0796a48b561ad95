// Volume-conservation shift, eq. (17); formula and sign in VolumeCorrection.hpp.
#include "effects/VolumeCorrection.hpp"
#include "effects/EffectFactories.hpp"
#include "core/Parameter.hpp"
#include <cmath>

namespace shizuku {

namespace key {  // const: internal linkage
const ParameterGroup volume("system/sphSchemes: shifting/volumeCorrection",
    "Volume-conservation shift of interior particles, eq. 17 (docs/method.md 7).");
const ScalarParameter C = volume.scalar("C", dim::none, "coefficient C_vol (shift = C h sum ...)").def(0.1).min(0).max(1);
}  // namespace key

template <int D>
std::unique_ptr<Effect<D>> makeVolumeCorrection(const Dictionary& d, const FlowState<D>&) { return std::make_unique<VolumeCorrection<D>>(key::C.read(d)); }

template <int D>
std::string VolumeCorrection<D>::describe() const {
  return cat("C = ", C_, " (shift length C h per unit density error), interior particles, "
             "neighbours within 1.1 sqrt(D) d0, wall and near-surface terms zero");
}

template <int D>
void VolumeCorrection<D>::addShift(const FlowState<D>& s, std::vector<Vec<D>>& dr) {
  const auto& nl = s.neighbours;
  const auto& rho = s.particles.density;
  const double invRho0 = 1.0 / s.rho0;
  const double rStar = 1.1 * std::sqrt(double(D)) * s.d0;
  const double coeff = C_ * s.h;
  const long n = long(s.size());
  long count = 0;
#pragma omp parallel for schedule(static) reduction(+ : count)
  for (long i = 0; i < n; ++i) {
    if (!s.isFluid(i) || s.surfaceClass(i) != SurfaceClass::interior) continue;
    const double ei = rho[i] * invRho0 - 1.0;
    Vec<D> sum = Vec<D>::Zero();
    // A neighbour's own density counts only when its kernel sum is whole: a wall, or a
    // fluid particle near the surface (its sum truncated by the missing outside),
    // contributes zero, or the kernel deficit would read as under-density and pull
    // the interior outward (docs/method.md 7, implementation notes).
    const auto errorSum = [&](Index k) {
      const Index j = nl.j[k];
      const bool whole = s.isFluid(j) && s.surfaceClass(j) == SurfaceClass::interior;
      return ei + (whole ? rho[j] * invRho0 - 1.0 : 0.0);
    };
    Index k = nl.begin(i);
    const Index e = nl.end(i);
    for (; k + 1 < e; k += 2) {  // two pairs' square roots and divisions in one instruction each
      Vec<D> rij[2];
      const DoublePair r = nl.r2(std::size_t(i), std::size_t(k), rij);
      const DoublePair q = DoublePair{errorSum(k), errorSum(k + 1)} / r;
      for (int lane = 0; lane < 2; ++lane)
        if (r[lane] < rStar && r[lane] > 0) sum += q[lane] * rij[lane];
    }
    for (; k < e; ++k) {
      const Vec<D> rij = nl.rij(std::size_t(i), k);
      const double r = rij.norm();
      if (!(r < rStar) || !(r > 0)) continue;
      sum += (errorSum(k) / r) * rij;
    }
    dr[i] += coeff * sum;
    ++count;
  }
  this->actionCount_ = count;
}

SHIZUKU_EFFECT(VolumeCorrection, makeVolumeCorrection);

}  // namespace shizuku
