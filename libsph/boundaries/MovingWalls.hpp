// The wall regions that move (docs/boundaries.md, "Moving walls"; docs/method.md 11.1),
// at run time. Built only when a wall region of particlesDict has a `motion`; a case
// without one builds nothing of this (no field, no loop, no pipeline line).
//   - place(t):             every moving wall particle to x = R(t) X + b(t), X its rest
//                           position (the particle field `restPosition`, which restarts read
//                           back, so a restart continues the motion exactly), its wall normal
//                           turned with it (`wallNormal` = R(t) `restNormal`, WallNormals.hpp);
//                           the poses at t kept for the leak test.
//   - prescribeVelocity(t): the velocities U = R'(t) X + b'(t), set at the start of a step to
//                           their value at its end, t^{n+1}: the wall row's velocity term
//                           (eq. 11a) then drives the fluid's normal velocity to the wall's at
//                           t^{n+1}, and the no-slip mirror velocity is the wall's at the step's
//                           end; after the step they are the velocities of the walls' new time.
//   - extremes(t):          the largest speed and acceleration of any moving wall particle,
//                           bounded by those of the corners of each wall's rest box (both are
//                           affine in X, so over a box they peak at a corner): no pass over the
//                           particles and the same on every rank. TimeLoop takes the limits
//                           dt <= maxCo h / max|U_w| (the wall's Courant number, as the fluid's)
//                           and dt <= 0.25 sqrt(h / max|a_w|) (as a body force) at the step's
//                           start and one previous step later.
//   - sweptBox:             the box a wall's outer box sweeps over a time interval, for the
//                           domain's default bounds: sampled at most 1 ms apart (2001 to 2e6
//                           instants) and padded by half a sample gap times the largest
//                           corner speed, so a fast oscillation is not missed between samples.
// Particles carry the index of their motion + 1 in the field `motion` (0: fixed).
// Reads no dictionary keys (WallMotion reads the `motion` sub-dictionaries).
#pragma once
#include "particles/ParticleSet.hpp"
#include "particles/WallBox.hpp"
#include "particles/WallMotion.hpp"
#include <memory>
#include <string>
#include <vector>

namespace shizuku {

template <int D>
class MovingWalls {
 public:
  // motions[k] moves the particles with field motion == k + 1; names[k] is its region's,
  // boxes[k] its outer box at rest (WallBox::outerMin, outerMax), which holds its particles.
  MovingWalls(std::vector<std::shared_ptr<WallMotion<D>>> motions, std::vector<std::string> names,
              std::vector<std::pair<Vec<D>, Vec<D>>> boxes);

  void place(ParticleSet<D>& P, double t);
  void prescribeVelocity(ParticleSet<D>& P, double t);
  // Largest speed and acceleration at time t of a moving wall's rest-box corners.
  void extremes(double t, double& speed, double& acceleration);
  // The poses at the last place() and at the one before (equal after the first).
  const std::vector<Pose<D>>& poses() const { return now_; }
  const std::vector<Pose<D>>& previousPoses() const { return before_; }
  // One line per moving region, for the pipeline.
  std::vector<std::string> describe() const;

  // The bounding box of w's outer box moved by m over [t0, t1].
  static void sweptBox(const WallBox<D>& w, WallMotion<D>& m, double t0, double t1, Vec<D>& lo, Vec<D>& hi);

 private:
  void evaluate(double t);
  std::vector<std::shared_ptr<WallMotion<D>>> motions_;
  std::vector<std::string> names_;
  std::vector<std::pair<Vec<D>, Vec<D>>> boxes_;
  std::vector<Pose<D>> now_, before_, scratch_;
  bool placed_ = false;
};

}  // namespace shizuku
