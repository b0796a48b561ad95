// The domain of a run (docs/boundaries.md, "Domain, outflow and leaks"): the box a fluid
// particle must stay in; one that leaves it is removed (isph/Outflow), not a failure.
//   - `domain { min (..); max (..); }` in system/controlDict: that box;
//   - else, where the case has a container wall (a wall box without `solid yes`): the
//     union of every wall's bounds, each wall box (its surface grown by its layers)
//     extended beyond each OPEN face by the box's own size in that direction, so that
//     spray rising above an open top falls back in while a droplet that falls outside the
//     tank leaves; a solid (a solid box, a curved or STL body) bounds its own box;
//   - else unbounded (only the speed and non-finite guards apply): solids alone hold no
//     fluid, and the fluid around them may go anywhere.
// A wall kind adds its bounds through wallBounds (its outer box).
// Errors (InputError naming file, line, keyword): min >= max in some direction, or a
// domain that does not hold every fluid particle of the initial state.
// Reads (system/controlDict): domain { min; max; } (m), declared in Domain.cpp.
#pragma once
#include "core/Dictionary.hpp"
#include "particles/ParticleSet.hpp"
#include "particles/WallBox.hpp"
#include <string>
#include <vector>

namespace shizuku {

template <int D>
class Domain {
 public:
  // Unbounded.
  Domain() = default;
  Domain(const Vec<D>& min, const Vec<D>& max) : bounded_(true), min_(min), max_(max) {}

  // The domain of a case: the controlDict's `domain`, or the walls' default; checked
  // against the fluid particles of `p`.
  static Domain read(const Dictionary& controlDict, const std::vector<WallBox<D>>& walls, const ParticleSet<D>& p);
  // The default bounds of a wall box: its outer box, extended beyond each open face.
  static void wallBounds(const WallBox<D>& w, Vec<D>& lo, Vec<D>& hi);

  bool bounded() const { return bounded_; }
  const Vec<D>& min() const { return min_; }
  const Vec<D>& max() const { return max_; }
  bool contains(const Vec<D>& x) const {
    if (!bounded_) return true;
    for (int k = 0; k < D; ++k)
      if (!(x[k] >= min_[k] && x[k] <= max_[k])) return false;
    return true;
  }
  // The face a point outside left by ("above +y", ...), for the messages.
  std::string side(const Vec<D>& x) const;
  // For -dryRun and the log.
  std::string describe() const { return describe_; }

 private:
  bool bounded_ = false;
  Vec<D> min_ = Vec<D>::Zero(), max_ = Vec<D>::Zero();
  std::string describe_ = "unbounded (no container wall, no controlDict domain)";
};

}  // namespace shizuku
