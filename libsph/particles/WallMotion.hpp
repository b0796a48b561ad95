// The prescribed rigid motion of a wall region (docs/boundaries.md, "Moving walls";
// docs/method.md 11.1): a wall particle at rest position X (where particlesDict builds it)
// is at
//   x(t) = R(t) X + b(t),   u(t) = R'(t) X + b'(t),   a(t) = R''(t) X + b''(t),
// the pose (R, b) being the composition of the motion's steps in file order, each a rigid
// map x -> R_k x + b_k of world coordinates (the first step applied first):
//   translation:  R = I, b = d(t): `displacement ("d_x(t)" "d_y(t)" ["d_z(t)"])` (muParser
//                 expressions of t) or `table "file"` (rows t d_x d_y [d_z]), `interpolation
//                 linear|spline`;
//   oscillating:  R = I, b = r(t) A sin(2 pi t / T + phase): `amplitude (..)` [m],
//                 `period T` [s], `phase` (degrees, default 0), `rampTime T_r` [s] (default 0,
//                 none): r rises as (1 - cos(pi t / T_r))/2 over T_r (MotionSignal.hpp);
//   rotation:     about `centre c` by `angle` (degrees, counter-clockwise; an expression of t,
//                 or a `table` with rows t angle), in 3D about `axis (..)` (right hand):
//                 R = R(theta), b = c - R c.
// Two steps compose as R = R2 R1, b = R2 b1 + b2, their time derivatives by the product
// rule, so velocities and accelerations are exact for exact signals. A motion with several
// steps holds them as named sub-dictionaries, applied in file order:
//   motion { roll { type rotation; ... } sway { type oscillating; ... } }
// Errors (InputError naming file, line and keyword): an unknown type, a rotation without
// a centre (or without an axis in 3D), an expression that does not parse or is not finite
// at t = 0, a table that cannot be read or whose times do not increase (the table's file
// and line named), an empty motion.
// Reads (system/particlesDict regions/<name>/motion): type; displacement; table;
// interpolation; amplitude; period; phase; rampTime; centre; axis; angle.
#pragma once
#include "core/Dictionary.hpp"
#include "particles/MotionSignal.hpp"
#include <memory>
#include <string>
#include <vector>

namespace shizuku {

// The rigid map x = R X + b and its first and second time derivatives.
template <int D>
struct Pose {
  Mat<D> R = Mat<D>::Identity(), dR = Mat<D>::Zero(), ddR = Mat<D>::Zero();
  Vec<D> b = Vec<D>::Zero(), db = Vec<D>::Zero(), ddb = Vec<D>::Zero();
  Vec<D> position(const Vec<D>& X) const { return R * X + b; }
  Vec<D> velocity(const Vec<D>& X) const { return dR * X + db; }
  Vec<D> acceleration(const Vec<D>& X) const { return ddR * X + ddb; }
  Vec<D> restPosition(const Vec<D>& x) const { return R.transpose() * (x - b); }
  // This pose followed by `next`.
  Pose then(const Pose& next) const;
};

template <int D>
class WallMotion {
 public:
  // The motion of the wall region whose `motion` sub-dictionary is `dict`; table files
  // are relative to caseDir (or absolute).
  static std::shared_ptr<WallMotion> read(const Dictionary& dict, const std::string& caseDir);
  // The pose at time t (evaluates the signals; not thread-safe, no allocation).
  Pose<D> pose(double t);
  // "rotation about (0.45 0) by expression ("4*sin(t)") deg", steps joined by " then ".
  std::string describe() const;

 private:
  struct Step {
    enum class Kind { translation, rotation } kind = Kind::translation;
    std::unique_ptr<MotionSignal> signal;  // displacement (D components) or angle (1, radians)
    Vec<D> centre = Vec<D>::Zero();
    Vec<3> axis = Vec<3>::UnitZ();
    std::string text;                       // for describe()
  };
  static Step readStep(const Dictionary& d, const std::string& caseDir);
  static Pose<D> stepPose(Step& s, double t);
  std::vector<Step> steps_;
};

}  // namespace shizuku
