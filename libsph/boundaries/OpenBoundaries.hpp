// Inlets and outlets at run time (docs/boundaries.md, "Inlets and outlets"; the regions
// are read and first filled by particles/OpenBoundaryRegion):
//   - an inlet's particles move at the prescribed velocity u(x, t); one that crosses the
//     inlet's face becomes fluid (it keeps its id, velocity and pressure), and a new inlet
//     particle takes its place one buffer length upstream (a fresh id, nextId), so the
//     buffer stays full on the lattice;
//   - a fluid particle that crosses an outlet's face (within the outlet's extent across
//     the direction) becomes an outlet particle; outlet particles move with the velocity
//     the step's corrector gave them (the Shepard average of their fluid neighbours' velocity,
//     a zero normal gradient; kept without fluid neighbours: WallParticles.hpp), hold the
//     outlet's prescribed pressure, and are removed past the buffer's far face; one carried
//     back upstream more than d0/2 past the face (a backflow) becomes fluid again and is
//     uncounted from the captured ones.
// Released and captured particles are counted per region (flux function object) and in
// FlowState::balance. Inside the step, an inlet particle is a wall particle showing its
// prescribed velocity, an outlet particle a Dirichlet pressure (OpenBoundaryRows.hpp,
// WallParticles.hpp) and both are seen by the viscous term with their own velocity.
// Built only when the case has inlets or outlets. O(N) per step; no allocation once the
// buffers have their capacity.
// Reads no dictionary keys (the regions carry theirs).
#pragma once
#include "boundaries/Domain.hpp"
#include "operators/FlowState.hpp"
#include "particles/OpenBoundaryRegion.hpp"
#include <memory>

namespace shizuku {

template <int D>
class OpenBoundaries {
 public:
  // Checks each buffer against the kernel support (its length along the direction
  // must reach 2h) and the domain (it must lie inside): errors name the region's keys.
  OpenBoundaries(std::vector<OpenBoundaryRegion<D>> regions, const FlowState<D>& s, const Domain<D>& domain);
  ~OpenBoundaries();
  // Inlet velocities u(x, s.time) and outlet pressures on the buffer particles (at the start;
  // afterStep keeps them after each step).
  void prescribe(FlowState<D>& s);
  // After a step (s.time is its end), in one pass: buffers moved by s.dt, inlet
  // velocities set at s.time, release, capture (at the outlet's pressure, which the
  // pressure equation then keeps), removal past the far faces. Returns whether particle
  // types or the count changed (the caller refreshes the step's arrays).
  bool afterStep(FlowState<D>& s);
  const std::vector<OpenBoundaryRegion<D>>& regions() const { return regions_; }
  // Particles released (inlets) or captured (outlets) by each region since this run began.
  const std::vector<BoundaryCrossings>& crossings() const { return crossings_; }
  std::vector<std::string> describe() const;

 private:
  int regionOf(const Vec<D>& x, bool inlet) const;
  Vec<D> inletVelocity(int r, const Vec<D>& x, double t) const;
  void numberReleased(ParticleSet<D>& P) const;

  std::vector<OpenBoundaryRegion<D>> regions_;
  std::vector<std::unique_ptr<InletVelocity<D>>> velocity_;  // per region; null for outlets
  std::vector<BoundaryCrossings> crossings_;
  std::vector<std::uint8_t> remove_;  // scratch: outlet particles past their far face
  std::vector<std::size_t> released_; // scratch: the inlet particles added this step (ids to give)
  double d0_ = 0;
};

}  // namespace shizuku
