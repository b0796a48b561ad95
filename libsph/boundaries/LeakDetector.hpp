// Wall leaks (docs/boundaries.md, "Domain, outflow and leaks"): a fluid particle that
//   - lies inside a wall box's layer region deeper than half a spacing past the wall
//     surface (at or beyond the first row of wall particles), or
//   - crossed the layers of a closed wall face since the previous step (was on one side
//     of them and is now on the other, through the face),
// has leaked through the wall. O(N x walls) per step, no allocation once `leaks` has
// its capacity. Open faces are not checked (fluid may leave through them). A solid wall
// box (an obstacle) is checked for the first condition only: crossing it in one step
// would take a move longer than its thickness, which the Courant limit (0.2 h) forbids
// for any obstacle thicker than a spacing. A solid box's face that lies against another
// wall (its centre, d0/2 outside the face, is inside that wall's layers or solid: a box on
// the tank's floor) is covered: depth in the box is measured from its other faces, so fluid
// squeezed between the floor and the box's bottom row is a leak. So is a curved or STL solid (WallBox::body):
// a particle inside it with phi < -d0/2 (past its first layer) is a leak through its
// surface; only particles in its bounding box evaluate phi.
// A moving wall (WallBox::motion >= 0) is tested in its own frame: the particle's position
// is taken back to the wall's rest frame with the wall's pose now (X = R^T (x - b)), its
// previous position with the pose one step earlier.
// Reads no dictionary keys (the walls come from particlesDict through the generator).
#pragma once
#include "particles/NeighbourList.hpp"
#include "particles/ParticleSet.hpp"
#include "particles/WallBox.hpp"
#include "particles/WallMotion.hpp"
#include <string>
#include <vector>

namespace shizuku {

struct Leak {
  Index particle = 0;   // index in the particle arrays
  int wall = 0;         // index in walls()
  int face = 0;         // 2k (-x_k) or 2k + 1 (+x_k); kBodySurface for a curved or STL solid
  bool crossed = false; // crossed the layers in one step (else: found inside them)
};

template <int D>
class LeakDetector {
 public:
  // Marks the covered faces of the solid boxes among `walls`.
  explicit LeakDetector(std::vector<WallBox<D>> walls);
  bool active() const { return !walls_.empty(); }
  const std::vector<WallBox<D>>& walls() const { return walls_; }
  // The leaks of the fluid particles of p; `previous` holds their positions one step
  // earlier, same order (empty: the crossing test is skipped). Sorted by particle.
  // poses, previousPoses: the moving walls' poses now and one step earlier, indexed by
  // WallBox::motion (empty without moving walls).
  void find(const ParticleSet<D>& p, const std::vector<Vec<D>>& previous, const PeriodicBox<D>& periodic,
            std::vector<Leak>& leaks, const std::vector<Pose<D>>& poses = {},
            const std::vector<Pose<D>>& previousPoses = {}) const;
  // "wall 'tank', face left (-x)"; "wall 'pier' (solid cylinder)".
  std::string describe(const Leak& l) const;

 private:
  bool crossed(const WallBox<D>& w, int face, const Vec<D>& from, const Vec<D>& to) const;
  std::vector<WallBox<D>> walls_;
};

// "left (-x)", "right (+x)", "bottom (-y)", "top (+y)", "front (-z)", "back (+z)", and
// "surface (of a curved or STL solid)" for kBodySurface.
const char* faceLabel(int face);

}  // namespace shizuku
