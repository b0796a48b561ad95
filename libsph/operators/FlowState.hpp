// Everything a stage of the ISPH step reads or writes (docs/method.md 13): the
// particles, the neighbour list and per-pair weights of this step, the
// physical constants and the per-step derived fields. Effects receive it;
// arrays that only an effect needs belong to that effect, not here.
#pragma once
#include "core/FluidBalance.hpp"
#include "core/types.hpp"
#include "decomposition/Halo.hpp"
#include "kernels/Kernel.hpp"
#include "operators/Ops.hpp"
#include "particles/NeighbourList.hpp"
#include "particles/ParticleSet.hpp"

namespace shizuku {

template <int D> struct Pose;

template <int D>
struct FlowState {
  ParticleSet<D> particles;
  Kernel<D> kernel;
  PeriodicBox<D> periodic;
  NeighbourList<D> neighbours;           // CSR, built once per step at r^n
  PairWeights<D> weights;                // corrected gradient and Laplacian weights
  std::vector<std::uint8_t> isFluidMask; // 1 for fluid particles (weights are computed for them)
  // 1 for inlet and outlet particles, whose velocity neighbours see as it is (no wall
  // mirror); empty in a case without inlets and outlets.
  std::vector<std::uint8_t> isBufferMask;
  bool hasOpenBoundaries = false;        // the case has inlets or outlets

  // constants (the effects keep their own: g in gravity, nu in viscosity)
  double d0 = 0, h = 0, rho0 = 1000;

  // time
  double time = 0, dt = 0;
  long step = 0;
  // fluid removed, released and captured since the start from particlesDict (kept across
  // restarts in uniform/time): the mass balance and healthChecks/maxLostFraction
  FluidBalance balance;

  // per-step derived fields (sized once, reused every step)
  std::vector<double> divR;              // -sum V r_ij . gradW_ij (free-surface indicator, docs/method.md 5.1)
  std::vector<Vec<D>> gradC;             // kernel-sum gradient, inward (normals, docs/method.md 5.3)
  std::vector<Vec<D>> uStar;             // predicted velocity u* (fluid), Shepard-interpolated (walls)

  // surface fit (docs/method.md 8.2), allocated only when an effect needs it. particles.normal
  // keeps the detector's normal (OPS projects with it); the fit's normal is apart.
  std::vector<Vec<D>> fitNormal;         // fitted outward normal, the detector's where not fitted
  std::vector<double> fitDistance;       // signed distance s_i / d0 (positive outside), NaN where not fitted
  std::vector<double> curvature;         // kappa_i * d0 (eq. 20), NaN where not computed

  // The moving walls' poses at `time`, indexed by WallBox::motion (MovingWalls::poses();
  // nullptr in a case without moving walls): where a rigid wall's rest points are now.
  const std::vector<Pose<D>>* wallPoses = nullptr;

  // A distributed run's halo (nullptr in a serial run): the particles past numOwned() are
  // ghosts, copies of other ranks' particles (docs/parallel.md 4).
  const Halo<D>* halo = nullptr;

  double V() const { return particles.volume(); }
  std::size_t numOwned() const { return halo ? halo->numOwned() : particles.size(); }
  // Refresh the ghosts' values of a per-particle field from their owners: called after a
  // pass computes a field that a later pass reads at neighbours (docs/parallel.md 5).
  template <class T> void exchange(std::vector<T>& field) const { if (halo) halo->update(field); }
  std::size_t size() const { return particles.size(); }
  bool isFluid(std::size_t i) const { return isFluidMask[i] != 0; }
  // isFluidMask (and isBufferMask with open boundaries) from the particle types, sized to
  // the particle count: after the types, the count or the order changed.
  void refreshTypeMasks();
  SurfaceClass surfaceClass(std::size_t i) const { return particles.surfaceClass(i); }

  // W_ij of pair k of row i at the particles' current positions (like r_ij, computed
  // where a pass needs it rather than stored: 8 bytes a pair).
  double w(std::size_t i, Index k) const { return kernel.w(neighbours.r(i, std::size_t(k))); }
  // Summation density <rho>_i = m sum_j W_ij incl. self and walls (eq. 18), for all particles.
  void computeDensity();
};

}  // namespace shizuku
